//! The surface every chapter crate exposes, as a type: its identity, its
//! experiments, what a command line may hand it, how it runs, and its bench
//! workloads. `xtask` drives any [`Chapter`] through this trait alone and
//! never reaches into a chapter's modules.

use std::path::Path;
use std::str::FromStr;

use crate::bench::Workload;
use crate::experiment::{ExperimentId, UnknownExperiment};
use crate::plan::ChapterId;
use crate::readings::Axis;
use crate::runner::RunOptions;
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

/// A chapter of the thesis as the harness runs it.
pub trait Chapter: 'static {
    /// Its slug and build identity.
    const ID: ChapterId;
    /// The short name `--chapter` also accepts (`ch6`).
    const ALIAS: &'static str;
    /// Its experiments (declared with [`crate::experiments!`]).
    type Experiment: ExperimentId + FromStr<Err = UnknownExperiment> + Send + Sync;
    /// What it takes from the command line, checked.
    type Inputs;
    /// What its experiments produce, for its report.
    type Results;
    /// What can stop it.
    type Error: std::error::Error + Send + Sync + 'static;

    /// What one trial of each experiment costs (by the name its trials' keys
    /// carry); an experiment left out costs [`TrialCost::UNDECLARED`].
    const TRIAL_COSTS: &'static [TrialCost] = &[];

    /// Every experiment, in report order.
    fn experiments() -> &'static [Self::Experiment];

    /// The thesis's open choices this chapter declares (see [`crate::Axis`]).
    fn readings() -> &'static [&'static Axis] {
        &[]
    }

    /// Checks what the command line hands in, for `experiments`, before any
    /// chapter runs (so a bad file stops the run before a trial is stored).
    fn inputs(
        given: &CommandInputs<'_>,
        experiments: &[Self::Experiment],
        master_seed: u64,
        scale: Scale,
    ) -> Result<Self::Inputs, Self::Error>;

    /// Runs (or, as `options.mode` says, loads or verifies) `experiments`.
    fn reproduce(
        options: &RunOptions,
        experiments: &[Self::Experiment],
        inputs: &Self::Inputs,
    ) -> Result<Self::Results, Self::Error>;

    /// Deterministic batches `cargo xtask bench` times.
    fn workloads() -> Result<Vec<Workload<'static>>, Self::Error>;

    /// The calibrations of its synthetic humans and models.
    fn calibrations() -> Vec<Calibration> {
        Vec::new()
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

/// A [`Chapter`] that takes nothing from the command line but its
/// experiments: implement this, and [`Chapter`] follows (with `Inputs = ()`).
pub trait ChapterWithoutInputs: 'static {
    /// Its slug and build identity.
    const ID: ChapterId;
    /// The short name `--chapter` also accepts.
    const ALIAS: &'static str;
    /// Its experiments.
    type Experiment: ExperimentId + FromStr<Err = UnknownExperiment> + Send + Sync;
    /// What its experiments produce.
    type Results;
    /// What can stop it.
    type Error: std::error::Error + Send + Sync + 'static;

    /// What one trial of each experiment costs (see [`Chapter::TRIAL_COSTS`]).
    const TRIAL_COSTS: &'static [TrialCost] = &[];

    /// Every experiment, in report order.
    fn experiments() -> &'static [Self::Experiment];

    /// Its open choices.
    fn readings() -> &'static [&'static Axis] {
        &[]
    }

    /// Its calibrations.
    fn calibrations() -> Vec<Calibration> {
        Vec::new()
    }

    /// Runs (or loads or verifies) `experiments`.
    fn reproduce(options: &RunOptions, experiments: &[Self::Experiment]) -> Result<Self::Results, Self::Error>;

    /// Deterministic batches `cargo xtask bench` times.
    fn workloads() -> Result<Vec<Workload<'static>>, Self::Error>;
}

impl<C: ChapterWithoutInputs> Chapter for C {
    const ID: ChapterId = C::ID;
    const ALIAS: &'static str = C::ALIAS;
    type Experiment = C::Experiment;
    type Inputs = ();
    type Results = C::Results;
    type Error = C::Error;
    const TRIAL_COSTS: &'static [TrialCost] = C::TRIAL_COSTS;

    fn experiments() -> &'static [Self::Experiment] {
        C::experiments()
    }

    fn readings() -> &'static [&'static Axis] {
        C::readings()
    }

    fn calibrations() -> Vec<Calibration> {
        C::calibrations()
    }

    fn inputs(
        _given: &CommandInputs<'_>,
        _experiments: &[Self::Experiment],
        _master_seed: u64,
        _scale: Scale,
    ) -> Result<(), Self::Error> {
        Ok(())
    }

    fn reproduce(options: &RunOptions, experiments: &[Self::Experiment], _inputs: &()) -> Result<C::Results, C::Error> {
        C::reproduce(options, experiments)
    }

    fn workloads() -> Result<Vec<Workload<'static>>, Self::Error> {
        C::workloads()
    }
}
