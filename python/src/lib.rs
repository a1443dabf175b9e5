//! `rlfd` for Python: the reproduction's validated domains as Gymnasium
//! environments and its learning-from-demonstration algorithms on NumPy
//! arrays, compiled into the extension module `rlfd._rlfd` (PyO3, abi3).
//!
//! What it is: [`domain`] (each domain moved one agent step at a time with
//! its own seeded generator, Keepaway as the keepers' SMDP decisions),
//! [`vector`] (N instances stepped per call), [`render`] (RGB pictures), and
//! [`py`] (the Python classes over those and over `rlfd-lfd`'s RIPPER,
//! RE-IRL and SBS, `rlfd-rl`'s tile coder and `rlfd-env`'s demonstration
//! files). The pure-Python package `rlfd/` beside this crate builds the
//! Gymnasium classes, wrappers and documented API on top.
//!
//! What it is not: no science of its own. Every simulator, learner and file
//! format is the workspace's crate, used by path and unchanged; this crate
//! only adapts calls, checks arguments and copies numbers, so Python gets
//! the Rust numbers bit for bit (`tests/fixtures.rs` writes the reference
//! trajectories and results that `tests/test_same_numbers.py` compares).

pub mod domain;
pub mod py;
pub mod render;
pub mod vector;

pub use py::_rlfd;
