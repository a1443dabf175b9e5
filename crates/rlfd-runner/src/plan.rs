//! Planning a command: every trial of every selected chapter and experiment
//! at every run point, listed without running a set-up or a trial (each
//! chapter plans its batches as values), dealt to shards by cost, and
//! checked against a store.
//!
//! One record path is one trial, whichever run points share it (a reading
//! that leaves a trial's parameters alone gives the same identity); it
//! belongs to the first group (chapter, run point, experiment) that lists
//! it. A plan can be written to a file (`cargo xtask slurm` does, once for
//! all the tasks) and read back, checked to be of the same command and
//! build.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use rlfd_harness::{BUILD_IDENTITY, Lookup, RecordId, ResultStore, TrialKey, deal};
use serde::{Deserialize, Serialize};

use crate::command::{Role, RunPoint, Selection};
use crate::error::RunnerError;

/// One experiment of one chapter at one run point, and its trials.
#[derive(Clone, Debug)]
pub struct Group {
    /// The chapter's position in the selection.
    pub chapter: usize,
    /// The experiment as its trials' keys name it (the store's folder).
    pub experiment: String,
    /// Where it runs.
    pub point: RunPoint,
    /// Its trials (indices into [`Plan::trials`]).
    pub trials: Vec<usize>,
}

/// One trial of the plan.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Trial {
    /// Its record's path.
    pub path: PathBuf,
    /// Its key.
    pub key: TrialKey,
    /// The master seed of its run.
    pub master_seed: u64,
    /// Its own seed.
    pub seed: u64,
    /// Its identity.
    pub id: RecordId,
    /// Its expected CPU seconds.
    pub seconds: f64,
    /// Its expected memory in flight, MiB.
    pub mib: f64,
}

/// Every trial a command runs, grouped as the chapters run them.
pub struct Plan<'a> {
    /// The command, checked.
    pub selection: &'a Selection<'a>,
    /// Per chapter, run point and experiment, in running order.
    pub groups: Vec<Group>,
    /// Every trial once, ordered by record path.
    pub trials: Vec<Trial>,
}

/// Plans `selection` against the store at `results`.
pub fn plan<'a>(selection: &'a Selection<'a>, results: &Path) -> Result<Plan<'a>, RunnerError> {
    let store = ResultStore::new(results);
    let named = selection.named();
    let given = selection.inputs();
    let scale = selection.command.scale;
    let mut groups = Vec::new();
    let mut by_path: BTreeMap<PathBuf, Trial> = BTreeMap::new();
    let mut listed: Vec<Vec<PathBuf>> = Vec::new();
    for (c, chapter) in selection.chapters.iter().enumerate() {
        chapter.check_inputs(&given, &named, &selection.context())?;
        for point in selection.points(*chapter) {
            let plan = chapter.plan(&given, &point.experiments(&named), &point.context(scale))?;
            for batch in plan.batches() {
                let cost = chapter.trial_cost(batch.experiment());
                let mut paths = Vec::new();
                for t in batch.planned(&store) {
                    paths.push(t.path.clone());
                    by_path.entry(t.path.clone()).or_insert(Trial {
                        path: t.path,
                        key: t.key,
                        master_seed: point.seed,
                        seed: t.seed,
                        id: t.id,
                        seconds: cost.seconds(scale),
                        mib: cost.paper_mib,
                    });
                }
                groups.push(Group {
                    chapter: c,
                    experiment: batch.experiment().to_string(),
                    point: point.clone(),
                    trials: Vec::new(),
                });
                listed.push(paths);
            }
        }
    }
    let trials: Vec<Trial> = by_path.into_values().collect();
    let index: BTreeMap<&PathBuf, usize> = trials.iter().enumerate().map(|(i, t)| (&t.path, i)).collect();
    for (group, paths) in groups.iter_mut().zip(&listed) {
        group.trials = paths.iter().map(|p| index[p]).collect();
    }
    Ok(Plan { selection, groups, trials })
}

/// A plan as a file holds it.
#[derive(Serialize, Deserialize)]
struct PlanFile {
    /// The command it plans (its semantic part).
    command: String,
    /// The build identity.
    build: String,
    /// The trials (paths below the store's root).
    trials: Vec<Trial>,
    /// The groups: chapter slug, experiment, seed, reading label, trials.
    groups: Vec<(String, String, u64, String, Vec<usize>)>,
}

impl<'a> Plan<'a> {
    /// The shard (from 0) of each trial.
    pub fn deal(&self, count: u32) -> Vec<u32> {
        let groups: Vec<Vec<usize>> = self.groups.iter().map(|g| g.trials.clone()).collect();
        let seconds: Vec<f64> = self.trials.iter().map(|t| t.seconds).collect();
        deal::deal(&groups, &seconds, count)
    }

    /// Per shard (from 0): its trials' expected CPU seconds and count.
    pub fn loads(&self, count: u32) -> Vec<(f64, usize)> {
        let seconds: Vec<f64> = self.trials.iter().map(|t| t.seconds).collect();
        deal::loads(&self.deal(count), &seconds, count)
    }

    /// Whether each trial has a readable record of its own identity.
    pub fn stored(&self, store: &ResultStore) -> Vec<bool> {
        self.trials
            .iter()
            .map(|t| matches!(store.lookup::<serde::de::IgnoredAny>(&t.path, &t.id), Lookup::Fresh(_)))
            .collect()
    }

    /// The plan as a file holds it (paths below `results`).
    pub fn to_file(&self, results: &Path) -> Vec<u8> {
        let stored = PlanFile {
            command: self.selection.semantic_command(),
            build: BUILD_IDENTITY.to_string(),
            trials: self
                .trials
                .iter()
                .map(|t| Trial { path: t.path.strip_prefix(results).unwrap_or(&t.path).to_path_buf(), ..t.clone() })
                .collect(),
            groups: self
                .groups
                .iter()
                .map(|g| {
                    let slug = self.selection.chapters[g.chapter].slug().to_string();
                    (slug, g.experiment.clone(), g.point.seed, g.point.reading.label(), g.trials.clone())
                })
                .collect(),
        };
        serde_json::to_vec(&stored).expect("plans serialise")
    }

    /// Checks that `bytes` (a plan file at `path`) is the plan of this
    /// plan's command and build, with the same trials and groups: a plan
    /// written by another command or build is refused, naming why.
    pub fn check_file(&self, path: &Path, bytes: &[u8], results: &Path) -> Result<(), RunnerError> {
        let refuse = |why: String| RunnerError::Plan { path: path.to_path_buf(), why };
        let stored: PlanFile = serde_json::from_slice(bytes)
            .map_err(|e| refuse(format!("it is not a plan written by `cargo xtask slurm` ({e})")))?;
        let command = self.selection.semantic_command();
        if stored.command != command {
            return Err(refuse(format!(
                "it is of `{}`, not of `{command}`; rerun `cargo xtask slurm` with these flags",
                stored.command
            )));
        }
        if stored.build != BUILD_IDENTITY {
            return Err(refuse("it was made by another build; rerun `cargo xtask slurm` with this build".into()));
        }
        let mine: PlanFile = serde_json::from_slice(&self.to_file(results)).expect("a plan reads back");
        if stored.trials != mine.trials || stored.groups != mine.groups {
            return Err(refuse("its trials differ from this command's (another version of the code?)".into()));
        }
        Ok(())
    }
}

/// What a store lacks for a command's report.
pub struct Completeness {
    /// Per chapter slug: its experiments complete at the headline run (and
    /// its sweeps), in order.
    pub kept: BTreeMap<&'static str, Vec<String>>,
    /// Per chapter slug: the experiments left out, with (missing, planned) trials.
    pub left_out: BTreeMap<&'static str, Vec<(String, usize, usize)>>,
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
    /// Checks that the store at `results` holds a record (of any code
    /// version, as `report` reads them) of every trial `plan` lists.
    pub fn check(plan: &Plan<'_>, results: &Path) -> Completeness {
        let store = ResultStore::new(results);
        let mut unreadable = Vec::new();
        let present: Vec<bool> = plan
            .trials
            .iter()
            .map(|t| match store.lookup::<serde::de::IgnoredAny>(&t.path, &t.id) {
                Lookup::Fresh(_) => true,
                found => {
                    if let Lookup::Unreadable { path, reason } = found {
                        unreadable.push((path, reason));
                    }
                    !ResultStore::other_versions::<serde::de::IgnoredAny>(&t.path, &t.key, t.seed, &t.id).is_empty()
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
        // An experiment is complete when its headline trials and its sweeps' are.
        let mut by_experiment: BTreeMap<(usize, String), (usize, usize)> = BTreeMap::new();
        for g in plan.groups.iter().filter(|g| matches!(g.point.role, Role::Headline | Role::Sweep { .. })) {
            let e = by_experiment.entry((g.chapter, g.experiment.clone())).or_default();
            e.0 += g.trials.iter().filter(|&&i| !present[i]).count();
            e.1 += g.trials.len();
        }
        for ((chapter, experiment), (missing, planned)) in by_experiment {
            let slug = plan.selection.chapters[chapter].slug();
            if missing == 0 {
                c.kept.entry(slug).or_default().push(experiment);
            } else {
                c.left_out.entry(slug).or_default().push((experiment, missing, planned));
            }
        }
        for g in plan.groups.iter().filter(|g| g.point.role.is_robustness()) {
            let slug = plan.selection.chapters[g.chapter].slug();
            if c.kept.get(slug).is_some_and(|k| k.contains(&g.experiment)) {
                *c.robustness_missing.entry(slug).or_default() += g.trials.iter().filter(|&&i| !present[i]).count();
            }
        }
        c.robustness_missing.retain(|_, n| *n > 0);
        c
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
