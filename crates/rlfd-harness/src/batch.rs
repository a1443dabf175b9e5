//! An experiment's trials as a value: a [`Batch`] is planned without running
//! anything (its set-up's determinants and one [`Planned`] trial each: key,
//! seed, parameters, identity), and the harness runs, loads, verifies,
//! plans and shards it as operations on that value.
//!
//! A chapter says what an experiment computes with a [`TrialRunner`]: a
//! serialisable value holding what determines the experiment's set-up (the
//! master seed its demonstrations are drawn from, a demonstrator's
//! parameters, the digest of a user's file), a `setup` that makes what the
//! trials share (demonstrations, learned rules, IRL weights: possibly
//! expensive, so run only when a trial has to be computed or a report needs
//! it), and a `run` for one trial. The harness computes every identity from
//! the serialised runner and the trial's serialised parameters ([`RecordId`]);
//! no chapter assembles a fingerprint by hand, and a reading changes exactly
//! the trials whose parameters (or set-up) it changes.
//!
//! [`AnyBatch`] is the same batch with its types erased, for what needs only
//! its trials' keys, seeds and record paths (planning a sharded run, dealing
//! trials to shards, naming what a store lacks) or stages a share of its
//! trials for the [`crate::pipeline`].

use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::error::HarnessError;
use crate::experiment::ExperimentId;
use crate::fingerprint::Fingerprint;
use crate::pipeline::Staged;
use crate::readings::Reading;
use crate::run::{RunOptions, compute_and_store, execute};
use crate::scale::Scale;
use crate::seed::{TrialKey, derive_seed};
use crate::store::{Lookup, RecordId, ResultStore};

/// Where a chapter plans its experiments: the master seed, the scale and
/// the reading of the thesis's open choices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RunContext {
    /// The master seed (every trial's seed derives from it).
    pub master_seed: u64,
    /// The scale.
    pub scale: Scale,
    /// The reading the trials follow.
    pub reading: Reading,
}

impl RunContext {
    /// The default reading at `master_seed` and `scale`.
    pub fn new(master_seed: u64, scale: Scale) -> Self {
        RunContext { master_seed, scale, reading: Reading::defaults() }
    }

    /// The same context under `reading`.
    pub fn under(&self, reading: Reading) -> Self {
        RunContext { reading, ..self.clone() }
    }
}

/// What an experiment computes: its set-up and one trial.
pub trait TrialRunner: Serialize + Sync {
    /// What the trials share, made once per batch by [`TrialRunner::setup`].
    type Setup: Send + Sync;
    /// One trial's parameters (serialised into its identity).
    type Params: Serialize + Sync;
    /// One trial's result (stored as JSON).
    type Result: Serialize + DeserializeOwned + Send;
    /// What can stop the set-up (and, through `From`, the harness).
    type Error: From<HarnessError> + Send;

    /// Makes what the trials share. Deterministic: a function of the
    /// runner's serialised fields alone.
    fn setup(&self) -> Result<Self::Setup, Self::Error>;

    /// Runs one trial (infallible once the parameters are checked).
    fn run(&self, setup: &Self::Setup, params: &Self::Params, seed: u64) -> Self::Result;
}

/// One planned trial.
#[derive(Clone, Debug)]
pub struct Planned<P> {
    /// Its key.
    pub key: TrialKey,
    /// Its seed.
    pub seed: u64,
    /// Its identity.
    pub id: RecordId,
    /// Its parameters.
    pub params: P,
}

/// One trial as planning lists it (types erased).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlannedTrial {
    /// Its key.
    pub key: TrialKey,
    /// Its seed.
    pub seed: u64,
    /// Its identity.
    pub id: RecordId,
    /// The file its record has (or will have).
    pub path: PathBuf,
}

/// An experiment's trials at one master seed, scale and reading.
pub struct Batch<R: TrialRunner> {
    /// The chapter's slug.
    pub chapter: &'static str,
    /// The experiment as its trials' keys name it (the store's folder).
    pub experiment: &'static str,
    /// The experiment's declared behaviour version.
    pub behaviour: u32,
    /// The scale.
    pub scale: Scale,
    /// The master seed.
    pub master_seed: u64,
    runner: R,
    setup_digest: u64,
    code: String,
    trials: Vec<Planned<R::Params>>,
}

impl<R: TrialRunner> Batch<R> {
    /// An empty batch of `experiment` in `chapter` under `ctx`, whose set-up
    /// and trials `runner` computes.
    pub fn new(ctx: &RunContext, chapter: &'static str, experiment: impl ExperimentId, runner: R) -> Self {
        let runner_json = serde_json::to_vec(&runner).expect("a trial runner serialises");
        let code = Fingerprint::new()
            .str("rlfd-code/v1")
            .str(crate::BUILD_IDENTITY)
            .u64(u64::from(experiment.behaviour()))
            .hex();
        Batch {
            chapter,
            experiment: experiment.name(),
            behaviour: experiment.behaviour(),
            scale: ctx.scale,
            master_seed: ctx.master_seed,
            setup_digest: Fingerprint::new().str("rlfd-setup/v1").bytes(&runner_json).value(),
            runner,
            code,
            trials: Vec::new(),
        }
    }

    /// Adds trial `trial` of `condition` with `params`.
    pub fn trial(&mut self, condition: &str, trial: u32, params: R::Params) {
        let key = TrialKey::new(self.chapter, self.experiment, condition, trial);
        let params_json = serde_json::to_vec(&params).expect("trial parameters serialise");
        let id = RecordId {
            params: Fingerprint::new().str("rlfd-params/v1").u64(self.setup_digest).bytes(&params_json).hex(),
            code: self.code.clone(),
        };
        self.trials.push(Planned { seed: derive_seed(self.master_seed, &key), key, id, params });
    }

    /// The runner.
    pub fn runner(&self) -> &R {
        &self.runner
    }

    /// The planned trials, in order.
    pub fn trials(&self) -> &[Planned<R::Params>] {
        &self.trials
    }

    /// The record path of `trial` in `store`.
    pub fn path(&self, store: &ResultStore, trial: &Planned<R::Params>) -> PathBuf {
        store.path(self.scale, self.master_seed, &trial.key, &trial.id)
    }

    /// Runs the set-up, then computes (or loads, or verifies, as
    /// `options.mode` says) every trial, and returns the set-up and the
    /// results in trial order.
    pub fn execute(&self, options: &RunOptions) -> Result<Executed<R>, R::Error> {
        let setup = self.runner.setup()?;
        let results = execute(self, options, &setup)?;
        Ok(Executed { setup, results })
    }
}

/// A batch's set-up and its results, in trial order.
pub struct Executed<R: TrialRunner> {
    /// What the set-up made.
    pub setup: R::Setup,
    /// One result per planned trial, in order.
    pub results: Vec<R::Result>,
}

/// A batch with its types erased.
pub trait AnyBatch: Sync {
    /// The chapter's slug.
    fn chapter(&self) -> &'static str;
    /// The experiment (as its trials' keys name it).
    fn experiment(&self) -> &'static str;
    /// Its trials, with their record paths in `store`.
    fn planned(&self, store: &ResultStore) -> Vec<PlannedTrial>;
    /// How many trials it has.
    fn len(&self) -> usize;
    /// Whether it has none.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Stages the trials whose record paths are in `assigned` for a
    /// pipelined run ([`crate::pipeline`]): those stored are counted as
    /// reused; those not, and not in `claimed` (a trial that two run points
    /// share is computed once), wait and are added to `claimed`. Runs
    /// nothing.
    fn stage<'s>(
        &'s self,
        options: &RunOptions,
        assigned: &BTreeSet<PathBuf>,
        claimed: &mut BTreeSet<PathBuf>,
    ) -> Box<dyn Staged + 's>;
}

/// Why a shard's share of a batch could not be run.
#[derive(Debug, thiserror::Error)]
#[error("{chapter} {experiment}: {message}")]
pub struct BatchError {
    /// The chapter.
    pub chapter: &'static str,
    /// The experiment.
    pub experiment: &'static str,
    /// What went wrong, in one line.
    pub message: String,
}

impl<R> AnyBatch for Batch<R>
where
    R: TrialRunner,
    R::Error: std::fmt::Display,
{
    fn chapter(&self) -> &'static str {
        self.chapter
    }

    fn experiment(&self) -> &'static str {
        self.experiment
    }

    fn len(&self) -> usize {
        self.trials.len()
    }

    fn planned(&self, store: &ResultStore) -> Vec<PlannedTrial> {
        self.trials
            .iter()
            .map(|t| PlannedTrial { key: t.key.clone(), seed: t.seed, id: t.id.clone(), path: self.path(store, t) })
            .collect()
    }

    fn stage<'s>(
        &'s self,
        options: &RunOptions,
        assigned: &BTreeSet<PathBuf>,
        claimed: &mut BTreeSet<PathBuf>,
    ) -> Box<dyn Staged + 's> {
        let mut waiting = Vec::new();
        for (i, t) in self.trials.iter().enumerate() {
            let path = self.path(&options.store, t);
            if !assigned.contains(&path) {
                continue;
            }
            if matches!(options.store.lookup::<serde::de::IgnoredAny>(&path, &t.id), Lookup::Fresh(_)) {
                options.tally.update(&t.key, self.behaviour, |e| {
                    e.keys.push(t.key.clone());
                    e.reused += 1;
                });
            } else if claimed.insert(path) {
                waiting.push(i);
            }
        }
        Box::new(StagedBatch {
            batch: self,
            options: options.clone(),
            left: AtomicUsize::new(waiting.len()),
            waiting,
            setup: Mutex::new(SetupSlot::NotMade),
        })
    }
}

/// A batch's set-up in a pipelined run.
enum SetupSlot<S> {
    NotMade,
    Made(Arc<S>),
    Failed(String),
    Dropped,
}

/// A batch staged for a pipelined run.
struct StagedBatch<'a, R: TrialRunner> {
    batch: &'a Batch<R>,
    options: RunOptions,
    waiting: Vec<usize>,
    left: AtomicUsize,
    setup: Mutex<SetupSlot<R::Setup>>,
}

impl<R> StagedBatch<'_, R>
where
    R: TrialRunner,
    R::Error: std::fmt::Display,
{
    fn error(&self, message: String) -> BatchError {
        BatchError { chapter: self.batch.chapter, experiment: self.batch.experiment, message }
    }

    /// The set-up, made now if no trial has made it.
    fn setup(&self) -> Result<Arc<R::Setup>, BatchError> {
        let mut slot = self.setup.lock().expect("no worker panics holding a set-up");
        match &*slot {
            SetupSlot::Made(s) => Ok(Arc::clone(s)),
            SetupSlot::Failed(m) => Err(self.error(m.clone())),
            SetupSlot::Dropped => unreachable!("a set-up is dropped after the batch's last trial"),
            SetupSlot::NotMade => match self.batch.runner.setup() {
                Ok(s) => {
                    let s = Arc::new(s);
                    *slot = SetupSlot::Made(Arc::clone(&s));
                    Ok(s)
                }
                Err(e) => {
                    let m = format!("set-up failed: {e}");
                    *slot = SetupSlot::Failed(m.clone());
                    Err(self.error(m))
                }
            },
        }
    }
}

impl<R> Staged for StagedBatch<'_, R>
where
    R: TrialRunner,
    R::Error: std::fmt::Display,
{
    fn chapter(&self) -> &'static str {
        self.batch.chapter
    }

    fn experiment(&self) -> &'static str {
        self.batch.experiment
    }

    fn waiting(&self) -> usize {
        self.waiting.len()
    }

    fn compute(&self, n: usize) -> Result<(), BatchError> {
        let setup = self.setup()?;
        let trial = &self.batch.trials[self.waiting[n]];
        let path = self.batch.path(&self.options.store, trial);
        match self.options.store.lookup::<serde::de::IgnoredAny>(&path, &trial.id) {
            // Stored meanwhile (by another process sharing the store).
            Lookup::Fresh(_) => self.options.tally.update(&trial.key, self.batch.behaviour, |e| {
                e.keys.push(trial.key.clone());
                e.reused += 1;
            }),
            found => {
                compute_and_store(self.batch, &self.options, &setup, trial, found)
                    .map_err(|e| self.error(e.to_string()))?;
                self.options.tally.update(&trial.key, self.batch.behaviour, |e| {
                    e.keys.push(trial.key.clone());
                    e.computed += 1;
                });
            }
        }
        drop(setup);
        if self.left.fetch_sub(1, Ordering::AcqRel) == 1 {
            *self.setup.lock().expect("no worker panics holding a set-up") = SetupSlot::Dropped;
        }
        Ok(())
    }
}
