//! The trial harness: everything between "run this experiment" and a
//! directory of finished, reusable trial results.
//!
//! What it is: [`seed`] derives every trial's seed from (master seed,
//! chapter, experiment, condition, trial) with a hash written out in the code;
//! [`Scale`] names the two sizes of every experiment; [`ResultStore`] writes
//! each finished trial once, atomically (temporary file, then rename), keyed
//! by its seed-bearing id and a [`Fingerprint`] of its parameters and of the
//! code that ran it; [`run_trials`] runs trials in parallel with `rayon`,
//! reuses finished ones, collects results in trial order and shows a
//! progress bar on a terminal; [`RunMetadata`] is what varies from run to run
//! (commit, host, wall time, `--jobs`) and goes to `run.json`.
//!
//! What it is not: no science. It does not know what a trial computes; the
//! chapter crates hand it closures. It never reduces results (sums, means):
//! callers reduce sequentially over the ordered results, so output bytes do
//! not depend on the number of threads.

mod bench;
mod error;
mod fingerprint;
mod metadata;
mod progress;
mod runner;
mod scale;
pub mod seed;
mod store;

pub use bench::Workload;
pub use error::HarnessError;
pub use fingerprint::Fingerprint;
pub use metadata::RunMetadata;
pub use progress::Progress;
pub use runner::{ABORT_AFTER_ENV, RunOptions, TrialOutcomes, TrialSpec, run_trials};
pub use scale::Scale;
pub use seed::{TrialKey, derive_seed};
pub use store::{ResultStore, StoredTrial, write_atomically};
