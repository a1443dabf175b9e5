//! One of N machines' share of a command: the plan dealt by expected cost
//! ([`rlfd_harness::deal`]), and a shard runs only its own trials that are
//! not stored yet, planning each (chapter, run point) once and running a
//! batch's set-up only when one of its own trials must be computed. It
//! writes trial records and no report.

use std::collections::BTreeSet;
use std::fmt;
use std::path::PathBuf;
use std::str::FromStr;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use rlfd_harness::ResultStore;

use crate::Machine;
use crate::error::RunnerError;
use crate::plan::{Plan, Trial};

/// Shard `index` of `count` (1 ≤ index ≤ count).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// From 1.
    pub index: u32,
    /// How many shards share the run.
    pub count: u32,
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let form = "expected I/N, shard I of N (e.g. 2/8)";
        let (i, n) = s.split_once('/').ok_or_else(|| form.to_string())?;
        let number = |t: &str| t.parse::<u32>().map_err(|_| format!("\"{t}\" is not a whole number; {form}"));
        let (index, count) = (number(i)?, number(n)?);
        if count == 0 {
            return Err("a run needs at least 1 shard".into());
        }
        if index == 0 || index > count {
            return Err(format!("shard {index} does not exist: shards are numbered 1 to {count}"));
        }
        Ok(Shard { index, count })
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// A shard's share of a plan.
pub struct Share {
    /// Its trials (indices into the plan's).
    pub mine: BTreeSet<usize>,
    /// Those not stored yet.
    pub waiting: BTreeSet<usize>,
    /// Its expected CPU seconds, and the plan's.
    pub seconds: (f64, f64),
}

impl Share {
    /// `shard`'s share of `plan`, against the store at `results`.
    pub fn of(plan: &Plan<'_>, shard: Shard, store: &ResultStore) -> Share {
        let deal = plan.deal(shard.count);
        let mine: BTreeSet<usize> = (0..plan.trials.len()).filter(|&i| deal[i] == shard.index - 1).collect();
        let stored = plan.stored(store);
        let waiting = mine.iter().copied().filter(|&i| !stored[i]).collect();
        let seconds = (mine.iter().map(|&i| plan.trials[i].seconds).sum(), plan.trials.iter().map(|t| t.seconds).sum());
        Share { mine, waiting, seconds }
    }
}

/// What a shard's run did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShardRun {
    /// Trials computed.
    pub computed: usize,
    /// Per chapter (in running order): trials computed and their CPU
    /// seconds (set-ups included), as the workers timed them.
    pub chapters: Vec<(&'static str, usize, f64)>,
    /// Per chapter, the trials computed at its headline point and sweeps
    /// (what a report's own run reads; the rest are the robustness run's).
    pub headline: Vec<(&'static str, usize)>,
    /// Records that could not be read and were recomputed, with why.
    pub replaced: Vec<(PathBuf, String)>,
}

/// Runs `share` of `plan` through one pool of `machine.jobs` workers
/// ([`rlfd_harness::pipeline`]): every (chapter, run point) with trials
/// waiting is planned and staged first, then their trials run in the
/// plan's order with no pause between batches. `log` hears one line per
/// (chapter, run point) as its last trial is stored.
pub fn run(
    plan: &Plan<'_>,
    share: &Share,
    shard: Shard,
    machine: &Machine,
    log: &mut (dyn FnMut(String) + Send),
) -> Result<ShardRun, RunnerError> {
    let selection = plan.selection;
    let options = machine.options(rlfd_harness::RunMode::Run);
    let assigned: BTreeSet<PathBuf> = share.mine.iter().map(|&i| plan.trials[i].path.clone()).collect();
    // The (chapter, run point) pairs with trials waiting, in running order.
    let mut todo: Vec<(usize, &crate::command::RunPoint)> = Vec::new();
    for g in &plan.groups {
        if g.trials.iter().any(|i| share.waiting.contains(i)) && !todo.contains(&(g.chapter, &g.point)) {
            todo.push((g.chapter, &g.point));
        }
    }
    let named = selection.named();
    let given = selection.inputs();
    let mut planned = Vec::with_capacity(todo.len());
    for &(c, point) in &todo {
        let chapter = selection.chapters[c];
        planned.push(chapter.plan(&given, &point.experiments(&named), &point.context(selection.command.scale))?);
    }
    let mut claimed = BTreeSet::new();
    let mut staged = Vec::new();
    // For each staged batch, its (chapter, run point); and per point, its batches left.
    let mut owner = Vec::new();
    for (p, plan) in planned.iter().enumerate() {
        for batch in plan.batches() {
            staged.push(batch.stage(&options, &assigned, &mut claimed));
            owner.push(p);
        }
    }
    let points_left: Vec<AtomicUsize> = (0..todo.len())
        .map(|p| AtomicUsize::new(owner.iter().zip(&staged).filter(|(o, s)| **o == p && s.waiting() > 0).count()))
        .collect();
    // Per point: its trials to compute, and its trials in all.
    let of_point = |p: usize, count: &dyn Fn(&dyn rlfd_harness::AnyBatch, usize) -> usize| -> usize {
        planned[p].batches().into_iter().enumerate().map(|(i, b)| count(b, i)).sum()
    };
    let first_of: Vec<usize> = (0..todo.len()).map(|p| owner.iter().position(|&o| o == p).unwrap_or(0)).collect();
    let computed: Vec<usize> =
        (0..todo.len()).map(|p| of_point(p, &|_, i| staged[first_of[p] + i].waiting())).collect();
    let total: Vec<usize> = (0..todo.len()).map(|p| of_point(p, &|b, _| b.len())).collect();
    let started = std::time::Instant::now();
    let log = Mutex::new(log);
    let finished = |b: usize| {
        let p = owner[b];
        if points_left[p].fetch_sub(1, Ordering::AcqRel) == 1 {
            let (c, point) = todo[p];
            // A whole run (1/1) says it as `reproduce` always has.
            let prefix = if shard.count == 1 { String::new() } else { format!("shard {shard}: ") };
            let sweep = if matches!(point.role, crate::command::Role::Sweep { .. }) { " (sweep)" } else { "" };
            let line = format!(
                "{prefix}{}: seed {}, reading {}{sweep}: {} trials computed, {} reused ({:.1} s into the run)",
                selection.chapters[c].slug(),
                point.seed,
                point.reading,
                computed[p],
                total[p] - computed[p],
                started.elapsed().as_secs_f64()
            );
            (log.lock().expect("no worker panics while logging"))(line);
        }
    };
    let piped = rlfd_harness::run_pipelined(&staged, machine.jobs, &finished)?;
    drop(staged);
    let mut headline: Vec<(&'static str, usize)> = Vec::new();
    for (p, &(c, point)) in todo.iter().enumerate() {
        if point.role.is_robustness() {
            continue;
        }
        let slug = selection.chapters[c].slug();
        match headline.iter_mut().find(|h| h.0 == slug) {
            Some(h) => h.1 += computed[p],
            None => headline.push((slug, computed[p])),
        }
    }
    let mut run = ShardRun { computed: piped.computed(), chapters: piped.chapters, headline, replaced: Vec::new() };
    for t in options.tally.experiments().into_values() {
        run.replaced.extend(t.replaced);
    }
    let stored = plan.stored(&options.store);
    let left: Vec<&Trial> = share.mine.iter().filter(|&&i| !stored[i]).map(|&i| &plan.trials[i]).collect();
    if let Some(first) = left.first() {
        return Err(RunnerError::ShardLeft {
            shard: shard.to_string(),
            left: left.len(),
            first: format!("{} ({})", first.key, first.path.display()),
        });
    }
    Ok(run)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_refuse_in_one_sentence() {
        assert_eq!("2/8".parse::<Shard>(), Ok(Shard { index: 2, count: 8 }));
        assert_eq!("1/1".parse::<Shard>().unwrap().to_string(), "1/1");
        assert_eq!("0/4".parse::<Shard>().unwrap_err(), "shard 0 does not exist: shards are numbered 1 to 4");
        assert_eq!("5/4".parse::<Shard>().unwrap_err(), "shard 5 does not exist: shards are numbered 1 to 4");
        assert_eq!("x".parse::<Shard>().unwrap_err(), "expected I/N, shard I of N (e.g. 2/8)");
        assert_eq!(
            "x/4".parse::<Shard>().unwrap_err(),
            "\"x\" is not a whole number; expected I/N, shard I of N (e.g. 2/8)"
        );
        assert_eq!("1/0".parse::<Shard>().unwrap_err(), "a run needs at least 1 shard");
    }
}
