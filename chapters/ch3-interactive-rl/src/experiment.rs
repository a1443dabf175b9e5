//! The chapter's experiments through the harness: the four conditions of
//! section 3.3.2 (small/large state space × guidance/no guidance), three
//! trials each as the thesis ran ([`Experiment::Sorting`]), a hundred each so
//! that the comparisons can be tested ([`Experiment::SortingPowered`]). The
//! report's sensitivity to the large space's reading noise is
//! [`Experiment::SortingPowered`] swept over the `perception-noise` reading
//! (see [`crate::SWEEPS`]): the same trials the robustness run's reading cells
//! compute at the master seed, so the two cannot disagree.
//!
//! Every trial is one training session ([`crate::session`]) keyed by
//! `(ch3-interactive-rl, experiment, condition, trial)`, seeded with
//! `derive_seed` and identified by the experiment's behaviour version, the
//! build identity, the condition and its serialised setup.

use std::collections::BTreeMap;
use std::fmt;

use rlfd_harness::{Batch, HarnessError, RunContext, RunOptions, Scale, TrialRunner};
use rlfd_rl::random::seeded;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::CHAPTER;
use crate::learner::LearnerParams;
use crate::nao::{Durations, SHIFT_PROBABILITY, StateSpace};
use crate::session::{SessionRecord, SessionSetup, run_session};
use crate::teacher::TeacherProtocol;

/// What can stop the chapter.
#[derive(Debug, Error)]
pub enum Ch3Error {
    /// A parameter outside its domain.
    #[error("parameter `{name}` = {value} is invalid: {expected}")]
    Param { name: &'static str, value: String, expected: &'static str },
    /// Storing or loading trials failed.
    #[error(transparent)]
    Harness(#[from] HarnessError),
}

fn param(name: &'static str, value: impl fmt::Display, expected: &'static str) -> Ch3Error {
    Ch3Error::Param { name, value: value.to_string(), expected }
}

rlfd_harness::experiments! {
    /// The chapter's experiments, with the behaviour version that keys their
    /// stored trials (bump it when what the experiment computes changes).
    #[derive(Serialize, Deserialize)]
    pub enum Experiment for CHAPTER {
        /// Section 3.4: four conditions, three trials each (Table 3.2, Figure 3.4).
        Sorting = "sorting", behaviour 1,
        /// The same with 100 trials per condition, for t-tests (not in the thesis).
        SortingPowered = "sorting-100", behaviour 1,
    }
}

/// One of the thesis's four conditions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Condition {
    /// Figure 3.4a.
    SmallGuidance,
    /// Figure 3.4b.
    LargeGuidance,
    /// Figure 3.4c.
    SmallNoGuidance,
    /// Figure 3.4d.
    LargeNoGuidance,
}

impl Condition {
    /// The conditions in Table 3.2's column order (Figure 3.4a–d).
    pub const ALL: [Condition; 4] =
        [Condition::SmallGuidance, Condition::LargeGuidance, Condition::SmallNoGuidance, Condition::LargeNoGuidance];

    /// The condition of `space` with or without guidance.
    pub fn of(space: StateSpace, guidance: bool) -> Condition {
        match (space, guidance) {
            (StateSpace::Small, true) => Condition::SmallGuidance,
            (StateSpace::Large, true) => Condition::LargeGuidance,
            (StateSpace::Small, false) => Condition::SmallNoGuidance,
            (StateSpace::Large, false) => Condition::LargeNoGuidance,
        }
    }

    /// The state space.
    pub fn space(self) -> StateSpace {
        match self {
            Condition::SmallGuidance | Condition::SmallNoGuidance => StateSpace::Small,
            Condition::LargeGuidance | Condition::LargeNoGuidance => StateSpace::Large,
        }
    }

    /// Whether the teacher guides.
    pub fn guidance(self) -> bool {
        matches!(self, Condition::SmallGuidance | Condition::LargeGuidance)
    }

    /// The name in result paths: `small-guidance`, …
    pub fn slug(self) -> &'static str {
        match self {
            Condition::SmallGuidance => "small-guidance",
            Condition::LargeGuidance => "large-guidance",
            Condition::SmallNoGuidance => "small-no-guidance",
            Condition::LargeNoGuidance => "large-no-guidance",
        }
    }

    /// The label of `thesis-numbers.toml`: `small_guidance`, …
    pub fn published_key(self) -> &'static str {
        match self {
            Condition::SmallGuidance => "small_guidance",
            Condition::LargeGuidance => "large_guidance",
            Condition::SmallNoGuidance => "small_no_guidance",
            Condition::LargeNoGuidance => "large_no_guidance",
        }
    }

    /// For people: `Small, guidance`.
    pub fn label(self) -> &'static str {
        match self {
            Condition::SmallGuidance => "Small, guidance",
            Condition::LargeGuidance => "Large, guidance",
            Condition::SmallNoGuidance => "Small, no guidance",
            Condition::LargeNoGuidance => "Large, no guidance",
        }
    }

    /// The thesis's panel of Figure 3.4: `3.4a` … `3.4d`.
    pub fn figure(self) -> &'static str {
        match self {
            Condition::SmallGuidance => "3.4a",
            Condition::LargeGuidance => "3.4b",
            Condition::SmallNoGuidance => "3.4c",
            Condition::LargeNoGuidance => "3.4d",
        }
    }
}

/// The parameters of a sorting experiment (every condition shares them;
/// the state space picks the learner's ε decay).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SortingParams {
    /// Trials per condition (thesis: 3).
    pub trials: u32,
    /// Algorithm 1 in the small space (thesis: α 0.3, γ 0.75, Q₀ 0.5, ε 0.1, δε 0.002).
    pub learner_small: LearnerParams,
    /// Algorithm 1 in the large space (δε 0.001).
    pub learner_large: LearnerParams,
    /// The teacher's protocol (thesis: 20 initial, 5 after a mistake; rewards ±1 ours).
    pub protocol: TeacherProtocol,
    /// Large-space reading noise (ours: 0.2, fixed before any learner ran).
    pub shift_probability: f64,
    /// Seconds per action (calibrated on the thesis's 9.8 s mean).
    pub durations: Durations,
    /// Clean objects into each cup that end training (thesis: 3).
    pub objects_per_cup: u32,
    /// Actions after which an unfinished session stops (ours: 5,000, far
    /// beyond the thesis's longest mean of 367).
    pub max_actions: u32,
}

impl SortingParams {
    /// The thesis's setting with `trials` per condition.
    pub fn thesis(trials: u32) -> SortingParams {
        SortingParams {
            trials,
            learner_small: LearnerParams::thesis(StateSpace::Small),
            learner_large: LearnerParams::thesis(StateSpace::Large),
            protocol: TeacherProtocol::thesis(),
            shift_probability: SHIFT_PROBABILITY,
            durations: Durations::thesis(),
            objects_per_cup: 3,
            max_actions: 5_000,
        }
    }

    /// The parameters of `experiment` at `scale`: 3 trials per condition
    /// for [`Experiment::Sorting`] at both scales; 100 (paper) or 10 (quick)
    /// for [`Experiment::SortingPowered`].
    pub fn of(experiment: Experiment, scale: Scale) -> SortingParams {
        let trials = match (experiment, scale) {
            (Experiment::Sorting, _) => 3,
            (Experiment::SortingPowered, Scale::Paper) => 100,
            (Experiment::SortingPowered, Scale::Quick) => 10,
        };
        SortingParams::thesis(trials)
    }

    /// The paper scale of the thesis's experiment (3 trials per condition).
    pub fn paper() -> SortingParams {
        SortingParams::of(Experiment::Sorting, Scale::Paper)
    }

    /// The quick scale of the thesis's experiment (the same: it takes milliseconds).
    pub fn quick() -> SortingParams {
        SortingParams::of(Experiment::Sorting, Scale::Quick)
    }

    /// Checks every field once.
    pub fn check(&self) -> Result<(), Ch3Error> {
        if self.trials == 0 {
            return Err(param("trials", self.trials, "at least 1"));
        }
        for l in [&self.learner_small, &self.learner_large] {
            if let Some((name, value, expected)) = l.invalid() {
                return Err(param(name, value, expected));
            }
        }
        let p = &self.protocol;
        if !(p.correct_reward.is_finite() && p.wrong_reward.is_finite()) {
            return Err(param("protocol.correct_reward/wrong_reward", p.correct_reward, "finite rewards"));
        }
        if !(0.0..=1.0).contains(&self.shift_probability) {
            return Err(param("shift_probability", self.shift_probability, "a probability in [0, 1]"));
        }
        if !self.durations.is_valid() {
            return Err(param("durations", format!("{:?}", self.durations), "finite positive units and unit length"));
        }
        if self.objects_per_cup == 0 {
            return Err(param("objects_per_cup", self.objects_per_cup, "at least 1"));
        }
        if self.max_actions == 0 {
            return Err(param("max_actions", self.max_actions, "at least 1"));
        }
        Ok(())
    }

    /// The session setup of `condition`.
    pub fn setup(&self, condition: Condition) -> SessionSetup {
        let space = condition.space();
        SessionSetup {
            space,
            guidance: condition.guidance(),
            learner: match space {
                StateSpace::Small => self.learner_small,
                StateSpace::Large => self.learner_large,
            },
            protocol: self.protocol,
            shift_probability: self.shift_probability,
            durations: self.durations,
            objects_per_cup: self.objects_per_cup,
            max_actions: self.max_actions,
        }
    }
}

/// A sorting experiment's results.
#[derive(Clone, Debug)]
pub struct SortingResults {
    /// Which experiment.
    pub experiment: Experiment,
    /// The scale it ran at.
    pub scale: Scale,
    /// The master seed.
    pub seed: u64,
    /// Its parameters.
    pub params: SortingParams,
    /// Per condition, its sessions in trial order.
    pub trials: BTreeMap<Condition, Vec<SessionRecord>>,
}

/// One training session per trial, with the session's setup as the
/// trial's parameters; nothing is set up beforehand.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Sessions;

impl TrialRunner for Sessions {
    type Setup = ();
    type Params = SessionSetup;
    type Result = SessionRecord;
    type Error = Ch3Error;

    fn setup(&self) -> Result<(), Ch3Error> {
        Ok(())
    }

    fn run(&self, _: &(), setup: &SessionSetup, seed: u64) -> SessionRecord {
        run_session(setup, &mut seeded(seed))
    }
}

/// A sorting experiment's batch: its four conditions' sessions.
pub struct SortingBatch {
    /// Which experiment.
    pub experiment: Experiment,
    /// Its parameters.
    pub params: SortingParams,
    /// The sessions, condition after condition in [`Condition::ALL`]'s order.
    pub batch: Batch<Sessions>,
}

/// Plans a sorting experiment: the four conditions, each `params.trials`
/// sessions; the run's `perception-noise` reading sets the large space's
/// shift probability (the small space's features are exact) and its
/// `reward-sizes` reading the teacher's praise and punishment.
pub fn plan_sorting(ctx: &RunContext, experiment: Experiment) -> Result<SortingBatch, Ch3Error> {
    let params = SortingParams::of(experiment, ctx.scale);
    params.check()?;
    let mut batch = Batch::new(ctx, CHAPTER, experiment, Sessions);
    let rewards = crate::readings::reward_sizes(&ctx.reading);
    for c in Condition::ALL {
        let mut setup = params.setup(c);
        setup.protocol.correct_reward = rewards.praise;
        setup.protocol.wrong_reward = rewards.punishment;
        if c.space() == StateSpace::Large {
            setup.shift_probability = crate::readings::shift_probability(&ctx.reading);
        }
        for t in 0..params.trials {
            batch.trial(c.slug(), t, setup);
        }
    }
    Ok(SortingBatch { experiment, params, batch })
}

impl SortingBatch {
    /// Runs (or loads) the batch and groups its sessions per condition.
    pub fn execute(&self, options: &RunOptions) -> Result<SortingResults, Ch3Error> {
        let results = self.batch.execute(options)?.results;
        let mut trials: BTreeMap<Condition, Vec<SessionRecord>> = BTreeMap::new();
        let per = self.params.trials as usize;
        for (i, r) in results.into_iter().enumerate() {
            trials.entry(Condition::ALL[i / per]).or_default().push(r);
        }
        Ok(SortingResults {
            experiment: self.experiment,
            scale: self.batch.scale,
            seed: self.batch.master_seed,
            params: self.params.clone(),
            trials,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn experiment_names_parse_and_unknown_ones_list_the_valid() {
        for e in Experiment::ALL {
            assert_eq!(e.name().parse::<Experiment>(), Ok(e));
        }
        let err = "maze".parse::<Experiment>().unwrap_err().to_string();
        assert_eq!(err, "unknown experiment \"maze\" for ch3-interactive-rl (expected one of: sorting, sorting-100)");
    }

    #[test]
    fn conditions_follow_table_3_2_s_columns() {
        let keys: Vec<&str> = Condition::ALL.iter().map(|c| c.published_key()).collect();
        let published = rlfd_report::published::published().strings("ch3.table_3_2.conditions").unwrap();
        assert_eq!(keys, published);
        for c in Condition::ALL {
            assert_eq!(Condition::of(c.space(), c.guidance()), c);
        }
    }

    #[test]
    fn parameters_are_the_thesis_s_and_are_checked() {
        let p = SortingParams::paper();
        assert_eq!(p.trials, 3);
        assert_eq!(SortingParams::of(Experiment::SortingPowered, Scale::Paper).trials, 100);
        assert!(p.check().is_ok());
        assert_eq!(p.setup(Condition::LargeNoGuidance).learner.epsilon_decay, 0.001);
        assert_eq!(p.setup(Condition::SmallGuidance).learner.epsilon_decay, 0.002);
        let bad = SortingParams { shift_probability: 1.5, ..p.clone() };
        assert_eq!(
            bad.check().unwrap_err().to_string(),
            "parameter `shift_probability` = 1.5 is invalid: a probability in [0, 1]"
        );
        let bad = SortingParams { trials: 0, ..p };
        assert!(bad.check().unwrap_err().to_string().contains("`trials`"));
    }
}
