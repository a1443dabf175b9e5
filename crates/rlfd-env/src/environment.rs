//! The episodic task interface every domain implements.
//!
//! A domain (the Maze, Mario, Keepaway, …) is an [`Environment`]: it holds its
//! own state, exposes it as a real-valued vector, and moves on one discrete
//! action at a time. It never sees an agent: learners see only the state
//! vector, the reward and whether the episode ended.
//!
//! Randomness comes in through the `rng` argument (the caller's seeded
//! generator), never from a generator the environment owns, so that a trial is
//! one reproducible stream.

use rand::Rng;

/// What one action did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    /// The environment's reward for the transition (never shaped).
    pub reward: f64,
    /// The new state is terminal: the episode is over and its potential is 0.
    pub terminal: bool,
}

/// An episodic task with discrete actions.
pub trait Environment {
    /// Number of actions, numbered `0..num_actions()`.
    fn num_actions(&self) -> usize;

    /// Length of the state vector.
    fn state_dim(&self) -> usize;

    /// Starts a new episode.
    fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R);

    /// The current state vector (valid after [`Environment::reset`]).
    fn state(&self) -> &[f64];

    /// Takes `action` in the current state.
    ///
    /// Calling `step` after a terminal step is a logic error; domains may panic.
    fn step<R: Rng + ?Sized>(&mut self, action: usize, rng: &mut R) -> Step;
}
