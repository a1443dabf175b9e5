//! The trial harness: everything between "run this experiment" and a
//! directory of finished, reusable trial results.
//!
//! What it is: [`Chapter`] is the surface every chapter crate implements
//! (its experiments, inputs, results and error as types); [`experiments!`] declares a chapter's experiments with their
//! behaviour versions; [`TrialPlan`] turns (experiment, condition, trial,
//! parameters and inputs) into a [`TrialSpec`] whose seed comes from
//! [`derive_seed`] (master seed, chapter, experiment, condition, trial) and
//! whose identity is a [`Fingerprint`] of the chapter's build identity
//! (rustc release, versions of its dependency closure), the experiment's
//! behaviour version and the determinants: never the source text.
//! [`ResultStore`] writes each finished trial once per identity, atomically;
//! [`run_trials`] runs trials in parallel with `rayon`, reuses finished ones,
//! loads records of other versions for `report`, recomputes a sample for
//! `verify`, lists trials without running them or runs one shard's share of
//! them ([`RunMode`]), collects results in trial order, counts every
//! outcome in one [`Tally`] and shows a progress bar on a terminal;
//! [`RunMetadata`] is what varies from run to run (commit, host, wall time,
//! `--jobs`) and goes to `run.json`.
//!
//! ```
//! use rlfd_harness::{ChapterId, Fingerprint, ResultStore, RunOptions, Scale, TrialPlan, run_trials};
//!
//! const SLUG: &str = "ch0-toy";
//! rlfd_harness::experiments! {
//!     /// A toy chapter's one experiment.
//!     pub enum Experiment for SLUG {
//!         /// Sums of seeds.
//!         Sums = "sums", behaviour 1,
//!     }
//! }
//! const CHAPTER: ChapterId = ChapterId { slug: SLUG, build: "doc-test build" };
//!
//! let dir = std::env::temp_dir().join(format!("rlfd-harness-doc-{}", std::process::id()));
//! let options = RunOptions::new(ResultStore::new(&dir), 20160501, Scale::Quick, 2);
//! let plan = TrialPlan::new(&options, CHAPTER, Experiment::Sums);
//! let specs: Vec<_> = (0..4).map(|t| plan.spec("only", t, Fingerprint::new().u64(7), 7u64)).collect();
//! let first = run_trials(&options, "sums", &specs, |s| s.seed % 100 + s.params)?;
//! let again = run_trials(&options, "sums", &specs, |_| -> u64 { unreachable!("reused") })?;
//! assert_eq!((first.computed, again.reused), (4, 4));
//! assert_eq!(first.results, again.results);
//! assert_eq!(options.tally.totals(), (4, 4, 0, 0));
//! # std::fs::remove_dir_all(&dir).unwrap();
//! # Ok::<(), rlfd_harness::HarnessError>(())
//! ```
//!
//! What it is not: no science. It does not know what a trial computes; the
//! chapter crates hand it closures. It never reduces results (sums, means):
//! callers reduce sequentially over the ordered results, so output bytes do
//! not depend on the number of threads.

mod bench;
mod chapter;
mod error;
mod experiment;
mod fingerprint;
mod metadata;
mod plan;
mod progress;
mod readings;
mod runner;
mod scale;
pub mod seed;
mod store;
mod tally;

pub use bench::Workload;
pub use chapter::{Calibration, Chapter, ChapterWithoutInputs, CommandInputs, THESIS_MASTER_SEED, TrialCost};
pub use error::HarnessError;
pub use experiment::{ExperimentId, UnknownExperiment};
pub use fingerprint::Fingerprint;
pub use metadata::{ChapterTime, RunMetadata};
pub use plan::{ChapterId, TrialPlan};
pub use progress::Progress;
pub use readings::{Axis, Level, Reading, ReadingError};
pub use runner::{
    ABORT_AFTER_ENV, Batch, Batches, PlannedTrial, RunMode, RunOptions, TrialOutcomes, TrialSpec, run_trials,
};
pub use scale::Scale;
pub use seed::{TrialKey, derive_seed};
pub use store::{FORMAT, Lookup, OtherVersion, ResultStore, StoredTrial, write_atomically, write_new};
pub use tally::{ExperimentTally, Tally};
