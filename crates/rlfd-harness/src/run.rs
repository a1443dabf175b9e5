//! Running a batch's trials: in parallel, reusing finished ones, collected
//! in order.
//!
//! [`RunMode`] says what a run may do with the store: compute what has no
//! record of its identity ([`RunMode::Run`]), only read records
//! ([`RunMode::Load`], optionally of other code versions, as `report`
//! does), or recompute a sample and compare it byte for byte with the store
//! ([`RunMode::Verify`]). Every outcome is counted in the options' [`Tally`].

use std::collections::BTreeSet;

use rayon::prelude::*;

use crate::batch::{Batch, TrialRunner};
use crate::error::HarnessError;
use crate::progress::Progress;
use crate::seed::TrialKey;
use crate::store::{FORMAT, Lookup, ResultStore, StoredTrial};
use crate::tally::Tally;

/// What a run may do with the store.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RunMode {
    /// Compute every trial that has no readable record of its identity
    /// (an unreadable one is replaced, and counted in the tally).
    Run,
    /// Only read records; a missing one is an error. With `any_version`, a
    /// trial without a record of its identity is read from a record of the
    /// same parameters made by other code (the newest behaviour version),
    /// and counted as such.
    Load {
        /// Accept records of other code versions.
        any_version: bool,
    },
    /// Recompute the trials in `sample` and require the bytes of their
    /// records; read the others as [`RunMode::Load`] does (current identity).
    Verify {
        /// The trials to recompute.
        sample: BTreeSet<TrialKey>,
    },
}

/// How to run.
#[derive(Clone, Debug)]
pub struct RunOptions {
    /// Worker threads (≥ 1).
    pub jobs: usize,
    /// Show a progress bar (only ever on a terminal).
    pub progress: bool,
    /// Where finished trials are stored.
    pub store: ResultStore,
    /// What the run may do.
    pub mode: RunMode,
    /// Where the outcomes are counted.
    pub tally: Tally,
}

impl RunOptions {
    /// Options that compute what is missing, with a fresh tally.
    pub fn new(store: ResultStore, jobs: usize) -> Self {
        RunOptions { jobs, progress: false, store, mode: RunMode::Run, tally: Tally::new() }
    }

    /// The same options in another mode, with a fresh tally.
    pub fn with_mode(&self, mode: RunMode) -> Self {
        RunOptions { mode, tally: Tally::new(), ..self.clone() }
    }
}

/// Where one result came from.
enum Source {
    Computed,
    Reused,
    Verified,
    Other { behaviour: u32, build: String },
}

/// Runs `batch`'s trials with `setup`, storing each as it finishes;
/// returns one result per trial, in order.
pub(crate) fn execute<R: TrialRunner>(
    batch: &Batch<R>,
    options: &RunOptions,
    setup: &R::Setup,
) -> Result<Vec<R::Result>, R::Error> {
    let store = &options.store;
    let trials = batch.trials();
    let label = format!("{} {}", batch.chapter, batch.experiment);
    let progress = Progress::new(&label, trials.len() as u64, options.progress);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.max(1))
        .build()
        .map_err(|e| HarnessError::Pool { jobs: options.jobs, message: e.to_string() })?;
    let outcomes: Vec<Result<(R::Result, Source), HarnessError>> = pool.install(|| {
        trials
            .par_iter()
            .map(|trial| {
                let path = batch.path(store, trial);
                let outcome = match (&options.mode, store.lookup::<R::Result>(&path, &trial.id)) {
                    (RunMode::Verify { sample }, Lookup::Fresh(_)) if sample.contains(&trial.key) => {
                        let stored = std::fs::read(&path).map_err(|source| HarnessError::Io {
                            action: "cannot read",
                            path: path.clone(),
                            source,
                        })?;
                        let recomputed = computed_record(batch, setup, trial);
                        if ResultStore::encode(&recomputed)? != stored {
                            return Err(HarnessError::Diverges { trial: trial.key.to_string(), path });
                        }
                        (recomputed.result, Source::Verified)
                    }
                    (_, Lookup::Fresh(result)) => (result, Source::Reused),
                    (RunMode::Run, found @ (Lookup::Unreadable { .. } | Lookup::Missing)) => {
                        (compute_and_store(batch, options, setup, trial, found)?, Source::Computed)
                    }
                    (_, Lookup::Unreadable { path, reason }) => {
                        return Err(HarnessError::Unreadable { trial: trial.key.to_string(), path, reason });
                    }
                    (mode, Lookup::Missing) => {
                        let others = ResultStore::other_versions::<R::Result>(&path, &trial.key, trial.seed, &trial.id);
                        let any_version = matches!(mode, RunMode::Load { any_version: true });
                        match others.into_iter().next().filter(|_| any_version) {
                            Some(o) => (
                                o.stored.result,
                                Source::Other { behaviour: o.stored.behaviour, build: o.stored.build },
                            ),
                            None => {
                                let others = ResultStore::other_versions::<serde::de::IgnoredAny>(
                                    &path, &trial.key, trial.seed, &trial.id,
                                )
                                .len();
                                options.tally.update(&trial.key, batch.behaviour, |t| t.missing += 1);
                                return Err(HarnessError::Missing { trial: trial.key.to_string(), path, others });
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
    let mut results = Vec::with_capacity(trials.len());
    for (trial, outcome) in trials.iter().zip(outcomes) {
        let (result, source) = outcome?;
        let key = &trial.key;
        options.tally.update(key, batch.behaviour, |t| {
            t.keys.push(key.clone());
            match source {
                Source::Computed => t.computed += 1,
                Source::Reused => t.reused += 1,
                Source::Verified => t.verified += 1,
                Source::Other { behaviour, build } => *t.other_versions.entry((behaviour, build)).or_default() += 1,
            }
        });
        results.push(result);
    }
    Ok(results)
}

/// Runs `trial` of `batch` and makes its record (the current identity).
fn computed_record<R: TrialRunner>(
    batch: &Batch<R>,
    setup: &R::Setup,
    trial: &crate::batch::Planned<R::Params>,
) -> StoredTrial<R::Result> {
    StoredTrial {
        format: FORMAT,
        key: trial.key.clone(),
        seed: trial.seed,
        behaviour: batch.behaviour,
        build: crate::BUILD_IDENTITY.to_string(),
        id: trial.id.clone(),
        result: batch.runner().run(setup, &trial.params, trial.seed),
    }
}

/// Computes `trial` of `batch` and stores its record, where the store held
/// `found` for it (no record, or an unreadable one, which is replaced and
/// counted in the tally).
pub(crate) fn compute_and_store<R: TrialRunner, T>(
    batch: &Batch<R>,
    options: &RunOptions,
    setup: &R::Setup,
    trial: &crate::batch::Planned<R::Params>,
    found: Lookup<T>,
) -> Result<R::Result, HarnessError> {
    let store = &options.store;
    let path = batch.path(store, trial);
    let stored = computed_record(batch, setup, trial);
    match found {
        Lookup::Unreadable { path: bad, reason } => {
            store.replace(&path, &stored)?;
            options.tally.update(&trial.key, batch.behaviour, |t| t.replaced.push((bad, reason)));
        }
        _ => store.save(&path, &stored)?,
    }
    Ok(stored.result)
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use serde::Serialize;

    use super::*;
    use crate::batch::{AnyBatch, RunContext};
    use crate::scale::Scale;

    #[derive(Clone, Copy)]
    struct Exp(u32);
    impl crate::ExperimentId for Exp {
        fn name(self) -> &'static str {
            "exp"
        }
        fn behaviour(self) -> u32 {
            self.0
        }
    }

    /// A runner whose set-up is its offset and whose trial adds it to the
    /// parameter; `setups` counts the set-ups run.
    #[derive(Serialize)]
    struct Adder {
        offset: u64,
        #[serde(skip)]
        setups: std::sync::atomic::AtomicUsize,
    }

    impl TrialRunner for Adder {
        type Setup = u64;
        type Params = u64;
        type Result = Vec<u64>;
        type Error = HarnessError;
        fn setup(&self) -> Result<u64, HarnessError> {
            self.setups.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
            // An offset this large stands for a set-up that cannot be made.
            if self.offset == u64::MAX {
                return Err(HarnessError::Pool { jobs: 0, message: "no set-up for this offset".into() });
            }
            Ok(self.offset)
        }
        fn run(&self, setup: &u64, params: &u64, seed: u64) -> Vec<u64> {
            vec![setup + params, seed % 1000]
        }
    }

    fn adder(offset: u64) -> Adder {
        Adder { offset, setups: Default::default() }
    }

    fn batch(behaviour: u32, offset: u64, n: u32) -> Batch<Adder> {
        let mut b = Batch::new(&RunContext::new(5, Scale::Quick), "ch", Exp(behaviour), adder(offset));
        for t in 0..n {
            b.trial("c", t, u64::from(t) * 10);
        }
        b
    }

    fn temp(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rlfd-run-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    fn options(dir: &PathBuf, jobs: usize) -> RunOptions {
        RunOptions::new(ResultStore::new(dir), jobs)
    }

    #[test]
    fn results_come_back_in_order_are_reused_and_identities_follow_parameters() {
        let dir = temp("reuse");
        let o = options(&dir, 2);
        let first = batch(1, 7, 20).execute(&o).unwrap();
        assert_eq!(first.results[3][0], 37);
        let again = batch(1, 7, 20);
        let out = again.execute(&options(&dir, 1)).unwrap();
        assert_eq!(out.results, first.results);
        let t = o.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!((t.computed, t.behaviour), (20, 1));
        assert_eq!(t.keys, again.trials().iter().map(|s| s.key.clone()).collect::<Vec<_>>());
        // The same trial with other parameters (another reading) is another
        // identity beside it, with the same seed; other set-up determinants too.
        let mut moved = Batch::new(&RunContext::new(5, Scale::Quick), "ch", Exp(1), adder(7));
        moved.trial("c", 3, 31);
        let b = batch(1, 7, 20);
        assert_eq!(moved.trials()[0].seed, b.trials()[3].seed);
        assert_ne!(moved.trials()[0].id.params, b.trials()[3].id.params);
        assert_eq!(moved.trials()[0].id.code, b.trials()[3].id.code);
        assert_ne!(batch(1, 8, 20).trials()[3].id.params, b.trials()[3].id.params);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn versions_sit_side_by_side_and_load_says_which_it_read() {
        let dir = temp("versions");
        let o = options(&dir, 2);
        let v1 = batch(1, 0, 3).execute(&o).unwrap();
        // A new behaviour version is a new code digest: computed, beside the old.
        let v2 = batch(2, 0, 3);
        assert_ne!(v2.trials()[0].id.code, batch(1, 0, 3).trials()[0].id.code);
        v2.execute(&o).unwrap();
        let files = std::fs::read_dir(dir.join("quick/seed-5/ch/exp/c")).unwrap().count();
        assert_eq!(files, 6);
        // Load of a version with no records: strict fails naming the trial and the others.
        let strict = o.with_mode(RunMode::Load { any_version: false });
        let e = batch(3, 0, 3).execute(&strict).err().unwrap();
        assert!(e.to_string().contains("no stored result for ch/exp/c/trial 0"), "{e}");
        assert!(e.to_string().contains("2 record(s) of other behaviour versions"), "{e}");
        // Any version: the newest (2) is read and tallied as such.
        let any = o.with_mode(RunMode::Load { any_version: true });
        let loaded = batch(3, 0, 3).execute(&any).unwrap();
        assert_eq!(loaded.results, v1.results);
        let t = any.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!(t.other_versions.keys().map(|(b, _)| *b).collect::<Vec<_>>(), vec![2]);
        // Records of other parameters are never another version.
        let e = batch(3, 9, 3).execute(&any).err().unwrap();
        assert!(e.to_string().contains("no stored result"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn verify_recomputes_the_sample_and_names_a_tampered_record() {
        let dir = temp("verify");
        let o = options(&dir, 2);
        let b = batch(1, 0, 4);
        b.execute(&o).unwrap();
        let sample: BTreeSet<TrialKey> = [b.trials()[1].key.clone(), b.trials()[3].key.clone()].into();
        let v = o.with_mode(RunMode::Verify { sample: sample.clone() });
        b.execute(&v).unwrap();
        let t = v.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!((t.verified, t.reused), (2, 2));
        let path = b.path(&o.store, &b.trials()[3]);
        let text = std::fs::read_to_string(&path).unwrap().replace("[30,", "[31,");
        std::fs::write(&path, text).unwrap();
        let e = b.execute(&o.with_mode(RunMode::Verify { sample })).err().unwrap();
        assert!(e.to_string().starts_with("verification failed: ch/exp/c/trial 3 recomputed differs"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_corrupt_record_is_recomputed_and_reported() {
        let dir = temp("corrupt");
        let o = options(&dir, 1);
        let b = batch(1, 0, 2);
        let first = b.execute(&o).unwrap();
        let path = b.path(&o.store, &b.trials()[0]);
        std::fs::write(&path, b"{\"format\":3,").unwrap();
        let e = b.execute(&o.with_mode(RunMode::Load { any_version: false })).err().unwrap();
        assert!(e.to_string().contains("stored record of ch/exp/c/trial 0 cannot be read"), "{e}");
        let again = o.with_mode(RunMode::Run);
        assert_eq!(b.execute(&again).unwrap().results, first.results);
        let t = again.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        assert_eq!((t.computed, t.replaced.len()), (1, 1));
        assert_eq!(t.replaced[0].0, path);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// Every file below `dir`, with its bytes, by path below `dir`.
    fn files(dir: &std::path::Path) -> Vec<(PathBuf, Vec<u8>)> {
        let mut out = Vec::new();
        let mut todo = vec![dir.to_path_buf()];
        while let Some(d) = todo.pop() {
            for e in std::fs::read_dir(&d).unwrap() {
                let p = e.unwrap().path();
                if p.is_dir() {
                    todo.push(p);
                } else {
                    out.push((p.strip_prefix(dir).unwrap().to_path_buf(), std::fs::read(&p).unwrap()));
                }
            }
        }
        out.sort();
        out
    }

    /// Computes (or reuses) the trials of `b` whose record paths are in
    /// `assigned`, as a shard does: staged, then through the pipeline.
    fn run_share(b: &Batch<Adder>, o: &RunOptions, assigned: &BTreeSet<PathBuf>) {
        let staged = [b.stage(o, assigned, &mut BTreeSet::new())];
        crate::run_pipelined(&staged, o.jobs, &|_| {}).unwrap();
    }

    fn setups(b: &Batch<Adder>) -> usize {
        b.runner().setups.load(std::sync::atomic::Ordering::SeqCst)
    }

    #[test]
    fn a_pipelined_run_writes_what_batch_by_batch_runs_write() {
        // Four batches: the second is the first again (its trials share the
        // first's records), the third has one trial stored already, the
        // fourth is another behaviour version.
        let batches = || [batch(1, 3, 5), batch(1, 3, 5), batch(1, 4, 4), batch(2, 3, 2)];
        let reference = temp("pipe-reference");
        for b in batches() {
            b.execute(&options(&reference, 1)).unwrap();
        }
        for jobs in [1, 3] {
            let dir = temp(&format!("pipe-{jobs}"));
            let o = options(&dir, jobs);
            let bs = batches();
            run_share(&bs[2], &o, &[bs[2].path(&o.store, &bs[2].trials()[0])].into());
            let o = o.with_mode(RunMode::Run);
            let all: BTreeSet<PathBuf> = bs.iter().flat_map(|b| b.planned(&o.store)).map(|t| t.path).collect();
            let mut claimed = BTreeSet::new();
            let staged: Vec<Box<dyn crate::Staged + '_>> = bs.iter().map(|b| b.stage(&o, &all, &mut claimed)).collect();
            // Staging runs nothing; a shared trial waits once, a stored one not at all.
            assert_eq!(staged.iter().map(|s| s.waiting()).collect::<Vec<_>>(), [5, 0, 3, 2]);
            assert_eq!(bs.iter().map(setups).collect::<Vec<_>>(), [0, 0, 1, 0]);
            let heard = std::sync::Mutex::new(Vec::new());
            let ran = crate::run_pipelined(&staged, jobs, &|b| heard.lock().unwrap().push(b)).unwrap();
            drop(staged);
            let mut heard = heard.into_inner().unwrap();
            heard.sort();
            assert_eq!(heard, [0, 2, 3], "each batch with trials to compute is finished once");
            let chapters = ran.chapters();
            assert_eq!((chapters.len(), chapters[0].0, chapters[0].1), (1, "ch", 10));
            assert!(chapters[0].2 >= 0.0);
            let experiments: Vec<_> = ran.experiments.iter().map(|m| (m.chapter, m.experiment, m.trials)).collect();
            assert_eq!(experiments, [("ch", "exp", 10)]);
            // One set-up per batch that computed (the third's second one now).
            assert_eq!(bs.iter().map(setups).collect::<Vec<_>>(), [1, 0, 2, 1]);
            assert_eq!(o.tally.totals(), (10, 1, 0, 0));
            assert_eq!(files(&dir), files(&reference), "{jobs} workers");
            std::fs::remove_dir_all(&dir).unwrap();
        }
        std::fs::remove_dir_all(&reference).unwrap();
    }

    #[test]
    fn a_pipelined_run_stops_at_a_set_up_that_fails_and_names_the_batch() {
        let dir = temp("pipe-fails");
        let o = options(&dir, 2);
        let bs = [batch(1, 3, 2), batch(1, u64::MAX, 3)];
        let all: BTreeSet<PathBuf> = bs.iter().flat_map(|b| b.planned(&o.store)).map(|t| t.path).collect();
        let mut claimed = BTreeSet::new();
        let staged: Vec<Box<dyn crate::Staged + '_>> = bs.iter().map(|b| b.stage(&o, &all, &mut claimed)).collect();
        let e = crate::run_pipelined(&staged, 2, &|_| {}).unwrap_err();
        assert_eq!(e.to_string(), "ch exp: set-up failed: cannot start 0 worker threads: no set-up for this offset");
        // The first batch's trials that ran are stored; the failing batch wrote nothing.
        assert!(bs[1].planned(&o.store).iter().all(|t| !t.path.exists()));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_shard_runs_only_its_trials_and_its_set_up_only_when_needed() {
        let dir = temp("shard");
        let o = options(&dir, 2);
        let b = batch(1, 0, 6);
        // Planning runs nothing: the trials' paths come from the value alone.
        let planned = b.planned(&o.store);
        assert_eq!(planned.len(), 6);
        assert_eq!(planned[4].path, b.path(&o.store, &b.trials()[4]));
        assert_eq!(b.runner().setups.load(std::sync::atomic::Ordering::SeqCst), 0);
        assert!(!dir.exists(), "planning writes nothing");
        // A shard of trials 1 and 4 computes those two only.
        let assigned: BTreeSet<PathBuf> = [1, 4].iter().map(|&i| planned[i].path.clone()).collect();
        run_share(&b, &o, &assigned);
        assert_eq!(o.tally.totals(), (2, 0, 0, 0));
        for (i, t) in planned.iter().enumerate() {
            assert_eq!(t.path.exists(), i == 1 || i == 4, "trial {i}");
        }
        assert_eq!(b.runner().setups.load(std::sync::atomic::Ordering::SeqCst), 1);
        // Again: both stored, so no set-up and nothing computed.
        let again = o.with_mode(RunMode::Run);
        run_share(&b, &again, &assigned);
        assert_eq!(again.tally.totals(), (0, 2, 0, 0));
        assert_eq!(b.runner().setups.load(std::sync::atomic::Ordering::SeqCst), 1);
        // The rest, as a plain run, gives what an unsharded run gives.
        let all = b.execute(&o.with_mode(RunMode::Run)).unwrap();
        let fresh = temp("shard-fresh");
        assert_eq!(batch(1, 0, 6).execute(&options(&fresh, 1)).unwrap().results, all.results);
        std::fs::remove_dir_all(&dir).unwrap();
        std::fs::remove_dir_all(&fresh).unwrap();
    }
}
