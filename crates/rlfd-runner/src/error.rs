//! What can stop a run, in one line each: a chapter's own error (named with
//! the chapter), the harness's, the report's, or a command that asks for
//! something the build does not have.

use std::path::PathBuf;

use thiserror::Error;

/// What can stop a run.
#[derive(Debug, Error)]
pub enum RunnerError {
    /// A chapter's experiments or inputs.
    #[error("{chapter}: {source}")]
    Chapter {
        /// The chapter's slug.
        chapter: &'static str,
        /// Why.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// A chapter's claims or report could not be made.
    #[error("{chapter}: rendering: {source}")]
    Report {
        /// The chapter's slug.
        chapter: &'static str,
        /// Why.
        source: rlfd_report::Error,
    },
    /// The index or another page of the whole report.
    #[error("rendering {what}: {source}")]
    Render {
        /// What was rendered.
        what: &'static str,
        /// Why.
        source: rlfd_report::Error,
    },
    /// The store or a batch.
    #[error(transparent)]
    Harness(#[from] rlfd_harness::HarnessError),
    /// One shard's share of a batch.
    #[error(transparent)]
    Batch(#[from] rlfd_harness::BatchError),
    /// Merging stores.
    #[error(transparent)]
    Merge(#[from] rlfd_harness::merge::MergeError),
    /// A reading the chapters cannot take.
    #[error(transparent)]
    Reading(#[from] rlfd_harness::ReadingError),
    /// No chapter of that name.
    #[error("unknown chapter \"{name}\" (expected one of: {}; the thesis's other chapters are not built yet)", expected.join(", "))]
    UnknownChapter {
        /// The name given.
        name: String,
        /// The built chapters.
        expected: Vec<&'static str>,
    },
    /// No experiment of that name in the selected chapters.
    #[error("unknown experiment \"{name}\"{} (expected one of: {})", chapter.as_ref().map_or(String::new(), |c| format!(" for {c}")), expected.join(", "))]
    UnknownExperiment {
        /// The name given.
        name: String,
        /// The chapter asked, if one was.
        chapter: Option<String>,
        /// The experiments of the selected chapters.
        expected: Vec<&'static str>,
    },
    /// A demonstration file handed to a command whose chapters take none.
    #[error("--demonstrations applies to {takers}, which {}", if takers.contains(", ") { "are not selected" } else { "is not selected" })]
    DemonstrationsUnused {
        /// The experiments that take demonstration files.
        takers: String,
    },
    /// A plan file written by `cargo xtask slurm` that does not fit.
    #[error("the plan {path}: {why}")]
    Plan {
        /// The file.
        path: PathBuf,
        /// Why it does not fit.
        why: String,
    },
    /// A store lacks trials a report needs.
    #[error("{0}; run the shards or the reproduction that computes them, or pass --partial to render what is there")]
    Incomplete(String),
    /// A shard ended with trials of its own still without a record.
    #[error("shard {shard}: {left} of its trials have no record after the run, the first {first}")]
    ShardLeft {
        /// `I/N`.
        shard: String,
        /// How many.
        left: usize,
        /// The first, named.
        first: String,
    },
    /// Verification recomputed fewer records than chosen.
    #[error("verify: {chosen} trials ({records} records) were chosen but {verified} records recomputed")]
    Verify {
        /// Trials chosen.
        chosen: usize,
        /// Their records.
        records: usize,
        /// Records recomputed.
        verified: usize,
    },
    /// Nothing to render.
    #[error("nothing to render: no selected experiment has all its trials in {0}")]
    NothingToRender(PathBuf),
}
