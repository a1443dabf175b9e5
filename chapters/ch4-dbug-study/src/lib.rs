//! Chapter 4 of the thesis: the DBug user study, in which 31 naïve and
//! expert users each teach a Nao to catch hexbugs with Interactive
//! Reinforcement Learning, Behavior Networks and Confidence-Based Autonomy
//! for ten minutes, and the taught policies' accuracy is set against the
//! users' interactions and satisfaction (sections 4.2–4.5, Figures 4.2–4.8).
//!
//! What it is: the table as a simulator ([`dbug`]: camera, zones, hexbugs,
//! the robot's tools), the three learners ([`intrl`], [`bnets`], [`cba`]),
//! the synthetic users ([`users`]: traits drawn per user, the behaviours the
//! chapter describes, the questionnaire), the ten-minute sessions that put
//! them together ([`session`]), how a final policy is scored
//! ([`evaluation`]), the experiments through the harness ([`experiment`]:
//! the study repeated over draws of its users, the scripted ideal teacher)
//! and the report ([`report`]: Figures 4.2–4.8, the correlation table,
//! claims C4.1–C4.9).
//!
//! What it is not: no IO beyond the harness's result store, no printing, no
//! clock. `rlfd-runner` drives it through its `Chapter` implementation (plan,
//! execute, claims, [`report::chapter_report`]) and xtask
//! writes the files.

pub mod bnets;
pub mod calibrations;
pub mod cba;
/// The domain: the `rlfd-dbug` crate.
pub use rlfd_dbug as dbug;
pub mod evaluation;
pub mod experiment;
pub mod intrl;
pub mod readings;
pub mod report;
pub mod session;
pub mod users;

use rlfd_harness::{AnyAxis, AnyBatch, Batch, CommandInputs, RunContext, RunOptions};
use serde::{Deserialize, Serialize};

pub use experiment::{
    Ch4Error, IdealParams, IdealResults, IdealTrials, ParticipantRecord, StudyParams, StudyResults, StudyTrials,
};

/// The chapter's slug: its directory in reports and result stores.
pub const CHAPTER: &str = "ch4-dbug-study";

/// The three learners' parameters.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnerParams {
    pub intrl: intrl::IntRlParams,
    pub bnets: bnets::BnetsParams,
    pub cba: cba::CbaParams,
}

impl LearnerParams {
    /// The thesis's values (with the project's choices where it is silent),
    /// every reading at its default.
    pub const fn thesis() -> LearnerParams {
        LearnerParams {
            intrl: intrl::IntRlParams::thesis(),
            bnets: bnets::BnetsParams {
                order: bnets::NodeOrder::Postcondition,
                scoring: bnets::PassScoring::FullPass,
                wait_credit: bnets::WaitCredit::Scored,
            },
            cba: cba::CbaParams::thesis(),
        }
    }
}

rlfd_harness::experiments! {
    /// The chapter's experiments, with the behaviour version that keys their
    /// stored trials (bump it when what the experiment computes changes).
    pub enum Experiment for CHAPTER {
        /// Section 4.3: 31 participants × 3 algorithms, repeated over independent draws of the users.
        Study = "study", behaviour 3,
        /// The thesis's authors: "able to teach the task using all three methods within this time frame".
        IdealTeacher = "ideal-teacher", behaviour 3,
    }
}

/// The results of the experiments that ran.
#[derive(Clone, Debug, Default)]
pub struct Results {
    pub study: Option<StudyResults>,
    pub ideal: Option<IdealResults>,
}

/// The chapter's experiments' batches at one run point.
#[derive(Default)]
pub struct Plan {
    pub study: Option<Batch<StudyTrials>>,
    pub ideal: Option<Batch<IdealTrials>>,
}

/// Chapter 4 as the runner runs it (see [`rlfd_runner::Chapter`]).
#[derive(Clone, Copy, Debug)]
pub struct Ch4;

impl rlfd_runner::Chapter for Ch4 {
    const SLUG: &'static str = CHAPTER;
    const ALIAS: &'static str = "ch4";
    const TRIAL_COSTS: &'static [rlfd_harness::TrialCost] = &[
        // Paper scale: measured by the robustness run's shards 3, 9 and 12
        // of 16 (`reproduce --scale paper --robustness --seeds 10 --shard
        // I/16 --jobs 2`, 7 December 2026, quiet machine): 0.016 s a study
        // participant, 0.0065 s an ideal teacher (declared 0.025 and 0.008
        // before, timed beside other runs).
        rlfd_harness::TrialCost::new("study", 0.025, 0.016, 16.0),
        rlfd_harness::TrialCost::new("ideal-teacher", 0.008, 0.0065, 8.0),
    ];
    type Experiment = Experiment;
    type Inputs = ();
    type Plan = Plan;
    type Results = Results;
    type Error = Ch4Error;

    fn experiments() -> &'static [Experiment] {
        &Experiment::ALL
    }

    fn readings() -> &'static [&'static dyn AnyAxis] {
        &readings::AXES
    }

    fn calibrations() -> Vec<rlfd_harness::Calibration> {
        calibrations::all()
    }

    fn inputs(_: &CommandInputs<'_>, _: &[Experiment], _: &RunContext) -> Result<(), Ch4Error> {
        Ok(())
    }

    fn plan(ctx: &RunContext, experiments: &[Experiment], _: &()) -> Result<Plan, Ch4Error> {
        let mut plan = Plan::default();
        for e in experiments {
            match e {
                Experiment::Study => {
                    plan.study = Some(experiment::plan_study(ctx, &StudyParams::for_scale(ctx.scale))?)
                }
                Experiment::IdealTeacher => {
                    plan.ideal = Some(experiment::plan_ideal(ctx, &IdealParams::for_scale(ctx.scale))?)
                }
            }
        }
        Ok(plan)
    }

    fn batches(plan: &Plan) -> Vec<&dyn AnyBatch> {
        let mut out: Vec<&dyn AnyBatch> = Vec::new();
        out.extend(plan.study.iter().map(|b| b as &dyn AnyBatch));
        out.extend(plan.ideal.iter().map(|b| b as &dyn AnyBatch));
        out
    }

    fn execute(plan: &Plan, options: &RunOptions) -> Result<Results, Ch4Error> {
        Ok(Results {
            study: plan.study.as_ref().map(|b| experiment::run_study(b, options)).transpose()?,
            ideal: plan.ideal.as_ref().map(|b| experiment::run_ideal(b, options)).transpose()?,
        })
    }

    fn claims(results: &Results) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
        report::claims(results)
    }

    fn report(
        results: &Results,
        _sweeps: &[rlfd_runner::Swept<'_, Results>],
        provenance: &rlfd_report::Provenance,
    ) -> rlfd_report::Result<rlfd_report::ChapterReport> {
        report::chapter_report(results, provenance)
    }

    fn workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch4Error> {
        bench_workloads()
    }
}

/// The chapter's benchmark workloads for `cargo xtask bench`: the table
/// alone, and one ten-minute session of each algorithm with a drawn user
/// (simulated ticks per second).
pub fn bench_workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch4Error> {
    use session::{SessionParams, Teacher, run_session};
    use users::{Algorithm, Expertise, UserModel};
    let mut out = vec![rlfd_harness::Workload {
        domain: "dbug",
        name: "simulator".into(),
        unit: "ticks",
        run: Box::new(|seed| dbug::busy_table_ticks(seed, 60_000)),
    }];
    for a in Algorithm::ALL {
        out.push(rlfd_harness::Workload {
            domain: "dbug",
            name: format!("{}-session", a.key()),
            unit: "ticks",
            run: Box::new(move |seed| {
                let model = UserModel::thesis();
                let mut rng = rlfd_rl::random::seeded(seed);
                let traits = model.traits.draw(Expertise::Novice, &mut rng);
                let params = SessionParams::thesis();
                run_session(
                    a,
                    &Teacher { traits, session: 0, ideal: false },
                    &model,
                    &params,
                    &LearnerParams::thesis(),
                    &mut rng,
                );
                u64::from(dbug::seconds_to_ticks(params.seconds))
            }),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn experiments_parse_by_name() {
        assert_eq!("study".parse::<Experiment>(), Ok(Experiment::Study));
        assert_eq!("ideal-teacher".parse::<Experiment>(), Ok(Experiment::IdealTeacher));
        let e = "maze".parse::<Experiment>().unwrap_err().to_string();
        assert_eq!(e, "unknown experiment \"maze\" for ch4-dbug-study (expected one of: study, ideal-teacher)");
    }
}
