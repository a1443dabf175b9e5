//! `reproduce` and `report`: run (or load) every selected chapter at its
//! headline point (with its sweeps), render its report, add its robustness
//! section when asked, and return the files; the caller writes them and the
//! index.
//!
//! `reproduce` computes first ([`compute`]): every trial the command needs
//! that the store lacks, at every run point of every chapter, through one
//! pool of workers (the whole run as its one shard, [`crate::shard`]), so
//! no core waits at a batch's end for the last trial or for the next
//! batch's set-up; the rendering then reads the records.
//!
//! A report rendered from records of other code versions opens with a
//! banner naming the experiment and the version that made them; one
//! rendered with `--partial` from an incomplete store opens with what it
//! leaves out.

use std::time::Instant;

use rlfd_harness::{RunMode, Tally};
use rlfd_report::{Block, ChapterSummary, Provenance, ReportFile, Section, render_chapter};
use serde::{Deserialize, Serialize};

use crate::Machine;
use crate::command::Selection;
use crate::error::RunnerError;
use crate::plan::{Completeness, plan};
use crate::shard::{Shard, ShardRun, Share};

/// A chapter's summary as stored beside its report, for the index.
#[derive(Serialize, Deserialize)]
pub struct StoredSummary {
    /// The provenance line.
    pub generated_by: String,
    /// The summary.
    pub summary: ChapterSummary,
}

/// The file name of a chapter's stored summary.
pub const SUMMARY_FILE: &str = "summary.json";

/// What rendering the selected chapters produced.
pub struct Rendered {
    /// The chapters' files (each below its slug's directory).
    pub files: Vec<ReportFile>,
    /// The summaries of the chapters rendered.
    pub summaries: Vec<ChapterSummary>,
    /// Their slugs, in order.
    pub done: Vec<&'static str>,
    /// The headline runs' tally.
    pub tally: Tally,
    /// Each rendered chapter's wall time in seconds (trials, robustness, rendering).
    pub times: Vec<(String, f64)>,
}

/// Computes every trial of `selection` (at every run point) that the store
/// lacks, through one pool of `machine.jobs` workers; `None` when nothing
/// was missing. `log` hears the plan's size and one line per run point.
pub fn compute(
    selection: &Selection<'_>,
    machine: &Machine,
    log: &mut (dyn FnMut(String) + Send),
) -> Result<Option<ShardRun>, RunnerError> {
    let planned = plan(selection, &machine.results)?;
    let whole = Shard { index: 1, count: 1 };
    let share = Share::of(&planned, whole, &rlfd_harness::ResultStore::new(&machine.results));
    if share.waiting.is_empty() {
        return Ok(None);
    }
    let seconds: f64 = share.waiting.iter().map(|&i| planned.trials[i].seconds).sum();
    log(format!(
        "{} of the {} trials planned to compute (estimated {seconds:.0} CPU-s), {} workers",
        share.waiting.len(),
        planned.trials.len(),
        machine.jobs
    ));
    crate::shard::run(&planned, &share, whole, machine, log).map(Some)
}

/// Runs (or, in a load `mode`, reads) and renders every selected chapter;
/// with `incomplete`, only the experiments the store holds whole, with a
/// banner saying what is left out. `log` hears progress and warnings.
pub fn render(
    selection: &Selection<'_>,
    machine: &Machine,
    mode: &RunMode,
    provenance: &Provenance,
    incomplete: Option<&Completeness>,
    log: &mut dyn FnMut(String),
) -> Result<Rendered, RunnerError> {
    let options = machine.options(mode.clone());
    let given = selection.inputs();
    let ctx = selection.context();
    let mut out = Rendered {
        files: Vec::new(),
        summaries: Vec::new(),
        done: Vec::new(),
        tally: options.tally.clone(),
        times: Vec::new(),
    };
    for &chapter in &selection.chapters {
        let started = Instant::now();
        let (experiments, banner): (Vec<String>, Option<String>) = match incomplete {
            Some(c) => {
                let kept = c.kept.get(chapter.slug()).cloned().unwrap_or_default();
                if kept.is_empty() {
                    log(format!("warning: {} left out: none of its experiments is complete", chapter.slug()));
                    continue;
                }
                (kept, partial_banner(c, chapter.slug()))
            }
            None => (selection.named().iter().map(|s| s.to_string()).collect(), None),
        };
        let experiments: Vec<&str> = experiments.iter().map(String::as_str).collect();
        let ran = chapter.run(&given, &experiments, &ctx, &options, Some(provenance))?;
        let mut report = ran.report.expect("a report was asked for");
        let robustness_complete = incomplete.is_none_or(|c| !c.robustness_missing.contains_key(chapter.slug()));
        let (robustness, robustness_versions) = if selection.command.robustness.is_some() && robustness_complete {
            let points = crate::robustness::run(selection, chapter, machine, mode, log)?;
            (Some(points.robustness(selection, chapter, &ran.claims)), points.other_versions_part())
        } else {
            (None, None)
        };
        if let Some(banner) = other_versions_banner(&options.tally, chapter.slug(), robustness_versions) {
            log(format!("warning: {}", banner.replace('`', "")));
            report.sections.insert(
                0,
                Section {
                    title: "Records of another behaviour version".into(),
                    blocks: vec![Block::Paragraph(banner)],
                },
            );
        }
        if let Some(banner) = banner {
            report
                .sections
                .insert(0, Section { title: "Incomplete store".into(), blocks: vec![Block::Paragraph(banner)] });
        }
        if let Some(r) = &robustness {
            let headline = report.summary().claims;
            let section = r
                .section(&headline, provenance)
                .map_err(|source| RunnerError::Report { chapter: chapter.slug(), source })?;
            report.sections.push(section);
            // The pooled verdict decides the headline at the paper scale
            // only: a quick run is shorter than the thesis's, and its
            // verdicts stay "not evaluable" (the table still shows the pool).
            if selection.command.scale == rlfd_harness::Scale::Paper {
                r.decide(&mut report);
            }
        }
        out.files
            .extend(render_chapter(&report).map_err(|source| RunnerError::Report { chapter: chapter.slug(), source })?);
        let mut summary = report.summary();
        summary.robustness = robustness;
        let stored = StoredSummary { generated_by: provenance.line(), summary: summary.clone() };
        let mut json = serde_json::to_vec_pretty(&stored).expect("summaries serialise");
        json.push(b'\n');
        out.files.push(ReportFile { path: format!("{}/{SUMMARY_FILE}", chapter.slug()), bytes: json });
        out.summaries.push(summary);
        out.done.push(chapter.slug());
        out.times.push((chapter.slug().to_string(), started.elapsed().as_secs_f64()));
    }
    Ok(out)
}

/// The banner of a chapter rendered with `--partial` from a store that lacks
/// trials of it (`None` when it lacks none).
fn partial_banner(c: &Completeness, slug: &str) -> Option<String> {
    let mut parts: Vec<String> = c
        .left_out
        .get(slug)
        .into_iter()
        .flatten()
        .map(|(e, missing, planned)| format!("`{e}` is left out ({missing} of its {planned} trials are missing)"))
        .collect();
    if let Some(n) = c.robustness_missing.get(slug) {
        parts.push(format!("the robustness section is left out ({n} trials of its runs are missing)"));
    }
    (!parts.is_empty()).then(|| {
        format!(
            "*Incomplete.* This report was rendered with `--partial` from a store that lacks trials: {}. Compute them (`cargo xtask reproduce`, or the missing shards) and render again.",
            parts.join("; ")
        )
    })
}

/// The banner of a chapter whose report was rendered from records of other
/// code versions, naming each experiment and the version that made its
/// records; `None` when every record is current.
fn other_versions_banner(tally: &Tally, slug: &str, robustness: Option<String>) -> Option<String> {
    let mut parts = Vec::new();
    for ((chapter, experiment), t) in tally.experiments() {
        if chapter != slug || t.other_versions.is_empty() {
            continue;
        }
        let made: Vec<String> = t
            .other_versions
            .iter()
            .map(|((behaviour, build), n)| {
                let what = if *behaviour == t.behaviour {
                    format!("behaviour version {behaviour} built by {build}")
                } else {
                    format!("behaviour version {behaviour}")
                };
                format!("{n} of its {} trials come from {what}", t.keys.len())
            })
            .collect();
        parts.push(format!("`{experiment}` (current version {}): {}", t.behaviour, made.join("; ")));
    }
    parts.extend(robustness);
    (!parts.is_empty()).then(|| {
        format!(
            "*Not current.* This report was rendered from stored records that the current code would not reuse: {}. Rerun `cargo xtask reproduce` for those experiments to replace them.",
            parts.join("; ")
        )
    })
}
