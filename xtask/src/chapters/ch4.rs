//! Chapter 4's adapter: the DBug user study (Int-RL, Behavior Networks, CBA).

use anyhow::Result;
use ch4_dbug_study::Experiment;
use rlfd_harness::{RunOptions, Workload};
use rlfd_report::Provenance;

use super::{Chapter, ChapterRun};
use crate::cli::RunSettings;

pub struct Ch4;

impl Chapter for Ch4 {
    fn slug(&self) -> &'static str {
        ch4_dbug_study::CHAPTER
    }

    fn alias(&self) -> &'static str {
        "ch4"
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
        let results = ch4_dbug_study::reproduce(options, &experiments)?;
        let report = ch4_dbug_study::report::chapter_report(&results, provenance)?;
        let (computed, reused) = results.trial_counts();
        Ok(ChapterRun { report, computed, reused })
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>> {
        Ok(ch4_dbug_study::bench_workloads()?)
    }
}
