//! The agents' trials through the harness, in either domain: conditions
//! (an agent with the inputs it learns from) run or loaded as stored
//! trials ([`run_conditions`]), gathered per agent with the diverged ones
//! apart ([`by_agent`]); an experiment's five agents with some of them
//! rerun at every level of a reading ([`run_agents`]: the sensitivity
//! studies), each experiment one harness batch ([`run_readings`]).

use std::collections::BTreeMap;

use rlfd_harness::{Axis, Fingerprint, HarnessError, Reading, RunOptions, Scale, TrialPlan, TrialSpec, run_trials};
use serde::Serialize;
use serde::de::DeserializeOwned;

use super::agents::{Agent, Domain, TrialRecord, run_trial};
use super::inputs::AgentInputs;

/// A domain's parameters as its experiments run them.
pub trait ExperimentParams: Domain + Clone + Serialize + Sync
where
    Self::Trial: Serialize + DeserializeOwned + Send + Clone,
{
    /// Trials per condition.
    fn trials(&self) -> u32;
    /// The parameters of `agent` under `reading` (an axis changes only the
    /// agents that use what it sets).
    fn under(&self, reading: &Reading, agent: Agent) -> Self;
}

/// A condition: an agent and what it learns from, named in result paths.
#[derive(Clone, Debug)]
pub struct Condition<'a> {
    /// The condition's name in result paths (the agent's slug, or e.g. `dis-100`).
    pub name: String,
    /// The agent.
    pub agent: Agent,
    /// What it learns from.
    pub inputs: &'a AgentInputs,
    /// Fingerprint of those inputs (and of the demonstrations behind them).
    pub fingerprint: Fingerprint,
}

/// A condition's trials: those that ran to the end, and the episode of each
/// that diverged (recorded as such, never tabulated or tested as a result).
#[derive(Clone, Debug)]
pub struct Split<T> {
    /// Trials that ran every episode.
    pub trials: Vec<T>,
    /// The episode each diverged trial diverged in.
    pub diverged: Vec<u32>,
}

impl<T> Default for Split<T> {
    fn default() -> Self {
        Split { trials: Vec::new(), diverged: Vec::new() }
    }
}

/// Trials run and reused.
pub type Counts = (usize, usize);

/// Runs (or loads) the trials of every condition of `experiment` under the
/// run's reading, in order; `label` names the batch in progress output.
pub fn run_conditions<P>(
    options: &RunOptions,
    experiment: crate::Experiment,
    label: &str,
    params: &P,
    conditions: &[Condition<'_>],
) -> Result<(Vec<Split<P::Trial>>, Counts), HarnessError>
where
    P: ExperimentParams,
    P::Trial: Serialize + DeserializeOwned + Send + Clone,
{
    let (mut grouped, counts) =
        run_readings(options, experiment, label, params, &[(options.reading.clone(), conditions)])?;
    Ok((grouped.pop().expect("one reading, one group"), counts))
}

/// Runs (or loads) the trials of `experiment`'s conditions under several
/// readings (each condition's parameters and record path under its own), as
/// **one** harness batch: planning a sharded run (`RunMode::Plan`) lists an
/// experiment's first batch and stops there, so an experiment that ran its
/// readings one batch after another would leave the later ones unplanned
/// (the Slurm report once found them missing). Returns, per reading, the
/// groups of its conditions in order.
pub fn run_readings<P>(
    options: &RunOptions,
    experiment: crate::Experiment,
    label: &str,
    params: &P,
    readings: &[(Reading, &[Condition<'_>])],
) -> Result<(Vec<Vec<Split<P::Trial>>>, Counts), HarnessError>
where
    P: ExperimentParams,
    P::Trial: Serialize + DeserializeOwned + Send + Clone,
{
    // Every (reading, condition) in order, with its parameters.
    let flat: Vec<(usize, &Condition<'_>, P)> = readings
        .iter()
        .enumerate()
        .flat_map(|(r, (reading, conditions))| conditions.iter().map(move |c| (r, c, params.under(reading, c.agent))))
        .collect();
    let plans: Vec<TrialPlan> = readings
        .iter()
        .map(|(reading, _)| {
            let under = RunOptions { reading: reading.clone(), ..options.clone() };
            TrialPlan::new(&under, crate::CHAPTER_ID, experiment)
        })
        .collect();
    let specs: Vec<TrialSpec<usize>> = flat
        .iter()
        .enumerate()
        .flat_map(|(i, (r, condition, p))| {
            let params_json = serde_json::to_string(p).expect("parameters serialise");
            let determinants =
                Fingerprint::new().u64(condition.fingerprint.value()).str(&condition.name).str(&params_json);
            let plan = &plans[*r];
            (0..p.trials()).map(move |t| plan.spec(&condition.name, t, determinants, i))
        })
        .collect();
    let outcomes = run_trials(options, label, &specs, |spec| {
        let (_, condition, p) = &flat[spec.params];
        run_trial(condition.agent, p, Some(condition.inputs), spec.seed)
    })?;
    let mut grouped: Vec<Vec<Split<P::Trial>>> =
        readings.iter().map(|(_, conditions)| (0..conditions.len()).map(|_| Split::default()).collect()).collect();
    let offsets: Vec<usize> = readings
        .iter()
        .scan(0, |at, (_, conditions)| {
            let start = *at;
            *at += conditions.len();
            Some(start)
        })
        .collect();
    for (spec, result) in specs.iter().zip(outcomes.results) {
        let r = flat[spec.params].0;
        let split = &mut grouped[r][spec.params - offsets[r]];
        match result.diverged_at() {
            Some(episode) => split.diverged.push(episode),
            None => split.trials.push(result),
        }
    }
    Ok((grouped, (outcomes.computed, outcomes.reused)))
}

/// Per agent, its trials that ran to the end (an agent none of whose trials
/// did is absent).
pub type Trials<T> = BTreeMap<Agent, Vec<T>>;

/// Per agent with diverged trials, the episode each diverged in.
pub type Diverged = BTreeMap<Agent, Vec<u32>>;

/// The groups of [`run_conditions`] per agent of `conditions`.
pub fn by_agent<T>(conditions: &[Condition<'_>], grouped: Vec<Split<T>>) -> (Trials<T>, Diverged) {
    let mut trials = BTreeMap::new();
    let mut diverged = BTreeMap::new();
    for (c, split) in conditions.iter().zip(grouped) {
        if !split.diverged.is_empty() {
            diverged.insert(c.agent, split.diverged);
        }
        if !split.trials.is_empty() {
            trials.insert(c.agent, split.trials);
        }
    }
    (trials, diverged)
}

/// An agent at one level of a reading.
#[derive(Clone, Debug)]
pub struct LevelRun<T> {
    /// The agent.
    pub agent: Agent,
    /// The level's name.
    pub level: &'static str,
    /// The value the level sets (κ, β).
    pub value: f64,
    /// Whether these are the run's own trials (the run's reading's level).
    pub main: bool,
    /// Its trials, those whose learner diverged left out.
    pub trials: Vec<T>,
    /// The episode each diverged trial diverged in.
    pub diverged: Vec<u32>,
}

/// Agents at every level of a reading. Nothing is chosen from these runs.
#[derive(Clone, Debug)]
pub struct LevelRuns<T> {
    /// Each agent at every level in the axis's order, agent after agent.
    pub runs: Vec<LevelRun<T>>,
}

/// Which agents are rerun at every level of which axis (the sensitivity
/// study beside an experiment's five agents).
#[derive(Clone, Copy, Debug)]
pub struct LevelStudy<'a> {
    /// The reading's axis.
    pub axis: &'static Axis,
    /// The agents it changes that are rerun.
    pub agents: &'a [Agent],
}

/// An experiment's five agents under the run's reading, with its study's
/// agents at every level of the study's axis.
#[derive(Clone, Debug)]
pub struct AgentRuns<T> {
    /// Per agent, its trials that ran to the end.
    pub trials: Trials<T>,
    /// Per agent with diverged trials, the episode each diverged in.
    pub diverged: Diverged,
    /// The study's agents at every level.
    pub levels: LevelRuns<T>,
    /// Trials computed in this run (the levels' included).
    pub computed: usize,
    /// Trials reused from the store (the levels' included).
    pub reused: usize,
}

/// Runs (or loads) the five agents of `experiment`, all learning from
/// `inputs`, under the run's reading, and the study's agents at the other
/// levels of its axis (each under the run's reading with that level: the
/// trials a run of that reading would make, stored where it finds them),
/// all in one harness batch ([`run_readings`]; `label` names it). `value`
/// is what a reading sets (κ, β).
#[allow(clippy::too_many_arguments)]
pub fn run_agents<P>(
    options: &RunOptions,
    experiment: crate::Experiment,
    label: &str,
    params: &P,
    inputs: &AgentInputs,
    fingerprint: Fingerprint,
    study: LevelStudy<'_>,
    value: impl Fn(&Reading) -> f64,
) -> Result<AgentRuns<P::Trial>, HarnessError>
where
    P: ExperimentParams,
    P::Trial: Serialize + DeserializeOwned + Send + Clone,
{
    let condition = |a: Agent| Condition { name: a.slug(P::BASELINE).to_string(), agent: a, inputs, fingerprint };
    let conditions: Vec<Condition<'_>> = Agent::ALL.iter().map(|&a| condition(a)).collect();
    let studied: Vec<Condition<'_>> = study.agents.iter().map(|&a| condition(a)).collect();
    let own = options.reading.level_of(study.axis);
    let others: Vec<&'static rlfd_harness::Level> = study.axis.levels.iter().filter(|l| l.name != own).collect();
    let mut readings: Vec<(Reading, &[Condition<'_>])> = vec![(options.reading.clone(), &conditions)];
    readings.extend(others.iter().map(|&level| (options.reading.clone().with(study.axis, level), &studied[..])));
    let (mut grouped, (computed, reused)) = run_readings(options, experiment, label, params, &readings)?;
    let main = grouped.remove(0);
    let mut level_groups = others.iter().map(|l| l.name).zip(grouped);
    let (trials, diverged) = by_agent(&conditions, main);
    // Per level in the axis's order: its name, value, whether it is the run's, and per agent its split.
    let mut by_level: Vec<(&'static str, f64, bool, Vec<Split<P::Trial>>)> = Vec::new();
    for level in study.axis.levels {
        let v = value(&options.reading.clone().with(study.axis, level));
        if level.name == own {
            let groups = study
                .agents
                .iter()
                .map(|a| Split {
                    trials: trials.get(a).cloned().unwrap_or_default(),
                    diverged: diverged.get(a).cloned().unwrap_or_default(),
                })
                .collect();
            by_level.push((level.name, v, true, groups));
        } else {
            let (name, groups) = level_groups.next().expect("a group per other level, in order");
            debug_assert_eq!(name, level.name);
            by_level.push((level.name, v, false, groups));
        }
    }
    let mut runs = Vec::new();
    for (k, &agent) in study.agents.iter().enumerate() {
        for (level, value, main, groups) in &by_level {
            let Split { trials, diverged } = groups[k].clone();
            runs.push(LevelRun { agent, level, value: *value, main: *main, trials, diverged });
        }
    }
    let levels = LevelRuns { runs };
    Ok(AgentRuns { trials, diverged, levels, computed, reused })
}

/// Everything an experiment's report is made from, in either half: its
/// parameters `P`, demonstrations `D`, what the agents learned from them
/// `I`, and the trials `T` of its five agents and of its sensitivity study.
#[derive(Clone, Debug)]
pub struct Results<P, D, I, T> {
    /// The scale it ran at.
    pub scale: Scale,
    /// The master seed.
    pub seed: u64,
    /// The parameters, every axis at the run's reading.
    pub params: P,
    /// The demonstrations.
    pub demonstrations: D,
    /// What the agents learned from.
    pub inputs: I,
    /// Per agent, its trials in order, those whose learner diverged left
    /// out (an agent all of whose trials diverged is absent).
    pub trials: Trials<T>,
    /// Per agent with diverged trials, the episode each diverged in.
    pub diverged: Diverged,
    /// The study's agents at every level of its axis (the value of a run is
    /// what the level sets).
    pub levels: LevelRuns<T>,
    /// Trials computed in this run.
    pub computed: usize,
    /// Trials reused from the store.
    pub reused: usize,
}

impl<P, D, I, T> Results<P, D, I, T> {
    /// The results of `runs` under `options`, with what they were made from.
    pub fn new(options: &RunOptions, params: P, demonstrations: D, inputs: I, runs: AgentRuns<T>) -> Self {
        Results {
            scale: options.scale,
            seed: options.master_seed,
            params,
            demonstrations,
            inputs,
            trials: runs.trials,
            diverged: runs.diverged,
            levels: runs.levels,
            computed: runs.computed,
            reused: runs.reused,
        }
    }
}
