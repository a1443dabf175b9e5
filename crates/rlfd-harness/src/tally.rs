//! The tally of a run: per experiment, how many trials were computed, reused,
//! verified, or read from records of another behaviour version, and every
//! trial key seen. One [`Tally`] travels in [`crate::RunOptions`], so the
//! counts are kept in one place (the runner) and read once (by the caller).

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use crate::seed::TrialKey;

/// What happened to one experiment's trials.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ExperimentTally {
    /// The behaviour version the current code declares.
    pub behaviour: u32,
    /// Trials computed now.
    pub computed: usize,
    /// Trials read from records of the current version.
    pub reused: usize,
    /// Trials recomputed and found byte-identical to their records.
    pub verified: usize,
    /// Trials read from records of another behaviour version or build:
    /// (behaviour version, build identity) → count.
    pub other_versions: BTreeMap<(u32, String), usize>,
    /// Every trial of the experiment, in the order the chapter planned them.
    pub keys: Vec<TrialKey>,
    /// Records that could not be read and were recomputed, with why.
    pub replaced: Vec<(PathBuf, String)>,
    /// Trials a load found no record of (a load stops at the first batch
    /// that lacks some).
    pub missing: usize,
}

/// A shared, thread-safe tally (cheap to clone: clones share the counts).
#[derive(Clone, Debug, Default)]
pub struct Tally(Arc<Mutex<BTreeMap<(String, String), ExperimentTally>>>);

impl Tally {
    /// An empty tally.
    pub fn new() -> Self {
        Self::default()
    }

    pub(crate) fn update(&self, key: &TrialKey, behaviour: u32, f: impl FnOnce(&mut ExperimentTally)) {
        let mut map = self.0.lock().expect("no thread panics while holding the tally");
        let entry = map.entry((key.chapter.clone(), key.experiment.clone())).or_default();
        entry.behaviour = behaviour;
        f(entry);
    }

    /// Per (chapter, experiment), what happened, in name order.
    pub fn experiments(&self) -> BTreeMap<(String, String), ExperimentTally> {
        self.0.lock().expect("no thread panics while holding the tally").clone()
    }

    /// Totals over every experiment: (computed, reused, verified, other versions).
    pub fn totals(&self) -> (usize, usize, usize, usize) {
        self.experiments().values().fold((0, 0, 0, 0), |(c, r, v, o), e| {
            (c + e.computed, r + e.reused, v + e.verified, o + e.other_versions.values().sum::<usize>())
        })
    }
}
