//! One of N machines' share of a command: the plan dealt by expected cost
//! ([`rlfd_harness::deal`]), and a shard runs only its own trials that are
//! not stored yet, planning each (chapter, run point) once and running a
//! batch's set-up only when one of its own trials must be computed. It
//! writes trial records and no report.

use std::collections::BTreeSet;
use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use rlfd_harness::{Measured, PipelineRun, ResultStore};
use sha2::{Digest, Sha256};

use crate::Machine;
use crate::command::{Role, RunPoint};
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

    /// The share's identity: [`listing_digest`] of all its trials' record
    /// paths (below the store at `results`), in the plan's order, as
    /// `--dry-run` lists them against an empty store. Two runs of a shard
    /// computed the same trials (the same deal, parameters and code
    /// identities) when their digests agree: how a run timed shard by shard,
    /// at different times or commits, is checked to add up to one run.
    pub fn digest(&self, plan: &Plan<'_>, results: &Path) -> String {
        listing_digest(self.mine.iter().map(|&i| {
            let path = &plan.trials[i].path;
            path.strip_prefix(results).unwrap_or(path)
        }))
    }
}

/// The first 16 hexadecimal digits of the SHA-256 of `paths`, one a line
/// (each followed by a newline): `sha256sum` of the same listing agrees.
pub fn listing_digest<'p>(paths: impl IntoIterator<Item = &'p Path>) -> String {
    let mut hash = Sha256::new();
    for p in paths {
        hash.update(p.display().to_string().as_bytes());
        hash.update(b"\n");
    }
    hash.finalize()[..8].iter().map(|b| format!("{b:02x}")).collect()
}

/// What a shard's run did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShardRun {
    /// Trials computed.
    pub computed: usize,
    /// Per experiment (in running order): what its trials took, beside
    /// what its chapter declares for them.
    pub costs: Vec<ExperimentCost>,
    /// Per chapter, the trials computed at its headline point and sweeps
    /// (what a report's own run reads; the rest are the robustness run's).
    pub headline: Vec<(&'static str, usize)>,
    /// Records that could not be read and were recomputed, with why.
    pub replaced: Vec<(PathBuf, String)>,
}

impl ShardRun {
    /// Per chapter (in running order): trials computed and their CPU
    /// seconds (set-ups included), as the workers timed them.
    pub fn chapters(&self) -> Vec<(&'static str, usize, f64)> {
        PipelineRun { experiments: self.costs.iter().map(|c| c.measured.clone()).collect() }.chapters()
    }
}

/// What one experiment's computed trials took, as the workers timed them,
/// and what its chapter's [`rlfd_harness::TrialCost`] declares for them:
/// the check of the declared costs that deal shards and size cluster jobs.
#[derive(Clone, Debug, PartialEq)]
pub struct ExperimentCost {
    /// The trials computed and their seconds, set-ups included.
    pub measured: Measured,
    /// Their declared CPU seconds.
    pub declared: f64,
}

impl fmt::Display for ExperimentCost {
    /// `ch5-hat-keepaway keepaway: 142 trials, 637.0 s (4.49 s a trial; declared 8.56 s, measured 0.52×)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = &self.measured;
        let n = m.trials.max(1) as f64;
        write!(
            f,
            "{} {}: {} trials, {:.1} s ({:.3} s a trial; declared {:.3} s, measured {:.2}×)",
            m.chapter,
            m.experiment,
            m.trials,
            m.seconds,
            m.seconds / n,
            self.declared / n,
            if self.declared > 0.0 { m.seconds / self.declared } else { f64::NAN }
        )
    }
}

/// Planned trials a window of run points holds at most (plus its last
/// point's). Staging every point of chapter 4's robustness run at once
/// (297,350 planned trials) took 33 MB beside the 350 MB its plan holds
/// (the peak resident size, old and new code); a window keeps the staged
/// part near 2 MB whatever the command, and pauses the workers only at its
/// end.
pub const WINDOW_TRIALS: usize = 20_000;

/// Runs `share` of `plan` through one pool of `machine.jobs` workers
/// ([`rlfd_harness::pipeline`]): the (chapter, run point) pairs with trials
/// waiting are planned and staged a window at a time (consecutive points
/// up to [`WINDOW_TRIALS`] planned trials), and a window's trials run in
/// the plan's order with no pause between its batches. `log` hears one
/// line per (chapter, run point) as its last trial is stored.
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
    let mut todo: Vec<(usize, &RunPoint)> = Vec::new();
    for g in &plan.groups {
        if g.trials.iter().any(|i| share.waiting.contains(i)) && !todo.contains(&(g.chapter, &g.point)) {
            todo.push((g.chapter, &g.point));
        }
    }
    let named = selection.named();
    let given = selection.inputs();
    let started = std::time::Instant::now();
    let mut run = ShardRun::default();
    let mut next = 0;
    while next < todo.len() {
        let (mut planned, mut held) = (Vec::new(), 0);
        let first = next;
        while next < todo.len() && (planned.is_empty() || held < WINDOW_TRIALS) {
            let (c, point) = todo[next];
            let p = selection.chapters[c].plan(
                &given,
                &point.experiments(&named),
                &point.context(selection.command.scale),
            )?;
            held += p.batches().iter().map(|b| b.len()).sum::<usize>();
            planned.push(p);
            next += 1;
        }
        let window = Window { points: &todo[first..next], planned: &planned, shard, started };
        window.run(selection, &options, &assigned, machine.jobs, &mut run, log)?;
    }
    for t in options.tally.experiments().into_values() {
        run.replaced.extend(t.replaced);
    }
    // Each computed experiment's declared cost: its waiting trials' mean, times the trials computed.
    for cost in &mut run.costs {
        let of_it = |i: &&usize| {
            let k = &plan.trials[**i].key;
            (k.chapter.as_str(), k.experiment.as_str()) == (cost.measured.chapter, cost.measured.experiment)
        };
        let (n, declared) =
            share.waiting.iter().filter(of_it).fold((0usize, 0.0), |(n, s), &i| (n + 1, s + plan.trials[i].seconds));
        cost.declared = if n == 0 { 0.0 } else { declared / n as f64 * cost.measured.trials as f64 };
        let prefix = if shard.count == 1 { String::new() } else { format!("shard {shard}: ") };
        log(format!("{prefix}measured {cost}"));
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

/// Consecutive run points of a shard, planned, to stage and run together.
struct Window<'w, 'p> {
    points: &'w [(usize, &'p RunPoint)],
    planned: &'w [Box<dyn crate::chapter::AnyPlan + 'p>],
    shard: Shard,
    started: std::time::Instant,
}

impl Window<'_, '_> {
    /// Stages the window's batches (a trial two of its points share is
    /// computed once; one an earlier window stored is reused) and runs
    /// them, adding what it did to `run`.
    fn run(
        &self,
        selection: &crate::command::Selection<'_>,
        options: &rlfd_harness::RunOptions,
        assigned: &BTreeSet<PathBuf>,
        jobs: usize,
        run: &mut ShardRun,
        log: &mut (dyn FnMut(String) + Send),
    ) -> Result<(), RunnerError> {
        let mut claimed = BTreeSet::new();
        let mut staged = Vec::new();
        // Each staged batch's point, and per point its first staged batch.
        let mut owner = Vec::new();
        let mut first_of = Vec::new();
        for (p, plan) in self.planned.iter().enumerate() {
            first_of.push(staged.len());
            for batch in plan.batches() {
                staged.push(batch.stage(options, assigned, &mut claimed));
                owner.push(p);
            }
        }
        let n = self.points.len();
        let points_left: Vec<AtomicUsize> = (0..n)
            .map(|p| AtomicUsize::new(owner.iter().zip(&staged).filter(|(o, s)| **o == p && s.waiting() > 0).count()))
            .collect();
        // Per point: its trials to compute, and its trials in all.
        let batches: Vec<Vec<&dyn rlfd_harness::AnyBatch>> = self.planned.iter().map(|p| p.batches()).collect();
        let computed: Vec<usize> =
            (0..n).map(|p| (0..batches[p].len()).map(|i| staged[first_of[p] + i].waiting()).sum()).collect();
        let total: Vec<usize> = batches.iter().map(|b| b.iter().map(|b| b.len()).sum()).collect();
        let (shard, points, started) = (self.shard, self.points, self.started);
        let log = Mutex::new(log);
        let finished = |b: usize| {
            let p = owner[b];
            if points_left[p].fetch_sub(1, Ordering::AcqRel) == 1 {
                let (c, point) = points[p];
                // A whole run (1/1) says it as `reproduce` always has.
                let prefix = if shard.count == 1 { String::new() } else { format!("shard {shard}: ") };
                let sweep = if matches!(point.role, Role::Sweep { .. }) { " (sweep)" } else { "" };
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
        let piped = rlfd_harness::run_pipelined(&staged, jobs, &finished)?;
        run.computed += piped.computed();
        for m in piped.experiments {
            let same =
                |c: &&mut ExperimentCost| (c.measured.chapter, c.measured.experiment) == (m.chapter, m.experiment);
            match run.costs.iter_mut().find(same) {
                Some(c) => {
                    (c.measured.trials, c.measured.seconds) =
                        (c.measured.trials + m.trials, c.measured.seconds + m.seconds)
                }
                None => run.costs.push(ExperimentCost { measured: m, declared: 0.0 }),
            }
        }
        for (p, &(c, point)) in self.points.iter().enumerate() {
            if point.role.is_robustness() {
                continue;
            }
            let slug = selection.chapters[c].slug();
            match run.headline.iter_mut().find(|h| h.0 == slug) {
                Some(h) => h.1 += computed[p],
                None => run.headline.push((slug, computed[p])),
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_listings_digest_is_sha256sums() {
        // `printf 'paper/seed-1/ch3/e/c/trial-000.json\npaper/seed-1/ch3/e/c/trial-001.json\n' | sha256sum`
        // and `printf '' | sha256sum` (GNU coreutils 9.1).
        let two = ["paper/seed-1/ch3/e/c/trial-000.json", "paper/seed-1/ch3/e/c/trial-001.json"];
        assert_eq!(listing_digest(two.iter().map(Path::new)), "dde16695583e8c84");
        assert_eq!(listing_digest(two.iter().rev().map(Path::new)).len(), 16);
        assert_ne!(listing_digest(two.iter().rev().map(Path::new)), "dde16695583e8c84");
        assert_eq!(listing_digest(std::iter::empty()), "e3b0c44298fc1c14");
    }

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

    #[test]
    fn an_experiments_cost_says_measured_against_declared() {
        let measured =
            Measured { chapter: "ch5-hat-keepaway", experiment: "keepaway-learning", trials: 4, seconds: 22.0 };
        let cost = ExperimentCost { measured, declared: 44.0 };
        assert_eq!(
            cost.to_string(),
            "ch5-hat-keepaway keepaway-learning: 4 trials, 22.0 s (5.500 s a trial; declared 11.000 s, measured 0.50×)"
        );
    }
}
