//! `reproduce` and `report`: select chapters and experiments, run (or load)
//! their trials, render their reports, write them.

use std::path::Path;
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result, bail};
use ch6_irl_shaping::{DemonstrationSource, Experiment};
use rlfd_harness::{ResultStore, RunMetadata, RunOptions};
use rlfd_report::{Provenance, render_chapter, render_index};

use crate::cli::RunSettings;
use crate::output;

/// The chapters that exist, by slug, with their short aliases.
const CHAPTERS: [(&str, &str); 1] = [(ch6_irl_shaping::CHAPTER, "ch6")];

fn select_chapter(name: Option<&str>) -> Result<&'static str> {
    match name {
        None => Ok(CHAPTERS[0].0),
        Some(n) => {
            CHAPTERS.iter().find(|(slug, alias)| n == *slug || n == *alias).map(|(slug, _)| *slug).ok_or_else(|| {
                anyhow::anyhow!(
                    "unknown chapter \"{n}\" (expected one of: {}; chapters 3, 4 and 5 are not built yet)",
                    CHAPTERS.iter().map(|c| c.0).collect::<Vec<_>>().join(", ")
                )
            })
        }
    }
}

/// The command that determines the output: no `--jobs`, `--out`, `--results`.
pub fn semantic_command(s: &RunSettings, chapter: &str) -> String {
    let mut c = String::from("cargo xtask reproduce");
    if s.chapter.is_some() {
        c.push_str(&format!(" --chapter {chapter}"));
    }
    if let Some(e) = &s.experiment {
        c.push_str(&format!(" --experiment {e}"));
    }
    c.push_str(&format!(" --scale {} --seed {}", s.scale, s.seed));
    if let Some(d) = &s.demonstrations {
        let name = d.file_name().map_or_else(|| d.display().to_string(), |n| n.to_string_lossy().into_owned());
        c.push_str(&format!(" --demonstrations {name}"));
    }
    c
}

/// Runs (or with `load_only`, loads) and renders.
pub fn reproduce(s: &RunSettings, load_only: bool) -> Result<()> {
    let started = Instant::now();
    let chapter = select_chapter(s.chapter.as_deref())?;
    let experiments: Vec<Experiment> = match &s.experiment {
        None => Experiment::ALL.to_vec(),
        Some(e) => vec![e.parse::<Experiment>().map_err(anyhow::Error::msg)?],
    };
    let source = match &s.demonstrations {
        None => DemonstrationSource::Synthetic,
        Some(p) if experiments.iter().any(|e| e.uses_maze_demonstrations()) => DemonstrationSource::File(p.clone()),
        Some(_) => bail!("--demonstrations applies to the maze experiments, none of which is selected"),
    };
    output::check_writable(&s.out)?;

    let options = RunOptions {
        jobs: s.jobs,
        progress: s.progress,
        store: ResultStore::new(&s.results),
        master_seed: s.seed,
        scale: s.scale,
        load_only,
    };
    let results = ch6_irl_shaping::reproduce(&options, &experiments, &source).with_context(|| format!("{chapter}"))?;
    let provenance = Provenance::new(semantic_command(s, chapter), env!("CARGO_PKG_VERSION"));
    let report = ch6_irl_shaping::report::chapter_report(&results, &provenance).context("rendering the report")?;
    let mut files = render_chapter(&report).context("rendering the report")?;
    files.push(render_index(&[report.summary()], &provenance).context("rendering the index")?);
    output::write_tree(&s.out, &files, &[chapter])?;

    let (computed, reused) = results.trial_counts();
    let meta = RunMetadata {
        command: std::env::args().collect(),
        semantic_command: provenance.command.clone(),
        seed: s.seed,
        scale: s.scale.to_string(),
        jobs: s.jobs,
        commit: git_commit(),
        host: std::fs::read_to_string("/etc/hostname").ok().map(|h| h.trim().to_string()),
        started_unix: SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_secs())
            .saturating_sub(started.elapsed().as_secs()),
        wall_seconds: started.elapsed().as_secs_f64(),
        trials_computed: computed,
        trials_reused: reused,
        version: env!("CARGO_PKG_VERSION").into(),
    };
    let json = serde_json::to_vec_pretty(&meta).expect("metadata serialises");
    rlfd_harness::write_atomically(&s.out.join("run.json"), &json)?;
    eprintln!(
        "{}: {} trials computed, {} reused; report in {} ({:.1} s)",
        chapter,
        computed,
        reused,
        display(&s.out),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

fn display(p: &Path) -> String {
    p.display().to_string()
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
