//! The Maze experiments: the demonstrations and what the agents learn from
//! them ([`setup`]), then the thesis's 5 agents × trials × episodes
//! ([`run`], section 6.3.1) and a sensitivity study that is not in the thesis
//! ([`run_irl_scale`]), all through the harness.

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

/// The experiment's name in result paths and on the command line.
pub const EXPERIMENT: &str = crate::Experiment::Maze.name();

/// The sensitivity experiment's name.
pub const IRL_SCALE_EXPERIMENT: &str = crate::Experiment::MazeIrlScale.name();

/// The factors κ on the IRL reward the sensitivity experiment tries (κ = 1 is the main experiment).
pub const IRL_SCALES: [f64; 2] = [0.1, 0.01];

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
    /// The demonstrator's mean return as the thesis counts it: −1 per
    /// recorded step and +10 at the goal (the thesis's HMN).
    pub fn hmn(&self) -> f64 {
        let lengths = self.set.lengths();
        lengths.iter().map(|&l| -((l - 1) as f64) + 10.0).sum::<f64>() / lengths.len() as f64
    }
}

/// Everything the Maze report is made from.
#[derive(Clone, Debug)]
pub struct MazeResults {
    /// The scale it ran at.
    pub scale: Scale,
    /// The master seed.
    pub seed: u64,
    /// The parameters.
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
    /// Trials computed in this run.
    pub computed: usize,
    /// Trials reused from the store.
    pub reused: usize,
}

/// The parameters of a scale.
pub fn params_for(scale: Scale) -> MazeParams {
    match scale {
        Scale::Quick => MazeParams::quick(),
        Scale::Paper => MazeParams::paper(),
    }
}

/// Loads or records the demonstrations. A file's are checked
/// ([`crate::inputs::check`]): an error names the file and the problem.
pub fn demonstrations(master_seed: u64, source: &DemonstrationSource) -> Result<Demonstrations, MazeError> {
    match source {
        DemonstrationSource::Synthetic => {
            let mut rng = seeded(derive_seed(master_seed, &TrialKey::new(CHAPTER, EXPERIMENT, "demonstrator", 0)));
            let walks = MazeDemonstrator::thesis().record(
                &mut rng,
                demonstrator::thesis::COUNT,
                demonstrator::thesis::LENGTH_RANGE,
            );
            Ok(Demonstrations {
                set: to_demonstration_set(&walks),
                stats: Some(measure(&walks)),
                walks: Some(walks),
                source: source.clone(),
            })
        }
        DemonstrationSource::File(path) => {
            let set = DemonstrationSet::read_path(path, Some(4))?;
            check(&set).map_err(|error| MazeError::File { path: path.clone(), error })?;
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

/// Records (or reads) the demonstrations and derives the agents' inputs.
pub fn setup(options: &RunOptions, source: &DemonstrationSource) -> Result<MazeSetup, MazeError> {
    let params = params_for(options.scale);
    let demonstrations = demonstrations(options.master_seed, source)?;
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
    experiment: crate::Experiment,
    label: &str,
    setup: &MazeSetup,
    conditions: &[(String, MazeAgent, MazeParams)],
) -> Result<(Vec<Vec<MazeTrial>>, usize, usize), MazeError> {
    let base = base_fingerprint(setup);
    let plan = TrialPlan::new(options, crate::CHAPTER_ID, experiment);
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

/// Runs (or loads) the Maze experiment: the thesis's five agents.
pub fn run(options: &RunOptions, setup: &MazeSetup) -> Result<MazeResults, MazeError> {
    let conditions: Vec<(String, MazeAgent, MazeParams)> = MazeAgent::ALL
        .iter()
        .map(|&a| (a.slug().to_string(), a, crate::readings::maze_params(&options.reading, a, &setup.params)))
        .collect();
    let (grouped, computed, reused) = run_conditions(options, crate::Experiment::Maze, "maze", setup, &conditions)?;
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
    Ok(MazeResults {
        diverged,
        scale: options.scale,
        seed: options.master_seed,
        params: setup.params.clone(),
        demonstrations: setup.demonstrations.clone(),
        inputs: setup.inputs.clone(),
        trials,
        computed,
        reused,
    })
}

/// The sensitivity study's results: SIS and DIS with the IRL reward scaled by κ.
#[derive(Clone, Debug)]
pub struct IrlScaleResults {
    /// `(agent, κ, trials)`, agents SIS then DIS, κ in [`IRL_SCALES`] order;
    /// trials whose learner diverged left out.
    pub runs: Vec<(MazeAgent, f64, Vec<MazeTrial>)>,
    /// Per run, in the same order, how many trials diverged.
    pub diverged: Vec<usize>,
    /// Trials computed in this run.
    pub computed: usize,
    /// Trials reused from the store.
    pub reused: usize,
}

/// Runs (or loads) SIS and DIS with the RE-IRL reward multiplied by each κ
/// of [`IRL_SCALES`]. The thesis does not give the size of its IRL reward,
/// which sets the size of SIS's and DIS's shaping; this shows how much the
/// comparison depends on it. Nothing here is chosen from these results.
pub fn run_irl_scale(options: &RunOptions, setup: &MazeSetup) -> Result<IrlScaleResults, MazeError> {
    let mut conditions = Vec::new();
    for agent in [MazeAgent::Sis, MazeAgent::Dis] {
        for kappa in IRL_SCALES {
            conditions.push((
                format!("{}-kappa-{kappa}", agent.slug()),
                agent,
                MazeParams { irl_scale: kappa, ..setup.params.clone() },
            ));
        }
    }
    let (grouped, computed, reused) =
        run_conditions(options, crate::Experiment::MazeIrlScale, "maze-irl-scale", setup, &conditions)?;
    let diverged = grouped.iter().map(|g| g.iter().filter(|t| t.diverged_at.is_some()).count()).collect();
    let runs = conditions
        .iter()
        .zip(grouped)
        .map(|((_, agent, params), trials)| {
            (*agent, params.irl_scale, trials.into_iter().filter(|t| t.diverged_at.is_none()).collect())
        })
        .collect();
    Ok(IrlScaleResults { runs, diverged, computed, reused })
}
