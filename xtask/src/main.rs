//! `cargo xtask`: the command line of the reproduction.
//!
//! It holds no science and no run logic: it parses arguments, calls the
//! runner (`rlfd-runner`) with the registry of built chapters, and writes
//! what it returns; and it keeps the developer tools (golden, pdf, diff,
//! bench, calibrate, render). Tasks: `reproduce` (run trials, render reports),
//! `report` (re-render from stored results, of any behaviour version),
//! `verify` (recompute a sample of stored trials, compare byte for byte), `golden` (compare the
//! quick-scale report with `golden/`, or bless it), `bench` (steps per
//! second per domain and agent), `render` (draw a generated Mario level and
//! the demonstrator's path as SVG), `diff` (compare two report trees by
//! meaning; exit 1 when they differ), `pdf` (build and check the LaTeX),
//! `merge` (result stores into one), `slurm` (batch scripts: an array job of
//! shards, then the report); `reproduce --shard I/N` runs one shard's trials.
//! Errors are one line on stderr and a
//! non-zero exit.

mod bench;
mod calibrate;
mod chapters;
mod cli;
mod diff;
mod golden;
mod merge;
mod output;
mod pdf;
mod render;
mod shard;
mod slurm;
mod verify;

use std::process::ExitCode;

fn main() -> ExitCode {
    let args = match cli::parse() {
        Ok(args) => args,
        Err(exit) => return exit,
    };
    let result = match args.task {
        cli::Task::Reproduce(opts) => chapters::reproduce(&opts, chapters::Mode::Run),
        cli::Task::Shard { settings, shard, plan, dry_run } => shard::run(&settings, shard, plan.as_deref(), dry_run),
        cli::Task::Report { settings, partial, plan } => {
            chapters::reproduce(&settings, chapters::Mode::Report { partial, plan })
        }
        cli::Task::Merge(options) => merge::run(&options),
        cli::Task::Slurm(options) => slurm::run(&options),
        cli::Task::Verify { settings, sample, sample_seed } => verify::run(&settings, sample, sample_seed),
        cli::Task::Golden { bless } => golden::run(bless),
        cli::Task::Calibrate { model } => calibrate::run(model.as_deref()),
        cli::Task::Bench { quick } => bench::run(quick),
        cli::Task::RenderMario { level_seed, out } => render::mario(level_seed, &out),
        cli::Task::Diff(options) => return diff::run(&options),
        cli::Task::Pdf(options) => pdf::run(&options),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", one_line(&e));
            ExitCode::FAILURE
        }
    }
}

/// An error in one line: its chain of causes joined by ": ", leaving out a
/// cause whose text the message already holds (errors that print their
/// source themselves), with no backtrace.
fn one_line(e: &anyhow::Error) -> String {
    let mut msg = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if !msg.contains(&text) {
            if !msg.is_empty() {
                msg.push_str(": ");
            }
            msg.push_str(&text);
        }
    }
    msg.replace('\n', " ")
}
