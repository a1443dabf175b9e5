//! The agents' trials through the harness, in either domain: a condition
//! (an agent, and which of the set-up's inputs it learns from) planned into
//! a batch under the run's reading ([`add_conditions`]: each agent's
//! parameters are the reading's for that agent, so a reading changes only
//! the trials of the agents that use what it sets), the results grouped per
//! condition with the diverged trials apart ([`split`], [`by_agent`]), and
//! the sweeps' agents gathered per level for the sensitivity sections
//! ([`level_runs`]).

use std::collections::BTreeMap;

use rlfd_harness::{Batch, Planned, Reading, RunContext, Scale, TrialRunner};
use serde::{Deserialize, Serialize};

use super::agents::{Agent, Domain, TrialRecord};

/// A domain's parameters as its experiments run them.
pub trait ExperimentParams: Domain + Clone + Serialize + Sync {
    /// Trials per condition.
    fn trials(&self) -> u32;
    /// The parameters of `agent` under `reading` (an axis changes only the
    /// agents that use what it sets).
    fn under(&self, reading: &Reading, agent: Agent) -> Self;
}

/// One agent trial's parameters: the agent, which of the set-up's inputs it
/// learns from (an index), and its domain's parameters under the reading.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AgentTrial<P> {
    /// The agent.
    pub agent: Agent,
    /// Which of the set-up's inputs it learns from.
    pub inputs: usize,
    /// Its parameters.
    pub params: P,
}

/// A condition: an agent and what it learns from, named in result paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Condition {
    /// The condition's name in result paths (the agent's slug, or e.g. `dis-100`).
    pub name: String,
    /// The agent.
    pub agent: Agent,
    /// Which of the set-up's inputs it learns from.
    pub inputs: usize,
}

/// The five agents, each learning from the set-up's first inputs.
pub fn five_agents<P: Domain>() -> Vec<Condition> {
    Agent::ALL.iter().map(|&a| Condition { name: a.slug(P::BASELINE).to_string(), agent: a, inputs: 0 }).collect()
}

/// Adds `conditions`' trials, each with `params` under `reading` for its
/// agent, to `batch`.
pub fn add_conditions<R, P>(batch: &mut Batch<R>, params: &P, reading: &Reading, conditions: &[Condition])
where
    R: TrialRunner<Params = AgentTrial<P>>,
    P: ExperimentParams,
{
    for c in conditions {
        let p = params.under(reading, c.agent);
        for t in 0..p.trials() {
            batch.trial(&c.name, t, AgentTrial { agent: c.agent, inputs: c.inputs, params: p.clone() });
        }
    }
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

/// A batch's results grouped per condition of `conditions` (by the name
/// their keys carry), in order, the diverged apart.
pub fn split<P, T, E>(conditions: &[Condition], planned: &[Planned<AgentTrial<P>>], results: Vec<T>) -> Vec<Split<T>>
where
    T: TrialRecord<E>,
    E: rlfd_rl::Environment,
{
    let mut grouped: Vec<Split<T>> = conditions.iter().map(|_| Split::default()).collect();
    for (t, result) in planned.iter().zip(results) {
        let c = conditions.iter().position(|c| c.name == t.key.condition).expect("every trial is a condition's");
        match result.diverged_at() {
            Some(episode) => grouped[c].diverged.push(episode),
            None => grouped[c].trials.push(result),
        }
    }
    grouped
}

/// Per agent, its trials that ran to the end (an agent none of whose trials
/// did is absent).
pub type Trials<T> = BTreeMap<Agent, Vec<T>>;

/// Per agent with diverged trials, the episode each diverged in.
pub type Diverged = BTreeMap<Agent, Vec<u32>>;

/// The groups of [`split`] per agent of `conditions`.
pub fn by_agent<T>(conditions: &[Condition], grouped: Vec<Split<T>>) -> (Trials<T>, Diverged) {
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

impl<T> Default for LevelRuns<T> {
    fn default() -> Self {
        LevelRuns { runs: Vec::new() }
    }
}

/// One level of a sweep as [`level_runs`] reads it: its name, the value it
/// sets, whether it is the run's own, and the swept experiment's trials there.
pub type SweptLevel<'a, T> = (&'static str, f64, bool, &'a Trials<T>, &'a Diverged);

/// `agents` at every level of a sweep, in the axis's order, agent after agent.
pub fn level_runs<T: Clone>(agents: &[Agent], levels: &[SweptLevel<'_, T>]) -> LevelRuns<T> {
    let mut runs = Vec::new();
    for &agent in agents {
        for &(level, value, main, trials, diverged) in levels {
            runs.push(LevelRun {
                agent,
                level,
                value,
                main,
                trials: trials.get(&agent).cloned().unwrap_or_default(),
                diverged: diverged.get(&agent).cloned().unwrap_or_default(),
            });
        }
    }
    LevelRuns { runs }
}

/// Everything an experiment's report is made from, in either half: its
/// parameters `P`, demonstrations `D`, what the agents learned from them
/// `I`, and the trials `T` of its five agents and of its sweep.
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
    /// The sweep's agents at every level of its axis (filled from the
    /// sweep's runs for the report; empty otherwise).
    pub levels: LevelRuns<T>,
}

impl<P, D, I, T> Results<P, D, I, T> {
    /// The results of `conditions` grouped as [`split`] gives them.
    pub fn new(
        ctx: &RunContext,
        params: P,
        demonstrations: D,
        inputs: I,
        conditions: &[Condition],
        grouped: Vec<Split<T>>,
    ) -> Self {
        let (trials, diverged) = by_agent(conditions, grouped);
        Results {
            scale: ctx.scale,
            seed: ctx.master_seed,
            params,
            demonstrations,
            inputs,
            trials,
            diverged,
            levels: LevelRuns { runs: Vec::new() },
        }
    }
}
