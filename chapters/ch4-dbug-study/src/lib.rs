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
//! clock. `xtask` calls [`reproduce`] and [`report::chapter_report`] and
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

use rlfd_harness::RunOptions;
use serde::{Deserialize, Serialize};

pub use experiment::{Ch4Error, IdealParams, IdealResults, ParticipantRecord, StudyParams, StudyResults};

/// The chapter's slug: its directory in reports and result stores.
pub const CHAPTER: &str = "ch4-dbug-study";

/// The chapter as its stored trials name it (slug and build identity).
pub const CHAPTER_ID: rlfd_harness::ChapterId =
    rlfd_harness::ChapterId { slug: CHAPTER, build: rlfd_harness::BUILD_IDENTITY };

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
        Study = "study", behaviour 2,
        /// The thesis's authors: "able to teach the task using all three methods within this time frame".
        IdealTeacher = "ideal-teacher", behaviour 2,
    }
}

/// The results of the experiments that ran.
#[derive(Clone, Debug, Default)]
pub struct Results {
    pub study: Option<StudyResults>,
    pub ideal: Option<IdealResults>,
}

impl Results {
    /// Trials computed and reused over all experiments.
    pub fn trial_counts(&self) -> (usize, usize) {
        let s = self.study.as_ref().map_or((0, 0), |s| (s.computed, s.reused));
        let i = self.ideal.as_ref().map_or((0, 0), |i| (i.computed, i.reused));
        (s.0 + i.0, s.1 + i.1)
    }
}

/// Chapter 4 as the harness runs it (see [`rlfd_harness::Chapter`]).
#[derive(Clone, Copy, Debug)]
pub struct Ch4;

impl rlfd_harness::ChapterWithoutInputs for Ch4 {
    const ID: rlfd_harness::ChapterId = CHAPTER_ID;
    const ALIAS: &'static str = "ch4";
    const TRIAL_COSTS: &'static [rlfd_harness::TrialCost] = &[
        rlfd_harness::TrialCost::new("study", 0.025, 0.025, 16.0),
        rlfd_harness::TrialCost::new("ideal-teacher", 0.008, 0.008, 8.0),
    ];
    type Experiment = Experiment;
    type Results = Results;
    type Error = Ch4Error;

    fn experiments() -> &'static [Experiment] {
        &Experiment::ALL
    }

    fn readings() -> &'static [&'static rlfd_harness::Axis] {
        &readings::AXES
    }

    fn calibrations() -> Vec<rlfd_harness::Calibration> {
        calibrations::all()
    }

    fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Results, Ch4Error> {
        reproduce(options, experiments)
    }

    fn workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, Ch4Error> {
        bench_workloads()
    }
}

/// Runs the chosen experiments (or, as `options.mode` says, loads or verifies their stored trials).
pub fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Results, Ch4Error> {
    let mut results = Results::default();
    for e in experiments {
        match e {
            Experiment::Study => {
                results.study = Some(experiment::run_study(options, &StudyParams::for_scale(options.scale))?)
            }
            Experiment::IdealTeacher => {
                results.ideal = Some(experiment::run_ideal(options, &IdealParams::for_scale(options.scale))?)
            }
        }
    }
    Ok(results)
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
