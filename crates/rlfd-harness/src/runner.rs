//! Running trials: in parallel, reusing finished ones, collected in order.
//!
//! [`RunMode`] says what a batch may do: compute what has no record of its
//! identity ([`RunMode::Run`]), only read records ([`RunMode::Load`],
//! optionally of other behaviour versions, as `report` does), or recompute a
//! sample and compare it byte for byte with the store ([`RunMode::Verify`]),
//! list the trials without running any ([`RunMode::Plan`]), or run only the
//! trials a shard was given ([`RunMode::Shard`]). The last two return no
//! results: the batch ends with [`HarnessError::Withheld`] once its trials
//! are listed (and, in a shard, stored), which stops the chapter there, so a
//! planning or shard run drives one experiment at a time.
//! Every outcome is counted in the options' [`Tally`].

use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use rayon::prelude::*;
use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::error::HarnessError;
use crate::progress::Progress;
use crate::readings::Reading;
use crate::scale::Scale;
use crate::seed::TrialKey;
use crate::store::{FORMAT, Lookup, ResultStore, StoredTrial};
use crate::tally::Tally;

/// Fault injection for the resume tests: when this environment variable holds
/// a number `n`, the process aborts (as if killed) right after it has stored
/// its `n`-th newly computed trial. Never set it otherwise.
pub const ABORT_AFTER_ENV: &str = "RLFD_ABORT_AFTER_TRIALS";

static COMPUTED_IN_PROCESS: AtomicUsize = AtomicUsize::new(0);

/// What a run may do with the store.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RunMode {
    /// Compute every trial that has no readable record of its identity
    /// (an unreadable one is replaced, and counted in the tally).
    Run,
    /// Only read records; a missing one is an error. With `any_version`, a
    /// trial without a record of its identity is read from a record of
    /// another behaviour version or build (the newest), and counted as such.
    Load {
        /// Accept records of other identities.
        any_version: bool,
    },
    /// Recompute the trials in `sample` and require the bytes of their
    /// records; read the others as [`RunMode::Load`] does (current identity).
    ///
    /// With `other_builds`, a sampled trial with no record of the current
    /// identity is checked against a record of the same behaviour version
    /// made by another build (another rustc or dependency closure): its
    /// bytes must equal the recomputed record's with the build and
    /// fingerprint fields set to the stored ones. That tells a reviewer
    /// whether records a report marks as "not current" only because the
    /// build changed still reproduce. The others are then read as
    /// `Load { any_version: true }` reads them.
    Verify {
        /// The trials to recompute.
        sample: BTreeSet<TrialKey>,
        /// Also check records of other builds (same behaviour version).
        other_builds: bool,
    },
    /// Run nothing: list each batch's trials in `batches` and end the batch
    /// with [`HarnessError::Withheld`].
    Plan {
        /// Where the batches are listed.
        batches: Batches,
    },
    /// Compute (or reuse) only the trials whose record paths are in
    /// `assigned`, list the batch in `batches`, and end the batch with
    /// [`HarnessError::Withheld`] (a shard's results are read back by `report`).
    Shard {
        /// The record paths of the shard's trials.
        assigned: Arc<BTreeSet<PathBuf>>,
        /// Where the batches are listed.
        batches: Batches,
    },
}

/// One trial as a planning run lists it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlannedTrial {
    /// Its key.
    pub key: TrialKey,
    /// Its seed.
    pub seed: u64,
    /// Its identity.
    pub fingerprint: String,
    /// The file its record has (or will have).
    pub path: PathBuf,
}

/// One `run_trials` call of a planning or shard run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Batch {
    /// The batch's label (as the progress bar shows it).
    pub label: String,
    /// Its trials, in the chapter's order.
    pub trials: Vec<PlannedTrial>,
}

/// The batches a planning or shard run met, in order (clones share them).
#[derive(Clone, Debug, Default)]
pub struct Batches(Arc<Mutex<Vec<Batch>>>);

impl Batches {
    /// An empty list.
    pub fn new() -> Self {
        Self::default()
    }

    /// How many batches were met so far.
    pub fn len(&self) -> usize {
        self.0.lock().expect("no thread panics while holding the batches").len()
    }

    /// Whether none was met.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The batches, in the order they were met.
    pub fn take(&self) -> Vec<Batch> {
        std::mem::take(&mut *self.0.lock().expect("no thread panics while holding the batches"))
    }

    fn push(&self, batch: Batch) {
        self.0.lock().expect("no thread panics while holding the batches").push(batch);
    }
}

/// Two lists are equal when they are the same list.
impl PartialEq for Batches {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for Batches {}

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
    /// What the run may do.
    pub mode: RunMode,
    /// The reading of the thesis's open choices the trials follow.
    pub reading: Reading,
    /// Where the outcomes are counted.
    pub tally: Tally,
}

impl RunOptions {
    /// Options that compute what is missing, with a fresh tally.
    pub fn new(store: ResultStore, master_seed: u64, scale: Scale, jobs: usize) -> Self {
        RunOptions {
            jobs,
            progress: false,
            store,
            master_seed,
            scale,
            mode: RunMode::Run,
            reading: Reading::defaults(),
            tally: Tally::new(),
        }
    }

    /// The same options in another mode, with a fresh tally.
    pub fn with_mode(&self, mode: RunMode) -> Self {
        RunOptions { mode, tally: Tally::new(), ..self.clone() }
    }
}

/// One trial to run (made by [`crate::TrialPlan::spec`]).
#[derive(Clone, Debug)]
pub struct TrialSpec<P> {
    /// Its key.
    pub key: TrialKey,
    /// Its seed (see [`crate::derive_seed`]).
    pub seed: u64,
    /// Its experiment's behaviour version.
    pub behaviour: u32,
    /// Its chapter's build identity.
    pub build: &'static str,
    /// The reading it follows (only the axes that change its experiment).
    pub reading: Reading,
    /// Its identity: everything that determines its result.
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

/// Where one result came from.
enum Source {
    Computed,
    Reused,
    Verified,
    Other { behaviour: u32, build: String },
}

/// Runs every trial that has no record of its identity, stores each as it
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
    let store = &options.store;
    let planned = || Batch {
        label: label.to_string(),
        trials: specs
            .iter()
            .map(|spec| PlannedTrial {
                key: spec.key.clone(),
                seed: spec.seed,
                fingerprint: spec.fingerprint.clone(),
                path: store.path(options.scale, options.master_seed, &spec.reading, &spec.key, &spec.fingerprint),
            })
            .collect(),
    };
    let (specs, batches): (Vec<&TrialSpec<P>>, Option<&Batches>) = match &options.mode {
        RunMode::Plan { batches } => {
            batches.push(planned());
            return Err(HarnessError::Withheld { label: label.to_string() });
        }
        RunMode::Shard { assigned, batches } => {
            let mine = specs
                .iter()
                .filter(|spec| {
                    assigned.contains(&store.path(
                        options.scale,
                        options.master_seed,
                        &spec.reading,
                        &spec.key,
                        &spec.fingerprint,
                    ))
                })
                .collect();
            (mine, Some(batches))
        }
        _ => (specs.iter().collect(), None),
    };
    let abort_after: Option<usize> = std::env::var(ABORT_AFTER_ENV).ok().and_then(|v| v.parse().ok());
    let progress = Progress::new(label, specs.len() as u64, options.progress);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| HarnessError::Pool { jobs: options.jobs, message: e.to_string() })?;
    let outcomes: Vec<Result<(T, Source), HarnessError>> = pool.install(|| {
        specs
            .par_iter()
            .map(|spec| {
                let path = store.path(options.scale, options.master_seed, &spec.reading, &spec.key, &spec.fingerprint);
                let record = |result: T| StoredTrial {
                    format: FORMAT,
                    key: spec.key.clone(),
                    seed: spec.seed,
                    behaviour: spec.behaviour,
                    build: spec.build.to_string(),
                    fingerprint: spec.fingerprint.clone(),
                    result,
                };
                let lookup = store.lookup::<T>(&path, &spec.fingerprint);
                // The same trial's records made by other identities.
                let other_versions = || {
                    store.other_versions::<T>(
                        options.scale,
                        options.master_seed,
                        &spec.reading,
                        &spec.key,
                        spec.seed,
                        &spec.fingerprint,
                    )
                };
                let outcome = match (&options.mode, lookup) {
                    (RunMode::Verify { sample, .. }, Lookup::Fresh(_)) if sample.contains(&spec.key) => {
                        let stored = std::fs::read(&path).map_err(|source| HarnessError::Io {
                            action: "cannot read",
                            path: path.clone(),
                            source,
                        })?;
                        let recomputed = record(run(spec));
                        if ResultStore::encode(&recomputed)? != stored {
                            return Err(HarnessError::Diverges { trial: spec.key.to_string(), path });
                        }
                        (recomputed.result, Source::Verified)
                    }
                    (_, Lookup::Fresh(result)) => (result, Source::Reused),
                    (RunMode::Run | RunMode::Shard { .. }, Lookup::Unreadable { path: bad, reason }) => {
                        let stored = record(run(spec));
                        store.replace(&path, &stored)?;
                        options.tally.update(&spec.key, spec.behaviour, |t| t.replaced.push((bad, reason)));
                        (stored.result, Source::Computed)
                    }
                    (RunMode::Run | RunMode::Shard { .. }, Lookup::Missing) => {
                        let stored = record(run(spec));
                        store.save(&path, &stored)?;
                        let n = COMPUTED_IN_PROCESS.fetch_add(1, Ordering::SeqCst) + 1;
                        if abort_after.is_some_and(|limit| n >= limit) {
                            std::process::abort();
                        }
                        (stored.result, Source::Computed)
                    }
                    (_, Lookup::Unreadable { path, reason }) => {
                        return Err(HarnessError::Unreadable { trial: spec.key.to_string(), path, reason });
                    }
                    (RunMode::Verify { sample, other_builds: true }, Lookup::Missing)
                        if sample.contains(&spec.key)
                            && let Some(o) =
                                other_versions().into_iter().find(|o| o.stored.behaviour == spec.behaviour) =>
                    {
                        let stored = std::fs::read(&o.path).map_err(|source| HarnessError::Io {
                            action: "cannot read",
                            path: o.path.clone(),
                            source,
                        })?;
                        let mut recomputed = record(run(spec));
                        recomputed.build = o.stored.build.clone();
                        recomputed.fingerprint = o.stored.fingerprint.clone();
                        if ResultStore::encode(&recomputed)? != stored {
                            return Err(HarnessError::Diverges { trial: spec.key.to_string(), path: o.path });
                        }
                        (recomputed.result, Source::Verified)
                    }
                    (mode, Lookup::Missing) => {
                        // A sampled trial is only ever checked, never read from
                        // a record of another behaviour version.
                        let any_version = match mode {
                            RunMode::Load { any_version } => *any_version,
                            RunMode::Verify { sample, other_builds } => *other_builds && !sample.contains(&spec.key),
                            _ => false,
                        };
                        let other = if any_version { other_versions().into_iter().next() } else { None };
                        match other {
                            Some(o) => (
                                o.stored.result,
                                Source::Other { behaviour: o.stored.behaviour, build: o.stored.build },
                            ),
                            None => {
                                let others = other_versions().len();
                                options.tally.update(&spec.key, spec.behaviour, |t| t.missing += 1);
                                return Err(HarnessError::Missing { trial: spec.key.to_string(), path, others });
                            }
                        }
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
    for (spec, o) in specs.iter().copied().zip(outcomes) {
        let (r, source) = o?;
        if matches!(source, Source::Computed) {
            computed += 1;
        } else {
            reused += 1;
        }
        options.tally.update(&spec.key, spec.behaviour, |t| {
            t.keys.push(spec.key.clone());
            match source {
                Source::Computed => t.computed += 1,
                Source::Reused => t.reused += 1,
                Source::Verified => t.verified += 1,
                Source::Other { behaviour, build } => *t.other_versions.entry((behaviour, build)).or_default() += 1,
            }
        });
        results.push(r);
    }
    if let Some(batches) = batches {
        batches.push(planned());
        return Err(HarnessError::Withheld { label: label.to_string() });
    }
    Ok(TrialOutcomes { results, computed, reused })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::ExperimentId;
    use crate::fingerprint::Fingerprint;
    use crate::plan::{ChapterId, TrialPlan};
    use std::path::PathBuf;

    #[derive(Clone, Copy)]
    struct Exp(u32);
    impl ExperimentId for Exp {
        fn name(self) -> &'static str {
            "exp"
        }
        fn behaviour(self) -> u32 {
            self.0
        }
    }

    const CH: ChapterId = ChapterId { slug: "ch", build: "test build" };

    fn options(dir: &PathBuf, jobs: usize) -> RunOptions {
        RunOptions::new(ResultStore::new(dir), 5, Scale::Quick, jobs)
    }

    fn specs(options: &RunOptions, n: u32, behaviour: u32, param: u64) -> Vec<TrialSpec<u64>> {
        let plan = TrialPlan::new(options, CH, Exp(behaviour));
        (0..n).map(|t| plan.spec("c", t, Fingerprint::new().u64(param), u64::from(t) * param)).collect()
    }

    fn work(spec: &TrialSpec<u64>) -> Vec<u64> {
        vec![spec.params, spec.seed % 1000]
    }

    fn temp(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rlfd-runner-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn results_come_back_in_order_and_are_reused() {
        let dir = temp("reuse");
        let o = options(&dir, 2);
        let s = specs(&o, 20, 1, 10);
        let first = run_trials(&o, "test", &s, work).unwrap();
        assert_eq!(first.computed, 20);
        assert_eq!(first.results[7][0], 70);
        let again = run_trials(&options(&dir, 1), "test", &s, |_: &TrialSpec<u64>| -> Vec<u64> {
            panic!("must not recompute")
        })
        .unwrap();
        assert_eq!((again.computed, again.reused), (0, 20));
        assert_eq!(again.results, first.results);
        // The tally saw every key in plan order.
        let t = o.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!((t.computed, t.behaviour), (20, 1));
        assert_eq!(t.keys, s.iter().map(|s| s.key.clone()).collect::<Vec<_>>());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn versions_sit_side_by_side_and_load_says_which_it_read() {
        let dir = temp("versions");
        let o = options(&dir, 2);
        run_trials(&o, "test", &specs(&o, 3, 1, 10), work).unwrap();
        // A new behaviour version is a new identity: computed, beside the old.
        let v2 = run_trials(&o, "test", &specs(&o, 3, 2, 10), |s| vec![s.params + 1]).unwrap();
        assert_eq!(v2.computed, 3);
        let files = std::fs::read_dir(dir.join("quick/seed-5/ch/exp/c")).unwrap().count();
        assert_eq!(files, 6);
        // Both are still there: the old version reruns nothing.
        assert_eq!(run_trials(&o, "test", &specs(&o, 3, 1, 10), work).unwrap().reused, 3);
        // Load of a version with no records: strict fails naming the trial and the others.
        let strict = o.with_mode(RunMode::Load { any_version: false });
        let e = run_trials(&strict, "test", &specs(&strict, 3, 3, 10), work).unwrap_err();
        assert!(e.to_string().contains("no stored result for ch/exp/c/trial 0"), "{e}");
        assert!(e.to_string().contains("2 record(s) of other behaviour versions"), "{e}");
        assert_eq!(strict.tally.experiments()[&("ch".to_string(), "exp".to_string())].missing, 3);
        // Any version: the newest (2) is read and tallied as such.
        let any = o.with_mode(RunMode::Load { any_version: true });
        let loaded = run_trials(&any, "test", &specs(&any, 3, 3, 10), work).unwrap();
        assert_eq!(loaded.results, v2.results);
        let t = any.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!(t.other_versions.into_iter().collect::<Vec<_>>(), vec![((2, "test build".to_string()), 3)]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn verify_recomputes_the_sample_and_names_a_tampered_record() {
        let dir = temp("verify");
        let o = options(&dir, 2);
        let s = specs(&o, 4, 1, 10);
        run_trials(&o, "test", &s, work).unwrap();
        let sample: BTreeSet<TrialKey> = [s[1].key.clone(), s[3].key.clone()].into();
        let v = o.with_mode(RunMode::Verify { sample: sample.clone(), other_builds: false });
        let out = run_trials(&v, "test", &s, work).unwrap();
        let t = v.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!((t.verified, t.reused), (2, 2));
        assert_eq!(out.results[3], vec![30, s[3].seed % 1000]);
        // Alter one sampled record by hand: verification names it.
        let path = o.store.path(Scale::Quick, 5, &Reading::defaults(), &s[3].key, &s[3].fingerprint);
        let text = std::fs::read_to_string(&path).unwrap().replace("[30,", "[31,");
        std::fs::write(&path, text).unwrap();
        let v = o.with_mode(RunMode::Verify { sample, other_builds: false });
        let e = run_trials(&v, "test", &s, work).unwrap_err();
        assert!(e.to_string().starts_with("verification failed: ch/exp/c/trial 3 recomputed differs"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn verify_checks_records_of_another_build_of_the_same_behaviour() {
        let dir = temp("other-builds");
        let o = options(&dir, 2);
        // Records made by another build (e.g. before a dependency changed).
        let old = ChapterId { slug: "ch", build: "older build" };
        let built = |options: &RunOptions, build: ChapterId, behaviour: u32| -> Vec<TrialSpec<u64>> {
            let plan = TrialPlan::new(options, build, Exp(behaviour));
            (0..3).map(|t| plan.spec("c", t, Fingerprint::new().u64(10), u64::from(t) * 10)).collect()
        };
        run_trials(&o, "test", &built(&o, old, 1), work).unwrap();
        let sample: BTreeSet<TrialKey> = [TrialKey::new("ch", "exp", "c", 1)].into();
        // Plain verify wants records of the current build.
        let strict = o.with_mode(RunMode::Verify { sample: sample.clone(), other_builds: false });
        assert!(run_trials(&strict, "test", &built(&strict, CH, 1), work).is_err());
        // With other builds: trial 1 recomputed against the old record, the others read from it.
        let v = o.with_mode(RunMode::Verify { sample: sample.clone(), other_builds: true });
        let out = run_trials(&v, "test", &built(&v, CH, 1), work).unwrap();
        let t = v.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!(t.verified, 1);
        assert_eq!(t.other_versions.values().sum::<usize>(), 2);
        assert_eq!(out.results[1], vec![10, out.results[1][1]]);
        // A different computation under the same version is caught, naming the old record.
        let v = o.with_mode(RunMode::Verify { sample: sample.clone(), other_builds: true });
        let e = run_trials(&v, "test", &built(&v, CH, 1), |s| vec![s.params + 1]).unwrap_err();
        assert!(e.to_string().starts_with("verification failed: ch/exp/c/trial 1 recomputed differs"), "{e}");
        // A record of another behaviour version is not a check of this one.
        let v = o.with_mode(RunMode::Verify { sample, other_builds: true });
        let e = run_trials(&v, "test", &built(&v, CH, 2), work).unwrap_err();
        assert!(e.to_string().contains("no stored result for ch/exp/c/trial 1"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_corrupt_record_is_recomputed_and_reported() {
        let dir = temp("corrupt");
        let o = options(&dir, 1);
        let s = specs(&o, 2, 1, 10);
        let first = run_trials(&o, "test", &s, work).unwrap();
        let path = o.store.path(Scale::Quick, 5, &Reading::defaults(), &s[0].key, &s[0].fingerprint);
        std::fs::write(&path, b"{\"format\":2,").unwrap();
        // Load refuses it by name.
        let load = o.with_mode(RunMode::Load { any_version: false });
        let e = run_trials(&load, "test", &s, work).unwrap_err();
        assert!(e.to_string().contains("stored record of ch/exp/c/trial 0 cannot be read"), "{e}");
        // Run replaces it and says so.
        let again = o.with_mode(RunMode::Run);
        let out = run_trials(&again, "test", &s, work).unwrap();
        assert_eq!((out.computed, out.results.clone()), (1, first.results));
        let t = again.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!(t.replaced.len(), 1);
        assert_eq!(t.replaced[0].0, path);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_plan_lists_the_batch_and_a_shard_runs_only_its_trials() {
        let dir = temp("shard");
        let o = options(&dir, 2);
        let s = specs(&o, 6, 1, 10);
        // Planning runs nothing and lists every trial with its record's path.
        let batches = Batches::new();
        let plan = o.with_mode(RunMode::Plan { batches: batches.clone() });
        let e = run_trials(&plan, "test", &s, |_: &TrialSpec<u64>| -> Vec<u64> { panic!("planning runs nothing") })
            .unwrap_err();
        assert!(matches!(e, HarnessError::Withheld { .. }), "{e}");
        let listed = batches.take();
        assert_eq!(listed.len(), 1);
        assert_eq!(listed[0].trials.len(), 6);
        assert_eq!(listed[0].trials[4].key, s[4].key);
        assert_eq!(
            listed[0].trials[4].path,
            o.store.path(Scale::Quick, 5, &Reading::defaults(), &s[4].key, &s[4].fingerprint)
        );
        assert!(!dir.exists(), "planning writes nothing");
        // A shard of trials 1 and 4 computes those two only.
        let assigned: BTreeSet<PathBuf> = [1, 4].iter().map(|&i| listed[0].trials[i].path.clone()).collect();
        let shard = o.with_mode(RunMode::Shard { assigned: Arc::new(assigned), batches: batches.clone() });
        let e = run_trials(&shard, "test", &s, work).unwrap_err();
        assert!(matches!(e, HarnessError::Withheld { .. }), "{e}");
        assert_eq!(batches.len(), 1);
        assert_eq!(shard.tally.totals(), (2, 0, 0, 0));
        for (i, t) in listed[0].trials.iter().enumerate() {
            assert_eq!(t.path.exists(), i == 1 || i == 4, "trial {i}");
        }
        // Run again: both are reused, nothing recomputed.
        let again = o.with_mode(RunMode::Shard { assigned: shard_paths(&listed[0], &[1, 4]), batches: Batches::new() });
        let _ = run_trials(&again, "test", &s, |_: &TrialSpec<u64>| -> Vec<u64> { panic!("stored already") });
        assert_eq!(again.tally.totals(), (0, 2, 0, 0));
        // The rest, as a plain run, gives what an unsharded run gives.
        let all = run_trials(&o, "test", &s, work).unwrap();
        assert_eq!((all.computed, all.reused), (4, 2));
        let fresh = temp("shard-fresh");
        assert_eq!(
            run_trials(&options(&fresh, 1), "test", &specs(&options(&fresh, 1), 6, 1, 10), work).unwrap().results,
            all.results
        );
        std::fs::remove_dir_all(&dir).unwrap();
        std::fs::remove_dir_all(&fresh).unwrap();
    }

    fn shard_paths(batch: &Batch, trials: &[usize]) -> Arc<BTreeSet<PathBuf>> {
        Arc::new(trials.iter().map(|&i| batch.trials[i].path.clone()).collect())
    }
}
