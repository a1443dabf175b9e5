//! The Mario AI experiment of section 6.3.2. The domain is the `rlfd-mario`
//! crate (its modules are re-exported here): the simulator, the 27 state
//! variables and the synthetic expert.
//!
//! Then the experiment: the parameters, the tile coding and Mario as a
//! domain of the five agents ([`params`]; SBS's potential searched over
//! packed states, [`similarity`]), what they learn from the
//! demonstrations ([`inputs`]) and the trials ([`experiment`]: Tables 6.3
//! and 6.4, the demonstration-length study of Figures 6.6 and 6.7), and the
//! simulator's validation against the real benchmark ([`validation`]).

pub mod experiment;
pub mod inputs;
pub mod params;
pub mod similarity;
pub mod validation;

pub use rlfd_mario::{
    ACTIONS, Keys, Level, LevelParams, MarioEnv, Mode, Status, World, demonstrator, env, level, observation,
    random_ticks, sprites, world,
};
