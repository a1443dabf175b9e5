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

use rlfd_harness::{ExperimentId, Fingerprint, HarnessError, RunOptions, Scale, TrialPlan, TrialSpec, run_trials};
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
use crate::teachers::{Teacher, demonstration};
use crate::{CHAPTER_ID, Experiment};

/// The experiment name of every learning trial's key.
pub const LEARNING_KEY: &str = "keepaway-learning";

/// The behaviour version of the learning trials (the HAT learners, their
/// features and the simulator they play in), shared by the four learning
/// experiments. 2: the simulator rebuilt on the keepaway 0.6 players'
/// skills and the server's collisions and vision, Weka's JRip, the teachers
/// recalibrated, greedy evaluations.
pub const LEARNING_BEHAVIOUR: u32 = 2;

/// The keepaway configurations the validation plays: (keepers, takers,
/// region side in m). The first is the thesis's.
pub const VALIDATION_CONFIGS: [(usize, usize, f64); 4] = [(3, 2, 20.0), (3, 2, 25.0), (4, 3, 20.0), (4, 3, 25.0)];

/// A configuration's name in result paths and tables (`3v2-20m`).
pub fn config_slug(c: (usize, usize, f64)) -> String {
    format!("{}v{}-{}m", c.0, c.1, c.2)
}

/// The learning trials as the store names them.
#[derive(Clone, Copy, Debug)]
struct LearningTrials;

impl ExperimentId for LearningTrials {
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
    /// A traced demonstration episode (for the picture).
    pub traced: Option<TracedEpisode>,
    /// Learning trials per condition, by slug, with the condition.
    pub learning: BTreeMap<String, (Condition, Vec<LearningTrial>)>,
    /// Trials computed in this run.
    pub computed: usize,
    /// Trials reused from the store.
    pub reused: usize,
}

impl Ch5Results {
    /// Trials computed and reused.
    pub fn trial_counts(&self) -> (usize, usize) {
        (self.computed, self.reused)
    }

    /// The trials of a condition, if it ran.
    pub fn trials(&self, c: &Condition) -> Option<&[LearningTrial]> {
        self.learning.get(&c.slug()).map(|(_, t)| t.as_slice())
    }
}

fn json<T: Serialize>(v: &T) -> String {
    serde_json::to_string(v).expect("parameters serialise")
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
            }
        })
        .collect()
}

/// The rule list a learning condition or a rules-alone run takes from a set
/// (Subject A's may be the thesis's printed list, by the reading).
pub fn rules_of<'a>(
    demos: &'a DemoInputs,
    set: DemoSetId,
    thesis_a: &'a DecisionList,
    use_thesis: bool,
) -> &'a DecisionList {
    if use_thesis && set == DemoSetId::A20 { thesis_a } else { &demos.get(set).rules }
}

/// Runs (or loads) the chosen experiments.
pub fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Ch5Results, Ch5Error> {
    let mut params = Ch5Params::for_scale(options.scale);
    params.learner = params.learner.clone().under(&options.reading);
    params.learner.check()?;
    let mut results = Ch5Results {
        scale: options.scale,
        seed: options.master_seed,
        params: params.clone(),
        experiments: experiments.to_vec(),
        demos: None,
        validation: BTreeMap::new(),
        calibration: None,
        rules_only: BTreeMap::new(),
        rules_explore: Vec::new(),
        reading: options.reading.label(),
        epsilon: params.learner.epsilon,
        thesis_a_rules: readings::thesis_a_rules(&options.reading),
        traced: None,
        learning: BTreeMap::new(),
        computed: 0,
        reused: 0,
    };
    let needs_demos = experiments.iter().any(|&e| e != Experiment::Validation);
    if needs_demos {
        results.demos = Some(prepare(options.master_seed)?);
    }
    if experiments.contains(&Experiment::Validation) {
        run_validation(options, &params, &mut results)?;
    }
    if experiments.contains(&Experiment::Demonstrations) {
        run_demonstrations(options, &params, &mut results)?;
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
        run_learning(options, &params, &conditions, &mut results)?;
    }
    Ok(results)
}

fn tally(results: &mut Ch5Results, computed: usize, reused: usize) {
    results.computed += computed;
    results.reused += reused;
}

fn run_validation(options: &RunOptions, params: &Ch5Params, results: &mut Ch5Results) -> Result<(), Ch5Error> {
    let plan = TrialPlan::new(options, CHAPTER_ID, Experiment::Validation);
    let plan = &plan;
    let fingerprint = Fingerprint::new().str(&params.validation_episodes.to_string());
    let mut specs: Vec<TrialSpec<(usize, BenchmarkPolicy)>> = Vec::new();
    for (c, &config) in VALIDATION_CONFIGS.iter().enumerate() {
        for p in BenchmarkPolicy::ALL {
            specs.push(plan.spec(&format!("{}-{}", config_slug(config), p.slug()), 0, fingerprint, (c, p)));
        }
    }
    let out = run_trials(options, "keepaway validation", &specs, |spec| {
        let (c, policy) = spec.params;
        validate(policy, VALIDATION_CONFIGS[c], params.validation_episodes, spec.seed)
    })?;
    for (spec, episodes) in specs.iter().zip(out.results) {
        results.validation.insert(spec.params, episodes);
    }
    tally(results, out.computed, out.reused);
    Ok(())
}

/// A trial of the demonstrations experiment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
enum DemoTrial {
    Calibration(CalibrationCheck),
    Traced(TracedEpisode),
    RulesOnly(Vec<u32>),
}

#[derive(Clone, Copy, Debug)]
enum DemoJob {
    Calibration,
    Traced,
    RulesOnly(DemoSetId),
    RulesExplore,
}

fn run_demonstrations(options: &RunOptions, params: &Ch5Params, results: &mut Ch5Results) -> Result<(), Ch5Error> {
    let demos = results.demos.as_ref().expect("prepared for this experiment");
    let thesis_a = thesis_a_rules();
    let use_thesis = results.thesis_a_rules;
    let plan = TrialPlan::new(options, CHAPTER_ID, Experiment::Demonstrations);
    let plan = &plan;
    let mut specs: Vec<TrialSpec<DemoJob>> = vec![
        plan.spec("calibration-check", 0, Fingerprint::new(), DemoJob::Calibration),
        plan.spec("traced-episode", 0, Fingerprint::new(), DemoJob::Traced),
    ];
    for id in DemoSetId::ALL {
        let rules = rules_of(demos, id, &thesis_a, use_thesis);
        let fp = Fingerprint::new().str(&json(rules)).str(&params.rules_only_episodes.to_string());
        specs.push(plan.spec(&format!("rules-only-{}", id.slug()), 0, fp, DemoJob::RulesOnly(id)));
    }
    let a_rules = rules_of(demos, DemoSetId::A20, &thesis_a, use_thesis);
    let fp = Fingerprint::new()
        .str(&json(a_rules))
        .str(&params.rules_only_episodes.to_string())
        .str(&json(&params.learner.epsilon));
    for t in 0..params.rules_explore_trials {
        specs.push(plan.spec("rules-explore-subject-a", t, fp, DemoJob::RulesExplore));
    }
    let out = run_trials(options, "keepaway demonstrations", &specs, |spec| match spec.params {
        DemoJob::Calibration => DemoTrial::Calibration(CalibrationCheck {
            episodes: Teacher::ALL
                .iter()
                .map(|t| {
                    let mut game = Keepaway::benchmark();
                    let m = t.model();
                    game.keep_history(m.history_needed());
                    let mut rng = seeded(CALIBRATION_SEED);
                    (0..CALIBRATION_EPISODES)
                        .map(|_| game.play_episode(&mut rng, |g, k, r| m.choose(g, k, r)).0)
                        .collect()
                })
                .collect(),
        }),
        DemoJob::Traced => {
            let model = Teacher::A.model();
            let mut game = Keepaway::benchmark();
            game.keep_history(model.history_needed());
            game.record_trace(true);
            let mut rng = seeded(spec.seed);
            let _ = demonstration::demonstrate(&mut game, &model, Teacher::A.label(), 0, &mut rng);
            DemoTrial::Traced(TracedEpisode { player: Teacher::A.label().into(), cycles: game.trace().to_vec() })
        }
        DemoJob::RulesOnly(id) => DemoTrial::RulesOnly(rules_only(
            rules_of(demos, id, &thesis_a, use_thesis),
            params.rules_only_episodes,
            spec.seed,
        )),
        DemoJob::RulesExplore => {
            DemoTrial::RulesOnly(rules_explore(a_rules, params.learner.epsilon, params.rules_only_episodes, spec.seed))
        }
    })?;
    for (spec, trial) in specs.iter().zip(out.results) {
        match (spec.params, trial) {
            (DemoJob::Calibration, DemoTrial::Calibration(c)) => results.calibration = Some(c),
            (DemoJob::Traced, DemoTrial::Traced(t)) => results.traced = Some(t),
            (DemoJob::RulesOnly(id), DemoTrial::RulesOnly(d)) => {
                results.rules_only.insert(id, d);
            }
            (DemoJob::RulesExplore, DemoTrial::RulesOnly(d)) => results.rules_explore.push(d),
            _ => unreachable!("each job stores its own kind of result"),
        }
    }
    tally(results, out.computed, out.reused);
    Ok(())
}

fn run_learning(
    options: &RunOptions,
    params: &Ch5Params,
    conditions: &[Condition],
    results: &mut Ch5Results,
) -> Result<(), Ch5Error> {
    let demos = results.demos.as_ref().expect("prepared for the learning experiments");
    let thesis_a = thesis_a_rules();
    let use_thesis = results.thesis_a_rules;
    let trial_params: Vec<TrialParams> = conditions
        .iter()
        .map(|c| TrialParams {
            hours: params.hours,
            eval_episodes: params.eval_episodes,
            greedy_episodes: params.greedy_episodes,
            learner: params.learner.clone(),
            method: c.method,
        })
        .collect();
    let plan = TrialPlan::new(options, CHAPTER_ID, LearningTrials);
    let plan = &plan;
    let mut specs = Vec::new();
    for (i, c) in conditions.iter().enumerate() {
        let mut fp = Fingerprint::new().str(&json(&trial_params[i]));
        if let Some(set) = c.set {
            fp = fp.str(&json(rules_of(demos, set, &thesis_a, use_thesis)));
        }
        for t in 0..params.trials {
            specs.push(plan.spec(&c.slug(), t, fp, i));
        }
    }
    let out = run_trials(options, "keepaway learning", &specs, |spec| {
        let c = &conditions[spec.params];
        let rules = c.set.map(|s| rules_of(demos, s, &thesis_a, use_thesis));
        run_learning_trial(&trial_params[spec.params], rules, spec.seed).expect("parameters checked before running")
    })?;
    let mut grouped: Vec<Vec<LearningTrial>> = vec![Vec::new(); conditions.len()];
    for (spec, trial) in specs.iter().zip(out.results) {
        grouped[spec.params].push(trial);
    }
    for (c, trials) in conditions.iter().zip(grouped) {
        results.learning.insert(c.slug(), (*c, trials));
    }
    tally(results, out.computed, out.reused);
    Ok(())
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
        // The `a-rules` reading's prefixes pick A (20)'s trials and no other.
        for slug in &unique {
            let a20 = slug.ends_with("-subject-a") && !slug.contains("half");
            assert_eq!(crate::readings::A_RULES.changes(LEARNING_KEY, slug), a20, "{slug}");
        }
    }

    #[test]
    fn scales_differ_only_in_size() {
        let (q, p) = (Ch5Params::quick(), Ch5Params::paper());
        assert_eq!(q.learner, p.learner);
        assert_eq!((p.trials, p.hours, p.window), (10, 30.0, 1000));
        assert!(q.hours < p.hours);
    }
}
