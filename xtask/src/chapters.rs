//! `reproduce` and `report`: the registry of built chapters, and the
//! command-line side of a run: the runner runs (or loads) and renders the
//! selected chapters; this writes their files, rebuilds the top-level index
//! from every chapter report present in the output, and writes `run.json`.

use std::path::Path;
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result, bail};
use rlfd_harness::{ChapterTime, RunMetadata, RunMode};
use rlfd_report::{ChapterSummary, Provenance, render_index};
use rlfd_runner::plan::{Completeness, plan};
use rlfd_runner::reproduce::{SUMMARY_FILE, StoredSummary, compute, render};
use rlfd_runner::{AnyChapter, Selection, erase};

use crate::cli::RunSettings;
use crate::output;

/// Every built chapter, in the thesis's order: the one registry.
pub fn registry() -> Vec<Box<dyn AnyChapter>> {
    vec![
        erase::<ch3_interactive_rl::Ch3>(),
        erase::<ch4_dbug_study::Ch4>(),
        erase::<ch5_hat_keepaway::Ch5>(),
        erase::<ch6_irl_shaping::Ch6>(),
    ]
}

/// What `reproduce` does with the store.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Compute what is missing (`reproduce`).
    Run,
    /// Only read records, of any code version (`report`).
    Report {
        /// When trials are missing, render the experiments that are complete.
        partial: bool,
        /// A plan written by `cargo xtask slurm` (checked to be this command's).
        plan: Option<std::path::PathBuf>,
    },
}

/// Prints a line of the runner's to stderr.
pub fn log(line: String) {
    eprintln!("{line}");
}

/// Runs (or with [`Mode::Report`], loads) and renders.
pub fn reproduce(s: &RunSettings, mode: Mode) -> Result<()> {
    let started = Instant::now();
    // The tree as the run found it: read after rendering, `git status` would
    // always see the run's own reports and say "-dirty".
    let commit = git_commit();
    let registry = registry();
    let selection = Selection::new(s.command.clone(), &registry)?;
    output::check_writable(&s.out)?;
    let ctx = selection.context();
    for chapter in &selection.chapters {
        chapter.check_inputs(&selection.inputs(), &selection.named(), &ctx)?;
    }
    let provenance = Provenance::new(selection.semantic_command(), env!("CARGO_PKG_VERSION"));
    let run_mode = match mode {
        Mode::Run => RunMode::Run,
        Mode::Report { .. } => RunMode::Load { any_version: true },
    };
    let mut logger = log;
    // Compute every missing trial first, through one pool (see
    // `rlfd_runner::reproduce::compute`); the rendering reads them.
    let computed = match mode {
        Mode::Run => compute(&selection, &s.machine, &mut logger)?,
        Mode::Report { .. } => None,
    };
    // Run and render every selected chapter before writing anything. When
    // `report` fails, the command's plan says whether trials are missing
    // and which; with `--partial` the complete experiments are rendered.
    let rendered = match (render(&selection, &s.machine, &run_mode, &provenance, None, &mut logger), &mode) {
        (Ok(r), _) => r,
        (Err(e), Mode::Report { partial, plan: file }) => {
            let planned = plan(&selection, &s.machine.results)?;
            if let Some(file) = file {
                let bytes = std::fs::read(file).with_context(|| format!("cannot read the plan {}", file.display()))?;
                planned.check_file(file, &bytes, &s.machine.results)?;
            }
            let c = Completeness::check(&planned, &s.machine.results);
            if c.missing.is_empty() {
                return Err(e.into());
            }
            let what = c.describe(&s.machine.results);
            if !partial {
                return Err(rlfd_runner::RunnerError::Incomplete(what).into());
            }
            eprintln!("warning: {what}; rendering what is there (--partial)");
            let r = render(&selection, &s.machine, &run_mode, &provenance, Some(&c), &mut logger)?;
            if r.done.is_empty() {
                bail!(
                    "nothing to render: no selected experiment has all its trials in {}",
                    s.machine.results.display()
                );
            }
            r
        }
        (Err(e), Mode::Run) => return Err(e.into()),
    };

    // The index covers every chapter whose report is in the output: the ones
    // rendered now, and the others as their stored summaries say.
    let mut summaries = Vec::new();
    for chapter in &registry {
        if let Some(r) = rendered.summaries.iter().find(|r| r.slug == chapter.slug()) {
            summaries.push(r.clone());
        } else if let Some(stored) = read_summary(&s.out.join(chapter.slug()).join(SUMMARY_FILE))? {
            summaries.push(stored);
        }
    }
    let mut files = rendered.files;
    files.extend(render_index(&summaries, &provenance).context("rendering the index")?);
    output::write_tree(&s.out, &files, &rendered.done)?;

    let per_experiment = rendered.tally.experiments();
    // The computing pass's share of each chapter: its headline trials (the
    // rendering then read them as stored) and every trial's CPU seconds.
    let first_pass = |chapter: &str| {
        computed.as_ref().map_or((0, 0.0), |c| {
            let headline = c.headline.iter().find(|h| h.0 == chapter).map_or(0, |h| h.1);
            (headline, c.chapters().iter().find(|t| t.0 == chapter).map_or(0.0, |t| t.2))
        })
    };
    let chapters: Vec<ChapterTime> = rendered
        .times
        .into_iter()
        .map(|(chapter, wall_seconds)| {
            let of_chapter = per_experiment.iter().filter(|((c, _), _)| *c == chapter).map(|(_, t)| t);
            let (computed, reused) = of_chapter.fold((0, 0), |(c, r), t| (c + t.computed, r + t.reused));
            let (before, trial_cpu_seconds) = first_pass(&chapter);
            ChapterTime {
                chapter,
                wall_seconds,
                trials_computed: computed + before,
                trials_reused: reused.saturating_sub(before),
                trial_cpu_seconds,
            }
        })
        .collect();
    let (computed, reused) = chapters.iter().fold((0, 0), |(c, r), t| (c + t.trials_computed, r + t.trials_reused));
    for t in per_experiment.values() {
        for (path, reason) in &t.replaced {
            eprintln!("warning: the record {} could not be read ({reason}) and was recomputed", path.display());
        }
    }
    let meta = RunMetadata {
        command: std::env::args().collect(),
        semantic_command: provenance.command.clone(),
        seed: s.command.seed,
        scale: s.command.scale.to_string(),
        jobs: s.machine.jobs,
        commit,
        host: std::fs::read_to_string("/etc/hostname").ok().map(|h| h.trim().to_string()),
        started_unix: SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_secs())
            .saturating_sub(started.elapsed().as_secs()),
        wall_seconds: started.elapsed().as_secs_f64(),
        trials_computed: computed,
        trials_reused: reused,
        version: env!("CARGO_PKG_VERSION").into(),
        chapters,
        analysis_plan: Some(rlfd_report::plan::analysis_plan().line()),
    };
    let json = serde_json::to_vec_pretty(&meta).expect("metadata serialises");
    rlfd_harness::write_atomically(&s.out.join("run.json"), &json)?;
    for c in &meta.chapters {
        eprintln!(
            "{}: {} trials computed, {} reused ({:.1} s to render; trials computed in {:.1} CPU-s)",
            c.chapter, c.trials_computed, c.trials_reused, c.wall_seconds, c.trial_cpu_seconds
        );
    }
    eprintln!(
        "{}: {computed} trials computed, {reused} reused; report in {} ({:.1} s)",
        rendered.done.join(", "),
        s.out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

fn read_summary(path: &Path) -> Result<Option<ChapterSummary>> {
    match std::fs::read(path) {
        Ok(bytes) => {
            let stored: StoredSummary = serde_json::from_slice(&bytes)
                .with_context(|| format!("{} is not a chapter summary (rerun that chapter)", path.display()))?;
            Ok(Some(stored.summary))
        }
        Err(_) => Ok(None),
    }
}

fn git_commit() -> Option<String> {
    let root = crate::cli::workspace_root();
    let head = std::process::Command::new("git").arg("-C").arg(&root).args(["rev-parse", "HEAD"]).output().ok()?;
    if !head.status.success() {
        return None;
    }
    let mut commit = String::from_utf8_lossy(&head.stdout).trim().to_string();
    let dirty = std::process::Command::new("git").arg("-C").arg(&root).args(["status", "--porcelain"]).output().ok()?;
    if !dirty.stdout.is_empty() {
        commit.push_str("-dirty");
    }
    Some(commit)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every declared trial cost names a store folder that the chapter's
    /// trials really use (as the quick-scale records in golden/records.tsv
    /// show), so a renamed or removed experiment cannot leave a stale cost
    /// behind: the shard planner would silently fall back to the default.
    #[test]
    fn declared_trial_costs_name_real_experiments() {
        let records = include_str!("../../golden/records.tsv");
        for chapter in registry() {
            for cost in chapter.trial_costs() {
                let prefix = format!("{}/{}/", chapter.slug(), cost.experiment);
                assert!(
                    records.lines().any(|l| l.starts_with(&prefix)),
                    "{}: a cost is declared for {}, which no trial uses",
                    chapter.slug(),
                    cost.experiment
                );
            }
        }
    }

    #[test]
    fn every_axis_is_well_declared() {
        for chapter in registry() {
            for axis in chapter.readings() {
                axis.check().unwrap_or_else(|e| panic!("{}: {e}", chapter.slug()));
            }
        }
    }
}
