//! `cargo xtask`: the command line of the reproduction.
//!
//! It holds no science: it parses arguments, calls the chapter crates, and
//! writes what they return. Tasks: `reproduce` (run trials, render reports),
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
mod robustness;
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
        cli::Task::Verify { settings, sample, sample_seed, other_builds } => {
            verify::run(&settings, sample, sample_seed, other_builds)
        }
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
            // One line: the chain of causes joined, no backtrace.
            let msg = format!("{e:#}").replace('\n', " ");
            eprintln!("error: {msg}");
            ExitCode::FAILURE
        }
    }
}
