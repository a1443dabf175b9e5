//! A command as the runner takes it: what determines the output (chapters,
//! experiment, scale, seed, reading, robustness, demonstrations), checked
//! against the registry of built chapters into a [`Selection`], and every
//! run point the command runs each chapter at ([`RunPoint`]).
//!
//! The run points of a chapter: the headline run (the command's seed and
//! reading); each sweep of a selected experiment at every other level of
//! its axis (that experiment only); with `--robustness`, the replications
//! (the master seed and `K − 1` seeds derived from it, at the command's
//! reading) and every other level of every axis, one axis at a time around
//! the command's reading, at the first `R` of those replication seeds. A
//! point identical to an earlier one is left out.

use std::path::PathBuf;

use rlfd_harness::{AnyAxis, CommandInputs, Reading, RunContext, Scale, TrialKey, derive_seed};

use crate::chapter::{AnyChapter, sweeps_of};
use crate::error::RunnerError;

/// Replications of a robustness run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Replications {
    /// Master seeds at the command's reading (`--seeds K`).
    pub seeds: u32,
    /// Master seeds at every other level of each axis (the first of the
    /// replication seeds).
    pub reading_seeds: u32,
}

/// What determines a run's output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Command {
    /// `--chapter` (slug or alias).
    pub chapter: Option<String>,
    /// `--experiment`.
    pub experiment: Option<String>,
    /// `--scale`.
    pub scale: Scale,
    /// `--seed`.
    pub seed: u64,
    /// `--reading`, as written.
    pub reading: Option<String>,
    /// `--robustness --seeds K`.
    pub robustness: Option<Replications>,
    /// `--demonstrations FILE`.
    pub demonstrations: Option<PathBuf>,
}

/// The `k`-th replication seed of `master`: `master` itself for `k = 0`,
/// else a seed derived from it (stable, listed in the report).
pub fn replication_seed(master: u64, k: u32) -> u64 {
    if k == 0 { master } else { derive_seed(master, &TrialKey::new("rlfd", "replication", "master-seed", k)) }
}

/// A command checked against the built chapters.
pub struct Selection<'a> {
    /// The command.
    pub command: Command,
    /// The selected chapters, in the thesis's order.
    pub chapters: Vec<&'a dyn AnyChapter>,
    /// The reading the command names (checked against every chapter's axes).
    pub reading: Reading,
}

impl<'a> Selection<'a> {
    /// Checks `command` against `registry` (every built chapter, in order).
    pub fn new(command: Command, registry: &'a [Box<dyn AnyChapter>]) -> Result<Selection<'a>, RunnerError> {
        let mut chapters: Vec<&dyn AnyChapter> = registry.iter().map(|c| c.as_ref()).collect();
        if let Some(name) = &command.chapter {
            let known: Vec<&'static str> = chapters.iter().map(|c| c.slug()).collect();
            chapters.retain(|c| name == c.slug() || name == c.alias());
            if chapters.is_empty() {
                return Err(RunnerError::UnknownChapter { name: name.clone(), expected: known });
            }
        }
        if let Some(e) = &command.experiment {
            let names: Vec<&'static str> = chapters.iter().flat_map(|c| c.experiments()).collect();
            chapters.retain(|c| c.experiments().contains(&e.as_str()));
            if chapters.is_empty() {
                return Err(RunnerError::UnknownExperiment {
                    name: e.clone(),
                    chapter: command.chapter.clone(),
                    expected: names,
                });
            }
        }
        if command.demonstrations.is_some() {
            let named: Vec<&str> = command.experiment.as_deref().into_iter().collect();
            let takes =
                chapters.iter().any(|c| c.demonstration_takers().iter().any(|e| named.is_empty() || named.contains(e)));
            if !takes {
                let takers: Vec<String> = registry
                    .iter()
                    .flat_map(|c| c.demonstration_takers().into_iter().map(move |e| format!("{}'s {e}", c.slug())))
                    .collect();
                return Err(RunnerError::DemonstrationsUnused { takers: takers.join(", ") });
            }
        }
        let axes: Vec<&'static dyn AnyAxis> = registry.iter().flat_map(|c| c.readings().iter().copied()).collect();
        let reading = match &command.reading {
            Some(text) => Reading::parse(text, &axes)?,
            None => Reading::defaults(),
        };
        Ok(Selection { command, chapters, reading })
    }

    /// The experiments the command names (none: all).
    pub fn named(&self) -> Vec<&str> {
        self.command.experiment.as_deref().into_iter().collect()
    }

    /// What the command hands the chapters.
    pub fn inputs(&self) -> CommandInputs<'_> {
        CommandInputs { demonstrations: self.command.demonstrations.as_deref() }
    }

    /// The headline run's context.
    pub fn context(&self) -> RunContext {
        RunContext { master_seed: self.command.seed, scale: self.command.scale, reading: self.reading.clone() }
    }

    /// The command that determines the output (no `--jobs`, `--out`,
    /// `--results`), with the chapter's slug rather than an alias and the
    /// demonstration file's name rather than its path.
    pub fn semantic_command(&self) -> String {
        let c = &self.command;
        let mut s = String::from("cargo xtask reproduce");
        if c.chapter.is_some()
            && let [chapter] = self.chapters.as_slice()
        {
            s.push_str(&format!(" --chapter {}", chapter.slug()));
        }
        if let Some(e) = &c.experiment {
            s.push_str(&format!(" --experiment {e}"));
        }
        s.push_str(&format!(" --scale {} --seed {}", c.scale, c.seed));
        if let Some(r) = &c.reading {
            s.push_str(&format!(" --reading {r}"));
        }
        if let Some(r) = c.robustness {
            s.push_str(&format!(" --robustness --seeds {}", r.seeds));
            if r.reading_seeds != r.seeds.min(crate::DEFAULT_READING_SEEDS) {
                s.push_str(&format!(" --reading-seeds {}", r.reading_seeds));
            }
        }
        if let Some(d) = &c.demonstrations {
            let name = d.file_name().map_or_else(|| d.display().to_string(), |n| n.to_string_lossy().into_owned());
            s.push_str(&format!(" --demonstrations {name}"));
        }
        s
    }

    /// Every run point of `chapter` under this command, in running order.
    pub fn points(&self, chapter: &dyn AnyChapter) -> Vec<RunPoint> {
        let c = &self.command;
        let named = self.named();
        let selected: Vec<&'static str> =
            chapter.experiments().into_iter().filter(|e| named.is_empty() || named.contains(e)).collect();
        let mut points =
            vec![RunPoint { seed: c.seed, reading: self.reading.clone(), role: Role::Headline, only: None }];
        for sweep in sweeps_of(chapter.sweeps(), &selected) {
            let own = self.reading.level_of(sweep.axis);
            for level in sweep.axis.level_names().into_iter().filter(|l| *l != own) {
                points.push(RunPoint {
                    seed: c.seed,
                    reading: self.reading.clone().with(sweep.axis, level),
                    role: Role::Sweep { axis: sweep.axis.name(), level },
                    only: Some(sweep.experiment),
                });
            }
        }
        if let Some(r) = c.robustness {
            for k in 1..r.seeds {
                points.push(RunPoint {
                    seed: replication_seed(c.seed, k),
                    reading: self.reading.clone(),
                    role: Role::Replication(k),
                    only: None,
                });
            }
            for &axis in chapter.readings() {
                let own = self.reading.level_of(axis);
                for level in axis.level_names().into_iter().filter(|l| *l != own) {
                    for k in 0..r.reading_seeds.min(r.seeds).max(1) {
                        points.push(RunPoint {
                            seed: replication_seed(c.seed, k),
                            reading: self.reading.clone().with(axis, level),
                            role: Role::Reading { axis: axis.name(), level, replication: k },
                            only: None,
                        });
                    }
                }
            }
            for crossing in chapter.crossings() {
                let [a, b] = crossing.axes;
                let (own_a, own_b) = (self.reading.level_of(a), self.reading.level_of(b));
                for la in a.level_names().into_iter().filter(|l| *l != own_a) {
                    for lb in b.level_names().into_iter().filter(|l| *l != own_b) {
                        for k in 0..r.reading_seeds.min(r.seeds).max(1) {
                            points.push(RunPoint {
                                seed: replication_seed(c.seed, k),
                                reading: self.reading.clone().with(a, la).with(b, lb),
                                role: Role::Crossed { axes: [a.name(), b.name()], levels: [la, lb], replication: k },
                                only: None,
                            });
                        }
                    }
                }
            }
        }
        let mut seen = std::collections::BTreeSet::new();
        points.retain(|p| seen.insert((p.seed, p.reading.clone(), p.only)));
        points
    }
}

/// What a run point is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The run whose report is written.
    Headline,
    /// A sweep's level beside the headline (one experiment).
    Sweep {
        /// The axis.
        axis: &'static str,
        /// The level.
        level: &'static str,
    },
    /// A replication at the command's reading (`k ≥ 1`; 0 is the headline).
    Replication(u32),
    /// Another level of an axis, at replication `replication`.
    Reading {
        /// The axis.
        axis: &'static str,
        /// The level.
        level: &'static str,
        /// Which replication seed.
        replication: u32,
    },
    /// A pair of levels of two crossed axes (neither the reading's own),
    /// at replication `replication`.
    Crossed {
        /// The axes.
        axes: [&'static str; 2],
        /// Their levels.
        levels: [&'static str; 2],
        /// Which replication seed.
        replication: u32,
    },
}

impl Role {
    /// A replication at the command's reading, or at another reading.
    pub fn is_robustness(&self) -> bool {
        matches!(self, Role::Replication(_) | Role::Reading { .. } | Role::Crossed { .. })
    }

    /// For a point at another reading: the axis (or the crossed axes, joined
    /// by ×), the level (or levels) and the replication.
    pub fn other_reading(&self) -> Option<(String, String, u32)> {
        match self {
            Role::Reading { axis, level, replication } => Some((axis.to_string(), level.to_string(), *replication)),
            Role::Crossed { axes, levels, replication } => Some((
                axes.join(rlfd_report::robustness::CROSSED),
                levels.join(rlfd_report::robustness::CROSSED),
                *replication,
            )),
            _ => None,
        }
    }
}

/// One (seed, reading) a command runs a chapter at.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RunPoint {
    /// The master seed of the run.
    pub seed: u64,
    /// The reading.
    pub reading: Reading,
    /// What it is for.
    pub role: Role,
    /// Only this experiment (a sweep's), else the command's.
    pub only: Option<&'static str>,
}

impl RunPoint {
    /// The context of the run.
    pub fn context(&self, scale: Scale) -> RunContext {
        RunContext { master_seed: self.seed, scale, reading: self.reading.clone() }
    }

    /// The experiments it runs, given the command's (none: all).
    pub fn experiments<'s>(&self, named: &[&'s str]) -> Vec<&'s str>
    where
        'static: 's,
    {
        match self.only {
            Some(e) => vec![e],
            None => named.to_vec(),
        }
    }
}
