//! What the harness knows of a chapter besides its batches: the thesis's
//! master seed, what a command line may hand a chapter, what one trial of
//! an experiment costs (for dealing shards and sizing cluster jobs), and
//! the calibrations of its synthetic humans. The chapter trait itself is
//! `rlfd-runner`'s, which also sees the report crate.

use std::path::Path;

use crate::scale::Scale;

/// The master seed of the thesis's reproduction: the date of the thesis's
/// defence, fixed before any trial ran. `--seed` overrides it.
pub const THESIS_MASTER_SEED: u64 = 20160501;

/// What a command line hands a chapter besides the seed and the scale.
#[derive(Clone, Copy, Debug, Default)]
pub struct CommandInputs<'a> {
    /// `--demonstrations FILE`: demonstrations to learn from instead of a
    /// synthetic demonstrator, for the chapters and experiments that take them.
    pub demonstrations: Option<&'a Path>,
}

/// What one trial of an experiment costs, as its chapter estimates it (from
/// a timed run): `reproduce --shard` balances shards by it, and
/// `cargo xtask slurm` derives each task's time and memory request from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrialCost {
    /// The experiment as its trials' keys name it (the store's folder).
    pub experiment: &'static str,
    /// CPU seconds of one trial at quick scale.
    pub quick_seconds: f64,
    /// CPU seconds of one trial at paper scale.
    pub paper_seconds: f64,
    /// Memory one trial in flight adds to its process at paper scale, in MiB.
    pub paper_mib: f64,
}

impl TrialCost {
    /// The cost of a trial whose chapter declares none: one second, 16 MiB.
    pub const UNDECLARED: TrialCost =
        TrialCost { experiment: "", quick_seconds: 1.0, paper_seconds: 1.0, paper_mib: 16.0 };

    /// The cost of a trial of `experiment`: CPU seconds at quick and paper
    /// scale, MiB in flight at paper scale.
    pub const fn new(experiment: &'static str, quick_seconds: f64, paper_seconds: f64, paper_mib: f64) -> TrialCost {
        TrialCost { experiment, quick_seconds, paper_seconds, paper_mib }
    }

    /// CPU seconds of one trial at `scale`.
    pub fn seconds(&self, scale: Scale) -> f64 {
        match scale {
            Scale::Quick => self.quick_seconds,
            Scale::Paper => self.paper_seconds,
        }
    }

    /// The cost `costs` declares for `experiment`, else [`TrialCost::UNDECLARED`].
    pub fn of(costs: &[TrialCost], experiment: &str) -> TrialCost {
        costs.iter().find(|c| c.experiment == experiment).copied().unwrap_or(TrialCost::UNDECLARED)
    }
}

/// A synthetic human's (or a model's) calibration, rerun by
/// `cargo xtask calibrate <model>`: it fits the model to what the thesis
/// says of its inputs (durations, lengths, rates; never a learner's result)
/// and returns a printable account of the fit beside the shipped constants.
#[derive(Clone, Copy, Debug)]
pub struct Calibration {
    /// Its name on the command line, e.g. `maze-demonstrator`.
    pub model: &'static str,
    /// What it fits, and on what, in one sentence.
    pub what: &'static str,
    /// Runs it (deterministic; seconds to minutes).
    pub run: fn() -> String,
}
