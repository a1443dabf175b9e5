//! `slurm`: batch scripts for a Slurm cluster, written from the plan of the
//! command they run (the scripts' text and the request are the runner's,
//! [`rlfd_runner::slurm`]): `plan.json`, `shards.sbatch` (an array of N
//! shards), `report.sbatch` (the report once every shard has succeeded) and
//! `submit.sh`; with `--submit`, submitted.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use rlfd_runner::Selection;
use rlfd_runner::plan::plan;
use rlfd_runner::slurm::{Request, scripts, slurm_time};

use crate::chapters::registry;
use crate::cli::RunSettings;

/// What `slurm` was asked.
#[derive(Clone, Debug)]
pub struct Options {
    /// The command the shards run.
    pub settings: RunSettings,
    /// Array tasks.
    pub shards: u32,
    /// CPUs per task.
    pub cpus_per_task: usize,
    /// Where to write the scripts.
    pub dir: PathBuf,
    /// Extra sbatch options for both jobs.
    pub sbatch: Vec<String>,
    /// Submit after writing.
    pub submit: bool,
}

/// `path` made absolute against the current directory.
fn absolute(path: &Path) -> Result<PathBuf> {
    if path.is_absolute() {
        return Ok(path.to_path_buf());
    }
    Ok(std::env::current_dir().context("cannot read the current directory")?.join(path))
}

pub fn run(o: &Options) -> Result<()> {
    let mut command = o.settings.command.clone();
    if let Some(d) = &command.demonstrations {
        if !d.is_file() {
            bail!("--demonstrations: {} is not a file", d.display());
        }
        command.demonstrations = Some(absolute(d)?);
    }
    let registry = registry();
    let selection = Selection::new(command.clone(), &registry)?;
    let results = absolute(&o.settings.machine.results)?;
    let planned = plan(&selection, &results)?;
    if planned.trials.is_empty() {
        bail!("the command plans no trials: nothing to run on a cluster");
    }
    let request = Request::of(&planned, o.shards, o.cpus_per_task);
    let dir = absolute(&o.dir)?;
    let options = rlfd_runner::slurm::Options {
        shards: o.shards,
        cpus_per_task: o.cpus_per_task,
        dir: dir.clone(),
        sbatch: o.sbatch.clone(),
        results: results.clone(),
        out: absolute(&o.settings.out)?,
        xtask: std::env::current_exe().context("cannot find the xtask binary")?,
    };
    let files = scripts(&options, &command, &selection.semantic_command(), &request)?;
    fs::create_dir_all(dir.join("logs")).with_context(|| format!("cannot create {}", dir.display()))?;
    rlfd_harness::write_atomically(&dir.join("plan.json"), &planned.to_file(&results))?;
    for (name, text) in &files {
        rlfd_harness::write_atomically(&dir.join(name), text.as_bytes())?;
    }
    eprintln!(
        "slurm: {} shards of {} trials ({:.0} CPU-s estimated in all; per task {} and {} MiB); scripts in {}",
        o.shards,
        request.trials,
        request.total_seconds,
        slurm_time(request.minutes),
        request.mib,
        dir.display()
    );
    if o.submit {
        let status = std::process::Command::new("bash")
            .arg(dir.join("submit.sh"))
            .status()
            .context("cannot run bash to submit the jobs")?;
        if !status.success() {
            bail!("submitting failed ({status}): is Slurm's sbatch on PATH and the controller up?");
        }
    } else {
        eprintln!("submit with: bash {}", dir.join("submit.sh").display());
    }
    Ok(())
}
