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
/// The build identity's rules and allowlist (the file `build.rs` includes).
#[path = "../build_identity.rs"]
mod build_identity;
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
pub use build_identity::{RESULT_CRATES, build_identity};

/// This build's identity, part of every trial's: the rustc release and the
/// versions of the crates whose bits enter a trial ([`RESULT_CRATES`], read
/// from the workspace's `Cargo.lock` by `build.rs`).
pub const BUILD_IDENTITY: &str = env!("RLFD_BUILD_IDENTITY");
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
