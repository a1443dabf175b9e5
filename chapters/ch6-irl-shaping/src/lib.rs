//! Chapter 6 of the thesis: learning from demonstration for shaping through
//! inverse reinforcement learning (Static and Dynamic IRL Shaping, SIS and
//! DIS), against SARSA(λ), HAT and SBS.
//!
//! What it is: the Maze experiment of section 6.3.1, whole: the domain
//! ([`maze`]: the modified Dyna Maze, its shortest paths, the synthetic
//! demonstrator), the five agents ([`agents`]), what they learn from the
//! demonstrations ([`inputs`]: RE-IRL, RIPPER, the similarity potential), the
//! experiment through the harness ([`experiment`]) and the report
//! ([`report`]: Tables 6.1 and 6.2, Figures 6.1–6.4, claims C6.1–C6.5 and
//! C6.11). The Mario AI half of the chapter (section 6.3.2) is not built yet.
//!
//! What it is not: no IO beyond the harness's result store and an optional
//! demonstration file, no printing, no clock. `xtask` calls [`reproduce`] and
//! [`report::chapter_report`] and writes the files.

pub mod agents;
pub mod experiment;
pub mod inputs;
pub mod maze;
pub mod report;

use std::str::FromStr;

use rlfd_harness::RunOptions;

pub use experiment::{DemonstrationSource, IrlScaleResults, MazeError, MazeResults};

/// The chapter's slug: its directory in reports and result stores.
pub const CHAPTER: &str = "ch6-irl-shaping";

/// The chapter's experiments.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Experiment {
    /// Section 6.3.1: the Maze.
    Maze,
    /// Not in the thesis: SIS and DIS in the Maze with the IRL reward scaled by κ.
    MazeIrlScale,
}

impl Experiment {
    /// Every experiment of the chapter.
    pub const ALL: [Experiment; 2] = [Experiment::Maze, Experiment::MazeIrlScale];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Experiment::Maze => experiment::EXPERIMENT,
            Experiment::MazeIrlScale => experiment::IRL_SCALE_EXPERIMENT,
        }
    }

    /// Whether the experiment learns from the Maze demonstrations.
    pub fn uses_maze_demonstrations(self) -> bool {
        matches!(self, Experiment::Maze | Experiment::MazeIrlScale)
    }
}

impl FromStr for Experiment {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Experiment::ALL.into_iter().find(|e| e.name() == s).ok_or_else(|| {
            let names: Vec<&str> = Experiment::ALL.iter().map(|e| e.name()).collect();
            format!("unknown experiment \"{s}\" for {CHAPTER} (expected one of: {})", names.join(", "))
        })
    }
}

/// The results of the chapter's experiments that ran.
#[derive(Clone, Debug, Default)]
pub struct Ch6Results {
    /// The Maze, if it ran.
    pub maze: Option<MazeResults>,
    /// The IRL-scale sensitivity study, if it ran.
    pub irl_scale: Option<IrlScaleResults>,
}

impl Ch6Results {
    /// Trials computed and reused over all experiments.
    pub fn trial_counts(&self) -> (usize, usize) {
        let m = self.maze.as_ref().map_or((0, 0), |m| (m.computed, m.reused));
        let k = self.irl_scale.as_ref().map_or((0, 0), |k| (k.computed, k.reused));
        (m.0 + k.0, m.1 + k.1)
    }
}

/// Runs (or, with `options.load_only`, loads) the chosen experiments.
pub fn reproduce(
    options: &RunOptions,
    experiments: &[Experiment],
    maze_demonstrations: &DemonstrationSource,
) -> Result<Ch6Results, MazeError> {
    let mut results = Ch6Results::default();
    let setup = if experiments.iter().any(|e| e.uses_maze_demonstrations()) {
        Some(experiment::setup(options, maze_demonstrations)?)
    } else {
        None
    };
    for e in experiments {
        let setup = setup.as_ref().expect("set up above for every Maze experiment");
        match e {
            Experiment::Maze => results.maze = Some(experiment::run(options, setup)?),
            Experiment::MazeIrlScale => results.irl_scale = Some(experiment::run_irl_scale(options, setup)?),
        }
    }
    Ok(results)
}

/// The chapter's benchmark workloads for `cargo xtask bench`: the Maze
/// simulator alone, and each agent learning whole trials at the paper's
/// parameters (one trial per batch).
pub fn bench_workloads() -> Result<Vec<rlfd_harness::Workload<'static>>, MazeError> {
    use agents::{MazeAgent, MazeParams, run_trial};
    let demos = experiment::demonstrations(DEFAULT_SEED, &DemonstrationSource::Synthetic)?;
    let params = MazeParams::paper();
    let inputs = inputs::prepare(DEFAULT_SEED, &params, &demos.set)?;
    let mut out = vec![rlfd_harness::Workload {
        domain: "maze",
        name: "simulator".into(),
        unit: "steps",
        run: Box::new(|seed| maze::random_walk_steps(seed, 100_000)),
    }];
    for agent in MazeAgent::ALL {
        let (params, agents) = (params.clone(), inputs.agents.clone());
        let name = if agent == MazeAgent::Sarsa { "sarsa-lambda".to_string() } else { agent.slug().to_string() };
        out.push(rlfd_harness::Workload {
            domain: "maze",
            name,
            unit: "steps",
            run: Box::new(move |seed| {
                run_trial(agent, &params, &agents, seed).steps.iter().map(|&s| u64::from(s)).sum()
            }),
        });
    }
    Ok(out)
}

/// The seed benchmarks use for the demonstrations (the default master seed).
const DEFAULT_SEED: u64 = 20160501;
