//! Many batches' trials through one pool of workers.
//!
//! [`Batch::execute`](crate::Batch::execute) runs one batch at a time: its
//! set-up, then its trials in parallel, and only then the next batch. On a
//! small machine that idles a core at every batch's end, while the last
//! trial runs alone, and during every set-up (chapter 6's inputs, about two
//! seconds of RIPPER on one core): a robustness run has hundreds of batches
//! of trials that take 10–60 s each. A pipelined run stages every batch
//! first ([`AnyBatch::stage`](crate::AnyBatch::stage): which of its trials
//! still have to be computed, nothing run), then hands the staged trials,
//! in the batches' order, to `jobs` workers that take the next one as soon
//! as they are free. A batch's set-up is made by the first worker that
//! needs it (the others wait for it only when they need the same one) and
//! dropped when the batch's last trial is done, so at most a few set-ups
//! are alive at once.
//!
//! Each trial's record is a function of its runner, set-up, parameters and
//! seed alone, so the records are the same bytes whatever the order and
//! the number of workers; only the tally's order of arrival changes, and
//! the tally keeps counts.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

use crate::batch::BatchError;

/// One batch's trials that a pipelined run computes (see the module docs).
pub trait Staged: Sync {
    /// The chapter's slug.
    fn chapter(&self) -> &'static str;
    /// The experiment (as its trials' keys name it).
    fn experiment(&self) -> &'static str;
    /// How many of its trials wait to be computed.
    fn waiting(&self) -> usize;
    /// Computes and stores waiting trial `n` (0 ≤ n < [`Staged::waiting`]),
    /// making the set-up first if no trial of the batch has yet.
    fn compute(&self, n: usize) -> Result<(), BatchError>;
}

/// What a pipelined run computed of one experiment, as the workers timed it.
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// The chapter's slug.
    pub chapter: &'static str,
    /// The experiment.
    pub experiment: &'static str,
    /// Trials computed.
    pub trials: usize,
    /// Seconds the workers spent on them, set-ups included (CPU seconds
    /// when the machine has a core per worker).
    pub seconds: f64,
}

/// What a pipelined run did, per experiment in the order first met.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PipelineRun {
    /// Per (chapter, experiment) with trials computed.
    pub experiments: Vec<Measured>,
}

impl PipelineRun {
    /// Trials computed in all.
    pub fn computed(&self) -> usize {
        self.experiments.iter().map(|m| m.trials).sum()
    }

    /// Per chapter, in the order first met: (chapter, trials computed, their seconds).
    pub fn chapters(&self) -> Vec<(&'static str, usize, f64)> {
        let mut out: Vec<(&'static str, usize, f64)> = Vec::new();
        for m in &self.experiments {
            match out.iter_mut().find(|c| c.0 == m.chapter) {
                Some(c) => (c.1, c.2) = (c.1 + m.trials, c.2 + m.seconds),
                None => out.push((m.chapter, m.trials, m.seconds)),
            }
        }
        out
    }
}

/// Computes every waiting trial of `staged` with `jobs` workers, in the
/// batches' order; `finished(b)` is called (from a worker) when batch `b`'s
/// last trial is stored. Stops at the first error (the trials already
/// stored stay stored) and returns it.
pub fn run_pipelined(
    staged: &[Box<dyn Staged + '_>],
    jobs: usize,
    finished: &(dyn Fn(usize) + Sync),
) -> Result<PipelineRun, BatchError> {
    let units: Vec<(usize, usize)> =
        staged.iter().enumerate().flat_map(|(b, s)| (0..s.waiting()).map(move |n| (b, n))).collect();
    let left: Vec<AtomicUsize> = staged.iter().map(|s| AtomicUsize::new(s.waiting())).collect();
    let mut experiments: Vec<(&'static str, &'static str)> = Vec::new();
    let mut measured_as = Vec::with_capacity(staged.len());
    for s in staged {
        let id = (s.chapter(), s.experiment());
        let at = experiments.iter().position(|&e| e == id).unwrap_or_else(|| {
            experiments.push(id);
            experiments.len() - 1
        });
        measured_as.push(at);
    }
    let tally: Mutex<Vec<(usize, f64)>> = Mutex::new(vec![(0, 0.0); experiments.len()]);
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let error: Mutex<Option<BatchError>> = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..jobs.max(1).min(units.len().max(1)) {
            scope.spawn(|| {
                while !stop.load(Ordering::Relaxed) {
                    let Some(&(b, n)) = units.get(next.fetch_add(1, Ordering::Relaxed)) else { break };
                    let started = Instant::now();
                    if let Err(e) = staged[b].compute(n) {
                        stop.store(true, Ordering::Relaxed);
                        error.lock().expect("no worker panics holding the error").get_or_insert(e);
                        break;
                    }
                    let seconds = started.elapsed().as_secs_f64();
                    {
                        let mut tally = tally.lock().expect("no worker panics holding the times");
                        let e = &mut tally[measured_as[b]];
                        (e.0, e.1) = (e.0 + 1, e.1 + seconds);
                    }
                    if left[b].fetch_sub(1, Ordering::AcqRel) == 1 {
                        finished(b);
                    }
                }
            });
        }
    });
    if let Some(e) = error.into_inner().expect("no worker panics holding the error") {
        return Err(e);
    }
    let tally = tally.into_inner().expect("no worker panics holding the times");
    let experiments = experiments
        .into_iter()
        .zip(tally)
        .filter(|(_, (trials, _))| *trials > 0)
        .map(|((chapter, experiment), (trials, seconds))| Measured { chapter, experiment, trials, seconds })
        .collect();
    Ok(PipelineRun { experiments })
}
