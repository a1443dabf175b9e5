//! The one home for running a reproduction, between the command line and
//! the chapters.
//!
//! What it is: [`Chapter`], the one trait a chapter crate implements (its
//! experiments, readings and sweeps, its experiments' trials as batches,
//! its claims from results alone, its report, workloads and calibrations),
//! and [`AnyChapter`], the same with its types erased ([`erase`]), which
//! the registry holds. A [`Command`] (what determines the output) is checked
//! against the registry into a [`Selection`], whose [`RunPoint`]s are every
//! (seed, reading) it runs a chapter at: the headline, its sweeps'
//! levels, and with `--robustness` the replications and the other levels of
//! every axis. [`plan::plan`] lists every trial of every point without
//! running anything; [`shard`] deals and runs one shard's share;
//! [`reproduce::render`] runs or loads the headline (with sweeps and the
//! robustness verdicts, computed from claims alone) and returns the report's
//! files; [`verify::verify`] recomputes a sample; [`slurm`] writes the
//! scripts' text; merging stores is the harness's ([`rlfd_harness::merge`]).
//!
//! What it is not: it knows no chapter (the registry is the command
//! line's), parses no arguments and writes no file: the caller gets files,
//! summaries and counts back, and a `log` callback hears progress.

pub mod chapter;
pub mod command;
mod error;
pub mod plan;
pub mod pooled;
pub mod reproduce;
pub mod robustness;
pub mod shard;
pub mod slurm;
pub mod verify;

use std::path::PathBuf;

pub use chapter::{AnyChapter, AnyPlan, Chapter, Crossing, Ran, Sweep, Swept, erase, run_all};
pub use command::{Command, Replications, Role, RunPoint, Selection, replication_seed};
pub use error::RunnerError;

/// Master seeds each other level of an axis runs at in a robustness run
/// (the first of the replication seeds), unless `--reading-seeds` says.
pub const DEFAULT_READING_SEEDS: u32 = 5;

/// Where and how trials run: threads, progress, the store.
#[derive(Clone, Debug)]
pub struct Machine {
    /// Worker threads.
    pub jobs: usize,
    /// Draw progress bars (only ever on a terminal).
    pub progress: bool,
    /// The result store.
    pub results: PathBuf,
}

impl Machine {
    /// Run options in `mode` with a fresh tally.
    pub fn options(&self, mode: rlfd_harness::RunMode) -> rlfd_harness::RunOptions {
        rlfd_harness::RunOptions {
            jobs: self.jobs,
            progress: self.progress,
            store: rlfd_harness::ResultStore::new(&self.results),
            mode,
            tally: rlfd_harness::Tally::new(),
        }
    }
}
