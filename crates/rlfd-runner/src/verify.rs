//! `verify`: recompute a sample of stored trials and compare each with its
//! record byte for byte: the check a reviewer runs before trusting a store.
//!
//! The sample is drawn by seed from the command's plan (the headline run
//! and its sweeps; with `--robustness`, every run point): within each
//! experiment the trials are ordered by `derive_seed(sample seed, key)`, and
//! the experiments are taken in turn, one trial each, until `N` are chosen,
//! so a small sample still covers every experiment. A trial kept under
//! several readings (a sweep's level that changes its parameters) has one
//! record per reading, and verifying it recomputes each. Every other trial
//! at those run points is loaded and must be current: a missing or stale
//! record fails before anything is recomputed.

use std::collections::{BTreeMap, BTreeSet};

use rlfd_harness::{RunMode, TrialKey, derive_seed};

use crate::Machine;
use crate::command::Selection;
use crate::error::RunnerError;

/// The trials of `by_experiment` to recompute: `n` of them, spread over the
/// experiments, chosen by `sample_seed`.
pub fn choose(by_experiment: &BTreeMap<(String, String), Vec<TrialKey>>, n: usize, sample_seed: u64) -> Vec<TrialKey> {
    let mut queues: Vec<Vec<TrialKey>> = by_experiment
        .values()
        .map(|keys| {
            let mut k = keys.clone();
            k.sort_by_key(|key| (std::cmp::Reverse(derive_seed(sample_seed, key)), key.clone()));
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

/// What a verification did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verified {
    /// Trials chosen.
    pub chosen: usize,
    /// Their records recomputed (one per reading keeping the trial).
    pub records: usize,
    /// Experiments they came from.
    pub experiments: usize,
    /// Trials the run points hold in all.
    pub total: usize,
}

/// Verifies `n` trials of `selection`'s store chosen by `sample_seed`.
pub fn verify(
    selection: &Selection<'_>,
    machine: &Machine,
    n: usize,
    sample_seed: u64,
) -> Result<Verified, RunnerError> {
    let plan = crate::plan::plan(selection, &machine.results)?;
    let mut by_experiment: BTreeMap<(String, String), Vec<TrialKey>> = BTreeMap::new();
    for t in &plan.trials {
        by_experiment.entry((t.key.chapter.clone(), t.key.experiment.clone())).or_default().push(t.key.clone());
    }
    let total = plan.trials.len();
    let sample: BTreeSet<TrialKey> = choose(&by_experiment, n, sample_seed).into_iter().collect();
    let records = plan.trials.iter().filter(|t| sample.contains(&t.key)).count();
    // Each sampled record is verified at the first run point that lists it
    // (a record several points share is recomputed once).
    let mut owner: Vec<Option<usize>> = vec![None; plan.trials.len()];
    let mut points: Vec<(usize, &crate::command::RunPoint)> = Vec::new();
    for g in &plan.groups {
        let p = match points.iter().position(|(c, p)| *c == g.chapter && **p == g.point) {
            Some(p) => p,
            None => {
                points.push((g.chapter, &g.point));
                points.len() - 1
            }
        };
        for &t in &g.trials {
            owner[t].get_or_insert(p);
        }
    }
    let named = selection.named();
    let given = selection.inputs();
    let mut verified = 0;
    let mut experiments = BTreeSet::new();
    for (p, (c, point)) in points.iter().enumerate() {
        let here: BTreeSet<TrialKey> = plan
            .trials
            .iter()
            .zip(&owner)
            .filter(|(t, o)| **o == Some(p) && sample.contains(&t.key))
            .map(|(t, _)| t.key.clone())
            .collect();
        let options = machine.options(RunMode::Verify { sample: here });
        let chapter = selection.chapters[*c];
        chapter.run(&given, &point.experiments(&named), &point.context(selection.command.scale), &options, None)?;
        verified += options.tally.totals().2;
        experiments.extend(options.tally.experiments().into_iter().filter(|(_, t)| t.verified > 0).map(|(k, _)| k));
    }
    if verified != records {
        return Err(RunnerError::Verify { chosen: sample.len(), records, verified });
    }
    Ok(Verified { chosen: sample.len(), records, experiments: experiments.len(), total })
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
