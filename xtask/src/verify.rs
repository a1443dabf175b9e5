//! `verify`: recompute a sample of stored trials and compare each with its
//! record byte for byte: the check a reviewer runs before trusting a store.
//!
//! The sample is drawn by seed: within each experiment the trials are
//! ordered by `derive_seed(sample seed, trial)`, and the experiments are
//! taken in turn, one trial each, until `N` are chosen, so a small sample
//! still covers every experiment. Every other trial is loaded (and must be
//! current): a missing or stale record fails before anything is recomputed.
//!
//! With `--other-builds`, the store is listed as `report` reads it (records
//! of any identity) and a sampled trial that has no record of this build is
//! checked against the record of the same behaviour version another build
//! made: the check that records a report marks "not current" only because
//! the build identity changed (a new rustc, a dependency's lock entry) still
//! reproduce byte for byte.
//!
//! A trial is named by its key; a run that keeps the same trial under
//! several readings (chapter 6's Maze runs SIS and DIS at every `irl-scale`
//! level) holds one record per reading, and verifying the trial recomputes
//! each of them.

use std::collections::{BTreeMap, BTreeSet};

use anyhow::{Context, Result};
use rlfd_harness::{RunMode, TrialKey, derive_seed};
use rlfd_report::Provenance;

use crate::chapters::{self, run_options, semantic_command};
use crate::cli::RunSettings;

/// The trials of `by_experiment` to recompute: `n` of them, spread over the
/// experiments, chosen by `sample_seed`.
pub fn choose(by_experiment: &BTreeMap<(String, String), Vec<TrialKey>>, n: usize, sample_seed: u64) -> Vec<TrialKey> {
    let mut queues: Vec<Vec<TrialKey>> = by_experiment
        .values()
        .map(|keys| {
            let mut k = keys.clone();
            k.sort_by_key(|key| (std::cmp::Reverse(derive_seed(sample_seed, key)), key.clone()));
            // A trial kept under several readings is one trial.
            k.dedup();
            k
        })
        .collect();
    let mut chosen = Vec::new();
    while chosen.len() < n && queues.iter().any(|q| !q.is_empty()) {
        for q in &mut queues {
            if chosen.len() < n
                && let Some(k) = q.pop()
            {
                chosen.push(k);
            }
        }
    }
    chosen
}

pub fn run(s: &RunSettings, n: usize, sample_seed: u64, other_builds: bool) -> Result<()> {
    let selected = chapters::select(s)?;
    let provenance = Provenance::new(semantic_command(s), env!("CARGO_PKG_VERSION"));
    // First pass: load every trial of the current version, or of any with
    // --other-builds (and learn their keys).
    let listing = run_options(s, RunMode::Load { any_version: other_builds });
    for chapter in &selected {
        chapter.run(s, &chapters::named(s), &listing, &provenance).with_context(|| chapter.slug().to_string())?;
    }
    let by_experiment: BTreeMap<(String, String), Vec<TrialKey>> =
        listing.tally.experiments().into_iter().map(|(k, t)| (k, t.keys)).collect();
    let total: usize = by_experiment.values().map(Vec::len).sum();
    let sample: BTreeSet<TrialKey> = choose(&by_experiment, n, sample_seed).into_iter().collect();
    let chosen = sample.len();
    // Each chosen trial's records: one per reading the run keeps it under.
    let records = by_experiment.values().flatten().filter(|k| sample.contains(*k)).count();
    let verify = run_options(s, RunMode::Verify { sample, other_builds });
    for chapter in &selected {
        chapter.run(s, &chapters::named(s), &verify, &provenance).with_context(|| chapter.slug().to_string())?;
    }
    let (_, _, verified, _) = verify.tally.totals();
    anyhow::ensure!(
        verified == records,
        "verify: {chosen} trials ({records} records) were chosen but {verified} records recomputed"
    );
    let experiments = verify.tally.experiments().values().filter(|t| t.verified > 0).count();
    let per_reading = if records > chosen {
        format!(" ({records} records: a trial kept under several readings is recomputed under each)")
    } else {
        String::new()
    };
    eprintln!(
        "verify: {chosen} trials recomputed from {experiments} experiments{per_reading}, each byte-identical to its record ({total} stored trials {})",
        if other_builds { "listed, of any build" } else { "checked current" }
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sample_covers_every_experiment_and_depends_on_the_seed() {
        let mut by: BTreeMap<(String, String), Vec<TrialKey>> = BTreeMap::new();
        for (e, n) in [("a", 50), ("b", 3), ("c", 10)] {
            by.insert(("ch".into(), e.into()), (0..n).map(|t| TrialKey::new("ch", e, "x", t)).collect());
        }
        let s = choose(&by, 5, 1);
        assert_eq!(s.len(), 5);
        for e in ["a", "b", "c"] {
            assert!(s.iter().any(|k| k.experiment == e), "{e} not sampled: {s:?}");
        }
        assert_eq!(choose(&by, 5, 1), s);
        assert_ne!(choose(&by, 5, 2), s);
        assert_eq!(choose(&by, 1000, 1).len(), 63);
        // A trial listed twice (kept under two readings) is chosen once.
        by.get_mut(&("ch".to_string(), "b".to_string())).unwrap().push(TrialKey::new("ch", "b", "x", 0));
        let all = choose(&by, 1000, 1);
        assert_eq!(all.len(), 63);
        assert_eq!(all.iter().collect::<BTreeSet<_>>().len(), 63);
    }
}
