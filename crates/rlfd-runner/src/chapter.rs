//! The one chapter trait, and the same chapter with its types erased.
//!
//! A chapter crate implements [`Chapter`]: its experiments and open choices,
//! what a command line may hand it, its experiments' trials as values
//! ([`Chapter::plan`]: one typed [`rlfd_harness::Batch`] per experiment, in
//! a plan type of its own), how the plan's results come together
//! ([`Chapter::execute`]), its claims' verdicts from those results alone
//! ([`Chapter::claims`]: no figure, no bootstrap table), its report, its
//! benchmark workloads and its calibrations. Because planning and running
//! consume the same plan value, a planned trial is always one that runs.
//!
//! [`AnyChapter`] is what the runner and the command line hold: one
//! registry of `Box<dyn AnyChapter>`, made by [`erase`].

use std::error::Error as StdError;
use std::str::FromStr;

use rlfd_harness::{
    AnyAxis, AnyBatch, Calibration, CommandInputs, ExperimentId, Reading, RunContext, RunOptions, TrialCost,
    UnknownExperiment, Workload,
};
use rlfd_report::claims::Claim;
use rlfd_report::{ChapterReport, Provenance};

use crate::error::RunnerError;

/// "This experiment sweeps this axis": the chapter's report shows the
/// experiment at every level of the axis (the other axes at the run's
/// reading), beside the run's own level. The one way an experiment varies
/// an open choice inside a report; the trials of each level are the ones a
/// run of that reading makes (only those whose parameters the axis changes
/// are new).
#[derive(Clone, Copy, Debug)]
pub struct Sweep {
    /// The experiment (as `--experiment` names it).
    pub experiment: &'static str,
    /// The axis it sweeps.
    pub axis: &'static dyn AnyAxis,
}

/// Two axes whose levels the robustness run crosses in full: beside each
/// axis's levels one at a time (the others at their defaults), every pair
/// of their non-default levels runs too, at the readings' replications.
/// For open choices that act together (chapter 6's IRL reward scale κ and
/// the tile width it is summed over), where one at a time cannot show how
/// they interact.
#[derive(Clone, Copy, Debug)]
pub struct Crossing {
    /// The two axes (both among the chapter's readings).
    pub axes: [&'static dyn AnyAxis; 2],
}

/// One level of a sweep and the experiment's results there.
#[derive(Debug)]
pub struct Swept<'a, R> {
    /// The axis.
    pub axis: &'static dyn AnyAxis,
    /// The level.
    pub level: &'static str,
    /// Whether it is the run's own level (its results are the headline's).
    pub own: bool,
    /// The chapter's results at that level (the swept experiment's only,
    /// unless the level is the run's own).
    pub results: &'a R,
}

/// A chapter of the thesis.
pub trait Chapter: 'static {
    /// Its slug: its directory in reports and result stores (`ch6-irl-shaping`).
    const SLUG: &'static str;
    /// The short name `--chapter` also accepts (`ch6`).
    const ALIAS: &'static str;
    /// What one trial of each experiment costs (by the name its trials'
    /// keys carry); an experiment left out costs [`TrialCost::UNDECLARED`].
    /// Every computing run checks them: it ends with a `measured` line per
    /// experiment, its trials' seconds against these
    /// ([`crate::shard::ExperimentCost`]).
    const TRIAL_COSTS: &'static [TrialCost] = &[];

    /// Its experiments (declared with [`rlfd_harness::experiments!`]).
    type Experiment: ExperimentId + FromStr<Err = UnknownExperiment> + Send + Sync;
    /// What it takes from the command line, checked.
    type Inputs: Sync;
    /// Its experiments' batches at one run point.
    type Plan: Sync;
    /// What its experiments produce, for its claims and report.
    type Results;
    /// What can stop it.
    type Error: StdError + Send + Sync + 'static;

    /// Every experiment, in report order.
    fn experiments() -> &'static [Self::Experiment];

    /// The thesis's open choices it declares.
    fn readings() -> &'static [&'static dyn AnyAxis] {
        &[]
    }

    /// The axes its experiments sweep for their reports.
    fn sweeps() -> &'static [Sweep] {
        &[]
    }

    /// The pairs of its axes the robustness run crosses in full.
    fn crossings() -> &'static [Crossing] {
        &[]
    }

    /// Whether `experiment` learns from a demonstration file the command
    /// line hands in (`--demonstrations`).
    fn takes_demonstrations(_experiment: Self::Experiment) -> bool {
        false
    }

    /// Checks what the command line hands in, for `experiments`, before any
    /// chapter runs (a bad file stops the run before a trial is stored).
    /// A chapter none of whose experiments takes an input ignores it.
    fn inputs(
        given: &CommandInputs<'_>,
        experiments: &[Self::Experiment],
        ctx: &RunContext,
    ) -> Result<Self::Inputs, Self::Error>;

    /// Plans `experiments` at `ctx`: their batches, computing no trial and
    /// no set-up.
    fn plan(
        ctx: &RunContext,
        experiments: &[Self::Experiment],
        inputs: &Self::Inputs,
    ) -> Result<Self::Plan, Self::Error>;

    /// The plan's batches, types erased.
    fn batches(plan: &Self::Plan) -> Vec<&dyn AnyBatch>;

    /// Runs (or loads or verifies, as `options.mode` says) the plan's
    /// batches and gathers their results.
    fn execute(plan: &Self::Plan, options: &RunOptions) -> Result<Self::Results, Self::Error>;

    /// Its claims' verdicts, computed from the results alone (no figure,
    /// no bootstrap table): what the robustness run reads at every point.
    fn claims(results: &Self::Results) -> rlfd_report::Result<Vec<Claim>>;

    /// Its report: tables beside the thesis's, figures, the claims, the
    /// sweeps' sections.
    fn report(
        results: &Self::Results,
        sweeps: &[Swept<'_, Self::Results>],
        provenance: &Provenance,
    ) -> rlfd_report::Result<ChapterReport>;

    /// Deterministic batches `cargo xtask bench` times.
    fn workloads() -> Result<Vec<Workload<'static>>, Self::Error>;

    /// The calibrations of its synthetic humans and models.
    fn calibrations() -> Vec<Calibration> {
        Vec::new()
    }
}

/// A chapter's plan at one run point, types erased.
pub trait AnyPlan {
    /// Its batches.
    fn batches(&self) -> Vec<&dyn AnyBatch>;
}

/// What a chapter's run gave.
pub struct Ran {
    /// Its claims (always).
    pub claims: Vec<Claim>,
    /// Its report, when asked for.
    pub report: Option<ChapterReport>,
}

/// A sweep level to run beside the headline.
#[derive(Clone, Copy, Debug)]
pub struct SweepLevel {
    /// The sweep.
    pub sweep: Sweep,
    /// The level.
    pub level: &'static str,
}

/// A chapter as the runner holds it.
pub trait AnyChapter: Sync {
    /// Its slug.
    fn slug(&self) -> &'static str;
    /// Its short name.
    fn alias(&self) -> &'static str;
    /// The experiments `--experiment` accepts, in report order.
    fn experiments(&self) -> Vec<&'static str>;
    /// Its open choices.
    fn readings(&self) -> &'static [&'static dyn AnyAxis];
    /// Its sweeps.
    fn sweeps(&self) -> &'static [Sweep];
    /// The pairs of axes its robustness run crosses in full.
    fn crossings(&self) -> &'static [Crossing];
    /// What one trial of an experiment (as its keys name it) costs.
    fn trial_cost(&self, experiment: &str) -> TrialCost;
    /// Every cost it declares.
    fn trial_costs(&self) -> &'static [TrialCost];
    /// Its calibrations.
    fn calibrations(&self) -> Vec<Calibration>;
    /// Its experiments that learn from a demonstration file.
    fn demonstration_takers(&self) -> Vec<&'static str>;
    /// Its benchmark workloads.
    fn workloads(&self) -> Result<Vec<Workload<'static>>, RunnerError>;
    /// Checks the command line's inputs for `experiments` (none: all).
    fn check_inputs(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
    ) -> Result<(), RunnerError>;
    /// Plans `experiments` (none: all) at `ctx`.
    fn plan(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
    ) -> Result<Box<dyn AnyPlan + '_>, RunnerError>;
    /// Runs `experiments` (none: all) at `ctx` and returns the claims and,
    /// with `report`, the report (with every sweep of a selected experiment
    /// at every level, each run at its own reading of `ctx`).
    fn run(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
        options: &RunOptions,
        report: Option<&Provenance>,
    ) -> Result<Ran, RunnerError>;
}

/// `C` as the runner holds it.
pub fn erase<C: Chapter>() -> Box<dyn AnyChapter> {
    Box::new(Erased::<C>(std::marker::PhantomData))
}

struct Erased<C>(std::marker::PhantomData<fn() -> C>);

struct ErasedPlan<C: Chapter>(C::Plan);

impl<C: Chapter> AnyPlan for ErasedPlan<C> {
    fn batches(&self) -> Vec<&dyn AnyBatch> {
        C::batches(&self.0)
    }
}

impl<C: Chapter> Erased<C> {
    fn chapter_error(e: C::Error) -> RunnerError {
        RunnerError::Chapter { chapter: C::SLUG, source: Box::new(e) }
    }

    /// The experiments named (all when `names` is empty), in report order.
    fn selection(names: &[&str]) -> Result<Vec<C::Experiment>, RunnerError> {
        if names.is_empty() {
            return Ok(C::experiments().to_vec());
        }
        let named = names
            .iter()
            .map(|e| e.parse::<C::Experiment>())
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| RunnerError::Chapter { chapter: C::SLUG, source: Box::new(e) })?;
        Ok(C::experiments().iter().copied().filter(|e| named.iter().any(|n| n.name() == e.name())).collect())
    }

    fn inputs(
        given: &CommandInputs<'_>,
        experiments: &[C::Experiment],
        ctx: &RunContext,
    ) -> Result<C::Inputs, RunnerError> {
        C::inputs(given, experiments, ctx).map_err(Self::chapter_error)
    }

    fn results(
        ctx: &RunContext,
        experiments: &[C::Experiment],
        inputs: &C::Inputs,
        options: &RunOptions,
    ) -> Result<C::Results, RunnerError> {
        let plan = C::plan(ctx, experiments, inputs).map_err(Self::chapter_error)?;
        C::execute(&plan, options).map_err(Self::chapter_error)
    }
}

impl<C: Chapter> AnyChapter for Erased<C> {
    fn slug(&self) -> &'static str {
        C::SLUG
    }

    fn alias(&self) -> &'static str {
        C::ALIAS
    }

    fn experiments(&self) -> Vec<&'static str> {
        C::experiments().iter().map(|e| e.name()).collect()
    }

    fn readings(&self) -> &'static [&'static dyn AnyAxis] {
        C::readings()
    }

    fn sweeps(&self) -> &'static [Sweep] {
        C::sweeps()
    }

    fn crossings(&self) -> &'static [Crossing] {
        C::crossings()
    }

    fn trial_cost(&self, experiment: &str) -> TrialCost {
        TrialCost::of(C::TRIAL_COSTS, experiment)
    }

    fn trial_costs(&self) -> &'static [TrialCost] {
        C::TRIAL_COSTS
    }

    fn calibrations(&self) -> Vec<Calibration> {
        C::calibrations()
    }

    fn demonstration_takers(&self) -> Vec<&'static str> {
        C::experiments().iter().filter(|e| C::takes_demonstrations(**e)).map(|e| e.name()).collect()
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>, RunnerError> {
        C::workloads().map_err(Self::chapter_error)
    }

    fn check_inputs(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
    ) -> Result<(), RunnerError> {
        Self::inputs(given, &Self::selection(experiments)?, ctx).map(|_| ())
    }

    fn plan(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
    ) -> Result<Box<dyn AnyPlan + '_>, RunnerError> {
        let experiments = Self::selection(experiments)?;
        let inputs = Self::inputs(given, &experiments, ctx)?;
        let plan = C::plan(ctx, &experiments, &inputs).map_err(Self::chapter_error)?;
        Ok(Box::new(ErasedPlan::<C>(plan)))
    }

    fn run(
        &self,
        given: &CommandInputs<'_>,
        experiments: &[&str],
        ctx: &RunContext,
        options: &RunOptions,
        report: Option<&Provenance>,
    ) -> Result<Ran, RunnerError> {
        let selected = Self::selection(experiments)?;
        let inputs = Self::inputs(given, &selected, ctx)?;
        let results = Self::results(ctx, &selected, &inputs, options)?;
        let report_error = |source| RunnerError::Report { chapter: C::SLUG, source };
        let claims = C::claims(&results).map_err(report_error)?;
        let Some(provenance) = report else {
            return Ok(Ran { claims, report: None });
        };
        // Each sweep of a selected experiment at every level but the run's own.
        let mut swept: Vec<(SweepLevel, C::Results)> = Vec::new();
        for sweep in sweeps_of(C::sweeps(), &selected.iter().map(|e| e.name()).collect::<Vec<_>>()) {
            let own = ctx.reading.level_of(sweep.axis);
            for level in sweep.axis.level_names().into_iter().filter(|l| *l != own) {
                let at = ctx.under(ctx.reading.clone().with(sweep.axis, level));
                let only = Self::selection(&[sweep.experiment])?;
                swept.push((SweepLevel { sweep, level }, Self::results(&at, &only, &inputs, options)?));
            }
        }
        let mut levels: Vec<Swept<'_, C::Results>> = Vec::new();
        for sweep in sweeps_of(C::sweeps(), &selected.iter().map(|e| e.name()).collect::<Vec<_>>()) {
            let own = ctx.reading.level_of(sweep.axis);
            for level in sweep.axis.level_names() {
                let results = if level == own {
                    &results
                } else {
                    &swept
                        .iter()
                        .find(|(s, _)| {
                            s.sweep.axis.name() == sweep.axis.name()
                                && s.sweep.experiment == sweep.experiment
                                && s.level == level
                        })
                        .expect("every other level was run above")
                        .1
                };
                levels.push(Swept { axis: sweep.axis, level, own: level == own, results });
            }
        }
        let report = C::report(&results, &levels, provenance).map_err(report_error)?;
        Ok(Ran { claims, report: Some(report) })
    }
}

/// The sweeps of `sweeps` whose experiment is among `experiments`.
pub fn sweeps_of(sweeps: &'static [Sweep], experiments: &[&str]) -> Vec<Sweep> {
    sweeps.iter().copied().filter(|s| experiments.contains(&s.experiment)).collect()
}

/// The reading of `ctx` with `sweep`'s axis at `level`.
pub fn sweep_reading(reading: &Reading, sweep: &Sweep, level: &str) -> Reading {
    reading.clone().with(sweep.axis, level)
}

/// Plans and runs every experiment of `C` at `ctx` (default inputs) with
/// `options`: the chapter's results, as its own tests and examples use them.
pub fn run_all<C: Chapter>(ctx: &RunContext, options: &RunOptions) -> Result<C::Results, RunnerError> {
    let experiments = C::experiments();
    let inputs = C::inputs(&CommandInputs::default(), experiments, ctx).map_err(Erased::<C>::chapter_error)?;
    Erased::<C>::results(ctx, experiments, &inputs, options)
}
