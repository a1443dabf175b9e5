//! The Maze experiment: the demonstrations and what the agents learn from
//! them ([`setup`]), then the thesis's 5 agents × trials × episodes
//! ([`run`], section 6.3.1), with SIS and DIS also at the other levels of
//! the `irl-scale` reading (the sensitivity study of round 1, now the
//! reading's own trials), all through the harness.

use std::collections::BTreeMap;
use std::path::PathBuf;

use rlfd_harness::{
    Fingerprint, HarnessError, RunOptions, Scale, TrialKey, TrialPlan, TrialSpec, derive_seed, run_trials,
};
use rlfd_lfd::demonstration::{DemonstrationSet, ReadError};
use rlfd_rl::random::seeded;
use thiserror::Error;

use crate::CHAPTER;
use crate::agents::{MazeAgent, MazeParams, MazeTrial, run_trial};
use crate::inputs::{InputError, PreparedInputs, check, prepare};
use crate::maze::demonstrator::{
    self, Demonstration, DemonstrationStats, MazeDemonstrator, measure, to_demonstration_set,
};
use crate::maze::layout::LayoutId;
use crate::readings::HmnUnits;

/// The experiment's name in result paths and on the command line.
pub const EXPERIMENT: &str = crate::Experiment::Maze.name();

/// What can stop the Maze experiment.
#[derive(Debug, Error)]
pub enum MazeError {
    /// A demonstration file could not be read.
    #[error(transparent)]
    Read(#[from] ReadError),
    /// The demonstrations could not be used.
    #[error(transparent)]
    Inputs(#[from] InputError),
    /// The demonstrations of a user's file could not be used.
    #[error("{}: {error}", path.display())]
    File {
        /// The file.
        path: PathBuf,
        /// Why.
        error: InputError,
    },
    /// Storing or loading trials failed.
    #[error(transparent)]
    Harness(#[from] HarnessError),
    /// The Mario experiments failed.
    #[error(transparent)]
    Mario(#[from] crate::mario_experiment::MarioError),
    /// Demonstrations were handed in, but no selected experiment learns from them.
    #[error("--demonstrations applies to the maze experiments, none of which is selected")]
    DemonstrationsUnused,
}

/// Where the demonstrations come from.
#[derive(Clone, Debug, PartialEq)]
pub enum DemonstrationSource {
    /// The synthetic demonstrator ([`MazeDemonstrator`]).
    Synthetic,
    /// A file of the user's (CSV or JSON Lines, states (x, y), actions 0..4).
    File(PathBuf),
}

/// The demonstrations used, with what the report says about them.
#[derive(Clone, Debug)]
pub struct Demonstrations {
    /// The set (states (x, y), actions = moves).
    pub set: DemonstrationSet,
    /// The synthetic demonstrator's walks, when they came from it (for measurements and figures).
    pub walks: Option<Vec<Demonstration>>,
    /// Measurements, when the states lie on the Maze's lattice.
    pub stats: Option<DemonstrationStats>,
    /// Where they came from.
    pub source: DemonstrationSource,
}

impl Demonstrations {
    /// The demonstrator's mean return HMN in `units`: −1 per step and +10 at
    /// the goal, the steps being the recorded ones (the thesis's count) or
    /// the same paths' length in the agents' steps of 0.02 (half as many:
    /// the demonstrations are recorded at 0.01 per step).
    pub fn hmn(&self, units: HmnUnits) -> f64 {
        let per_step = match units {
            HmnUnits::Recorded => 1.0,
            HmnUnits::AgentSteps => 0.5,
        };
        let lengths = self.set.lengths();
        lengths.iter().map(|&l| -((l - 1) as f64) * per_step + 10.0).sum::<f64>() / lengths.len() as f64
    }
}

/// Everything the Maze report is made from.
#[derive(Clone, Debug)]
pub struct MazeResults {
    /// The scale it ran at.
    pub scale: Scale,
    /// The master seed.
    pub seed: u64,
    /// The parameters, every axis at the run's reading (see
    /// [`crate::readings::maze_params_shown`]).
    pub params: MazeParams,
    /// The demonstrations.
    pub demonstrations: Demonstrations,
    /// What the agents learned from.
    pub inputs: PreparedInputs,
    /// Per agent, its trials in order, those whose learner diverged left
    /// out (an agent all of whose trials diverged is absent).
    pub trials: BTreeMap<MazeAgent, Vec<MazeTrial>>,
    /// Per agent with diverged trials, the episode each diverged in.
    pub diverged: BTreeMap<MazeAgent, Vec<u32>>,
    /// SIS and DIS at every level of the `irl-scale` reading.
    pub irl_scale: IrlScaleResults,
    /// The units of HMN (the `hmn-units` reading).
    pub hmn_units: HmnUnits,
    /// Trials computed in this run.
    pub computed: usize,
    /// Trials reused from the store.
    pub reused: usize,
}

impl MazeResults {
    /// The demonstrator's mean return in the reading's units.
    pub fn hmn(&self) -> f64 {
        self.demonstrations.hmn(self.hmn_units)
    }
}

/// The parameters of a scale.
pub fn params_for(scale: Scale) -> MazeParams {
    match scale {
        Scale::Quick => MazeParams::quick(),
        Scale::Paper => MazeParams::paper(),
    }
}

/// Loads or records the demonstrations on the maze `layout` (the synthetic
/// demonstrator follows its route, from the same seed on either layout). A
/// file's are checked ([`crate::inputs::check`]): an error names the file
/// and the problem.
pub fn demonstrations(
    master_seed: u64,
    source: &DemonstrationSource,
    layout: LayoutId,
) -> Result<Demonstrations, MazeError> {
    match source {
        DemonstrationSource::Synthetic => {
            let mut rng = seeded(derive_seed(master_seed, &TrialKey::new(CHAPTER, EXPERIMENT, "demonstrator", 0)));
            let walks = MazeDemonstrator::on(layout).record(
                &mut rng,
                demonstrator::thesis::COUNT,
                demonstrator::thesis::LENGTH_RANGE,
            );
            Ok(Demonstrations {
                set: to_demonstration_set(&walks),
                stats: Some(measure(&walks, layout)),
                walks: Some(walks),
                source: source.clone(),
            })
        }
        DemonstrationSource::File(path) => {
            let set = DemonstrationSet::read_path(path, Some(4))?;
            check(&set, layout).map_err(|error| MazeError::File { path: path.clone(), error })?;
            Ok(Demonstrations { set, walks: None, stats: None, source: source.clone() })
        }
    }
}

/// What both Maze experiments start from.
#[derive(Clone, Debug)]
pub struct MazeSetup {
    /// The parameters of the scale.
    pub params: MazeParams,
    /// The demonstrations.
    pub demonstrations: Demonstrations,
    /// What the agents learn from.
    pub inputs: PreparedInputs,
}

/// Records (or reads) the demonstrations on the reading's layout and
/// derives the agents' inputs.
pub fn setup(options: &RunOptions, source: &DemonstrationSource) -> Result<MazeSetup, MazeError> {
    let params = MazeParams { layout: crate::readings::maze_layout(&options.reading), ..params_for(options.scale) };
    let demonstrations = demonstrations(options.master_seed, source, params.layout)?;
    let inputs = prepare_inputs(options.master_seed, &params, &demonstrations)?;
    Ok(MazeSetup { params, demonstrations, inputs })
}

/// [`prepare`] on the demonstrations; an error names their file, if they
/// came from one.
pub fn prepare_inputs(
    master_seed: u64,
    params: &MazeParams,
    demonstrations: &Demonstrations,
) -> Result<PreparedInputs, MazeError> {
    prepare(master_seed, params, &demonstrations.set).map_err(|error| match &demonstrations.source {
        DemonstrationSource::File(path) => MazeError::File { path: path.clone(), error },
        DemonstrationSource::Synthetic => MazeError::Inputs(error),
    })
}

/// Fingerprint of what every trial of a setup depends on (its inputs).
fn base_fingerprint(setup: &MazeSetup) -> Fingerprint {
    Fingerprint::new().u64(setup.inputs.fingerprint.value())
}

/// Runs (or loads) trials of `(condition, agent, params)`, in order.
fn run_conditions(
    options: &RunOptions,
    label: &str,
    setup: &MazeSetup,
    conditions: &[(String, MazeAgent, MazeParams)],
) -> Result<(Vec<Vec<MazeTrial>>, usize, usize), MazeError> {
    let base = base_fingerprint(setup);
    let plan = TrialPlan::new(options, crate::CHAPTER_ID, crate::Experiment::Maze);
    let plan = &plan;
    let specs: Vec<TrialSpec<usize>> = conditions
        .iter()
        .enumerate()
        .flat_map(|(c, (name, _, params))| {
            let determinants = base.str(name).str(&serde_json::to_string(params).expect("parameters serialise"));
            (0..params.trials).map(move |t| plan.spec(name, t, determinants, c))
        })
        .collect();
    let outcomes = run_trials(options, label, &specs, |spec| {
        let (_, agent, params) = &conditions[spec.params];
        run_trial(*agent, params, &setup.inputs.agents, spec.seed)
    })?;
    let mut grouped: Vec<Vec<MazeTrial>> = vec![Vec::new(); conditions.len()];
    for (spec, result) in specs.iter().zip(outcomes.results) {
        grouped[spec.params].push(result);
    }
    Ok((grouped, outcomes.computed, outcomes.reused))
}

/// Runs (or loads) the Maze experiment: the thesis's five agents under the
/// run's reading, and SIS and DIS at the other levels of `irl-scale` (each
/// under the run's reading with that level: the trials a run of that
/// reading would make, stored where it finds them).
pub fn run(options: &RunOptions, setup: &MazeSetup) -> Result<MazeResults, MazeError> {
    let conditions: Vec<(String, MazeAgent, MazeParams)> = MazeAgent::ALL
        .iter()
        .map(|&a| (a.slug().to_string(), a, crate::readings::maze_params(&options.reading, a, &setup.params)))
        .collect();
    let (grouped, mut computed, mut reused) = run_conditions(options, "maze", setup, &conditions)?;
    let mut trials = BTreeMap::new();
    let mut diverged = BTreeMap::new();
    for (c, group) in conditions.iter().zip(grouped) {
        let (ok, bad): (Vec<MazeTrial>, Vec<MazeTrial>) = group.into_iter().partition(|t| t.diverged_at.is_none());
        if !bad.is_empty() {
            diverged.insert(c.1, bad.iter().filter_map(|t| t.diverged_at).collect::<Vec<u32>>());
        }
        if !ok.is_empty() {
            trials.insert(c.1, ok);
        }
    }
    let irl_scale = run_irl_scale_levels(options, setup, &trials, &diverged)?;
    computed += irl_scale.computed;
    reused += irl_scale.reused;
    Ok(MazeResults {
        diverged,
        scale: options.scale,
        seed: options.master_seed,
        params: crate::readings::maze_params_shown(&options.reading, &setup.params),
        demonstrations: setup.demonstrations.clone(),
        inputs: setup.inputs.clone(),
        trials,
        irl_scale,
        hmn_units: crate::readings::hmn_units(&options.reading),
        computed,
        reused,
    })
}

/// SIS and DIS at one level of the `irl-scale` reading.
#[derive(Clone, Debug)]
pub struct IrlScaleRun {
    /// The agent (SIS or DIS).
    pub agent: MazeAgent,
    /// The level's name.
    pub level: &'static str,
    /// κ at that level.
    pub kappa: f64,
    /// Whether these are the run's own SIS and DIS (the run's reading's level).
    pub main: bool,
    /// Its trials, those whose learner diverged left out.
    pub trials: Vec<MazeTrial>,
    /// The episode each diverged trial diverged in.
    pub diverged: Vec<u32>,
}

/// SIS and DIS at every level of the `irl-scale` reading: how much the
/// comparison with SARSA depends on the size of the IRL reward, which the
/// thesis does not give. Nothing is chosen from these runs.
#[derive(Clone, Debug)]
pub struct IrlScaleResults {
    /// SIS then DIS, each at every level in the axis's order.
    pub runs: Vec<IrlScaleRun>,
    /// Trials computed for the other levels in this run.
    pub computed: usize,
    /// Trials of the other levels reused from the store.
    pub reused: usize,
}

/// Runs (or loads) SIS and DIS at the `irl-scale` levels other than the
/// run's, and gathers them with the run's own.
fn run_irl_scale_levels(
    options: &RunOptions,
    setup: &MazeSetup,
    main: &BTreeMap<MazeAgent, Vec<MazeTrial>>,
    main_diverged: &BTreeMap<MazeAgent, Vec<u32>>,
) -> Result<IrlScaleResults, MazeError> {
    use crate::readings::IRL_SCALE;
    let agents = [MazeAgent::Sis, MazeAgent::Dis];
    let own = options.reading.level_of(&IRL_SCALE);
    let (mut computed, mut reused) = (0, 0);
    let mut by_level: Vec<(&'static str, f64, bool, Vec<Vec<MazeTrial>>)> = Vec::new();
    for level in IRL_SCALE.levels {
        let reading = options.reading.clone().with(&IRL_SCALE, level);
        let kappa = crate::readings::irl_scale(&reading);
        if level.name == own {
            let groups = agents.iter().map(|a| main.get(a).cloned().unwrap_or_default()).collect();
            by_level.push((level.name, kappa, true, groups));
            continue;
        }
        let alt = RunOptions { reading, ..options.clone() };
        let conditions: Vec<(String, MazeAgent, MazeParams)> = agents
            .iter()
            .map(|&a| (a.slug().to_string(), a, crate::readings::maze_params(&alt.reading, a, &setup.params)))
            .collect();
        let label = format!("maze irl-scale={}", level.name);
        let (grouped, c, r) = run_conditions(&alt, &label, setup, &conditions)?;
        computed += c;
        reused += r;
        by_level.push((level.name, kappa, false, grouped));
    }
    let mut runs = Vec::new();
    for (k, &agent) in agents.iter().enumerate() {
        for (level, kappa, is_main, groups) in &by_level {
            let (trials, diverged) = if *is_main {
                (groups[k].clone(), main_diverged.get(&agent).cloned().unwrap_or_default())
            } else {
                let (ok, bad): (Vec<MazeTrial>, Vec<MazeTrial>) =
                    groups[k].iter().cloned().partition(|t| t.diverged_at.is_none());
                (ok, bad.iter().filter_map(|t| t.diverged_at).collect())
            };
            runs.push(IrlScaleRun { agent, level, kappa: *kappa, main: *is_main, trials, diverged });
        }
    }
    Ok(IrlScaleResults { runs, computed, reused })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hmn_counts_the_recorded_steps_or_the_agents_steps() {
        let d = demonstrations(rlfd_harness::THESIS_MASTER_SEED, &DemonstrationSource::Synthetic, LayoutId::LowDetour)
            .unwrap();
        let mean_steps = d.stats.as_ref().unwrap().mean_length;
        let recorded = d.hmn(HmnUnits::Recorded);
        assert!((recorded - (10.0 - mean_steps)).abs() < 1e-9, "{recorded} against {mean_steps} steps");
        assert!((-337.0..=-318.0).contains(&recorded), "the thesis's −327.5 give or take the set: {recorded}");
        let agent = d.hmn(HmnUnits::AgentSteps);
        assert!((agent - (10.0 - mean_steps / 2.0)).abs() < 1e-9);
        // About −160: the review's "at the agents' resolution its path would score about −161".
        assert!((-170.0..=-150.0).contains(&agent), "{agent}");
        // The same seed on another layout: the same person, its own route.
        let f = demonstrations(rlfd_harness::THESIS_MASTER_SEED, &DemonstrationSource::Synthetic, LayoutId::FloorRoute)
            .unwrap();
        assert_ne!(f.set.lengths(), d.set.lengths());
        assert_eq!(f.stats.unwrap().wall_touches, 0);
    }
}
