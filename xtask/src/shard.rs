//! `reproduce --shard I/N`: one of N machines' share of a reproduction.
//!
//! A run is first *planned*: every selected chapter's experiments, at every
//! (seed, reading) the command runs (the headline run, and with
//! `--robustness` each replication seed and each other level of each axis,
//! as [`crate::robustness`] runs them; a reading is skipped for an
//! experiment none of its axes changes, whose trials are the default
//! reading's), are driven in [`RunMode::Plan`], which lists each trial (its
//! record's path, key, seed and identity) and runs none. One record path is
//! one trial, whichever runs share it; it belongs to the first group
//! (chapter, run, experiment) that lists it.
//!
//! The plan is then dealt to N shards by expected cost (the chapters'
//! [`rlfd_harness::TrialCost`]): each group's trials stay together, so a
//! shard pays a group's set-up (demonstrations, derived inputs) once,
//! unless the group costs more than a shard's fair share (the total over
//! N), in which case it is cut, in path order, into pieces of about that
//! share; the pieces, heaviest first, go each to the shard with the least
//! load so far (ties to the lowest-numbered). The deal depends on the
//! command and the build alone, never on the store, so N processes anywhere
//! deal the same hands. A shard then drives, in [`RunMode::Shard`], only
//! the groups holding trials of its own that are not stored yet, and
//! computes just those; it writes trial records and no report.
//!
//! Planning runs every group's set-up, which can take minutes for a
//! robustness run; `--plan FILE` reads a plan written before (by
//! `cargo xtask slurm`, once for all the tasks), checked to be of the same
//! command and build.
//!
//! Planning relies on each experiment running its trials in one batch (one
//! `run_trials` call), which every chapter does: the batch that ends a
//! planning run is the experiment's whole list. Were a chapter to split an
//! experiment, a shard would find trials of its own left without a record
//! after its run and say so, and `report` would name the missing trials.
//!
//! The same plan tells `report` which trials a store lacks
//! ([`Completeness`]) and `cargo xtask slurm` what each task costs.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use anyhow::{Context, Result, bail};
use rlfd_harness::{Batches, Lookup, Reading, ResultStore, RunMode, TrialKey};
use rlfd_report::Provenance;
use serde::{Deserialize, Serialize};

use crate::chapters::{Chapter, named, reading, run_options, select};
use crate::cli::RunSettings;

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

/// One (seed, reading) a command runs each chapter at.
#[derive(Clone, Debug)]
pub struct RunPoint {
    /// The master seed of the run.
    pub seed: u64,
    /// The reading.
    pub reading: Reading,
    /// The headline run (the one whose report is written).
    pub headline: bool,
}

/// The runs of `chapter` a command makes: the headline run, then with
/// `--robustness` the replication seeds and every other level of each axis
/// (a run identical to an earlier one is left out).
pub fn run_points(chapter: &dyn Chapter, s: &RunSettings) -> Result<Vec<RunPoint>> {
    let mut points = vec![RunPoint { seed: s.seed, reading: reading(s)?, headline: true }];
    if s.robustness {
        for k in 0..s.seeds {
            points.push(RunPoint {
                seed: crate::robustness::replication_seed(s.seed, k),
                reading: Reading::defaults(),
                headline: false,
            });
        }
        for &axis in chapter.readings() {
            for level in axis.alternatives() {
                points.push(RunPoint { seed: s.seed, reading: Reading::defaults().with(axis, level), headline: false });
            }
        }
    }
    let mut seen = BTreeSet::new();
    points.retain(|p| seen.insert((p.seed, p.reading.label())));
    Ok(points)
}

/// One experiment of one chapter at one run point, and its trials.
#[derive(Clone, Debug)]
pub struct Group {
    /// The chapter's position in the selection.
    pub chapter: usize,
    /// The experiment (as `--experiment` names it).
    pub experiment: &'static str,
    /// Where it runs.
    pub point: RunPoint,
    /// Its trials (indices into [`Plan::trials`]).
    pub trials: Vec<usize>,
}

/// One trial of the plan.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Trial {
    /// Its record's path.
    pub path: PathBuf,
    /// The same below the store's root.
    pub relative: PathBuf,
    /// Its key.
    pub key: TrialKey,
    /// The master seed of its run.
    pub master_seed: u64,
    /// Its own seed.
    pub seed: u64,
    /// Its identity.
    pub fingerprint: String,
    /// Its expected CPU seconds.
    pub seconds: f64,
    /// Its expected memory in flight, MiB.
    pub mib: f64,
}

/// Every trial a command runs, grouped as the chapters run them.
pub struct Plan {
    /// The selected chapters.
    pub chapters: Vec<Box<dyn Chapter>>,
    /// Per chapter, experiment and run point, in running order.
    pub groups: Vec<Group>,
    /// Every trial once, ordered by record path.
    pub trials: Vec<Trial>,
}

/// Drives `chapter`'s `experiment` at `point` in `mode` and returns the
/// batches it met; the batch's [`rlfd_harness::HarnessError::Withheld`] that
/// ends the chapter is expected, any other error is returned.
fn drive(
    chapter: &dyn Chapter,
    s: &RunSettings,
    experiment: &str,
    point: &RunPoint,
    mode: impl FnOnce(Batches) -> RunMode,
    provenance: &Provenance,
) -> Result<(Vec<rlfd_harness::Batch>, rlfd_harness::Tally)> {
    let settings = RunSettings { seed: point.seed, progress: false, ..s.clone() };
    let batches = Batches::new();
    let mut options = run_options(&settings, mode(batches.clone()));
    options.reading = point.reading.clone();
    if let Err(e) = chapter.run(&settings, &[experiment], &options, provenance)
        && batches.is_empty()
    {
        return Err(e.context(format!(
            "{} {experiment} at seed {}, reading {}",
            chapter.slug(),
            point.seed,
            point.reading
        )));
    }
    Ok((batches.take(), options.tally))
}

/// Plans `jobs` on `--jobs` threads (each job runs its chapter's set-up),
/// gathered in the jobs' order.
fn plan_jobs(
    chapters: &[Box<dyn Chapter>],
    s: &RunSettings,
    provenance: &Provenance,
    jobs: &[(usize, RunPoint, &'static str)],
) -> Vec<Result<Vec<rlfd_harness::Batch>>> {
    let next = AtomicUsize::new(0);
    let planned: Mutex<Vec<Option<Result<Vec<rlfd_harness::Batch>>>>> =
        Mutex::new((0..jobs.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..s.jobs.clamp(1, jobs.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    let Some((c, point, experiment)) = jobs.get(j) else { break };
                    let listed = drive(
                        chapters[*c].as_ref(),
                        s,
                        experiment,
                        point,
                        |batches| RunMode::Plan { batches },
                        provenance,
                    )
                    .map(|(batches, _)| batches);
                    planned.lock().expect("no planning thread panics holding the list")[j] = Some(listed);
                }
            });
        }
    });
    planned
        .into_inner()
        .expect("no planning thread panicked")
        .into_iter()
        .map(|p| p.expect("every job was planned"))
        .collect()
}

/// Plans the command `s`: every trial of every selected chapter and
/// experiment at every run point.
pub fn plan(s: &RunSettings, provenance: &Provenance) -> Result<Plan> {
    let chapters = select(s)?;
    for chapter in &chapters {
        chapter.check_inputs(s, &named(s)).with_context(|| chapter.slug().to_string())?;
    }
    // Every (chapter, run, experiment) to plan, in running order. The
    // headline run is planned first: the experiment names its trials' keys
    // carry there (a chapter's experiment may store under another name, as
    // chapter 5's learning tables share one) decide which other readings
    // change an experiment's trials; one no chosen axis changes is skipped,
    // its trials being the default reading's.
    let mut jobs: Vec<(usize, RunPoint, &'static str)> = Vec::new();
    let mut later: Vec<(usize, RunPoint, &'static str)> = Vec::new();
    for (c, chapter) in chapters.iter().enumerate() {
        let experiments: Vec<&'static str> = chapter
            .experiments()
            .into_iter()
            .filter(|e| s.experiment.as_deref().is_none_or(|named| named == *e))
            .collect();
        for point in run_points(chapter.as_ref(), s)? {
            for &experiment in &experiments {
                if point.headline { &mut jobs } else { &mut later }.push((c, point.clone(), experiment));
            }
        }
    }
    let mut planned = plan_jobs(&chapters, s, provenance, &jobs);
    let mut keys: BTreeMap<(usize, &'static str), BTreeSet<String>> = BTreeMap::new();
    for ((c, _, experiment), batches) in jobs.iter().zip(&planned) {
        let names = keys.entry((*c, *experiment)).or_default();
        if let Ok(batches) = batches {
            names.extend(batches.iter().flat_map(|b| b.trials.iter().map(|t| t.key.experiment.clone())));
        }
    }
    later.retain(|(c, point, experiment)| {
        point.reading.is_default()
            || keys
                .get(&(*c, *experiment))
                .is_some_and(|names| names.iter().any(|k| point.reading.changes_experiment(k)))
    });
    planned.extend(plan_jobs(&chapters, s, provenance, &later));
    jobs.extend(later);
    // Back to running order: per chapter, run point by run point.
    let mut order: Vec<usize> = (0..jobs.len()).collect();
    order.sort_by_key(|&j| (jobs[j].0, !jobs[j].1.headline));
    let mut slots: Vec<Option<_>> = jobs.into_iter().zip(planned).map(Some).collect();
    let (jobs, planned): (Vec<_>, Vec<_>) =
        order.into_iter().map(|j| slots[j].take().expect("each job is taken once")).unzip();
    let mut groups = Vec::new();
    let mut by_path: BTreeMap<PathBuf, Trial> = BTreeMap::new();
    let mut listed: Vec<Vec<PathBuf>> = Vec::new();
    for ((c, point, experiment), batches) in jobs.into_iter().zip(planned) {
        let chapter = &chapters[c];
        let batches = batches?;
        let mut paths = Vec::new();
        for batch in batches {
            for t in batch.trials {
                let cost = chapter.trial_cost(&t.key.experiment);
                let relative = t.path.strip_prefix(&s.results).unwrap_or(&t.path).to_path_buf();
                paths.push(t.path.clone());
                by_path.entry(t.path.clone()).or_insert(Trial {
                    path: t.path,
                    relative,
                    key: t.key,
                    master_seed: point.seed,
                    seed: t.seed,
                    fingerprint: t.fingerprint,
                    seconds: cost.seconds(s.scale),
                    mib: cost.paper_mib,
                });
            }
        }
        groups.push(Group { chapter: c, experiment, point, trials: Vec::new() });
        listed.push(paths);
    }
    let trials: Vec<Trial> = by_path.into_values().collect();
    let index: BTreeMap<&PathBuf, usize> = trials.iter().enumerate().map(|(i, t)| (&t.path, i)).collect();
    for (group, paths) in groups.iter_mut().zip(&listed) {
        group.trials = paths.iter().map(|p| index[p]).collect();
    }
    Ok(Plan { chapters, groups, trials })
}

/// A plan as `--plan FILE` holds it.
#[derive(Serialize, Deserialize)]
struct PlanFile {
    /// The command it plans (its semantic part).
    command: String,
    /// The chapters' build identities, by slug.
    builds: BTreeMap<String, String>,
    /// The groups: chapter slug, experiment, seed, reading label, headline, trials.
    groups: Vec<(String, String, u64, String, bool, Vec<usize>)>,
    /// The trials (paths below the store's root).
    trials: Vec<Trial>,
}

/// The plan of `s`: read from `file` when given (checked to be of the same
/// command and build), else computed.
pub fn plan_for(s: &RunSettings, provenance: &Provenance, file: Option<&Path>) -> Result<Plan> {
    let Some(file) = file else {
        return plan(s, provenance);
    };
    let shown = file.display();
    let bytes = std::fs::read(file).with_context(|| format!("cannot read the plan {shown}"))?;
    let stored: PlanFile = serde_json::from_slice(&bytes)
        .map_err(|e| anyhow::anyhow!("{shown} is not a plan written by `cargo xtask slurm` ({e})"))?;
    let chapters = select(s)?;
    let command = crate::chapters::semantic_command(s);
    let builds: BTreeMap<String, String> =
        chapters.iter().map(|c| (c.slug().to_string(), c.build().to_string())).collect();
    if stored.command != command {
        bail!(
            "the plan {shown} is of `{}`, not of `{command}`; rerun `cargo xtask slurm` with these flags",
            stored.command
        );
    }
    if stored.builds != builds {
        bail!("the plan {shown} was made by another build of the chapters; rerun `cargo xtask slurm` with this build");
    }
    let axes: Vec<&'static rlfd_harness::Axis> = chapters.iter().flat_map(|c| c.readings().iter().copied()).collect();
    let mut groups = Vec::new();
    for (slug, name, seed, label, headline, trials) in stored.groups {
        let chapter = chapters.iter().position(|c| c.slug() == slug);
        let experiment = chapter.and_then(|c| chapters[c].experiments().into_iter().find(|e| *e == name));
        let (Some(chapter), Some(experiment)) = (chapter, experiment) else {
            bail!("the plan {shown} names {slug} {name}, which this build does not have");
        };
        let reading = if label == "default" { Reading::defaults() } else { Reading::parse(&label, &axes)? };
        if trials.iter().any(|&t| t >= stored.trials.len()) {
            bail!("the plan {shown} is damaged: a group names a trial it does not list");
        }
        groups.push(Group { chapter, experiment, point: RunPoint { seed, reading, headline }, trials });
    }
    let trials = stored.trials.into_iter().map(|t| Trial { path: s.results.join(&t.relative), ..t }).collect();
    Ok(Plan { chapters, groups, trials })
}

impl Plan {
    /// Writes the plan to `file` (for `--plan`).
    pub fn save(&self, s: &RunSettings, file: &Path) -> Result<()> {
        let stored = PlanFile {
            command: crate::chapters::semantic_command(s),
            builds: self.chapters.iter().map(|c| (c.slug().to_string(), c.build().to_string())).collect(),
            groups: self
                .groups
                .iter()
                .map(|g| {
                    (
                        self.chapters[g.chapter].slug().to_string(),
                        g.experiment.to_string(),
                        g.point.seed,
                        g.point.reading.label(),
                        g.point.headline,
                        g.trials.clone(),
                    )
                })
                .collect(),
            trials: self.trials.iter().map(|t| Trial { path: t.relative.clone(), ..t.clone() }).collect(),
        };
        let json = serde_json::to_vec(&stored).expect("plans serialise");
        rlfd_harness::write_atomically(file, &json)?;
        Ok(())
    }
}

impl Plan {
    /// The shard (from 0) of each trial: each group's own trials (those no
    /// earlier group lists) together, a group heavier than the fair share
    /// cut into pieces of about the fair share, the pieces heaviest first to
    /// the least-loaded shard (ties: plan order, then the lowest shard).
    pub fn deal(&self, count: u32) -> Vec<u32> {
        let mut owned = vec![false; self.trials.len()];
        let mut pieces: Vec<(f64, Vec<usize>)> = Vec::new();
        let total: f64 = self.trials.iter().map(|t| t.seconds).sum();
        let share = total / f64::from(count);
        for group in &self.groups {
            let mut own: Vec<usize> =
                group.trials.iter().copied().filter(|&t| !std::mem::replace(&mut owned[t], true)).collect();
            own.sort_unstable();
            own.dedup();
            let mut piece = (0.0, Vec::new());
            for t in own {
                piece.0 += self.trials[t].seconds;
                piece.1.push(t);
                if piece.0 >= share {
                    pieces.push(std::mem::take(&mut piece));
                }
            }
            if !piece.1.is_empty() {
                pieces.push(piece);
            }
        }
        let mut order: Vec<usize> = (0..pieces.len()).collect();
        order.sort_by(|&a, &b| pieces[b].0.total_cmp(&pieces[a].0).then(a.cmp(&b)));
        let mut load = vec![0.0_f64; count as usize];
        let mut shard_of = vec![0u32; self.trials.len()];
        for p in order {
            let lightest = (0..load.len()).min_by(|&x, &y| load[x].total_cmp(&load[y]).then(x.cmp(&y))).unwrap_or(0);
            load[lightest] += pieces[p].0;
            for &t in &pieces[p].1 {
                shard_of[t] = lightest as u32;
            }
        }
        shard_of
    }

    /// Per shard (from 0): its trials' expected CPU seconds and count.
    pub fn loads(&self, count: u32) -> Vec<(f64, usize)> {
        let mut loads = vec![(0.0, 0); count as usize];
        for (t, shard) in self.trials.iter().zip(self.deal(count)) {
            loads[shard as usize].0 += t.seconds;
            loads[shard as usize].1 += 1;
        }
        loads
    }

    /// Whether each trial has a readable record of its own identity.
    fn stored(&self, store: &ResultStore) -> Vec<bool> {
        self.trials
            .iter()
            .map(|t| matches!(store.lookup::<serde::de::IgnoredAny>(&t.path, &t.fingerprint), Lookup::Fresh(_)))
            .collect()
    }
}

/// Runs shard `shard` of the command `s` (or with `dry_run`, prints what it
/// would run): trial records only, no report.
pub fn run(s: &RunSettings, shard: Shard, plan_file: Option<&Path>, dry_run: bool) -> Result<()> {
    let started = Instant::now();
    let provenance = Provenance::new(crate::chapters::semantic_command(s), env!("CARGO_PKG_VERSION"));
    let plan = plan_for(s, &provenance, plan_file)?;
    let deal = plan.deal(shard.count);
    let mine: BTreeSet<usize> = (0..plan.trials.len()).filter(|&i| deal[i] == shard.index - 1).collect();
    let seconds: f64 = mine.iter().map(|&i| plan.trials[i].seconds).sum();
    let store = ResultStore::new(&s.results);
    let stored = plan.stored(&store);
    let waiting: BTreeSet<usize> = mine.iter().copied().filter(|&i| !stored[i]).collect();
    eprintln!(
        "shard {shard}: {} of the {} trials planned (estimated {:.0} CPU-s of {:.0}), {} already stored",
        mine.len(),
        plan.trials.len(),
        seconds,
        plan.trials.iter().map(|t| t.seconds).sum::<f64>(),
        mine.len() - waiting.len()
    );
    if dry_run {
        for &i in &waiting {
            let t = &plan.trials[i];
            println!("{}", t.path.strip_prefix(&s.results).unwrap_or(&t.path).display());
        }
        return Ok(());
    }
    let assigned: Arc<BTreeSet<PathBuf>> = Arc::new(mine.iter().map(|&i| plan.trials[i].path.clone()).collect());
    let mut computed = 0;
    let mut replaced = Vec::new();
    let mut waiting = waiting;
    for group in &plan.groups {
        if !group.trials.iter().any(|i| waiting.contains(i)) {
            continue;
        }
        for i in &group.trials {
            waiting.remove(i);
        }
        let chapter = plan.chapters[group.chapter].as_ref();
        let group_started = Instant::now();
        let mode = |batches| RunMode::Shard { assigned: assigned.clone(), batches };
        let (_, tally) = drive(chapter, s, group.experiment, &group.point, mode, &provenance)?;
        let (c, r, _, _) = tally.totals();
        computed += c;
        for t in tally.experiments().into_values() {
            replaced.extend(t.replaced);
        }
        eprintln!(
            "shard {shard}: {} {} (seed {}, reading {}): {c} computed, {r} reused ({:.1} s)",
            chapter.slug(),
            group.experiment,
            group.point.seed,
            group.point.reading,
            group_started.elapsed().as_secs_f64()
        );
    }
    for (path, reason) in &replaced {
        eprintln!("warning: the record {} could not be read ({reason}) and was recomputed", path.display());
    }
    let left: Vec<&Trial> = plan
        .stored(&store)
        .iter()
        .zip(&plan.trials)
        .enumerate()
        .filter(|(i, (ok, _))| mine.contains(i) && !**ok)
        .map(|(_, (_, t))| t)
        .collect();
    if let Some(first) = left.first() {
        bail!(
            "shard {shard}: {} of its trials have no record after the run, the first {} ({}); did a chapter split an experiment into several batches?",
            left.len(),
            first.key,
            first.path.display()
        );
    }
    eprintln!(
        "shard {shard}: {computed} trials computed, {} reused; records in {} ({:.1} s)",
        mine.len() - computed,
        s.results.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// What a store lacks for a command's report.
pub struct Completeness {
    /// Per chapter slug: its experiments complete at the headline run, in order.
    pub kept: BTreeMap<&'static str, Vec<&'static str>>,
    /// Per chapter slug: the experiments left out, with (missing, planned) trials.
    pub left_out: BTreeMap<&'static str, Vec<(&'static str, usize, usize)>>,
    /// Per chapter slug: trials missing from the robustness runs of the kept experiments.
    pub robustness_missing: BTreeMap<&'static str, usize>,
    /// Trials with no record of any version.
    pub missing: Vec<Trial>,
    /// Records of the current identity that cannot be read, with why (a
    /// trial with no other readable version is also missing).
    pub unreadable: Vec<(PathBuf, String)>,
    /// Trials planned.
    pub planned: usize,
}

impl Completeness {
    /// Checks that `s`'s store holds a record (of any behaviour version, as
    /// `report` reads them) of every trial the command plans.
    pub fn check(s: &RunSettings, provenance: &Provenance, plan_file: Option<&Path>) -> Result<Completeness> {
        let plan = plan_for(s, provenance, plan_file)?;
        let store = ResultStore::new(&s.results);
        let mut unreadable = Vec::new();
        let present: Vec<bool> = plan
            .trials
            .iter()
            .map(|t| match store.lookup::<serde::de::IgnoredAny>(&t.path, &t.fingerprint) {
                Lookup::Fresh(_) => true,
                found => {
                    if let Lookup::Unreadable { path, reason } = found {
                        unreadable.push((path, reason));
                    }
                    !ResultStore::other_versions_beside::<serde::de::IgnoredAny>(&t.path, &t.key, t.seed).is_empty()
                }
            })
            .collect();
        let mut c = Completeness {
            kept: BTreeMap::new(),
            left_out: BTreeMap::new(),
            robustness_missing: BTreeMap::new(),
            missing: plan.trials.iter().zip(&present).filter(|(_, p)| !**p).map(|(t, _)| t.clone()).collect(),
            unreadable,
            planned: plan.trials.len(),
        };
        for g in plan.groups.iter().filter(|g| g.point.headline) {
            let slug = plan.chapters[g.chapter].slug();
            let missing = g.trials.iter().filter(|&&i| !present[i]).count();
            if missing == 0 {
                c.kept.entry(slug).or_default().push(g.experiment);
            } else {
                c.left_out.entry(slug).or_default().push((g.experiment, missing, g.trials.len()));
            }
        }
        for g in plan.groups.iter().filter(|g| !g.point.headline) {
            let slug = plan.chapters[g.chapter].slug();
            if c.kept.get(slug).is_some_and(|k| k.contains(&g.experiment)) {
                *c.robustness_missing.entry(slug).or_default() += g.trials.iter().filter(|&&i| !present[i]).count();
            }
        }
        c.robustness_missing.retain(|_, n| *n > 0);
        Ok(c)
    }

    /// One line naming what is missing, by chapter and experiment.
    pub fn describe(&self, store: &Path) -> String {
        let mut by: BTreeMap<(&str, &str), (usize, &Trial)> = BTreeMap::new();
        for t in &self.missing {
            by.entry((&t.key.chapter, &t.key.experiment)).or_insert((0, t)).0 += 1;
        }
        let parts: Vec<String> = by
            .iter()
            .map(|((chapter, experiment), (n, first))| {
                format!("{chapter}/{experiment}: {n} (first {} at seed {})", first.key, first.master_seed)
            })
            .collect();
        let mut line = format!(
            "the store {} lacks {} of the {} trials this report needs: {}",
            store.display(),
            self.missing.len(),
            self.planned,
            parts.join("; ")
        );
        if let Some((path, reason)) = self.unreadable.first() {
            line.push_str(&format!(
                "; {} record(s) cannot be read and are taken as missing, the first {} ({reason})",
                self.unreadable.len(),
                path.display()
            ));
        }
        line
    }
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
