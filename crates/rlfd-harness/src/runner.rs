//! Running trials: in parallel, reusing finished ones, collected in order.

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;
use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::error::HarnessError;
use crate::progress::Progress;
use crate::scale::Scale;
use crate::seed::TrialKey;
use crate::store::{Lookup, ResultStore, StoredTrial};

/// Fault injection for the resume tests: when this environment variable holds
/// a number `n`, the process aborts (as if killed) right after it has stored
/// its `n`-th newly computed trial. Never set it otherwise.
pub const ABORT_AFTER_ENV: &str = "RLFD_ABORT_AFTER_TRIALS";

static COMPUTED_IN_PROCESS: AtomicUsize = AtomicUsize::new(0);

/// How to run.
#[derive(Clone, Debug)]
pub struct RunOptions {
    /// Worker threads (≥ 1).
    pub jobs: usize,
    /// Show a progress bar (only ever on a terminal).
    pub progress: bool,
    /// Where finished trials are stored.
    pub store: ResultStore,
    /// The master seed (part of the store's path).
    pub master_seed: u64,
    /// The scale (part of the store's path).
    pub scale: Scale,
    /// Only load stored results; a missing or stale one is an error.
    pub load_only: bool,
}

/// One trial to run.
#[derive(Clone, Debug)]
pub struct TrialSpec<P> {
    /// Its identity.
    pub key: TrialKey,
    /// Its seed (see [`crate::derive_seed`]).
    pub seed: u64,
    /// Fingerprint of everything that determines its result.
    pub fingerprint: String,
    /// Its parameters.
    pub params: P,
}

/// The results of a batch, in the order of the specs.
#[derive(Clone, Debug)]
pub struct TrialOutcomes<T> {
    /// One result per spec, in order.
    pub results: Vec<T>,
    /// How many were computed now.
    pub computed: usize,
    /// How many came from the store.
    pub reused: usize,
}

/// Runs every trial that has no fresh stored result, stores each as it
/// finishes, and returns all results in the order of `specs`.
pub fn run_trials<P, T, F>(
    options: &RunOptions,
    label: &str,
    specs: &[TrialSpec<P>],
    run: F,
) -> Result<TrialOutcomes<T>, HarnessError>
where
    P: Sync,
    T: Serialize + DeserializeOwned + Send,
    F: Fn(&TrialSpec<P>) -> T + Sync,
{
    let abort_after: Option<usize> = std::env::var(ABORT_AFTER_ENV).ok().and_then(|v| v.parse().ok());
    let progress = Progress::new(label, specs.len() as u64, options.progress);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| HarnessError::Pool { jobs: options.jobs, message: e.to_string() })?;
    let outcomes: Vec<Result<(T, bool), HarnessError>> = pool.install(|| {
        specs
            .par_iter()
            .map(|spec| {
                let path = options.store.path(options.scale, options.master_seed, &spec.key);
                let reused = match options.store.lookup::<T>(&path, &spec.fingerprint) {
                    Lookup::Fresh(result) => Some(result),
                    Lookup::Stale { found } if options.load_only => {
                        return Err(HarnessError::Stale { path, found, expected: spec.fingerprint.clone() });
                    }
                    Lookup::Missing if options.load_only => {
                        return Err(HarnessError::Missing { trial: spec.key.to_string(), path });
                    }
                    _ => None,
                };
                let outcome = match reused {
                    Some(result) => (result, true),
                    None => {
                        let result = run(spec);
                        let stored = StoredTrial {
                            format: 1,
                            key: spec.key.clone(),
                            seed: spec.seed,
                            fingerprint: spec.fingerprint.clone(),
                            result,
                        };
                        options.store.save(&path, &stored)?;
                        let n = COMPUTED_IN_PROCESS.fetch_add(1, Ordering::SeqCst) + 1;
                        if abort_after.is_some_and(|limit| n >= limit) {
                            std::process::abort();
                        }
                        (stored.result, false)
                    }
                };
                progress.inc();
                Ok(outcome)
            })
            .collect()
    });
    progress.finish();
    let mut results = Vec::with_capacity(specs.len());
    let (mut computed, mut reused) = (0, 0);
    for o in outcomes {
        let (r, was_reused) = o?;
        if was_reused {
            reused += 1
        } else {
            computed += 1
        }
        results.push(r);
    }
    Ok(TrialOutcomes { results, computed, reused })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::seed::derive_seed;
    use std::path::PathBuf;

    fn options(dir: &PathBuf, jobs: usize) -> RunOptions {
        RunOptions {
            jobs,
            progress: false,
            store: ResultStore::new(dir),
            master_seed: 5,
            scale: Scale::Quick,
            load_only: false,
        }
    }

    fn specs(n: u32, fingerprint: &str) -> Vec<TrialSpec<u64>> {
        (0..n)
            .map(|t| {
                let key = TrialKey::new("ch", "exp", "c", t);
                TrialSpec {
                    seed: derive_seed(5, &key),
                    key,
                    fingerprint: fingerprint.into(),
                    params: u64::from(t) * 10,
                }
            })
            .collect()
    }

    #[test]
    fn results_come_back_in_order_and_are_reused() {
        let dir = std::env::temp_dir().join(format!("rlfd-runner-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let s = specs(20, "f1");
        let work = |spec: &TrialSpec<u64>| -> Vec<u64> { vec![spec.params, spec.seed % 1000] };
        let first = run_trials(&options(&dir, 2), "test", &s, work).unwrap();
        assert_eq!(first.computed, 20);
        assert_eq!(first.results[7][0], 70);
        let again = run_trials(&options(&dir, 1), "test", &s, |_: &TrialSpec<u64>| -> Vec<u64> {
            panic!("must not recompute")
        })
        .unwrap();
        assert_eq!((again.computed, again.reused), (0, 20));
        assert_eq!(again.results, first.results);
        // A changed fingerprint is never reused.
        let changed = run_trials(&options(&dir, 2), "test", &specs(20, "f2"), work).unwrap();
        assert_eq!(changed.computed, 20);
        // Load-only with a missing trial names it.
        let mut lo = options(&dir, 1);
        lo.load_only = true;
        let e = run_trials(&lo, "test", &specs(21, "f2"), work).unwrap_err();
        assert!(e.to_string().contains("no stored result for ch/exp/c/trial 20"), "{e}");
        let e = run_trials(&lo, "test", &specs(3, "f3"), work).unwrap_err();
        assert!(e.to_string().contains("made by other code or parameters"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
