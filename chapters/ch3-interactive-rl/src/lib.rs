//! Chapter 3 of the thesis: the effect of human guidance and of the state
//! space's size on Interactive Reinforcement Learning, with an expert
//! teacher training a seated Nao robot to sort objects into two cups.
//!
//! What it is: the whole chapter. The domain ([`nao`]: a kinematic
//! simulation of the table, the robot's state in the small (360 states) and
//! large (6,480 states) space, the camera's readings, correct sorting plans,
//! per-action durations calibrated on the thesis's 9.8 s mean), the guidance
//! regions of Table 3.1 ([`guidance`]), the scripted expert teacher following
//! the thesis's protocol ([`teacher`]), Algorithm 1 ([`learner`]), one
//! training session ([`session`]), the experiments through the harness
//! ([`experiment`]: the thesis's four conditions with 3 trials each, and the
//! same with 100 trials, swept over the reading noise) and the report
//! ([`report`]: Table 3.2, Figure 3.4, the reductions, claims C3.1–C3.5, the
//! noise sweep).
//!
//! What it is not: no IO beyond the harness's result store, no printing, no
//! clock. The runner drives it through [`Ch3`] (`rlfd_runner::Chapter`).

pub mod calibrations;
pub mod experiment;
pub mod guidance;
pub mod learner;
/// The domain: the `rlfd-nao` crate.
pub use rlfd_nao as nao;
pub mod readings;
pub mod report;
pub mod session;
pub mod teacher;

use rlfd_harness::{AnyAxis, AnyBatch, CommandInputs, RunContext, RunOptions};

pub use experiment::{Ch3Error, Condition, Experiment, SortingBatch, SortingParams, SortingResults};

/// The chapter's slug: its directory in reports and result stores.
pub const CHAPTER: &str = "ch3-interactive-rl";

/// The results of the chapter's experiments that ran.
#[derive(Clone, Debug, Default)]
pub struct Results {
    /// The thesis's design: 3 trials per condition.
    pub sorting: Option<SortingResults>,
    /// 100 trials per condition.
    pub powered: Option<SortingResults>,
}

/// The chapter's experiments' batches at one run point.
#[derive(Default)]
pub struct Plan {
    /// The thesis's design.
    pub sorting: Option<SortingBatch>,
    /// 100 trials per condition.
    pub powered: Option<SortingBatch>,
}

/// The chapter's sweeps: the 100-trial experiment at every level of
/// `perception-noise`, the report's sensitivity to the large space's
/// reading noise. Each level's trials are the ones a run of that reading
/// makes (the small space's, which the noise does not touch, are shared), so
/// the sensitivity table at a level and the robustness run's reading cell at
/// the master seed are the same numbers.
pub static SWEEPS: [rlfd_runner::Sweep; 1] =
    [rlfd_runner::Sweep { experiment: "sorting-100", axis: &readings::PERCEPTION_NOISE }];

/// Chapter 3 as the runner runs it (see [`rlfd_runner::Chapter`]).
#[derive(Clone, Copy, Debug)]
pub struct Ch3;

impl rlfd_runner::Chapter for Ch3 {
    const SLUG: &'static str = CHAPTER;
    const ALIAS: &'static str = "ch3";
    const TRIAL_COSTS: &'static [rlfd_harness::TrialCost] = &[
        rlfd_harness::TrialCost::new("sorting", 0.001, 0.001, 4.0),
        rlfd_harness::TrialCost::new("sorting-100", 0.001, 0.001, 4.0),
    ];
    type Experiment = Experiment;
    type Inputs = ();
    type Plan = Plan;
    type Results = Results;
    type Error = Ch3Error;

    fn experiments() -> &'static [Experiment] {
        &Experiment::ALL
    }

    fn readings() -> &'static [&'static dyn AnyAxis] {
        &readings::AXES
    }

    fn inputs(_: &CommandInputs<'_>, _: &[Experiment], _: &RunContext) -> Result<(), Ch3Error> {
        Ok(())
    }

    fn plan(ctx: &RunContext, experiments: &[Experiment], _: &()) -> Result<Plan, Ch3Error> {
        let mut plan = Plan::default();
        for &e in experiments {
            match e {
                Experiment::Sorting => plan.sorting = Some(experiment::plan_sorting(ctx, e)?),
                Experiment::SortingPowered => plan.powered = Some(experiment::plan_sorting(ctx, e)?),
            }
        }
        Ok(plan)
    }

    fn batches(plan: &Plan) -> Vec<&dyn AnyBatch> {
        let mut out: Vec<&dyn AnyBatch> = Vec::new();
        out.extend(plan.sorting.iter().map(|b| &b.batch as &dyn AnyBatch));
        out.extend(plan.powered.iter().map(|b| &b.batch as &dyn AnyBatch));
        out
    }

    fn execute(plan: &Plan, options: &RunOptions) -> Result<Results, Ch3Error> {
        Ok(Results {
            sorting: plan.sorting.as_ref().map(|b| b.execute(options)).transpose()?,
            powered: plan.powered.as_ref().map(|b| b.execute(options)).transpose()?,
        })
    }

    fn claims(results: &Results) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
        report::claims(results)
    }

    fn report(
        results: &Results,
        sweeps: &[rlfd_runner::Swept<'_, Results>],
        provenance: &rlfd_report::Provenance,
    ) -> rlfd_report::Result<rlfd_report::ChapterReport> {
        let noise: Vec<report::NoiseLevel<'_>> = sweeps
            .iter()
            .filter_map(|s| {
                let level = readings::PERCEPTION_NOISE.levels.iter().find(|l| l.name == s.level)?;
                Some(report::NoiseLevel { rate: level.value, own: s.own, results: s.results.powered.as_ref()? })
            })
            .collect();
        report::chapter_report(results, &noise, provenance)
    }

    fn sweeps() -> &'static [rlfd_runner::Sweep] {
        &SWEEPS
    }

    fn calibrations() -> Vec<rlfd_harness::Calibration> {
        calibrations::all()
    }

    fn workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch3Error> {
        bench_workloads()
    }
}

/// The chapter's benchmark workloads for `cargo xtask bench`: the
/// simulator alone (random legal actions in the large space), and a whole
/// training session (world, teacher and Algorithm 1) of each condition at
/// the thesis's parameters (`small-guided` … `large-unguided`; one session
/// per batch, counted in actions).
pub fn bench_workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch3Error> {
    let params = SortingParams::paper();
    params.check()?;
    let mut out = vec![rlfd_harness::Workload {
        domain: "nao",
        name: "simulator".into(),
        unit: "steps",
        run: Box::new(|seed| nao::random_walk_steps(seed, 100_000)),
    }];
    for condition in Condition::ALL {
        let setup = params.setup(condition);
        out.push(rlfd_harness::Workload {
            domain: "nao",
            name: match condition {
                Condition::SmallGuidance => "small-guided",
                Condition::LargeGuidance => "large-guided",
                Condition::SmallNoGuidance => "small-unguided",
                Condition::LargeNoGuidance => "large-unguided",
            }
            .into(),
            unit: "steps",
            run: Box::new(move |seed| {
                u64::from(session::run_session(&setup, &mut rlfd_rl::random::seeded(seed)).actions)
            }),
        });
    }
    Ok(out)
}
