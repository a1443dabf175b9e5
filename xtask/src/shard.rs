//! `reproduce --shard I/N`: one of N machines' share of a command (the
//! runner plans the command and deals it by cost; see
//! [`rlfd_runner::shard`]). With `--plan FILE` (written by `cargo xtask
//! slurm`) the plan is checked to be this command's and this build's.

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result};
use rlfd_harness::ResultStore;
use rlfd_runner::Selection;
use rlfd_runner::plan::plan;
use rlfd_runner::shard::{Shard, Share, run as run_shard};

use crate::chapters::{log, registry};
use crate::cli::RunSettings;

/// Runs shard `shard` of the command `s` (or with `dry_run`, prints what it
/// would run): trial records only, no report.
pub fn run(s: &RunSettings, shard: Shard, plan_file: Option<&Path>, dry_run: bool) -> Result<()> {
    let started = Instant::now();
    let registry = registry();
    let selection = Selection::new(s.command.clone(), &registry)?;
    let planned = plan(&selection, &s.machine.results)?;
    if let Some(file) = plan_file {
        let bytes = std::fs::read(file).with_context(|| format!("cannot read the plan {}", file.display()))?;
        planned.check_file(file, &bytes, &s.machine.results)?;
    }
    let share = Share::of(&planned, shard, &ResultStore::new(&s.machine.results));
    eprintln!(
        "shard {shard}: {} of the {} trials planned (estimated {:.0} CPU-s of {:.0}), {} already stored; share {}",
        share.mine.len(),
        planned.trials.len(),
        share.seconds.0,
        share.seconds.1,
        share.mine.len() - share.waiting.len(),
        share.digest(&planned, &s.machine.results)
    );
    if dry_run {
        for &i in &share.waiting {
            let t = &planned.trials[i];
            println!("{}", t.path.strip_prefix(&s.machine.results).unwrap_or(&t.path).display());
        }
        return Ok(());
    }
    let mut logger = log;
    let ran = run_shard(&planned, &share, shard, &s.machine, &mut logger)?;
    for (path, reason) in &ran.replaced {
        eprintln!("warning: the record {} could not be read ({reason}) and was recomputed", path.display());
    }
    eprintln!(
        "shard {shard}: {} trials computed, {} reused; records in {} ({:.1} s)",
        ran.computed,
        share.mine.len() - ran.computed,
        s.machine.results.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
