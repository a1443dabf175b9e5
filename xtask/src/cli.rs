//! Arguments: parsed by clap, then checked into settings (paths, chapters,
//! experiments) before anything runs. A bad flag or value is one line on
//! stderr and exit code 2.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use rlfd_harness::Scale;
use rlfd_runner::{Command, Machine, Replications};

/// The default master seed of every run.
pub const DEFAULT_SEED: u64 = rlfd_harness::THESIS_MASTER_SEED;

#[derive(Parser, Debug)]
#[command(
    name = "cargo xtask",
    about = "Reproduce the thesis \"Reinforcement Learning from Demonstration\" (H. B. Suay): run its experiments, render its reports.",
    disable_version_flag = true
)]
struct Cli {
    #[command(subcommand)]
    task: RawTask,
}

#[derive(Subcommand, Debug)]
enum RawTask {
    /// Run every (or one) chapter's experiments from a seed and render the reports.
    Reproduce {
        #[command(flatten)]
        run: RunArgs,
        /// Run only shard I of N of the trials (dealt by expected cost) and write trial records, no report.
        #[arg(long, value_name = "I/N")]
        shard: Option<rlfd_runner::shard::Shard>,
        /// With --shard: print the shard's trials still to compute, and run nothing.
        #[arg(long, requires = "shard")]
        dry_run: bool,
        /// With --shard: the plan of this command written by `cargo xtask slurm` (instead of planning again).
        #[arg(long, requires = "shard", value_name = "FILE")]
        plan: Option<PathBuf>,
    },
    /// Re-render the reports from stored results (of any behaviour version), without running trials.
    Report {
        #[command(flatten)]
        run: RunArgs,
        /// Render what the store holds when trials are missing (leaving out incomplete experiments).
        #[arg(long)]
        partial: bool,
        /// The plan of this command written by `cargo xtask slurm` (to name missing trials without planning).
        #[arg(long, value_name = "FILE")]
        plan: Option<PathBuf>,
    },
    /// Merge result stores (e.g. each shard's) into one.
    Merge {
        /// The stores to merge.
        #[arg(required = true, value_name = "STORE")]
        stores: Vec<PathBuf>,
        /// The store to merge into (default: results/ in the workspace).
        #[arg(long)]
        results: Option<PathBuf>,
        /// The scale of the run the stores hold.
        #[arg(long, default_value = "paper", value_parser = parse_scale)]
        scale: Scale,
        /// The master seed of the run the stores hold (its replication seeds are accepted too).
        #[arg(long, default_value_t = DEFAULT_SEED)]
        seed: u64,
    },
    /// Write (and optionally submit) Slurm batch scripts: an array job of shards and a report job after it.
    Slurm {
        #[command(flatten)]
        run: RunArgs,
        /// Array tasks (shards).
        #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u32).range(1..=10000))]
        shards: u32,
        /// CPUs per task (each task runs that many trials at once).
        #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u16).range(1..=512))]
        cpus_per_task: u16,
        /// Where to write the scripts (default: target/rlfd/slurm).
        #[arg(long)]
        dir: Option<PathBuf>,
        /// An extra sbatch option for both jobs, e.g. --sbatch=--partition=short (repeatable).
        #[arg(long = "sbatch", value_name = "OPTION", allow_hyphen_values = true)]
        sbatch: Vec<String>,
        /// Submit the jobs (sbatch) after writing the scripts.
        #[arg(long)]
        submit: bool,
    },
    /// Recompute a sample of stored trials and compare each with its record byte for byte.
    Verify {
        #[command(flatten)]
        run: RunArgs,
        /// How many trials to recompute (spread over the experiments).
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u32).range(1..))]
        sample: u32,
        /// The seed that chooses the sample (default: the master seed).
        #[arg(long)]
        sample_seed: Option<u64>,
    },
    /// Regenerate the quick-scale report and compare it with golden/ (or bless it).
    Golden {
        /// Replace golden/ with the regenerated report.
        #[arg(long)]
        bless: bool,
    },
    /// Rerun a synthetic human's calibration and print it (without MODEL: list the models).
    Calibrate {
        /// The model, e.g. maze-demonstrator.
        model: Option<String>,
    },
    /// Measure steps per second per domain and agent.
    Bench {
        /// A shorter measurement (for smoke tests).
        #[arg(long)]
        quick: bool,
    },
    /// Compare two report trees: claims whose verdict changed, table cells, figures, files (exit 0 agree, 1 differ, 2 bad input).
    Diff {
        /// The old report tree (e.g. golden/).
        old: PathBuf,
        /// The new report tree (e.g. target/rlfd/report-quick).
        new: PathBuf,
        /// text (for a terminal) or markdown (for a pull-request comment).
        #[arg(long, default_value = "text")]
        format: crate::diff::Format,
        /// Changes shown per table, the rest counted (0: all).
        #[arg(long, default_value_t = 20)]
        limit: usize,
    },
    /// Build the report's LaTeX into PDFs (the whole report and each chapter) and check them.
    Pdf {
        /// The report tree (default: reports/).
        tree: Option<PathBuf>,
        /// Where the PDFs go (default: target/rlfd/pdf).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Only the whole document (report.pdf), not each chapter alone.
        #[arg(long)]
        whole_only: bool,
    },
    /// Draw a generated domain as SVG (`mario`: a level and the demonstrator's path on it).
    Render {
        /// What to draw.
        #[arg(value_parser = ["mario"])]
        what: String,
        /// The level's seed (the same level on any machine).
        #[arg(long)]
        level_seed: u64,
        /// Output file (default: `mario_level_<seed>.svg` in the current directory).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

#[derive(Args, Debug)]
struct RunArgs {
    /// Chapter to run (e.g. ch6-irl-shaping or ch6); all built chapters if absent.
    #[arg(long)]
    chapter: Option<String>,
    /// Experiment within the chapter (e.g. maze); all if absent.
    #[arg(long)]
    experiment: Option<String>,
    /// quick (seconds, what golden/ holds) or paper (the thesis's trial counts).
    #[arg(long, default_value = "paper", value_parser = parse_scale)]
    scale: Scale,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=512))]
    jobs: Option<u16>,
    /// Master seed.
    #[arg(long, default_value_t = DEFAULT_SEED)]
    seed: u64,
    /// Report directory (default: reports/ at paper scale, target/rlfd/report-quick at quick scale).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Result store (default: results/ in the workspace).
    #[arg(long)]
    results: Option<PathBuf>,
    /// Maze demonstrations to use instead of the synthetic demonstrator (CSV or JSON Lines).
    #[arg(long)]
    demonstrations: Option<PathBuf>,
    /// Never draw a progress bar.
    #[arg(long)]
    no_progress: bool,
    /// A reading of the thesis's open choices, `axis=level[,axis=level…]` (default: every axis at its default).
    #[arg(long)]
    reading: Option<String>,
    /// Also rerun every verdict over replication seeds and over each level of each reading axis.
    #[arg(long)]
    robustness: bool,
    /// Replications of the robustness run (the master seed and K − 1 seeds derived from it).
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=1000))]
    seeds: u32,
    /// Replications at each other level of each reading axis (the first of the replication seeds; default: 5, at most --seeds).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    reading_seeds: Option<u32>,
}

fn parse_scale(s: &str) -> Result<Scale, String> {
    s.parse()
}

/// Settings of `reproduce` and `report`: what determines the output (the
/// runner's [`Command`]), where and how trials run, and where the report goes.
#[derive(Clone, Debug)]
pub struct RunSettings {
    pub command: Command,
    pub machine: Machine,
    pub out: PathBuf,
}

/// A checked task.
pub enum Task {
    Reproduce(RunSettings),
    Shard { settings: RunSettings, shard: rlfd_runner::shard::Shard, plan: Option<PathBuf>, dry_run: bool },
    Report { settings: RunSettings, partial: bool, plan: Option<PathBuf> },
    Merge(crate::merge::Options),
    Slurm(crate::slurm::Options),
    Verify { settings: RunSettings, sample: usize, sample_seed: u64 },
    Golden { bless: bool },
    Calibrate { model: Option<String> },
    Bench { quick: bool },
    RenderMario { level_seed: u64, out: PathBuf },
    Diff(crate::diff::Options),
    Pdf(crate::pdf::Options),
}

/// The parsed command line.
pub struct Parsed {
    pub task: Task,
}

/// The workspace root (the parent of `xtask/`).
pub fn workspace_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask lives in the workspace").to_path_buf()
}

fn settings(a: RunArgs) -> RunSettings {
    let root = workspace_root();
    let out = a.out.unwrap_or_else(|| match a.scale {
        Scale::Paper => root.join("reports"),
        Scale::Quick => root.join("target/rlfd/report-quick"),
    });
    let jobs = a.jobs.map_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()), usize::from);
    let robustness = a.robustness.then(|| Replications {
        seeds: a.seeds,
        reading_seeds: a.reading_seeds.unwrap_or(rlfd_runner::DEFAULT_READING_SEEDS).min(a.seeds),
    });
    RunSettings {
        command: Command {
            chapter: a.chapter,
            experiment: a.experiment,
            scale: a.scale,
            seed: a.seed,
            reading: a.reading,
            robustness,
            demonstrations: a.demonstrations,
        },
        machine: Machine { jobs, progress: !a.no_progress, results: a.results.unwrap_or_else(|| root.join("results")) },
        out,
    }
}

/// Parses the process's arguments; on a bad argument prints one line and returns the exit code.
pub fn parse() -> Result<Parsed, ExitCode> {
    // `cargo xtask` passes the arguments after the alias; drop a leading "xtask" if present.
    let mut args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    if args.get(1).is_some_and(|a| a == "xtask") {
        args.remove(1);
    }
    match Cli::try_parse_from(args) {
        Ok(cli) => Ok(Parsed {
            task: match cli.task {
                RawTask::Reproduce { run, shard: None, .. } => Task::Reproduce(settings(run)),
                RawTask::Reproduce { run, shard: Some(shard), dry_run, plan } => {
                    Task::Shard { settings: settings(run), shard, plan, dry_run }
                }
                RawTask::Report { run, partial, plan } => Task::Report { settings: settings(run), partial, plan },
                RawTask::Merge { stores, results, scale, seed } => Task::Merge(crate::merge::Options {
                    sources: stores,
                    into: results.unwrap_or_else(|| workspace_root().join("results")),
                    scale,
                    seed,
                }),
                RawTask::Slurm { run, shards, cpus_per_task, dir, sbatch, submit } => {
                    Task::Slurm(crate::slurm::Options {
                        settings: settings(run),
                        shards,
                        cpus_per_task: usize::from(cpus_per_task),
                        dir: dir.unwrap_or_else(|| workspace_root().join("target/rlfd/slurm")),
                        sbatch,
                        submit,
                    })
                }
                RawTask::Verify { run, sample, sample_seed } => {
                    let settings = settings(run);
                    let sample_seed = sample_seed.unwrap_or(settings.command.seed);
                    Task::Verify { settings, sample: sample as usize, sample_seed }
                }
                RawTask::Golden { bless } => Task::Golden { bless },
                RawTask::Calibrate { model } => Task::Calibrate { model },
                RawTask::Bench { quick } => Task::Bench { quick },
                RawTask::Diff { old, new, format, limit } => {
                    Task::Diff(crate::diff::Options { old, new, format, limit })
                }
                RawTask::Pdf { tree, out, whole_only } => Task::Pdf(crate::pdf::Options {
                    tree: tree.unwrap_or_else(|| workspace_root().join("reports")),
                    out: out.unwrap_or_else(|| workspace_root().join("target/rlfd/pdf")),
                    whole_only,
                }),
                RawTask::Render { what: _, level_seed, out } => Task::RenderMario {
                    level_seed,
                    out: out.unwrap_or_else(|| PathBuf::from(format!("mario_level_{level_seed}.svg"))),
                },
            },
        }),
        Err(e) => {
            use clap::error::ErrorKind;
            match e.kind() {
                ErrorKind::DisplayHelp
                | ErrorKind::DisplayVersion
                | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                    let _ = e.print();
                    Err(if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                        ExitCode::from(2)
                    } else {
                        ExitCode::SUCCESS
                    })
                }
                _ => {
                    let text = e.to_string();
                    let first = text.lines().next().unwrap_or("invalid arguments").trim();
                    let first = first.strip_prefix("error: ").unwrap_or(first);
                    eprintln!("error: {first} (see `cargo xtask --help`)");
                    Err(ExitCode::from(2))
                }
            }
        }
    }
}
