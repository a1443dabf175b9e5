//! Chapter 5's adapter: Human-Agent Transfer in 3 vs 2 Keepaway.

use anyhow::Result;
use ch5_hat_keepaway::Experiment;
use rlfd_harness::{RunOptions, Workload};
use rlfd_report::Provenance;

use super::{Chapter, ChapterRun};
use crate::cli::RunSettings;

pub struct Ch5;

impl Chapter for Ch5 {
    fn slug(&self) -> &'static str {
        ch5_hat_keepaway::CHAPTER
    }

    fn alias(&self) -> &'static str {
        "ch5"
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
        let results = ch5_hat_keepaway::reproduce(options, &experiments)?;
        let report = ch5_hat_keepaway::report::chapter_report(&results, provenance)?;
        let (computed, reused) = results.trial_counts();
        Ok(ChapterRun { report, computed, reused })
    }

    fn workloads(&self) -> Result<Vec<Workload<'static>>> {
        Ok(ch5_hat_keepaway::bench_workloads()?)
    }
}
