//! 3 vs 2 Keepaway (Stone, Sutton & Kuhlmann 2005), simulated from scratch
//! with the soccer server's physics: the domain of the thesis's chapter 5.
//!
//! - [`geometry`]: plane vectors;
//! - [`server`]: rcssserver 11's constants and one 100 ms cycle of physics;
//! - [`skills`]: the players' moving, intercepting and kicking skills;
//! - [`players`]: the hand-coded GetOpen and the takers' policy;
//! - [`state`]: the macro-actions and the 13 state variables;
//! - [`sim`]: the referee and the game, driven one decision at a time.
//!
//! What it is not: it knows no learner, teacher or rule set (the tidy test
//! keeps agents out of this folder); the keepers' choices come from outside
//! through [`Keepaway::run`] and [`Keepaway::act`].

pub mod geometry;
pub mod players;
pub mod server;
pub mod sim;
pub mod skills;
pub mod state;

pub use geometry::Vec2;
pub use sim::{
    CYCLES_PER_HOUR, CYCLES_PER_SECOND, EndCause, KEEPERS, Keepaway, KeepawayParamError, KeepawayParams, Snapshot,
    Status, TAKERS, other_two,
};
pub use state::{KeeperAction, STATE_VARS};
