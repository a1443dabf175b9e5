//! `reproduce` and `report`: select chapters and experiments, run (or load)
//! their trials, render their reports, write them, and rebuild the
//! top-level index from every chapter report present in the output.
//!
//! Each chapter crate implements [`rlfd_harness::Chapter`]; one generic
//! [`adapter::Adapter`] translates the command line's settings into calls
//! to it, and [`all`] is the registry.

mod adapter;

use std::path::Path;
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result, bail};
use rlfd_harness::{ChapterTime, ResultStore, RunMetadata, RunMode, RunOptions, Tally, Workload};
use rlfd_report::{
    Block, ChapterReport, ChapterSummary, Provenance, ReportFile, Section, render_chapter, render_index,
};
use serde::{Deserialize, Serialize};

use crate::cli::RunSettings;
use crate::output;

/// What a chapter's run produced (the trial counts are in the options' tally).
pub struct ChapterRun {
    pub report: ChapterReport,
}

/// What `reproduce` does with the store.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Compute what is missing (`reproduce`).
    Run,
    /// Only read records, of any behaviour version (`report`).
    Report {
        /// When trials are missing, render the experiments that are complete.
        partial: bool,
        /// A plan written before (`--plan`), to name missing trials without planning.
        plan: Option<std::path::PathBuf>,
    },
}

/// A chapter as the command line sees it (shared by the threads that plan
/// a sharded run).
pub trait Chapter: Sync {
    /// The crate's slug (its report directory).
    fn slug(&self) -> &'static str;
    /// A short name accepted by `--chapter` (e.g. `ch6`).
    fn alias(&self) -> &'static str;
    /// The experiments `--experiment` accepts.
    fn experiments(&self) -> Vec<&'static str>;
    /// The open choices it declares.
    fn readings(&self) -> &'static [&'static rlfd_harness::Axis];
    /// The calibrations of its synthetic humans and models.
    fn calibrations(&self) -> Vec<rlfd_harness::Calibration>;
    /// Its build identity (part of every trial's identity).
    fn build(&self) -> &'static str;
    /// What one trial of an experiment (as its trials' keys name it) costs.
    fn trial_cost(&self, experiment: &str) -> rlfd_harness::TrialCost;
    /// Runs the experiments named (or loads or verifies them, as `options.mode` says)
    /// (all when `experiments` is empty) and builds the report.
    fn run(
        &self,
        settings: &RunSettings,
        experiments: &[&str],
        options: &RunOptions,
        provenance: &Provenance,
    ) -> Result<ChapterRun>;
    /// Deterministic work for `bench`.
    fn workloads(&self) -> Result<Vec<Workload<'static>>>;
    /// Checks the settings' inputs (files the user hands in) before any
    /// chapter runs, so a bad input stops the run before a trial is stored.
    fn check_inputs(&self, settings: &RunSettings, experiments: &[&str]) -> Result<()>;
}

/// Every built chapter, in the thesis's order.
pub fn all() -> Vec<Box<dyn Chapter>> {
    use adapter::Adapter;
    vec![
        Box::new(Adapter::<ch3_interactive_rl::Ch3>::new(ch3_interactive_rl::report::chapter_report)),
        Box::new(Adapter::<ch4_dbug_study::Ch4>::new(ch4_dbug_study::report::chapter_report)),
        Box::new(Adapter::<ch5_hat_keepaway::Ch5>::new(ch5_hat_keepaway::report::chapter_report)),
        Box::new(Adapter::<ch6_irl_shaping::Ch6>::new(ch6_irl_shaping::report::chapter_report)),
    ]
}

/// The chapters and experiment a command line selects.
pub fn select(s: &RunSettings) -> Result<Vec<Box<dyn Chapter>>> {
    let mut chapters = all();
    if let Some(name) = &s.chapter {
        let known: Vec<String> = chapters.iter().map(|c| c.slug().to_string()).collect();
        chapters.retain(|c| name == c.slug() || name == c.alias());
        if chapters.is_empty() {
            bail!(
                "unknown chapter \"{name}\" (expected one of: {}; the thesis's other chapters are not built yet)",
                known.join(", ")
            );
        }
    }
    if let Some(e) = &s.experiment {
        let names: Vec<&str> = chapters.iter().flat_map(|c| c.experiments()).collect();
        chapters.retain(|c| c.experiments().contains(&e.as_str()));
        if chapters.is_empty() {
            bail!(
                "unknown experiment \"{e}\"{} (expected one of: {})",
                s.chapter.as_ref().map_or(String::new(), |c| format!(" for {c}")),
                names.join(", ")
            );
        }
    }
    Ok(chapters)
}

/// The experiments `--experiment` names (none: all).
pub fn named(s: &RunSettings) -> Vec<&str> {
    s.experiment.as_deref().into_iter().collect()
}

/// The command that determines the output: no `--jobs`, `--out`, `--results`.
pub fn semantic_command(s: &RunSettings) -> String {
    let mut c = String::from("cargo xtask reproduce");
    if let Some(chapter) = &s.chapter {
        let slug = all()
            .into_iter()
            .find(|ch| chapter == ch.slug() || chapter == ch.alias())
            .map_or(chapter.clone(), |ch| ch.slug().to_string());
        c.push_str(&format!(" --chapter {slug}"));
    }
    if let Some(e) = &s.experiment {
        c.push_str(&format!(" --experiment {e}"));
    }
    c.push_str(&format!(" --scale {} --seed {}", s.scale, s.seed));
    if let Some(r) = &s.reading {
        c.push_str(&format!(" --reading {r}"));
    }
    if s.robustness {
        c.push_str(&format!(" --robustness --seeds {}", s.seeds));
    }
    if let Some(d) = &s.demonstrations {
        let name = d.file_name().map_or_else(|| d.display().to_string(), |n| n.to_string_lossy().into_owned());
        c.push_str(&format!(" --demonstrations {name}"));
    }
    c
}

/// A chapter's summary as stored beside its report, for the index.
#[derive(Serialize, Deserialize)]
struct StoredSummary {
    generated_by: String,
    summary: ChapterSummary,
}

const SUMMARY_FILE: &str = "summary.json";

/// The options a command line's settings give, in `mode`.
pub fn run_options(s: &RunSettings, mode: RunMode) -> RunOptions {
    RunOptions {
        jobs: s.jobs,
        progress: s.progress,
        store: ResultStore::new(&s.results),
        master_seed: s.seed,
        scale: s.scale,
        mode,
        reading: rlfd_harness::Reading::defaults(),
        tally: Tally::new(),
    }
}

/// Runs (or with [`Mode::Report`], loads) and renders.
pub fn reproduce(s: &RunSettings, mode: Mode) -> Result<()> {
    let started = Instant::now();
    let chapters = select(s)?;
    if s.demonstrations.is_some() && !chapters.iter().any(|c| c.slug() == ch6_irl_shaping::CHAPTER) {
        bail!("--demonstrations applies to chapter 6's maze experiments, which are not selected");
    }
    output::check_writable(&s.out)?;
    for chapter in &chapters {
        chapter.check_inputs(s, &named(s)).with_context(|| chapter.slug().to_string())?;
    }
    let provenance = Provenance::new(semantic_command(s), env!("CARGO_PKG_VERSION"));
    let run_mode = match mode {
        Mode::Run => RunMode::Run,
        Mode::Report { .. } => RunMode::Load { any_version: true },
    };
    // Run and render every selected chapter before writing anything. When
    // `report` fails, a plan of the command says whether trials are missing
    // and which; with `--partial` the complete experiments are rendered.
    let rendered = match (render(s, &chapters, &run_mode, &provenance, None), &mode) {
        (Ok(r), _) => r,
        (Err(e), Mode::Report { partial, plan }) => {
            let c = crate::shard::Completeness::check(s, &provenance, plan.as_deref())?;
            if c.missing.is_empty() {
                return Err(e);
            }
            let what = c.describe(&s.results);
            if !partial {
                bail!(
                    "{what}; run the shards or the reproduction that computes them, or pass --partial to render what is there"
                );
            }
            eprintln!("warning: {what}; rendering what is there (--partial)");
            render(s, &chapters, &run_mode, &provenance, Some(&c))?
        }
        (Err(e), Mode::Run) => return Err(e),
    };
    let Rendered { mut files, rendered, done, tally: options_tally, times } = rendered;

    // The index covers every chapter whose report is in the output: the ones
    // rendered now, and the others as their stored summaries say.
    let mut summaries = Vec::new();
    for chapter in all() {
        if let Some(s) = rendered.iter().find(|r| r.slug == chapter.slug()) {
            summaries.push(s.clone());
        } else if let Some(stored) = read_summary(&s.out.join(chapter.slug()).join(SUMMARY_FILE))? {
            summaries.push(stored);
        }
    }
    files.extend(render_index(&summaries, &provenance).context("rendering the index")?);
    output::write_tree(&s.out, &files, &done)?;

    let (computed, reused, _, _) = options_tally.totals();
    let per_experiment = options_tally.experiments();
    let chapters: Vec<ChapterTime> = times
        .into_iter()
        .map(|(chapter, wall_seconds)| {
            let of_chapter = per_experiment.iter().filter(|((c, _), _)| *c == chapter).map(|(_, t)| t);
            let (trials_computed, trials_reused) = of_chapter.fold((0, 0), |(c, r), t| (c + t.computed, r + t.reused));
            ChapterTime { chapter, wall_seconds, trials_computed, trials_reused }
        })
        .collect();
    for t in per_experiment.values() {
        for (path, reason) in &t.replaced {
            eprintln!("warning: the record {} could not be read ({reason}) and was recomputed", path.display());
        }
    }
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
        chapters,
    };
    let json = serde_json::to_vec_pretty(&meta).expect("metadata serialises");
    rlfd_harness::write_atomically(&s.out.join("run.json"), &json)?;
    for c in &meta.chapters {
        eprintln!(
            "{}: {} trials computed, {} reused ({:.1} s)",
            c.chapter, c.trials_computed, c.trials_reused, c.wall_seconds
        );
    }
    eprintln!(
        "{}: {computed} trials computed, {reused} reused; report in {} ({:.1} s)",
        done.join(", "),
        s.out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// What rendering the selected chapters produced.
struct Rendered {
    files: Vec<ReportFile>,
    rendered: Vec<ChapterSummary>,
    done: Vec<&'static str>,
    tally: Tally,
    /// Each rendered chapter's wall time in seconds (trials, robustness run, rendering).
    times: Vec<(String, f64)>,
}

/// Runs (or loads) and renders every chapter of `chapters`; with
/// `incomplete`, only the experiments the store holds whole, with a banner
/// saying what is left out.
fn render(
    s: &RunSettings,
    chapters: &[Box<dyn Chapter>],
    mode: &RunMode,
    provenance: &Provenance,
    incomplete: Option<&crate::shard::Completeness>,
) -> Result<Rendered> {
    let mut options = run_options(s, mode.clone());
    options.reading = reading(s)?;
    let mut files: Vec<ReportFile> = Vec::new();
    let mut rendered: Vec<ChapterSummary> = Vec::new();
    let mut done: Vec<&'static str> = Vec::new();
    let mut times: Vec<(String, f64)> = Vec::new();
    for chapter in chapters {
        let started = Instant::now();
        let (experiments, banner) = match incomplete {
            Some(c) => {
                let kept = c.kept.get(chapter.slug()).cloned().unwrap_or_default();
                if kept.is_empty() {
                    eprintln!("warning: {} left out: none of its experiments is complete", chapter.slug());
                    continue;
                }
                (kept, partial_banner(c, chapter.slug()))
            }
            None => (named(s), None),
        };
        let mut run = chapter.run(s, &experiments, &options, provenance).with_context(|| chapter.slug().to_string())?;
        let robustness_complete = incomplete.is_none_or(|c| !c.robustness_missing.contains_key(chapter.slug()));
        let robustness = if s.robustness && robustness_complete {
            let runs = crate::robustness::Runs { mode: mode.clone(), experiments: &experiments, provenance };
            Some(crate::robustness::run(chapter.as_ref(), s, s.seeds, &runs)?)
        } else {
            None
        };
        let robustness_other = robustness.as_ref().map(|(_, other)| other);
        if let Some(banner) = other_versions_banner(&options.tally, chapter.slug(), robustness_other) {
            eprintln!("warning: {}", banner.replace('`', ""));
            run.report.sections.insert(
                0,
                Section {
                    title: "Records of another behaviour version".into(),
                    blocks: vec![Block::Paragraph(banner)],
                },
            );
        }
        if let Some(banner) = banner {
            run.report
                .sections
                .insert(0, Section { title: "Incomplete store".into(), blocks: vec![Block::Paragraph(banner)] });
        }
        let robustness = match robustness {
            Some((r, _)) => {
                let headline = run.report.summary().claims;
                run.report.sections.push(r.section(&headline).context("rendering the robustness section")?);
                Some(r)
            }
            None => None,
        };
        files.extend(render_chapter(&run.report).with_context(|| format!("rendering {}", chapter.slug()))?);
        let mut summary = run.report.summary();
        summary.robustness = robustness;
        let stored = StoredSummary { generated_by: provenance.line(), summary: summary.clone() };
        let mut json = serde_json::to_vec_pretty(&stored).expect("summaries serialise");
        json.push(b'\n');
        files.push(ReportFile { path: format!("{}/{SUMMARY_FILE}", chapter.slug()), bytes: json });
        rendered.push(summary);
        done.push(chapter.slug());
        times.push((chapter.slug().to_string(), started.elapsed().as_secs_f64()));
    }
    if done.is_empty() {
        bail!("nothing to render: no selected experiment has all its trials in {}", s.results.display());
    }
    Ok(Rendered { files, rendered, done, tally: options.tally, times })
}

/// The reading `--reading` names, checked against every chapter's axes.
pub fn reading(s: &RunSettings) -> Result<rlfd_harness::Reading> {
    let Some(text) = &s.reading else {
        return Ok(rlfd_harness::Reading::defaults());
    };
    let axes: Vec<&'static rlfd_harness::Axis> = all().iter().flat_map(|c| c.readings().iter().copied()).collect();
    Ok(rlfd_harness::Reading::parse(text, &axes)?)
}

/// The banner of a chapter rendered with `--partial` from a store that lacks
/// trials of it (`None` when it lacks none).
fn partial_banner(c: &crate::shard::Completeness, slug: &str) -> Option<String> {
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
/// behaviour versions or builds, naming each experiment and the version that
/// made its records; `None` when every record is current.
fn other_versions_banner(
    tally: &Tally,
    slug: &str,
    robustness: Option<&crate::robustness::OtherRecords>,
) -> Option<String> {
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
    if let Some(other) = robustness.filter(|o| !o.by_version.is_empty()) {
        // A trial several runs share (a reading that leaves an experiment
        // alone reads the headline's) counts once per run.
        let made: Vec<String> = other
            .by_version
            .iter()
            .map(|((behaviour, current, build), n)| {
                let which = if *current { "the current behaviour version" } else { "another behaviour version" };
                format!("{n} from {which} {behaviour} built by {build}")
            })
            .collect();
        parts.push(format!(
            "the robustness section's replications and readings (`--robustness`): of the {} trials they read, {}",
            other.trials,
            made.join("; ")
        ));
    }
    (!parts.is_empty()).then(|| {
        format!(
            "*Not current.* This report was rendered from stored records that the current code would not reuse: {}. Rerun `cargo xtask reproduce` for those experiments to replace them.",
            parts.join("; ")
        )
    })
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

    /// Every declared trial cost names a store folder that the chapter's
    /// trials really use (as the quick-scale records in golden/records.tsv
    /// show), so a renamed or removed experiment cannot leave a stale cost
    /// behind: the shard planner would silently fall back to the default.
    #[test]
    fn declared_trial_costs_name_real_experiments() {
        let records = include_str!("../../../golden/records.tsv");
        fn check<C: rlfd_harness::Chapter>(records: &str) {
            for cost in C::TRIAL_COSTS {
                let prefix = format!("{}/{}/", C::ID.slug, cost.experiment);
                assert!(
                    records.lines().any(|l| l.starts_with(&prefix)),
                    "{}: a cost is declared for {}, which no trial uses",
                    C::ID.slug,
                    cost.experiment
                );
            }
        }
        check::<ch3_interactive_rl::Ch3>(records);
        check::<ch4_dbug_study::Ch4>(records);
        check::<ch5_hat_keepaway::Ch5>(records);
        check::<ch6_irl_shaping::Ch6>(records);
    }
}
