//! The one adapter between the command line and any chapter: a
//! [`rlfd_harness::Chapter`] plus the function that turns its results into
//! a report. Everything it knows of a chapter comes through those two.

use anyhow::Result;
use rlfd_harness::{CommandInputs, ExperimentId, RunOptions, TrialCost, Workload};
use rlfd_report::{ChapterReport, Provenance};

use super::{Chapter, ChapterRun};
use crate::cli::RunSettings;

/// Renders a chapter's results.
pub type ReportFn<R> = fn(&R, &Provenance) -> rlfd_report::Result<ChapterReport>;

/// A chapter `C` and its report.
pub struct Adapter<C: rlfd_harness::Chapter> {
    report: ReportFn<C::Results>,
}

impl<C: rlfd_harness::Chapter> Adapter<C> {
    /// The adapter of `C`, whose results `report` renders.
    pub fn new(report: ReportFn<C::Results>) -> Self {
        Adapter { report }
    }

    /// The experiments named (all when `experiments` is empty), in report order.
    fn selection(experiments: &[&str]) -> Result<Vec<C::Experiment>> {
        if experiments.is_empty() {
            return Ok(C::experiments().to_vec());
        }
        let named = experiments.iter().map(|e| e.parse::<C::Experiment>()).collect::<Result<Vec<_>, _>>()?;
        Ok(C::experiments().iter().copied().filter(|e| named.iter().any(|n| n.name() == e.name())).collect())
    }

    fn inputs(s: &RunSettings, experiments: &[C::Experiment]) -> Result<C::Inputs> {
        let given = CommandInputs { demonstrations: s.demonstrations.as_deref() };
        Ok(C::inputs(&given, experiments, s.seed, s.scale)?)
    }
}

impl<C: rlfd_harness::Chapter> Chapter for Adapter<C> {
    fn slug(&self) -> &'static str {
        C::ID.slug
    }

    fn alias(&self) -> &'static str {
        C::ALIAS
    }

    fn experiments(&self) -> Vec<&'static str> {
        C::experiments().iter().map(|e| e.name()).collect()
    }

    fn readings(&self) -> &'static [&'static rlfd_harness::Axis] {
        C::readings()
    }

    fn calibrations(&self) -> Vec<rlfd_harness::Calibration> {
        C::calibrations()
    }

    fn build(&self) -> &'static str {
        C::ID.build
    }

    fn trial_cost(&self, experiment: &str) -> TrialCost {
        TrialCost::of(C::TRIAL_COSTS, experiment)
    }

    fn run(
        &self,
        settings: &RunSettings,
        experiment: &[&str],
        options: &RunOptions,
        provenance: &Provenance,
    ) -> Result<ChapterRun> {
        let experiments = Self::selection(experiment)?;
        let inputs = Self::inputs(settings, &experiments)?;
        let results = C::reproduce(options, &experiments, &inputs)?;
        Ok(ChapterRun { report: (self.report)(&results, provenance)? })
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>> {
        Ok(C::workloads()?)
    }

    fn check_inputs(&self, settings: &RunSettings, experiment: &[&str]) -> Result<()> {
        Self::inputs(settings, &Self::selection(experiment)?).map(|_| ())
    }
}
