//! The Maze of the thesis's section 6.3.1: the modified Dyna Maze (Sutton &
//! Barto), continuous over the unit square with four moves, its shortest
//! paths, and the synthetic demonstrator standing in for the thesis's human.
//!
//! - [`env`](mod@env): the [`rlfd_env::Environment`] (moves of 0.02, walls, −1 per step, +10 at the goal);
//! - [`layout`]: the walls (the thesis's figure and the unlisted ones, as readings);
//! - [`search`]: shortest paths over the demonstrator's lattice;
//! - [`demonstrator`]: the synthetic demonstrator and its calibration on the thesis's inputs.
//!
//! What it is not: an agent, a shaping or an experiment (chapter 6's crate
//! holds those). The crate depends on `rlfd-env` alone among the workspace's
//! libraries, so it cannot name a learner.

pub mod demonstrator;
pub mod env;
pub mod layout;
pub mod search;

pub use env::{Maze, MazeRewards, Move};
pub use layout::MazeLayout;

/// Takes `steps` uniformly random moves in the agent's Maze (restarting at
/// the goal) and returns `steps`: the simulator alone, for speed measurements.
pub fn random_walk_steps(seed: u64, steps: u64) -> u64 {
    use rlfd_env::Environment;
    let mut rng = rlfd_env::random::seeded(seed);
    let mut env = Maze::thesis_agent();
    env.reset(&mut rng);
    for _ in 0..steps {
        if env.step(rlfd_env::random::below(&mut rng, 4), &mut rng).terminal {
            env.reset(&mut rng);
        }
    }
    steps
}
