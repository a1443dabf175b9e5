//! What every domain of the reproduction stands on, and nothing more: the
//! episodic task interface, the seeded random generator, and the format of
//! demonstrations.
//!
//! What it is: [`Environment`] (an episodic task with discrete actions and a
//! real-valued state vector, moved on by one [`Step`] at a time); [`random`]
//! (the ChaCha8 generator every simulation and learner draws from, seeded by
//! the harness, and the pinned draws built on it); [`demonstration`]
//! (trajectories of states and actions in memory, CSV and JSON Lines, with
//! file:line:field errors).
//!
//! What it is not: no learner, no shaping, no experiment. The domain crates
//! (`domains/*`: the Nao sorting world, the DBug table, Keepaway, the Maze,
//! Mario) depend on this crate alone among the workspace's libraries, so
//! Cargo itself keeps every simulator free of agents; `rlfd-rl` (the
//! learners) and `rlfd-lfd` (learning from demonstration) build on it.
//!
//! ```
//! use rlfd_env::random::{seeded, below};
//! let mut rng = seeded(7);
//! let a = below(&mut rng, 4);
//! assert!(a < 4);
//! assert_eq!(below(&mut seeded(7), 1000), below(&mut seeded(7), 1000));
//! ```

pub mod demonstration;
pub mod environment;
pub mod random;

pub use environment::{Environment, Step};
