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
//! ([`experiment`]: the thesis's four conditions with 3 trials each, the same
//! with 100 trials, and a reading-noise sensitivity study) and the report
//! ([`report`]: Table 3.2, Figure 3.4, the reductions, claims C3.1–C3.5).
//!
//! What it is not: no IO beyond the harness's result store, no printing, no
//! clock. `xtask` calls [`reproduce`] and [`report::chapter_report`] and
//! writes the files.

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

use rlfd_harness::RunOptions;

pub use experiment::{Ch3Error, Condition, Experiment, NoiseResults, SortingParams, SortingResults};

/// The chapter's slug: its directory in reports and result stores.
pub const CHAPTER: &str = "ch3-interactive-rl";

/// The chapter as its stored trials name it (slug and build identity).
pub const CHAPTER_ID: rlfd_harness::ChapterId =
    rlfd_harness::ChapterId { slug: CHAPTER, build: rlfd_harness::BUILD_IDENTITY };

/// The results of the chapter's experiments that ran.
#[derive(Clone, Debug, Default)]
pub struct Results {
    /// The thesis's design: 3 trials per condition.
    pub sorting: Option<SortingResults>,
    /// 100 trials per condition.
    pub powered: Option<SortingResults>,
    /// The reading-noise study.
    pub noise: Option<NoiseResults>,
}

impl Results {
    /// Trials computed and reused over all experiments.
    pub fn trial_counts(&self) -> (usize, usize) {
        let mut counts = (0, 0);
        for (c, r) in [
            self.sorting.as_ref().map(|s| (s.computed, s.reused)),
            self.powered.as_ref().map(|s| (s.computed, s.reused)),
            self.noise.as_ref().map(|s| (s.computed, s.reused)),
        ]
        .into_iter()
        .flatten()
        {
            counts.0 += c;
            counts.1 += r;
        }
        counts
    }
}

/// Chapter 3 as the harness runs it (see [`rlfd_harness::Chapter`]).
#[derive(Clone, Copy, Debug)]
pub struct Ch3;

impl rlfd_harness::ChapterWithoutInputs for Ch3 {
    const ID: rlfd_harness::ChapterId = CHAPTER_ID;
    const ALIAS: &'static str = "ch3";
    const TRIAL_COSTS: &'static [rlfd_harness::TrialCost] = &[
        rlfd_harness::TrialCost::new("sorting", 0.001, 0.001, 4.0),
        rlfd_harness::TrialCost::new("sorting-100", 0.001, 0.001, 4.0),
        rlfd_harness::TrialCost::new("sorting-noise", 0.001, 0.001, 4.0),
    ];
    type Experiment = Experiment;
    type Results = Results;
    type Error = Ch3Error;

    fn experiments() -> &'static [Experiment] {
        &Experiment::ALL
    }

    fn readings() -> &'static [&'static rlfd_harness::Axis] {
        &readings::AXES
    }

    fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Results, Ch3Error> {
        reproduce(options, experiments)
    }

    fn calibrations() -> Vec<rlfd_harness::Calibration> {
        calibrations::all()
    }

    fn workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch3Error> {
        bench_workloads()
    }
}

/// Runs the chosen experiments (or, as `options.mode` says, loads or verifies their stored trials).
pub fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Results, Ch3Error> {
    let mut results = Results::default();
    for &e in experiments {
        match e {
            Experiment::Sorting => results.sorting = Some(experiment::run_sorting(options, e)?),
            Experiment::SortingPowered => results.powered = Some(experiment::run_sorting(options, e)?),
            Experiment::NoiseSensitivity => results.noise = Some(experiment::run_noise(options)?),
        }
    }
    Ok(results)
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
