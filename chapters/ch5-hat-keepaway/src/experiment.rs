//! The chapter's experiments through the harness: the benchmark policies
//! (simulator validation), the demonstrations (calibration check, rules-only
//! play, a traced episode) and the learning conditions of Tables 5.1–5.4.
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
use crate::inputs::{DemoInputs, DemoSetId, prepare};
use crate::keepaway::{Keepaway, KeeperAction, STATE_VARS, Snapshot};
use crate::learners::{LearnerParamError, LearnerParams, LearningTrial, Method, TrialParams, run_learning_trial};
use crate::teachers::calibration::{CALIBRATION_EPISODES, model_mean_seconds};
use crate::teachers::{Teacher, demonstration};
use crate::{CHAPTER_ID, Experiment};

/// The experiment name of every learning trial's key.
pub const LEARNING_KEY: &str = "keepaway-learning";

/// The behaviour version of the learning trials (the HAT learners, their
/// features and the simulator they play in), shared by the four learning
/// experiments.
pub const LEARNING_BEHAVIOUR: u32 = 1;

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
    /// Episodes of the sliding window of the final and hourly means (thesis: 1,000).
    pub window: usize,
    /// Episodes per benchmark policy (the benchmark's validation: 1,000).
    pub benchmark_episodes: usize,
    /// Episodes of the rules-only policy per demonstration set.
    pub rules_only_episodes: usize,
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
            window: 1000,
            benchmark_episodes: 1000,
            rules_only_episodes: 1000,
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
            window: 100,
            benchmark_episodes: 200,
            rules_only_episodes: 100,
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
            Experiment::Benchmarks | Experiment::Demonstrations => vec![],
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
    /// Per teacher (in [`Teacher::ALL`] order), the model's mean duration (s) over the calibration episodes.
    pub model_means: Vec<f64>,
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
    /// Episode durations (cycles) of each benchmark policy.
    pub benchmarks: BTreeMap<BenchmarkPolicy, Vec<u32>>,
    /// The teacher models' means over the calibration episodes.
    pub calibration: Option<CalibrationCheck>,
    /// Episode durations (cycles) of the rules-only policy of each set.
    pub rules_only: BTreeMap<DemoSetId, Vec<u32>>,
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

/// Runs (or loads) the chosen experiments.
pub fn reproduce(options: &RunOptions, experiments: &[Experiment]) -> Result<Ch5Results, Ch5Error> {
    let params = Ch5Params::for_scale(options.scale);
    params.learner.check()?;
    let mut results = Ch5Results {
        scale: options.scale,
        seed: options.master_seed,
        params: params.clone(),
        experiments: experiments.to_vec(),
        demos: None,
        benchmarks: BTreeMap::new(),
        calibration: None,
        rules_only: BTreeMap::new(),
        traced: None,
        learning: BTreeMap::new(),
        computed: 0,
        reused: 0,
    };
    let needs_demos = experiments.iter().any(|&e| e != Experiment::Benchmarks);
    if needs_demos {
        results.demos = Some(prepare(options.master_seed)?);
    }
    if experiments.contains(&Experiment::Benchmarks) {
        run_benchmarks(options, &params, &mut results)?;
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

fn run_benchmarks(options: &RunOptions, params: &Ch5Params, results: &mut Ch5Results) -> Result<(), Ch5Error> {
    let plan = TrialPlan::new(options, CHAPTER_ID, Experiment::Benchmarks);
    let plan = &plan;
    let fingerprint = Fingerprint::new().str(&params.benchmark_episodes.to_string());
    let specs: Vec<TrialSpec<BenchmarkPolicy>> =
        BenchmarkPolicy::ALL.iter().map(|&p| plan.spec(p.slug(), 0, fingerprint, p)).collect();
    let out = run_trials(options, "keepaway benchmarks", &specs, |spec| {
        let policy = spec.params;
        play_policy(params.benchmark_episodes, spec.seed, |s, rng| policy.choose(s, rng))
    })?;
    for (spec, durations) in specs.iter().zip(out.results) {
        results.benchmarks.insert(spec.params, durations);
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
}

fn run_demonstrations(options: &RunOptions, params: &Ch5Params, results: &mut Ch5Results) -> Result<(), Ch5Error> {
    let demos = results.demos.as_ref().expect("prepared for this experiment");
    let plan = TrialPlan::new(options, CHAPTER_ID, Experiment::Demonstrations);
    let plan = &plan;
    let mut jobs = vec![(DemoJob::Calibration, "calibration-check".to_string())];
    jobs.push((DemoJob::Traced, "traced-episode".to_string()));
    for id in DemoSetId::ALL {
        jobs.push((DemoJob::RulesOnly(id), format!("rules-only-{}", id.slug())));
    }
    let specs: Vec<TrialSpec<DemoJob>> = jobs
        .iter()
        .map(|(job, name)| {
            let determinants = match job {
                DemoJob::RulesOnly(id) => {
                    Fingerprint::new().str(&json(&demos.get(*id).rules)).str(&params.rules_only_episodes.to_string())
                }
                _ => Fingerprint::new(),
            };
            plan.spec(name, 0, determinants, *job)
        })
        .collect();
    let out = run_trials(options, "keepaway demonstrations", &specs, |spec| match spec.params {
        DemoJob::Calibration => DemoTrial::Calibration(CalibrationCheck {
            model_means: Teacher::ALL.iter().map(|t| model_mean_seconds(&t.model(), CALIBRATION_EPISODES)).collect(),
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
        DemoJob::RulesOnly(id) => {
            DemoTrial::RulesOnly(rules_only(&demos.get(id).rules, params.rules_only_episodes, spec.seed))
        }
    })?;
    for (spec, trial) in specs.iter().zip(out.results) {
        match (spec.params, trial) {
            (DemoJob::Calibration, DemoTrial::Calibration(c)) => results.calibration = Some(c),
            (DemoJob::Traced, DemoTrial::Traced(t)) => results.traced = Some(t),
            (DemoJob::RulesOnly(id), DemoTrial::RulesOnly(d)) => {
                results.rules_only.insert(id, d);
            }
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
    let trial_params: Vec<TrialParams> = conditions
        .iter()
        .map(|c| TrialParams {
            hours: params.hours,
            eval_episodes: params.eval_episodes,
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
            fp = fp.str(&json(&demos.get(set).rules));
        }
        for t in 0..params.trials {
            specs.push(plan.spec(&c.slug(), t, fp, i));
        }
    }
    let out = run_trials(options, "keepaway learning", &specs, |spec| {
        let c = &conditions[spec.params];
        let rules = c.set.map(|s| &demos.get(s).rules);
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
    }

    #[test]
    fn scales_differ_only_in_size() {
        let (q, p) = (Ch5Params::quick(), Ch5Params::paper());
        assert_eq!(q.learner, p.learner);
        assert_eq!((p.trials, p.hours, p.window), (10, 30.0, 1000));
        assert!(q.hours < p.hours);
    }
}
