//! The Maze experiment: the demonstrations, then 5 agents × trials ×
//! episodes through the harness (section 6.3.1).

use std::collections::BTreeMap;
use std::path::PathBuf;

use rlfd_harness::{Fingerprint, HarnessError, RunOptions, Scale, TrialKey, TrialSpec, derive_seed, run_trials};
use rlfd_lfd::demonstration::{DemonstrationSet, ReadError};
use rlfd_rl::random::seeded;
use thiserror::Error;

use crate::CHAPTER;
use crate::agents::{MazeAgent, MazeParams, MazeTrial, run_trial};
use crate::inputs::{InputError, PreparedInputs, prepare};
use crate::maze::demonstrator::{
    self, Demonstration, DemonstrationStats, MazeDemonstrator, measure, to_demonstration_set,
};

/// The experiment's name in result paths and on the command line.
pub const EXPERIMENT: &str = "maze";

/// What can stop the Maze experiment.
#[derive(Debug, Error)]
pub enum MazeError {
    /// A demonstration file could not be read.
    #[error(transparent)]
    Read(#[from] ReadError),
    /// The demonstrations could not be used.
    #[error(transparent)]
    Inputs(#[from] InputError),
    /// Storing or loading trials failed.
    #[error(transparent)]
    Harness(#[from] HarnessError),
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
    /// Per agent, its trials in order.
    pub trials: BTreeMap<MazeAgent, Vec<MazeTrial>>,
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

/// Loads or records the demonstrations.
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
            Ok(Demonstrations { set, walks: None, stats: None, source: source.clone() })
        }
    }
}

/// Runs (or loads) the Maze experiment.
pub fn run(options: &RunOptions, source: &DemonstrationSource) -> Result<MazeResults, MazeError> {
    let params = params_for(options.scale);
    let demonstrations = demonstrations(options.master_seed, source)?;
    let inputs = prepare(options.master_seed, &params, &demonstrations.set)?;
    let base = Fingerprint::new()
        .str(env!("RLFD_CODE_FINGERPRINT"))
        .str(&serde_json::to_string(&params).expect("parameters serialise"))
        .u64(inputs.fingerprint.value());
    let specs: Vec<TrialSpec<MazeAgent>> = MazeAgent::ALL
        .iter()
        .flat_map(|&agent| {
            (0..params.trials).map(move |t| {
                let key = TrialKey::new(CHAPTER, EXPERIMENT, agent.slug(), t);
                TrialSpec {
                    seed: derive_seed(options.master_seed, &key),
                    fingerprint: base.str(agent.slug()).hex(),
                    key,
                    params: agent,
                }
            })
        })
        .collect();
    let outcomes =
        run_trials(options, "maze", &specs, |spec| run_trial(spec.params, &params, &inputs.agents, spec.seed))?;
    let mut trials: BTreeMap<MazeAgent, Vec<MazeTrial>> = BTreeMap::new();
    for (spec, result) in specs.iter().zip(outcomes.results) {
        trials.entry(spec.params).or_default().push(result);
    }
    Ok(MazeResults {
        scale: options.scale,
        seed: options.master_seed,
        params,
        demonstrations,
        inputs,
        trials,
        computed: outcomes.computed,
        reused: outcomes.reused,
    })
}
