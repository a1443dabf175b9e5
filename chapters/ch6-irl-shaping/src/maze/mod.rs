//! The Maze experiment of section 6.3.1. The domain is the `rlfd-maze` crate
//! (its modules are re-exported here): the modified Dyna Maze, its shortest
//! paths and the synthetic demonstrator. Then the experiment: the parameters
//! and the Maze as a domain of the five agents ([`params`]), what they learn
//! from the demonstrations ([`inputs`]) and the trials ([`experiment`]).

pub mod experiment;
pub mod inputs;
pub mod kernel;
pub mod params;

pub use rlfd_maze::{Maze, MazeLayout, MazeRewards, Move, demonstrator, env, layout, random_walk_steps, search};
