//! Chapter 3's adapter: interactive RL with teacher guidance on the Nao sorting task.

use anyhow::Result;
use ch3_interactive_rl::Experiment;
use rlfd_harness::{RunOptions, Workload};
use rlfd_report::Provenance;

use super::{Chapter, ChapterRun};
use crate::cli::RunSettings;

pub struct Ch3;

impl Chapter for Ch3 {
    fn slug(&self) -> &'static str {
        ch3_interactive_rl::CHAPTER
    }

    fn alias(&self) -> &'static str {
        "ch3"
    }

    fn experiments(&self) -> Vec<&'static str> {
        Experiment::ALL.iter().map(|e| e.name()).collect()
    }

    fn run(
        &self,
        _settings: &RunSettings,
        experiment: Option<&str>,
        options: &RunOptions,
        provenance: &Provenance,
    ) -> Result<ChapterRun> {
        let experiments: Vec<Experiment> = match experiment {
            None => Experiment::ALL.to_vec(),
            Some(e) => vec![e.parse::<Experiment>().map_err(anyhow::Error::msg)?],
        };
        let results = ch3_interactive_rl::reproduce(options, &experiments)?;
        let report = ch3_interactive_rl::report::chapter_report(&results, provenance)?;
        let (computed, reused) = results.trial_counts();
        Ok(ChapterRun { report, computed, reused })
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>> {
        Ok(ch3_interactive_rl::bench_workloads()?)
    }
}
