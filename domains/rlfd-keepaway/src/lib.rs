//! Keepaway (Stone, Sutton & Kuhlmann 2005), simulated from scratch with the
//! soccer server's physics and the keepaway 0.6 players' skills: the domain
//! of the thesis's chapter 5 (3 vs 2 on 20 m × 20 m), for any of the
//! framework's configurations (3 to 5 keepers, 2 to 4 takers, any region).
//!
//! - [`geometry`]: plane vectors;
//! - [`server`]: rcssserver 11's constants, commands, one 100 ms cycle of
//!   physics and the collisions;
//! - [`skills`]: the players' turning, moving, intercepting and kicking skills;
//! - [`players`]: who goes for the ball, the hand-coded GetOpen and the takers' policy;
//! - [`state`]: the macro-actions and the state variables (13 in 3 vs 2);
//! - [`vision`]: how the players see the ball (the server's quantisation);
//! - [`sim`]: the referee and the game, driven one decision at a time;
//! - [`benchmarks`]: the keepaway 0.6 players' three fixed keeper policies
//!   (Always Hold, Random, Hand-coded).
//!
//! What it is not: it knows no learner, teacher or rule set (the crate
//! depends on `rlfd-env` alone among the workspace's libraries); the
//! keepers' choices come from outside
//! through [`Keepaway::run`] and [`Keepaway::act`].

pub mod benchmarks;
pub mod geometry;
pub mod players;
pub mod server;
pub mod sim;
pub mod skills;
pub mod state;
pub mod vision;

pub use benchmarks::BenchmarkPolicy;
pub use geometry::Vec2;
pub use sim::{
    BeliefRecord, CYCLES_PER_HOUR, CYCLES_PER_SECOND, EndCause, KEEPERS, Keepaway, KeepawayParamError, KeepawayParams,
    KickEvent, KickTally, MAX_KEEPERS, MAX_TAKERS, SeePhases, Snapshot, StateBuffer, Status, TAKERS, other_two,
};
pub use state::{KeeperAction, MAX_STATE_VARS, STATE_VARS, state_len};
