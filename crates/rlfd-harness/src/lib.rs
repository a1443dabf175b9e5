//! The trial harness: everything between "these are an experiment's
//! trials" and a directory of finished, reusable trial results.
//!
//! What it is: an experiment's trials are a value, a [`Batch`]: a
//! [`TrialRunner`] (what determines the experiment's set-up, the set-up
//! itself, one trial) and its planned trials (key, seed from
//! [`derive_seed`], parameters). Each trial's identity ([`RecordId`]) is
//! computed here from the serialised runner and parameters, the
//! experiment's behaviour version ([`experiments!`]) and the build identity
//! ([`BUILD_IDENTITY`]: the rustc release and the exact versions of the
//! crates whose bits enter a trial); never from source text, never
//! assembled by a chapter. [`Batch::execute`] runs, loads or verifies the
//! batch ([`RunMode`]) in parallel with `rayon`, reusing finished trials,
//! collecting results in trial order and counting every outcome in one
//! [`Tally`]; [`AnyBatch`] is the batch with its types erased, which plans
//! (lists trials and record paths without running a set-up or a trial) and
//! stages a share of its trials; [`pipeline`] runs many batches' staged
//! trials through one pool of workers, without a pause between batches.
//! [`ResultStore`] writes each finished trial once per identity,
//! atomically; [`deal`] splits a run's trials into shards by cost,
//! [`merge`] merges stores. [`Axis`] and [`Reading`] declare the
//! thesis's open choices with typed values. [`RunMetadata`] is what varies
//! from run to run and goes to `run.json`.
//!
//! ```
//! use rlfd_harness::{Batch, HarnessError, ResultStore, RunContext, RunOptions, Scale, TrialRunner};
//!
//! const SLUG: &str = "ch0-toy";
//! rlfd_harness::experiments! {
//!     /// A toy chapter's one experiment.
//!     pub enum Experiment for SLUG {
//!         /// Sums of seeds.
//!         Sums = "sums", behaviour 1,
//!     }
//! }
//! /// Adds a parameter to the seed; the set-up is an offset.
//! #[derive(serde::Serialize)]
//! struct Sums { offset: u64 }
//! impl TrialRunner for Sums {
//!     type Setup = u64;
//!     type Params = u64;
//!     type Result = u64;
//!     type Error = HarnessError;
//!     fn setup(&self) -> Result<u64, HarnessError> { Ok(self.offset) }
//!     fn run(&self, offset: &u64, p: &u64, seed: u64) -> u64 { seed % 100 + p + offset }
//! }
//!
//! let dir = std::env::temp_dir().join(format!("rlfd-harness-doc-{}", std::process::id()));
//! let options = RunOptions::new(ResultStore::new(&dir), 2);
//! let mut batch = Batch::new(&RunContext::new(20160501, Scale::Quick), SLUG, Experiment::Sums, Sums { offset: 1 });
//! for t in 0..4 {
//!     batch.trial("only", t, 7);
//! }
//! let first = batch.execute(&options)?;
//! let again = batch.execute(&options)?;
//! assert_eq!(first.results, again.results);
//! assert_eq!(options.tally.totals(), (4, 4, 0, 0));
//! # std::fs::remove_dir_all(&dir).unwrap();
//! # Ok::<(), rlfd_harness::HarnessError>(())
//! ```
//!
//! What it is not: no science and no report. It does not know what a
//! trial computes; the chapter crates hand it runners. It never reduces
//! results (sums, means): callers reduce sequentially over the ordered
//! results, so output bytes do not depend on the number of threads. The
//! chapter trait, run points, robustness and rendering are `rlfd-runner`'s.

mod batch;
mod bench;
/// The build identity's rules and allowlist (the file `build.rs` includes).
#[path = "../build_identity.rs"]
mod build_identity;
mod chapter;
pub mod deal;
mod error;
mod experiment;
mod fingerprint;
pub mod merge;
mod metadata;
pub mod pipeline;
mod progress;
mod readings;
mod run;
mod scale;
pub mod seed;
mod store;
mod tally;

pub use batch::{AnyBatch, Batch, BatchError, Executed, Planned, PlannedTrial, RunContext, TrialRunner};
pub use bench::Workload;
pub use build_identity::{RESULT_CRATES, build_identity};
pub use chapter::{Calibration, CommandInputs, THESIS_MASTER_SEED, TrialCost};
pub use error::HarnessError;
pub use experiment::{ExperimentId, UnknownExperiment};
pub use fingerprint::Fingerprint;
pub use metadata::{ChapterTime, RunMetadata};
pub use pipeline::{Measured, PipelineRun, Staged, run_pipelined};
pub use progress::Progress;
pub use readings::{AnyAxis, Axis, Level, Reading, ReadingError};
pub use run::{RunMode, RunOptions};
pub use scale::Scale;
pub use seed::{TrialKey, derive_seed};
pub use store::{FORMAT, Lookup, OtherVersion, RecordId, ResultStore, StoredTrial, write_atomically, write_new};
pub use tally::{ExperimentTally, Tally};

/// This build's identity, part of every trial's: the rustc release and the
/// versions of the crates whose bits enter a trial ([`RESULT_CRATES`], read
/// from the workspace's `Cargo.lock` by `build.rs`).
pub const BUILD_IDENTITY: &str = env!("RLFD_BUILD_IDENTITY");
#[cfg(test)]
mod identity_tests {
    use super::*;

    fn lock() -> String {
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../Cargo.lock")).unwrap()
    }

    /// The identity's rustc part, as this build's.
    fn rustc() -> &'static str {
        BUILD_IDENTITY.split("; ").next().unwrap()
    }

    /// `lock` with `name`'s version line replaced by `version`.
    fn bump(lock: &str, name: &str, version: &str) -> String {
        let at = lock.find(&format!("name = \"{name}\"\nversion = ")).unwrap_or_else(|| panic!("{name} is locked"));
        let line_start = at + lock[at..].find("version = ").unwrap();
        let line_end = line_start + lock[line_start..].find('\n').unwrap();
        format!("{}version = \"{version}\"{}", &lock[..line_start], &lock[line_end..])
    }

    #[test]
    fn the_identity_is_rustc_and_the_allowlisted_crates_of_the_lock() {
        let lock = lock();
        assert_eq!(build_identity(rustc(), &lock), BUILD_IDENTITY);
        assert!(rustc().starts_with("rustc "), "{BUILD_IDENTITY}");
        // Every allowlisted crate is locked (a renamed or dropped one is noticed here).
        for name in RESULT_CRATES {
            assert!(BUILD_IDENTITY.contains(&format!("; {name} ")), "{name} is not in {BUILD_IDENTITY}");
        }
    }

    #[test]
    fn a_report_xtask_or_test_dependency_leaves_the_identity_and_an_allowlisted_crate_moves_it() {
        let lock = lock();
        let identity = build_identity(rustc(), &lock);
        // Bumping what the report crate (minijinja, plotters, svg2pdf), the
        // command line (clap) or a test (proptest, html5ever) uses, or statrs
        // and its disabled nalgebra, changes nothing.
        for name in ["minijinja", "plotters", "svg2pdf", "clap", "proptest", "html5ever", "statrs", "nalgebra", "toml"]
        {
            assert_eq!(build_identity(rustc(), &bump(&lock, name, "99.0.0")), identity, "{name}");
        }
        // Adding a new dependency anywhere changes nothing either.
        let added = format!("{lock}\n[[package]]\nname = \"brand-new-report-crate\"\nversion = \"0.1.0\"\n");
        assert_eq!(build_identity(rustc(), &added), identity);
        // Bumping a crate whose bits enter a trial, or the compiler, does.
        for name in RESULT_CRATES {
            assert_ne!(build_identity(rustc(), &bump(&lock, name, "99.0.0")), identity, "{name}");
        }
        assert_ne!(build_identity("rustc 9.99.0 (000000000 2099-01-01)", &lock), identity);
    }
}
