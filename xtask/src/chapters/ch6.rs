//! Chapter 6's adapter: IRL shaping (the Maze and Mario).

use anyhow::{Result, anyhow};
use ch6_irl_shaping::{DemonstrationSource, Experiment};
use rlfd_harness::{RunOptions, Workload};
use rlfd_report::Provenance;

use super::{Chapter, ChapterRun};
use crate::cli::RunSettings;

pub struct Ch6;

impl Chapter for Ch6 {
    fn slug(&self) -> &'static str {
        ch6_irl_shaping::CHAPTER
    }

    fn alias(&self) -> &'static str {
        "ch6"
    }

    fn experiments(&self) -> Vec<&'static str> {
        Experiment::ALL.iter().map(|e| e.name()).collect()
    }

    fn run(
        &self,
        s: &RunSettings,
        experiment: Option<&str>,
        options: &RunOptions,
        provenance: &Provenance,
    ) -> Result<ChapterRun> {
        let (experiments, source) = selection(s, experiment)?;
        let results = ch6_irl_shaping::reproduce(options, &experiments, &source)?;
        let report = ch6_irl_shaping::report::chapter_report(&results, provenance)?;
        Ok(ChapterRun { report })
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>> {
        Ok(ch6_irl_shaping::bench_workloads()?)
    }

    fn check_inputs(&self, s: &RunSettings, experiment: Option<&str>) -> Result<()> {
        // A demonstration file is read and turned into the agents' inputs
        // now (a fraction of a second), so a bad file fails before any
        // chapter stores a trial.
        if let (_, DemonstrationSource::File(path)) = selection(s, experiment)? {
            let source = DemonstrationSource::File(path);
            let demos = ch6_irl_shaping::experiment::demonstrations(s.seed, &source)?;
            let params = ch6_irl_shaping::experiment::params_for(s.scale);
            ch6_irl_shaping::experiment::prepare_inputs(s.seed, &params, &demos)?;
        }
        Ok(())
    }
}

/// The experiments a command line selects and where their demonstrations come from.
fn selection(s: &RunSettings, experiment: Option<&str>) -> Result<(Vec<Experiment>, DemonstrationSource)> {
    let experiments: Vec<Experiment> = match experiment {
        None => Experiment::ALL.to_vec(),
        Some(e) => vec![e.parse::<Experiment>()?],
    };
    let source = match &s.demonstrations {
        None => DemonstrationSource::Synthetic,
        Some(p) if experiments.iter().any(|e| e.uses_maze_demonstrations()) => DemonstrationSource::File(p.clone()),
        Some(_) => return Err(anyhow!("--demonstrations applies to the maze experiments, none of which is selected")),
    };
    Ok((experiments, source))
}
