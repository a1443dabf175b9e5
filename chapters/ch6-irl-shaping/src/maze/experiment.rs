//! The Maze experiment: the demonstrations and what the agents learn from
//! them (the batch's set-up, [`MazeTrials`]), then the thesis's 5 agents ×
//! trials × episodes ([`plan`], [`run`], section 6.3.1), all through the
//! harness. The experiment sweeps `irl-scale` (the sensitivity study of
//! round 1): the report shows SIS and DIS at every level.

use std::path::PathBuf;

use rlfd_harness::{Batch, Fingerprint, RunContext, RunOptions, Scale, TrialKey, TrialRunner, derive_seed};
use rlfd_lfd::demonstration::DemonstrationSet;
use rlfd_rl::random::seeded;
use serde::Serialize;

use super::demonstrator::{self, Demonstration, DemonstrationStats, MazeDemonstrator, measure, to_demonstration_set};
use super::inputs::{PreparedInputs, check, prepare};
use super::layout::LayoutId;
use super::params::{MazeParams, MazeTrial};
use crate::readings::HmnUnits;
use crate::shaping::run_trial;
use crate::shaping::trials::{AgentTrial, Condition, Results, add_conditions, five_agents, split};
use crate::{CHAPTER, Ch6Error};

/// The experiment's name in result paths and on the command line.
pub const EXPERIMENT: &str = crate::Experiment::Maze.name();

/// Where the demonstrations come from.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum DemonstrationSource {
    /// The synthetic demonstrator ([`MazeDemonstrator`]).
    #[default]
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
    /// The units the demonstrator's return HMN is counted in (the
    /// `hmn-units` reading; [`demonstrations`] gives the thesis's).
    pub hmn_units: HmnUnits,
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

/// Everything the Maze report is made from; the study is SIS and DIS at
/// every level of the `irl-scale` reading (the value of a run is κ).
pub type MazeResults = Results<MazeParams, Demonstrations, PreparedInputs, MazeTrial>;

impl MazeResults {
    /// The demonstrator's mean return in the reading's units.
    pub fn hmn(&self) -> f64 {
        self.demonstrations.hmn(self.demonstrations.hmn_units)
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
/// file's are checked ([`super::inputs::check`]): an error names the file
/// and the problem.
pub fn demonstrations(
    master_seed: u64,
    source: &DemonstrationSource,
    layout: LayoutId,
) -> Result<Demonstrations, Ch6Error> {
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
                hmn_units: HmnUnits::default(),
            })
        }
        DemonstrationSource::File(path) => {
            let set = DemonstrationSet::read_path(path, Some(4))?;
            check(&set, layout).map_err(|error| Ch6Error::File { path: path.clone(), error })?;
            Ok(Demonstrations { set, walks: None, stats: None, source: source.clone(), hmn_units: HmnUnits::default() })
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

/// [`prepare`] on the demonstrations; an error names their file, if they
/// came from one.
pub fn prepare_inputs(
    master_seed: u64,
    params: &MazeParams,
    demonstrations: &Demonstrations,
) -> Result<PreparedInputs, Ch6Error> {
    prepare(master_seed, params, &demonstrations.set).map_err(|error| match &demonstrations.source {
        DemonstrationSource::File(path) => Ch6Error::File { path: path.clone(), error },
        DemonstrationSource::Synthetic => Ch6Error::Inputs(error),
    })
}

/// The Maze's trials: the set-up records (or reads) the demonstrations on
/// the reading's layout and derives the agents' inputs; a trial is one
/// agent's learning run.
#[derive(Clone, Debug, Serialize)]
pub struct MazeTrials {
    /// The master seed the demonstrations and RE-IRL's baseline are drawn from.
    pub master_seed: u64,
    /// Where the demonstrations come from, as it determines them:
    /// `synthetic`, or the digest of the file's bytes (never its path).
    pub demonstrations: String,
    /// The file, when they come from one.
    #[serde(skip)]
    pub source: DemonstrationSource,
    /// The parameters the set-up reads (the scale's, on the reading's layout).
    pub params: MazeParams,
}

impl MazeTrials {
    /// The runner of `ctx`'s Maze on `source` (whose file, if any, is read
    /// for its digest).
    pub fn new(ctx: &RunContext, source: &DemonstrationSource) -> Result<MazeTrials, Ch6Error> {
        let demonstrations = match source {
            DemonstrationSource::Synthetic => "synthetic".to_string(),
            DemonstrationSource::File(path) => {
                let bytes = std::fs::read(path).map_err(|e| {
                    Ch6Error::Read(rlfd_lfd::demonstration::ReadError {
                        file: path.display().to_string(),
                        line: None,
                        kind: rlfd_lfd::demonstration::ReadErrorKind::Io(e),
                    })
                })?;
                format!("file {}", Fingerprint::new().bytes(&bytes).hex())
            }
        };
        let params = MazeParams { layout: crate::readings::maze_layout(&ctx.reading), ..params_for(ctx.scale) };
        Ok(MazeTrials { master_seed: ctx.master_seed, demonstrations, source: source.clone(), params })
    }
}

impl TrialRunner for MazeTrials {
    type Setup = MazeSetup;
    type Params = AgentTrial<MazeParams>;
    type Result = MazeTrial;
    type Error = Ch6Error;

    fn setup(&self) -> Result<MazeSetup, Ch6Error> {
        let demonstrations = demonstrations(self.master_seed, &self.source, self.params.layout)?;
        let inputs = prepare_inputs(self.master_seed, &self.params, &demonstrations)?;
        Ok(MazeSetup { params: self.params.clone(), demonstrations, inputs })
    }

    fn run(&self, setup: &MazeSetup, trial: &AgentTrial<MazeParams>, seed: u64) -> MazeTrial {
        run_trial(trial.agent, &trial.params, Some(&setup.inputs.agents), seed)
    }
}

/// The Maze experiment at `ctx`: the five agents under the run's reading.
pub fn plan(ctx: &RunContext, source: &DemonstrationSource) -> Result<Batch<MazeTrials>, Ch6Error> {
    let runner = MazeTrials::new(ctx, source)?;
    let params = runner.params.clone();
    let mut batch = Batch::new(ctx, CHAPTER, crate::Experiment::Maze, runner);
    add_conditions(&mut batch, &params, &ctx.reading, &five_agents::<MazeParams>());
    Ok(batch)
}

/// Runs (or loads) the Maze experiment `batch` planned at `ctx`.
pub fn run(ctx: &RunContext, batch: &Batch<MazeTrials>, options: &RunOptions) -> Result<MazeResults, Ch6Error> {
    let out = batch.execute(options)?;
    let MazeSetup { params, mut demonstrations, inputs } = out.setup;
    demonstrations.hmn_units = crate::readings::hmn_units(&ctx.reading);
    let conditions: Vec<Condition> = five_agents::<MazeParams>();
    let grouped = split(&conditions, batch.trials(), out.results);
    let shown = crate::readings::maze_params_shown(&ctx.reading, &params);
    Ok(Results::new(ctx, shown, demonstrations, inputs, &conditions, grouped))
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
