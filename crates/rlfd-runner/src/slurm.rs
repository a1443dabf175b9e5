//! Slurm batch scripts written from the plan of the command they run: an
//! array job of N shards (task I runs `xtask reproduce --shard I/N` with the
//! command's flags into one result store) and a report job that renders the
//! report from that store once every shard has succeeded, with a
//! `submit.sh` that submits both (rerun after a failed or cancelled task:
//! every task reuses the records already stored and computes only what is
//! missing). The command line writes the files and submits.
//!
//! Each task's request comes from the chapters' declared per-trial costs
//! ([`rlfd_harness::TrialCost`]) over the plan's deal: the time is twice the
//! heaviest shard's CPU seconds over its CPUs (at least the longest trial),
//! plus 10 minutes for planning and the chapters' set-up; the memory is 512
//! MiB for the process and the plan, plus one heaviest trial per CPU. The
//! report job asks for 30 minutes plus a minute per thousand trials it
//! reads (it loads every record and runs the chapters' set-ups again).
//! Both are written into the script with the estimate they come from. The
//! scripts call the `xtask` binary that wrote them (by absolute path), so
//! build it once where every node can reach it; all paths in them are
//! absolute.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::command::Command;
use crate::plan::Plan;

/// What `slurm` was asked.
#[derive(Clone, Debug)]
pub struct Options {
    /// Array tasks.
    pub shards: u32,
    /// CPUs per task.
    pub cpus_per_task: usize,
    /// Where the scripts go (absolute).
    pub dir: PathBuf,
    /// Extra sbatch options for both jobs.
    pub sbatch: Vec<String>,
    /// The result store (absolute).
    pub results: PathBuf,
    /// The report's directory (absolute).
    pub out: PathBuf,
    /// The `xtask` binary (absolute).
    pub xtask: PathBuf,
}

/// A task's request, and the estimate behind it.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// Trials planned in all.
    pub trials: usize,
    /// The heaviest shard's expected CPU seconds and trials.
    pub heaviest: (f64, usize),
    /// Every shard's expected CPU seconds, summed.
    pub total_seconds: f64,
    /// The time limit, in minutes.
    pub minutes: u64,
    /// The memory, in MiB.
    pub mib: u64,
    /// The report job's time limit, in minutes.
    pub report_minutes: u64,
}

impl Request {
    /// The request for `plan` dealt to `shards` tasks of `cpus` CPUs each.
    pub fn of(plan: &Plan<'_>, shards: u32, cpus: usize) -> Request {
        let loads = plan.loads(shards);
        let heaviest = loads.iter().copied().fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
        let total_seconds = loads.iter().map(|l| l.0).sum();
        let longest_trial = plan.trials.iter().map(|t| t.seconds).fold(0.0, f64::max);
        let wall = (heaviest.0 / cpus as f64).max(longest_trial);
        let minutes = (2.0 * wall / 60.0).ceil() as u64 + 10;
        let minutes = minutes.div_ceil(5) * 5;
        let trial_mib = plan.trials.iter().map(|t| t.mib).fold(0.0, f64::max);
        let mib = (512.0 + cpus as f64 * trial_mib).ceil() as u64;
        let mib = mib.div_ceil(64) * 64;
        let report_minutes = (plan.trials.len() as u64).div_ceil(1000).saturating_add(30).div_ceil(5) * 5;
        Request { trials: plan.trials.len(), heaviest, total_seconds, minutes, mib, report_minutes }
    }
}

/// `H:MM:SS` for Slurm's `--time`.
pub fn slurm_time(minutes: u64) -> String {
    format!("{}:{:02}:00", minutes / 60, minutes % 60)
}

/// `text` as one shell word.
fn quote(text: &str) -> String {
    if !text.is_empty() && text.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c)) {
        text.to_string()
    } else {
        format!("'{}'", text.replace('\'', r"'\''"))
    }
}

/// The flags that select the command's trials (as `reproduce` takes them).
pub fn run_flags(s: &Command, results: &Path) -> Vec<String> {
    let mut flags = Vec::new();
    if let Some(c) = &s.chapter {
        flags.extend(["--chapter".to_string(), c.clone()]);
    }
    if let Some(e) = &s.experiment {
        flags.extend(["--experiment".to_string(), e.clone()]);
    }
    flags.extend(["--scale".to_string(), s.scale.to_string(), "--seed".to_string(), s.seed.to_string()]);
    if let Some(r) = &s.reading {
        flags.extend(["--reading".to_string(), r.clone()]);
    }
    if let Some(r) = s.robustness {
        flags.extend(["--robustness".to_string(), "--seeds".to_string(), r.seeds.to_string()]);
        flags.extend(["--reading-seeds".to_string(), r.reading_seeds.to_string()]);
    }
    if let Some(d) = &s.demonstrations {
        flags.extend(["--demonstrations".to_string(), d.display().to_string()]);
    }
    flags.extend(["--results".to_string(), results.display().to_string()]);
    flags
}

/// The three files, as (name, text).
pub fn scripts(
    o: &Options,
    command: &Command,
    semantic: &str,
    request: &Request,
) -> Result<Vec<(&'static str, String)>, std::fmt::Error> {
    let s = command;
    let dir = &o.dir;
    let logs = dir.join("logs");
    let mut flags = run_flags(s, &o.results);
    flags.extend(["--plan".to_string(), dir.join("plan.json").display().to_string()]);
    let flags: Vec<String> = flags.iter().map(|f| quote(f)).collect();
    let flags = flags.join(" ");
    let xtask = quote(&o.xtask.display().to_string());
    let command = semantic;
    let extra: String = o.sbatch.iter().map(|opt| format!("#SBATCH {opt}\n")).collect();
    let n = o.shards;
    let cpus = o.cpus_per_task;

    let mut shards = String::new();
    writeln!(shards, "#!/bin/bash")?;
    writeln!(shards, "# Shards of `{command}`: array task I runs `xtask reproduce --shard I/{n}`,")?;
    writeln!(shards, "# writing trial records (no report) into one store. Written by `cargo xtask slurm`;")?;
    writeln!(shards, "# submit with submit.sh (this array, then the report after it).")?;
    writeln!(shards, "#")?;
    writeln!(shards, "# Cost estimate (the chapters' declared CPU seconds per trial):")?;
    writeln!(
        shards,
        "#   {} trials, {:.0} CPU-s in all; the heaviest of the {n} shards: {} trials, {:.0} CPU-s,",
        request.trials, request.total_seconds, request.heaviest.1, request.heaviest.0
    )?;
    writeln!(shards, "#   about {:.0} min on {cpus} CPUs.", request.heaviest.0 / cpus as f64 / 60.0)?;
    writeln!(shards, "# Request per task: twice that (at least the longest trial) + 10 min for planning and set-up;")?;
    writeln!(shards, "#   512 MiB + {cpus} CPUs x the heaviest trial's memory.")?;
    writeln!(shards, "#SBATCH --job-name=rlfd-shards")?;
    writeln!(shards, "#SBATCH --array=1-{n}")?;
    writeln!(shards, "#SBATCH --cpus-per-task={cpus}")?;
    writeln!(shards, "#SBATCH --time={}", slurm_time(request.minutes))?;
    writeln!(shards, "#SBATCH --mem={}M", request.mib)?;
    writeln!(shards, "#SBATCH --output={}/shard-%A_%a.out", logs.display())?;
    shards.push_str(&extra);
    writeln!(shards, "set -euo pipefail")?;
    writeln!(
        shards,
        "exec {xtask} reproduce --shard \"$SLURM_ARRAY_TASK_ID/{n}\" --jobs \"${{SLURM_CPUS_PER_TASK:-{cpus}}}\" --no-progress {flags}"
    )?;

    let out = quote(&o.out.display().to_string());
    let mut report = String::new();
    writeln!(report, "#!/bin/bash")?;
    writeln!(report, "# The report of `{command}`, rendered from the store the shards filled.")?;
    writeln!(report, "# Written by `cargo xtask slurm`; submit.sh runs it after every shard has succeeded.")?;
    writeln!(report, "#SBATCH --job-name=rlfd-report")?;
    writeln!(report, "#SBATCH --cpus-per-task={cpus}")?;
    writeln!(report, "# Request: 30 min + 1 min per 1,000 trials it reads.")?;
    writeln!(report, "#SBATCH --time={}", slurm_time(request.report_minutes))?;
    writeln!(report, "#SBATCH --mem=2048M")?;
    writeln!(report, "#SBATCH --output={}/report-%j.out", logs.display())?;
    report.push_str(&extra);
    writeln!(report, "set -euo pipefail")?;
    writeln!(
        report,
        "exec {xtask} report --jobs \"${{SLURM_CPUS_PER_TASK:-{cpus}}}\" --no-progress {flags} --out {out}"
    )?;

    let mut submit = String::new();
    writeln!(submit, "#!/bin/bash")?;
    writeln!(submit, "# Submits the {n} shards of `{command}` as one array job, then the report,")?;
    writeln!(submit, "# to run once every shard has succeeded. Run it again after a failed or")?;
    writeln!(submit, "# cancelled task: finished trials are reused, only missing ones are computed.")?;
    writeln!(submit, "set -euo pipefail")?;
    writeln!(submit, "here=\"$(cd \"$(dirname \"$0\")\" && pwd)\"")?;
    writeln!(submit, "mkdir -p \"$here/logs\"")?;
    writeln!(submit, "shards=$(sbatch --parsable \"$here/shards.sbatch\")")?;
    writeln!(submit, "shards=${{shards%%;*}}")?;
    writeln!(submit, "report=$(sbatch --parsable --dependency=afterok:\"$shards\" \"$here/report.sbatch\")")?;
    writeln!(submit, "report=${{report%%;*}}")?;
    writeln!(
        submit,
        "echo \"submitted: shards job $shards (array 1-{n}), report job $report (after every shard succeeds)\""
    )?;
    Ok(vec![("shards.sbatch", shards), ("report.sbatch", report), ("submit.sh", submit)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_and_words_are_written_as_slurm_and_the_shell_read_them() {
        assert_eq!(slurm_time(15), "0:15:00");
        assert_eq!(slurm_time(125), "2:05:00");
        assert_eq!(quote("/a/b-c_d.e"), "/a/b-c_d.e");
        assert_eq!(quote("it's here"), "'it'\\''s here'");
        assert_eq!(quote(""), "''");
    }
}
