//! The Maze experiment of section 6.3.1. The domain (declared in the
//! manifest, so it never names an agent): the modified Dyna Maze ([`env`](mod@env),
//! [`layout`]), its shortest paths ([`search`]) and the synthetic
//! demonstrator ([`demonstrator`]). Then the experiment: the parameters and
//! the Maze as a domain of the five agents ([`params`]), what they learn
//! from the demonstrations ([`inputs`]) and the trials ([`experiment`]).

pub mod demonstrator;
pub mod env;
pub mod experiment;
pub mod inputs;
pub mod layout;
pub mod params;
pub mod search;

pub use env::{Maze, MazeRewards, Move};
pub use layout::MazeLayout;

/// Takes `steps` uniformly random moves in the agent's Maze (restarting at
/// the goal) and returns `steps`: the simulator alone, for speed measurements.
pub fn random_walk_steps(seed: u64, steps: u64) -> u64 {
    use rlfd_rl::Environment;
    let mut rng = rlfd_rl::random::seeded(seed);
    let mut env = Maze::thesis_agent();
    env.reset(&mut rng);
    for _ in 0..steps {
        if env.step(rlfd_rl::random::below(&mut rng, 4), &mut rng).terminal {
            env.reset(&mut rng);
        }
    }
    steps
}
