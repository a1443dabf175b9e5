//! The Mario AI experiment of section 6.3.2. The domain (declared in the
//! manifest, so it never names an agent): our own Mario-like platformer
//! after the 2009 Mario AI Benchmark (Karakovskiy & Togelius), written for
//! speed, and its synthetic expert.
//!
//! - [`level`]: tiles and the level generator (zones by weighted odds, enemy templates).
//! - [`sprites`]: enemies, shells, bullet bills, power-ups, fireballs.
//! - [`world`]: Mario's physics, the spawner, collisions, the scoring and the timer.
//! - [`observation`]: the thesis's 27 state variables.
//! - [`env`](mod@env): the [`rlfd_rl::Environment`] (12 actions, a random level and start mode per episode).
//! - [`demonstrator`]: the synthetic expert and its calibration.
//!
//! What the domain is not: a pixel-exact copy of the benchmark (the Java
//! code is not ours to copy; ours follows its rules and constants in its
//! units), or an agent: nothing in it imports a learner.
//!
//! Then the experiment: the parameters, the tile coding and Mario as a
//! domain of the five agents ([`params`]), what they learn from the
//! demonstrations ([`inputs`]) and the trials ([`experiment`]: Tables 6.3
//! and 6.4, the demonstration-length study of Figures 6.6 and 6.7).

pub mod demonstrator;
pub mod env;
pub mod experiment;
pub mod inputs;
pub mod level;
pub mod observation;
pub mod params;
pub mod sprites;
pub mod world;

pub use env::{ACTIONS, MarioEnv};
pub use level::{Level, LevelParams};
pub use world::{Keys, Mode, Status, World};

/// Plays `ticks` ticks of uniformly random actions on the experiment's levels
/// (a new level at every episode's end) and returns `ticks`: the simulator
/// alone, observation included, for speed measurements.
pub fn random_ticks(seed: u64, ticks: u64) -> u64 {
    use rlfd_rl::Environment;
    let mut rng = rlfd_rl::random::seeded(seed);
    let mut env = MarioEnv::new(LevelParams::EXPERIMENT);
    env.reset(&mut rng);
    for _ in 0..ticks {
        if env.step(rlfd_rl::random::below(&mut rng, ACTIONS), &mut rng).terminal {
            env.reset(&mut rng);
        }
    }
    ticks
}
