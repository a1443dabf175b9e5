//! `reproduce --robustness`: every verdict recomputed over independent
//! replications and over the readings of the thesis's open choices.
//!
//! Besides the headline run (default reading, master seed), it runs each
//! chapter at `K` master seeds (the master seed and `K − 1` seeds derived
//! from it) with every axis at its default, and at the master seed once per
//! non-default level of each axis with the other axes at their defaults
//! (one factor at a time, so the cost grows with the sum of the levels, not
//! their product). Each run is an ordinary run through the store: resumable,
//! and only the trials an axis changes are recomputed. Only the verdicts of
//! those runs are kept; the reports written are the headline run's, with a
//! robustness section and a robustness line per claim in the scorecard.

use std::collections::BTreeMap;

use anyhow::{Context, Result};
use rlfd_harness::{Reading, RunMode, Tally, TrialKey, derive_seed};
use rlfd_report::robustness::{AxisInfo, ClaimRobustness, LevelInfo, Robustness};
use rlfd_report::{ChapterSummary, Provenance};

use crate::chapters::{Chapter, run_options};
use crate::cli::RunSettings;

/// The `k`-th replication seed of `master`: `master` itself for `k = 0`,
/// else a seed derived from it (stable, listed in the report).
pub fn replication_seed(master: u64, k: u32) -> u64 {
    if k == 0 { master } else { derive_seed(master, &TrialKey::new("rlfd", "replication", "master-seed", k)) }
}

/// Records the replications and readings read that the current code would
/// not reuse (made by another behaviour version or build), so that the
/// report says so as it does for the headline run's.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OtherRecords {
    /// Trials the replications and readings read or computed, in all.
    pub trials: usize,
    /// (behaviour version, whether it is its experiment's current one,
    /// build identity) → trials read from its records.
    pub by_version: BTreeMap<(u32, bool, String), usize>,
}

impl OtherRecords {
    /// Adds what one run of `slug` read.
    fn add(&mut self, tally: &Tally, slug: &str) {
        for ((chapter, _), t) in tally.experiments() {
            if chapter != slug {
                continue;
            }
            self.trials += t.keys.len();
            for ((behaviour, build), n) in t.other_versions {
                *self.by_version.entry((behaviour, behaviour == t.behaviour, build)).or_default() += n;
            }
        }
    }
}

/// The claims' verdicts of one run of `chapter` at `seed` under `reading`;
/// the records it read of other versions go to `other`.
fn verdicts(
    chapter: &dyn Chapter,
    s: &RunSettings,
    run: &Runs<'_>,
    seed: u64,
    reading: &Reading,
    other: &mut OtherRecords,
) -> Result<ChapterSummary> {
    let settings = RunSettings { seed, ..s.clone() };
    let mut options = run_options(&settings, run.mode.clone());
    options.reading = reading.clone();
    let run = chapter
        .run(&settings, run.experiments, &options, run.provenance)
        .with_context(|| format!("{} at seed {seed}, reading {reading}", chapter.slug()))?;
    other.add(&options.tally, chapter.slug());
    let (computed, reused, _, _) = options.tally.totals();
    eprintln!("{}: seed {seed}, reading {reading}: {computed} trials computed, {reused} reused", chapter.slug());
    Ok(run.report.summary())
}

/// How the replications and readings run: `RunMode::Run` for `reproduce`,
/// a load for `report`; over the experiments named (all if none).
pub struct Runs<'a> {
    /// What the runs may do with the store.
    pub mode: RunMode,
    /// The experiments (none: all).
    pub experiments: &'a [&'a str],
    /// The command's provenance.
    pub provenance: &'a Provenance,
}

/// Runs the replications and readings of `chapter` and gathers their
/// verdicts, and the records of other versions they read.
pub fn run(chapter: &dyn Chapter, s: &RunSettings, seeds: u32, runs: &Runs<'_>) -> Result<(Robustness, OtherRecords)> {
    let seed_list: Vec<u64> = (0..seeds).map(|k| replication_seed(s.seed, k)).collect();
    let mut other = OtherRecords::default();
    let mut by_seed = Vec::new();
    for &seed in &seed_list {
        by_seed.push(verdicts(chapter, s, runs, seed, &Reading::defaults(), &mut other)?);
    }
    let mut by_reading = Vec::new();
    let mut axes = Vec::new();
    for &axis in chapter.readings() {
        axes.push(AxisInfo {
            name: axis.name.into(),
            question: axis.question.into(),
            default: axis.default.into(),
            why_default: axis.why_default.into(),
            levels: axis
                .levels
                .iter()
                .map(|l| LevelInfo { name: l.name.into(), meaning: l.meaning.into(), source: l.source.into() })
                .collect(),
        });
        for level in axis.alternatives() {
            let reading = Reading::defaults().with(axis, level);
            by_reading.push((axis.name, level.name, verdicts(chapter, s, runs, s.seed, &reading, &mut other)?));
        }
    }
    let claims = by_seed[0]
        .claims
        .iter()
        .map(|c| {
            let find = |summary: &ChapterSummary| {
                summary
                    .claims
                    .iter()
                    .find(|x| x.id == c.id)
                    .map_or(rlfd_report::claims::Verdict::NotEvaluable, |x| x.verdict)
            };
            ClaimRobustness {
                id: c.id.clone(),
                seeds: by_seed.iter().map(find).collect(),
                readings: by_reading
                    .iter()
                    .map(|(a, l, summary)| (a.to_string(), l.to_string(), find(summary)))
                    .collect(),
            }
        })
        .collect();
    Ok((Robustness { seeds: seed_list, axes, claims }, other))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replication_seeds_start_at_the_master_and_are_pinned() {
        assert_eq!(replication_seed(20160501, 0), 20160501);
        let s: Vec<u64> = (1..4).map(|k| replication_seed(20160501, k)).collect();
        assert!(s.iter().all(|&x| x != 20160501));
        assert_ne!(s[0], s[1]);
        assert_eq!(s, (1..4).map(|k| replication_seed(20160501, k)).collect::<Vec<_>>());
    }
}
