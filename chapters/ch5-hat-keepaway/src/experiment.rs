//! The chapter's experiments through the harness: the benchmark policies in
//! four keepaway configurations (the simulator's validation against the real
//! server), the demonstrations (calibration check, the rules played alone,
//! a traced episode) and the learning conditions of Tables 5.1–5.4.
//!
//! Every learning condition is one method with one demonstration set (or
//! none), run for `trials` trials of `hours` simulated hours. Conditions
//! shared by several tables (No Prior, PPR on Subject A, …) are the same
//! stored trials whichever experiment asked for them: their keys use the
//! one experiment name [`LEARNING_KEY`].

use std::collections::BTreeMap;

use std::sync::{Arc, Mutex};

use rlfd_harness::{AnyBatch, Batch, ExperimentId, HarnessError, RunContext, RunOptions, Scale, TrialRunner};
use rlfd_lfd::ripper::{DecisionList, RipperError};
use rlfd_rl::random::seeded;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::benchmarks::BenchmarkPolicy;
use crate::inputs::{DemoInputs, DemoSetId, prepare, thesis_a_rules};
use crate::keepaway::{EndCause, Keepaway, KeepawayParams, KeeperAction, MAX_STATE_VARS, STATE_VARS, Snapshot};
use crate::learners::{LearnerParamError, LearnerParams, LearningTrial, Method, TrialParams, run_learning_trial};
use crate::readings;
use crate::teachers::calibration::{CALIBRATION_EPISODES, CALIBRATION_SEED};
use crate::teachers::{FrequentPasser, Teacher, demonstration};
use crate::{CHAPTER, Experiment};

/// The experiment name of every learning trial's key.
pub const LEARNING_KEY: &str = "keepaway-learning";

/// The behaviour version of the learning trials (the HAT learners, their
/// features and the simulator they play in), shared by the four learning
/// experiments. 2: the simulator rebuilt on the keepaway 0.6 players'
/// skills and the server's collisions and vision, Weka's JRip, the teachers
/// recalibrated, greedy evaluations. 3: players know only their own kicks
/// and hear one teammate's ball message a cycle later (issue 28). 4: every
/// teacher's perception noise declared 0 m instead of fitted (Subject B's
/// was 0.8 m), which changes B's, B Fast's and B Limited's recordings and
/// rules (issue 28). 5: the players sense collisions with the ball
/// (`updateBallForCollision`) and see in phases as keepaway.sh starts them
/// (`SeePhases::KEEPAWAY_SH`), which lengthens every keeper policy's
/// episodes (issue 28). 6: a see of a ball beyond 20 m leaves out its
/// velocity as the server's does (`sendHighBall`), the player keeping the
/// one it predicted (issue 28).
pub const LEARNING_BEHAVIOUR: u32 = 6;

/// The keepaway configurations the validation plays: (keepers, takers,
/// region side in m). The first is the thesis's.
pub const VALIDATION_CONFIGS: [(usize, usize, f64); 4] = [(3, 2, 20.0), (3, 2, 25.0), (4, 3, 20.0), (4, 3, 25.0)];

/// A configuration's name in result paths and tables (`3v2-20m`).
pub fn config_slug(c: (usize, usize, f64)) -> String {
    format!("{}v{}-{}m", c.0, c.1, c.2)
}

/// The learning trials as the store names them.
#[derive(Clone, Copy, Debug)]
struct LearningKey;

impl ExperimentId for LearningKey {
    fn name(self) -> &'static str {
        LEARNING_KEY
    }
    fn behaviour(self) -> u32 {
        LEARNING_BEHAVIOUR
    }
}

/// What can stop the chapter's experiments.
#[derive(Debug, Error)]
pub enum Ch5Error {
    /// RIPPER refused a demonstration set.
    #[error("RIPPER")]
    Ripper(#[from] RipperError),
    /// A learner's parameters are invalid.
    #[error(transparent)]
    Learner(#[from] LearnerParamError),
    /// Storing or loading trials failed.
    #[error(transparent)]
    Harness(#[from] HarnessError),
}

/// The parameters of a scale.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ch5Params {
    /// Trials per learning condition (thesis: 10).
    pub trials: u32,
    /// Simulated hours per trial (thesis: 30).
    pub hours: f64,
    /// Episodes of the jumpstart evaluation (thesis: 1,000).
    pub eval_episodes: usize,
    /// Episodes of each greedy evaluation, at the start and every integral hour (ours).
    pub greedy_episodes: usize,
    /// Episodes of the sliding window of the final and hourly means (thesis: 1,000).
    pub window: usize,
    /// Episodes per benchmark policy and configuration (the oracle's 2,000).
    pub validation_episodes: usize,
    /// Episodes of the rules-only policy per demonstration set.
    pub rules_only_episodes: usize,
    /// Trials of Subject A's rules played with the learners' exploration (C5.10), each `rules_only_episodes`.
    pub rules_explore_trials: u32,
    /// The episode duration whose first crossing is timed (thesis: 14 s).
    pub threshold_seconds: f64,
    /// The keepers' learner.
    pub learner: LearnerParams,
}

impl Ch5Params {
    /// The thesis's scale.
    pub fn paper() -> Self {
        Ch5Params {
            trials: 10,
            hours: 30.0,
            eval_episodes: 1000,
            greedy_episodes: 100,
            window: 1000,
            validation_episodes: 2000,
            rules_only_episodes: 1000,
            rules_explore_trials: 10,
            threshold_seconds: 14.0,
            learner: LearnerParams::thesis(),
        }
    }

    /// Every code path in seconds: 3 trials of one simulated hour, windows of 100 episodes.
    pub fn quick() -> Self {
        Ch5Params {
            trials: 3,
            hours: 1.0,
            eval_episodes: 100,
            greedy_episodes: 10,
            window: 100,
            validation_episodes: 100,
            rules_only_episodes: 100,
            rules_explore_trials: 3,
            ..Self::paper()
        }
    }

    /// The parameters of `scale`.
    pub fn for_scale(scale: Scale) -> Self {
        match scale {
            Scale::Quick => Self::quick(),
            Scale::Paper => Self::paper(),
        }
    }
}

/// A learning condition: a method and the demonstration set its rules come from.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Condition {
    /// How the rules are used.
    pub method: Method,
    /// Whose rules (`None` for No Prior).
    pub set: Option<DemoSetId>,
}

impl Condition {
    /// No Prior.
    pub const NO_PRIOR: Condition = Condition { method: Method::NoPrior, set: None };

    /// PPR on a set.
    pub const fn ppr(set: DemoSetId) -> Condition {
        Condition { method: Method::POLICY_REUSE, set: Some(set) }
    }

    /// The name in result paths.
    pub fn slug(&self) -> String {
        let method = match self.method {
            Method::NoPrior => return "no-prior".into(),
            Method::ValueBonus { .. } => "value-bonus",
            Method::ExtraAction { .. } => "extra-action",
            Method::PolicyReuse { .. } => "ppr",
        };
        format!("{method}-{}", self.set.map_or("none", DemoSetId::slug))
    }

    /// The conditions of an experiment, in its table's order.
    pub fn of(experiment: Experiment) -> Vec<Condition> {
        use DemoSetId::*;
        match experiment {
            Experiment::Hat => vec![
                Condition::NO_PRIOR,
                Condition { method: Method::VALUE_BONUS, set: Some(A20) },
                Condition { method: Method::EXTRA_ACTION, set: Some(A20) },
                Condition::ppr(A20),
            ],
            Experiment::Teachers => {
                vec![Condition::NO_PRIOR, Condition::ppr(A20), Condition::ppr(B), Condition::ppr(C)]
            }
            Experiment::DemoSets => vec![
                Condition::NO_PRIOR,
                Condition::ppr(A20),
                Condition::ppr(A10),
                Condition::ppr(C),
                Condition::ppr(AcBest),
                Condition::ppr(AcWorst),
            ],
            Experiment::Handicaps => {
                vec![Condition::NO_PRIOR, Condition::ppr(B), Condition::ppr(BLimited), Condition::ppr(BFast)]
            }
            Experiment::Validation | Experiment::Demonstrations => vec![],
        }
    }
}

/// A traced episode: where everything was at every cycle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TracedEpisode {
    /// Who played the keeper with the ball.
    pub player: String,
    /// One snapshot per cycle, from the start.
    pub cycles: Vec<Snapshot>,
}

/// The demonstrations experiment's stored products.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CalibrationCheck {
    /// Per teacher (in [`Teacher::ALL`] order), the durations (cycles) of the
    /// calibration episodes its model plays.
    pub episodes: Vec<Vec<u32>>,
}

impl CalibrationCheck {
    /// Per teacher, the mean duration (s).
    pub fn model_means(&self) -> Vec<f64> {
        self.episodes
            .iter()
            .map(|d| {
                d.iter().map(|&c| f64::from(c)).sum::<f64>()
                    / d.len().max(1) as f64
                    / crate::keepaway::CYCLES_PER_SECOND
            })
            .collect()
    }
}

/// One validation episode, as the oracle's analysis summarises one.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct EpisodeRecord {
    /// Duration in cycles.
    pub duration: u32,
    /// Whether the ball left the region (else the takers took it).
    pub out: bool,
    /// Completed passes (a keeper's kick after another keeper's, no taker kick between).
    pub passes: u16,
    /// Kick commands of the keepers.
    pub keeper_kicks: u16,
    /// Kick commands of the takers.
    pub taker_kicks: u16,
    /// Which team kicked last (`Some(true)`: a keeper), as the oracle's
    /// analysis counts it (in the order the server received the kicks).
    #[serde(default)]
    pub last_by_keeper: Option<bool>,
    /// Whether the episode ended within 10 cycles of a strong (≥ 50) keeper
    /// kick with no taker kick since (a pass that rolled out or was taken).
    #[serde(default)]
    pub lost_pass: bool,
    /// Whether both teams sent a kick command in the last cycle in which
    /// anyone did (the team counted last is then the one received last).
    #[serde(default)]
    pub both_teams_last: bool,
}

/// Everything the report is made from.
#[derive(Clone, Debug)]
pub struct Ch5Results {
    /// The scale.
    pub scale: Scale,
    /// The master seed.
    pub seed: u64,
    /// The parameters.
    pub params: Ch5Params,
    /// The experiments that ran.
    pub experiments: Vec<Experiment>,
    /// The demonstrations and rules, when an experiment needed them.
    pub demos: Option<DemoInputs>,
    /// The validation's episodes per configuration (index into [`VALIDATION_CONFIGS`]) and policy.
    pub validation: BTreeMap<(usize, BenchmarkPolicy), Vec<EpisodeRecord>>,
    /// The teacher models' calibration episodes.
    pub calibration: Option<CalibrationCheck>,
    /// Episode durations (cycles) of the rules-only policy of each set.
    pub rules_only: BTreeMap<DemoSetId, Vec<u32>>,
    /// Subject A's rules played with the learners' ε-exploration: per trial, the durations (cycles).
    pub rules_explore: Vec<Vec<u32>>,
    /// The reading the results were made under (its label).
    pub reading: String,
    /// The learners' exploration rate under that reading.
    pub epsilon: f64,
    /// Whether Subject A's rules are the thesis's printed list.
    pub thesis_a_rules: bool,
    /// Which of Subjects B and C passes frequently under that reading.
    pub passer: FrequentPasser,
    /// C5.3's threshold under that reading.
    pub threshold: readings::ThresholdReading,
    /// A traced demonstration episode (for the picture).
    pub traced: Option<TracedEpisode>,
    /// Learning trials per condition, by slug, with the condition.
    pub learning: BTreeMap<String, (Condition, Vec<LearningTrial>)>,
}

impl Ch5Results {
    /// The trials of a condition, if it ran.
    pub fn trials(&self, c: &Condition) -> Option<&[LearningTrial]> {
        self.learning.get(&c.slug()).map(|(_, t)| t.as_slice())
    }
}

/// Plays `episodes` episodes with every keeper following `choose`; returns the durations.
pub fn play_policy(
    episodes: usize,
    seed: u64,
    mut choose: impl FnMut(&[f64; STATE_VARS], &mut rlfd_rl::random::SimRng) -> KeeperAction,
) -> Vec<u32> {
    let mut game = Keepaway::benchmark();
    let mut rng = seeded(seed);
    let mut state = [0.0; STATE_VARS];
    (0..episodes)
        .map(|_| {
            game.play_episode(&mut rng, |g, k, rng| {
                g.state_vars(k, &mut state);
                choose(&state, rng)
            })
            .0
        })
        .collect()
}

/// The rules-only policy: every keeper does what the decision list says.
pub fn rules_only(rules: &DecisionList, episodes: usize, seed: u64) -> Vec<u32> {
    play_policy(episodes, seed, |s, _| KeeperAction::ALL[rules.predict(s).min(2)])
}

/// The rules with the learners' exploration: every keeper explores with
/// probability `epsilon` (an action uniformly at random) and otherwise does
/// what the decision list says (C5.10's like-for-like comparison).
pub fn rules_explore(rules: &DecisionList, epsilon: f64, episodes: usize, seed: u64) -> Vec<u32> {
    play_policy(episodes, seed, |s, rng| {
        if rlfd_rl::random::uniform01(rng) < epsilon {
            KeeperAction::ALL[rlfd_rl::random::below(rng, 3)]
        } else {
            KeeperAction::ALL[rules.predict(s).min(2)]
        }
    })
}

/// A benchmark policy's validation episodes in a configuration.
pub fn validate(
    policy: BenchmarkPolicy,
    config: (usize, usize, f64),
    episodes: usize,
    seed: u64,
) -> Vec<EpisodeRecord> {
    let (nk, nt, side) = config;
    let mut game =
        Keepaway::new(KeepawayParams::configuration(nk, nt, side)).expect("the validation configurations are valid");
    let len = game.params().state_len();
    let mut rng = seeded(seed);
    let mut state = [0.0; MAX_STATE_VARS];
    (0..episodes)
        .map(|_| {
            let (duration, cause) = game.play_episode(&mut rng, |g, _, rng| {
                g.state_vars_into(&mut state[..len]);
                policy.choose_in(&state[..len], nk, nt, rng)
            });
            let t = game.tally();
            let short = |x: u32| u16::try_from(x).unwrap_or(u16::MAX);
            EpisodeRecord {
                duration,
                out: cause == EndCause::Out,
                passes: short(t.passes),
                keeper_kicks: short(t.keeper_kicks),
                taker_kicks: short(t.taker_kicks),
                last_by_keeper: t.last_by_keeper,
                lost_pass: t.lost_after_strong_kick(duration, 10),
                both_teams_last: t.both_teams_in_last_kick_cycle(),
            }
        })
        .collect()
}

/// Where a learning condition's or a rules-alone run's rule list comes
/// from: JRip on one of the sets, or the list the thesis prints for Subject
/// A (the `a-rules` reading's default, for A (20)'s trials).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum RuleSource {
    /// JRip's list of a demonstration set.
    Set {
        /// The set.
        set: DemoSetId,
        /// Which of B and C passed frequently when it was recorded, for the
        /// sets holding B's or C's episodes (`None` for A's alone): part of
        /// the trial's identity exactly where the `bc-styles` reading
        /// changes the rules.
        passer: Option<FrequentPasser>,
    },
    /// The list printed in section 5.4.
    ThesisA,
}

impl RuleSource {
    /// The rules of `set` under a reading that does (`thesis_a`) or does not
    /// take the printed list for Subject A's 20 demonstrations, with B's and
    /// C's styles as `passer` assigns them.
    pub fn of(set: DemoSetId, thesis_a: bool, passer: FrequentPasser) -> RuleSource {
        if thesis_a && set == DemoSetId::A20 {
            RuleSource::ThesisA
        } else {
            RuleSource::Set { set, passer: set.depends_on_bc_styles().then_some(passer) }
        }
    }
}

/// What the demonstrations and learning trials share: the teachers'
/// recordings and their rules, and the printed list for Subject A.
#[derive(Debug)]
pub struct Demos {
    /// Which of B and C passed frequently in these recordings.
    pub passer: FrequentPasser,
    /// Every set with its rules.
    pub inputs: DemoInputs,
    /// The thesis's printed list for Subject A.
    pub thesis_a: DecisionList,
}

impl Demos {
    /// The rules `source` names (recorded under these demonstrations' style assignment).
    pub fn rules(&self, source: RuleSource) -> &DecisionList {
        match source {
            RuleSource::Set { set, passer } => {
                debug_assert!(passer.is_none_or(|p| p == self.passer), "a trial's rules come from its own recordings");
                &self.inputs.get(set).rules
            }
            RuleSource::ThesisA => &self.thesis_a,
        }
    }
}

/// The teachers' recordings per master seed and style assignment, made once
/// per process and shared by the experiments that use them.
#[derive(Debug, Default)]
pub struct DemoCache(Mutex<Vec<(u64, Arc<Demos>)>>);

impl DemoCache {
    /// The recordings of `master_seed` with B's and C's styles as `passer` assigns them, made if not yet.
    pub fn get(&self, master_seed: u64, passer: FrequentPasser) -> Result<Arc<Demos>, Ch5Error> {
        let mut made = self.0.lock().expect("no thread panics holding the cache");
        if let Some((_, d)) = made.iter().find(|(s, d)| *s == master_seed && d.passer == passer) {
            return Ok(d.clone());
        }
        let d = Arc::new(Demos { passer, inputs: prepare(master_seed, passer)?, thesis_a: thesis_a_rules() });
        made.push((master_seed, d.clone()));
        Ok(d)
    }
}

/// The process's recordings.
fn demo_cache() -> &'static DemoCache {
    static CACHE: std::sync::OnceLock<DemoCache> = std::sync::OnceLock::new();
    CACHE.get_or_init(DemoCache::default)
}

/// The validation's trials: a benchmark policy's episodes in a configuration.
#[derive(Clone, Debug, Serialize)]
pub struct ValidationTrials {
    /// Episodes per policy and configuration.
    pub episodes: usize,
}

impl TrialRunner for ValidationTrials {
    type Setup = ();
    type Params = (usize, BenchmarkPolicy);
    type Result = Vec<EpisodeRecord>;
    type Error = Ch5Error;

    fn setup(&self) -> Result<(), Ch5Error> {
        Ok(())
    }

    fn run(&self, _: &(), &(c, policy): &(usize, BenchmarkPolicy), seed: u64) -> Vec<EpisodeRecord> {
        validate(policy, VALIDATION_CONFIGS[c], self.episodes, seed)
    }
}

/// A trial of the demonstrations experiment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum DemoTrial {
    /// The teacher models' calibration episodes.
    Calibration(CalibrationCheck),
    /// A traced episode of Subject A.
    Traced(TracedEpisode),
    /// Episode durations (cycles) of a rule list played.
    RulesOnly(Vec<u32>),
}

/// What one trial of the demonstrations experiment plays.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum DemoJob {
    /// The teacher models' calibration episodes (the calibration's own
    /// seed), B's and C's styles as the reading assigns them.
    Calibration {
        /// Which of B and C passes frequently.
        passer: FrequentPasser,
    },
    /// Subject A's traced episode.
    Traced,
    /// A rule list played alone, greedily.
    RulesOnly {
        /// The rules.
        rules: RuleSource,
        /// Episodes.
        episodes: usize,
    },
    /// A rule list played with the learners' exploration.
    RulesExplore {
        /// The rules.
        rules: RuleSource,
        /// Episodes.
        episodes: usize,
        /// The exploration rate.
        epsilon: f64,
    },
}

/// The demonstrations experiment's trials, on the recordings of a master seed.
#[derive(Clone, Debug, Serialize)]
pub struct DemonstrationTrials {
    /// The master seed the recordings are made from.
    pub master_seed: u64,
    /// Which of B and C passes frequently in the recordings (not part of
    /// every trial's identity: the trials that depend on it carry it in
    /// their parameters, so the `bc-styles` reading recomputes those alone).
    #[serde(skip)]
    pub passer: FrequentPasser,
}

impl TrialRunner for DemonstrationTrials {
    type Setup = Arc<Demos>;
    type Params = DemoJob;
    type Result = DemoTrial;
    type Error = Ch5Error;

    fn setup(&self) -> Result<Arc<Demos>, Ch5Error> {
        demo_cache().get(self.master_seed, self.passer)
    }

    fn run(&self, demos: &Arc<Demos>, job: &DemoJob, seed: u64) -> DemoTrial {
        match *job {
            DemoJob::Calibration { passer } => DemoTrial::Calibration(CalibrationCheck {
                episodes: Teacher::ALL
                    .iter()
                    .map(|t| {
                        let mut game = Keepaway::benchmark();
                        let m = t.model(passer);
                        game.keep_history(m.history_needed());
                        let mut rng = seeded(CALIBRATION_SEED);
                        (0..CALIBRATION_EPISODES)
                            .map(|_| game.play_episode(&mut rng, |g, k, r| m.choose(g, k, r)).0)
                            .collect()
                    })
                    .collect(),
            }),
            DemoJob::Traced => {
                let model = Teacher::A.model(demos.passer);
                let mut game = Keepaway::benchmark();
                game.keep_history(model.history_needed());
                game.record_trace(true);
                let mut rng = seeded(seed);
                let _ = demonstration::demonstrate(&mut game, &model, Teacher::A.label(), 0, &mut rng);
                DemoTrial::Traced(TracedEpisode { player: Teacher::A.label().into(), cycles: game.trace().to_vec() })
            }
            DemoJob::RulesOnly { rules, episodes } => {
                DemoTrial::RulesOnly(rules_only(demos.rules(rules), episodes, seed))
            }
            DemoJob::RulesExplore { rules, episodes, epsilon } => {
                DemoTrial::RulesOnly(rules_explore(demos.rules(rules), epsilon, episodes, seed))
            }
        }
    }
}

/// The learning trials, on the recordings of a master seed.
#[derive(Clone, Debug, Serialize)]
pub struct LearningTrials {
    /// The master seed the recordings are made from.
    pub master_seed: u64,
    /// Which of B and C passes frequently in the recordings (in the
    /// parameters of the trials that depend on it, [`RuleSource`]).
    #[serde(skip)]
    pub passer: FrequentPasser,
}

impl TrialRunner for LearningTrials {
    type Setup = Arc<Demos>;
    type Params = (TrialParams, Option<RuleSource>);
    type Result = LearningTrial;
    type Error = Ch5Error;

    fn setup(&self) -> Result<Arc<Demos>, Ch5Error> {
        demo_cache().get(self.master_seed, self.passer)
    }

    fn run(&self, demos: &Arc<Demos>, (params, rules): &(TrialParams, Option<RuleSource>), seed: u64) -> LearningTrial {
        run_learning_trial(params, rules.map(|r| demos.rules(r)), seed).expect("parameters checked before running")
    }
}

/// The chapter's experiments' batches at one run point.
pub struct Plan {
    /// The run's scale and seed.
    ctx: RunContext,
    /// The parameters under the run's reading.
    params: Ch5Params,
    /// The experiments planned.
    experiments: Vec<Experiment>,
    /// The validation.
    validation: Option<Batch<ValidationTrials>>,
    /// The demonstrations experiment, with which rule list Subject A's trials use.
    demonstrations: Option<Batch<DemonstrationTrials>>,
    /// The learning conditions and their trials.
    learning: Option<(Vec<Condition>, Batch<LearningTrials>)>,
}

/// Plans the chosen experiments at `ctx`.
pub fn plan(ctx: &RunContext, experiments: &[Experiment]) -> Result<Plan, Ch5Error> {
    let mut params = Ch5Params::for_scale(ctx.scale);
    params.learner = params.learner.clone().under(&ctx.reading);
    params.learner.check()?;
    let thesis_a = readings::thesis_a_rules(&ctx.reading);
    let passer = readings::frequent_passer(&ctx.reading);
    let mut plan = Plan {
        ctx: ctx.clone(),
        params: params.clone(),
        experiments: experiments.to_vec(),
        validation: None,
        demonstrations: None,
        learning: None,
    };
    if experiments.contains(&Experiment::Validation) {
        let mut batch =
            Batch::new(ctx, CHAPTER, Experiment::Validation, ValidationTrials { episodes: params.validation_episodes });
        for (c, &config) in VALIDATION_CONFIGS.iter().enumerate() {
            for p in BenchmarkPolicy::ALL {
                batch.trial(&format!("{}-{}", config_slug(config), p.slug()), 0, (c, p));
            }
        }
        plan.validation = Some(batch);
    }
    if experiments.contains(&Experiment::Demonstrations) {
        let runner = DemonstrationTrials { master_seed: ctx.master_seed, passer };
        let mut batch = Batch::new(ctx, CHAPTER, Experiment::Demonstrations, runner);
        batch.trial("calibration-check", 0, DemoJob::Calibration { passer });
        batch.trial("traced-episode", 0, DemoJob::Traced);
        for id in DemoSetId::ALL {
            let job = DemoJob::RulesOnly {
                rules: RuleSource::of(id, thesis_a, passer),
                episodes: params.rules_only_episodes,
            };
            batch.trial(&format!("rules-only-{}", id.slug()), 0, job);
        }
        let explore = DemoJob::RulesExplore {
            rules: RuleSource::of(DemoSetId::A20, thesis_a, passer),
            episodes: params.rules_only_episodes,
            epsilon: params.learner.epsilon,
        };
        for t in 0..params.rules_explore_trials {
            batch.trial("rules-explore-subject-a", t, explore);
        }
        plan.demonstrations = Some(batch);
    }
    let mut conditions: Vec<Condition> = Vec::new();
    for &e in experiments {
        for c in Condition::of(e) {
            if !conditions.iter().any(|d| d.slug() == c.slug()) {
                conditions.push(c);
            }
        }
    }
    if !conditions.is_empty() {
        let mut batch = Batch::new(ctx, CHAPTER, LearningKey, LearningTrials { master_seed: ctx.master_seed, passer });
        for c in &conditions {
            let trial = TrialParams {
                hours: params.hours,
                eval_episodes: params.eval_episodes,
                greedy_episodes: params.greedy_episodes,
                learner: params.learner.clone(),
                method: c.method,
            };
            let rules = c.set.map(|s| RuleSource::of(s, thesis_a, passer));
            for t in 0..params.trials {
                batch.trial(&c.slug(), t, (trial.clone(), rules));
            }
        }
        plan.learning = Some((conditions, batch));
    }
    Ok(plan)
}

impl Plan {
    /// Its batches, types erased.
    pub fn batches(&self) -> Vec<&dyn AnyBatch> {
        let mut out: Vec<&dyn AnyBatch> = Vec::new();
        out.extend(self.validation.iter().map(|b| b as &dyn AnyBatch));
        out.extend(self.demonstrations.iter().map(|b| b as &dyn AnyBatch));
        out.extend(self.learning.iter().map(|(_, b)| b as &dyn AnyBatch));
        out
    }

    /// Runs (or loads) every batch and gathers what the report is made from.
    pub fn execute(&self, options: &RunOptions) -> Result<Ch5Results, Ch5Error> {
        let ctx = &self.ctx;
        let mut results = Ch5Results {
            scale: ctx.scale,
            seed: ctx.master_seed,
            params: self.params.clone(),
            experiments: self.experiments.clone(),
            demos: None,
            validation: BTreeMap::new(),
            calibration: None,
            rules_only: BTreeMap::new(),
            rules_explore: Vec::new(),
            reading: ctx.reading.label(),
            epsilon: self.params.learner.epsilon,
            thesis_a_rules: readings::thesis_a_rules(&ctx.reading),
            passer: readings::frequent_passer(&ctx.reading),
            threshold: readings::threshold_reading(&ctx.reading),
            traced: None,
            learning: BTreeMap::new(),
        };
        if self.experiments.iter().any(|&e| e != Experiment::Validation) {
            results.demos = Some(demo_cache().get(ctx.master_seed, results.passer)?.inputs.clone());
        }
        if let Some(batch) = &self.validation {
            let out = batch.execute(options)?;
            for (t, episodes) in batch.trials().iter().zip(out.results) {
                results.validation.insert(t.params, episodes);
            }
        }
        if let Some(batch) = &self.demonstrations {
            let out = batch.execute(options)?;
            for (t, trial) in batch.trials().iter().zip(out.results) {
                match (t.params, trial) {
                    (DemoJob::Calibration { .. }, DemoTrial::Calibration(c)) => results.calibration = Some(c),
                    (DemoJob::Traced, DemoTrial::Traced(tr)) => results.traced = Some(tr),
                    (DemoJob::RulesOnly { rules: RuleSource::Set { set: id, .. }, .. }, DemoTrial::RulesOnly(d)) => {
                        results.rules_only.insert(id, d);
                    }
                    (DemoJob::RulesOnly { rules: RuleSource::ThesisA, .. }, DemoTrial::RulesOnly(d)) => {
                        results.rules_only.insert(DemoSetId::A20, d);
                    }
                    (DemoJob::RulesExplore { .. }, DemoTrial::RulesOnly(d)) => results.rules_explore.push(d),
                    _ => unreachable!("each job stores its own kind of result"),
                }
            }
        }
        if let Some((conditions, batch)) = &self.learning {
            let out = batch.execute(options)?;
            let per = self.params.trials as usize;
            let mut results_iter = out.results.into_iter();
            for c in conditions {
                results.learning.insert(c.slug(), (*c, results_iter.by_ref().take(per).collect()));
            }
        }
        Ok(results)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn condition_slugs_are_distinct_and_shared_across_tables() {
        let mut all = Vec::new();
        for e in Experiment::ALL {
            all.extend(Condition::of(e).iter().map(Condition::slug));
        }
        let mut unique = all.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), 11, "{unique:?}");
        assert!(unique.contains(&"ppr-subject-a".to_string()) && unique.contains(&"no-prior".to_string()));
        // The `a-rules` reading changes A (20)'s trials and no other.
        let ctx = RunContext::new(1, Scale::Quick);
        let thesis = ctx.under(rlfd_harness::Reading::defaults().with(&crate::readings::A_RULES, "ours"));
        let (a, b) = (plan(&ctx, &Experiment::ALL).unwrap(), plan(&thesis, &Experiment::ALL).unwrap());
        let (la, lb) = (&a.learning.as_ref().unwrap().1, &b.learning.as_ref().unwrap().1);
        for (x, y) in la.trials().iter().zip(lb.trials()) {
            let a20 = x.key.condition.ends_with("-subject-a") && !x.key.condition.contains("half");
            assert_eq!(x.id != y.id, a20, "{}", x.key);
        }
        // The `bc-styles` reading changes the trials of the sets holding B's
        // or C's episodes and no other (not No Prior's, not A's).
        let swapped = ctx.under(rlfd_harness::Reading::defaults().with(&crate::readings::BC_STYLES, "c-passes"));
        let c = plan(&swapped, &Experiment::ALL).unwrap();
        let lc = &c.learning.as_ref().unwrap().1;
        let mut changed = Vec::new();
        for (x, y) in la.trials().iter().zip(lc.trials()) {
            if x.id != y.id && x.key.trial == 0 {
                changed.push(x.key.condition.clone());
            }
        }
        assert_eq!(
            changed,
            [
                "ppr-subject-b",
                "ppr-subject-c",
                "ppr-subjects-a-c-best",
                "ppr-subjects-a-c-worst",
                "ppr-subject-b-limited",
                "ppr-subject-b-fast"
            ]
        );
        let (da, dc) = (a.demonstrations.as_ref().unwrap(), c.demonstrations.as_ref().unwrap());
        let changed: Vec<&str> = da
            .trials()
            .iter()
            .zip(dc.trials())
            .filter(|(x, y)| x.id != y.id)
            .map(|(x, _)| x.key.condition.as_str())
            .collect();
        assert!(changed.contains(&"calibration-check") && changed.contains(&"rules-only-subject-b"), "{changed:?}");
        assert!(!changed.iter().any(|c| c.ends_with("subject-a")), "{changed:?}");
    }

    #[test]
    fn scales_differ_only_in_size() {
        let (q, p) = (Ch5Params::quick(), Ch5Params::paper());
        assert_eq!(q.learner, p.learner);
        assert_eq!((p.trials, p.hours, p.window), (10, 30.0, 1000));
        assert!(q.hours < p.hours);
    }
}
