//! Mario for the thesis's section 6.3.2: our own platformer after the Mario AI
//! Benchmark 0.2.0 (Karakovskiy & Togelius; the version whose intermediate
//! reward is the thesis's reward table), written for speed, the thesis's 27
//! state variables, and the synthetic expert that stands in for the thesis's
//! human demonstrator. Its tick follows the benchmark's `LevelScene.tick`
//! order: on the benchmark's own levels and keys it replays 1,000 of 1,000
//! recorded forward-jumping episodes and 198 of 200 random ones tick for
//! tick (`examples/replay_oracle.rs`; the two differ where the benchmark's
//! sparkles, not simulated, hide an enemy). What stays simplified is listed
//! in chapter 6's `deviations.toml`.
//!
//! - [`level`]: tiles and the level generator (zones by weighted odds, enemy templates).
//! - [`sprites`]: enemies, shells, bullet bills, power-ups, fireballs.
//! - [`decay`]: damping speeds without subnormal arithmetic, bit for bit.
//! - [`world`]: Mario's physics, the spawner, collisions, the scoring and the timer.
//! - [`observation`]: the thesis's 27 state variables.
//! - [`env`](mod@env): the [`rlfd_env::Environment`] (12 actions, a random level and start mode per episode).
//! - [`demonstrator`]: the synthetic expert and its calibration.
//! - [`baseline`]: the oracle's fixed policies (random, forward-jumping), for comparison with the real benchmark.
//!
//! What it is not: a pixel-exact copy of the benchmark (the Java code is not
//! ours to copy; ours follows its rules and constants in its units), or an
//! agent: the crate depends on `rlfd-env` alone among the workspace's
//! libraries, so it cannot name a learner.

pub mod baseline;
pub mod decay;
pub mod demonstrator;
pub mod env;
pub mod level;
pub mod observation;
pub mod sprites;
pub mod world;

pub use env::{ACTIONS, MarioEnv};
pub use level::{Level, LevelParams};
pub use world::{Keys, Mode, Status, World};

/// Plays `ticks` ticks of uniformly random actions on the experiment's levels
/// (a new level at every episode's end) and returns `ticks`: the simulator
/// alone, observation included, for speed measurements.
pub fn random_ticks(seed: u64, ticks: u64) -> u64 {
    use rlfd_env::Environment;
    let mut rng = rlfd_env::random::seeded(seed);
    let mut env = MarioEnv::new(LevelParams::EXPERIMENT);
    env.reset(&mut rng);
    for _ in 0..ticks {
        if env.step(rlfd_env::random::below(&mut rng, ACTIONS), &mut rng).terminal {
            env.reset(&mut rng);
        }
    }
    ticks
}
