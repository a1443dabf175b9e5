//! One of N machines' share of a command: the plan dealt by expected cost
//! ([`rlfd_harness::deal`]), and a shard runs only its own trials that are
//! not stored yet, planning each (chapter, run point) once and running a
//! batch's set-up only when one of its own trials must be computed. It
//! writes trial records and no report.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::path::PathBuf;
use std::str::FromStr;

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
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ShardRun {
    /// Trials computed.
    pub computed: usize,
    /// Records that could not be read and were recomputed, with why.
    pub replaced: Vec<(PathBuf, String)>,
}

/// Runs `share` of `plan`; `log` hears one line per (chapter, run point)
/// that had trials to compute.
pub fn run(
    plan: &Plan<'_>,
    share: &Share,
    shard: Shard,
    machine: &Machine,
    log: &mut dyn FnMut(String),
) -> Result<ShardRun, RunnerError> {
    let selection = plan.selection;
    let options = machine.options(rlfd_harness::RunMode::Run);
    let assigned: BTreeSet<PathBuf> = share.mine.iter().map(|&i| plan.trials[i].path.clone()).collect();
    // The (chapter, run point) pairs with trials waiting, in running order.
    let mut todo: Vec<(usize, usize)> = Vec::new();
    let mut points: BTreeMap<(usize, usize), &crate::command::RunPoint> = BTreeMap::new();
    let mut point_ids: Vec<(usize, &crate::command::RunPoint)> = Vec::new();
    for g in &plan.groups {
        let p = match point_ids.iter().position(|(c, p)| *c == g.chapter && **p == g.point) {
            Some(i) => i,
            None => {
                point_ids.push((g.chapter, &g.point));
                point_ids.len() - 1
            }
        };
        points.insert((g.chapter, p), &g.point);
        if g.trials.iter().any(|i| share.waiting.contains(i)) && !todo.contains(&(g.chapter, p)) {
            todo.push((g.chapter, p));
        }
    }
    let named = selection.named();
    let given = selection.inputs();
    let mut run = ShardRun::default();
    for (c, p) in todo {
        let chapter = selection.chapters[c];
        let point = points[&(c, p)];
        let started = std::time::Instant::now();
        let before = options.tally.totals();
        let planned = chapter.plan(&given, &point.experiments(&named), &point.context(selection.command.scale))?;
        for batch in planned.batches() {
            batch.run_assigned(&options, &assigned)?;
        }
        let after = options.tally.totals();
        log(format!(
            "shard {shard}: {} (seed {}, reading {}): {} computed, {} reused ({:.1} s)",
            chapter.slug(),
            point.seed,
            point.reading,
            after.0 - before.0,
            after.1 - before.1,
            started.elapsed().as_secs_f64()
        ));
    }
    let (computed, _, _, _) = options.tally.totals();
    run.computed = computed;
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
