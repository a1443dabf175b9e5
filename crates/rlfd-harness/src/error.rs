//! The harness's errors: file-system trouble, named with the path.

use std::path::PathBuf;

use thiserror::Error;

/// What can go wrong while storing or loading trials.
#[derive(Debug, Error)]
pub enum HarnessError {
    /// A file or directory could not be created, written, renamed or read.
    #[error("{action} {path}: {source}")]
    Io {
        /// What was being done ("cannot create directory", …).
        action: &'static str,
        /// The path involved.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A stored result could not be encoded.
    #[error("cannot encode the result of {trial}: {source}")]
    Encode {
        /// The trial's id.
        trial: String,
        /// The underlying error.
        source: serde_json::Error,
    },
    /// A stored result is needed but missing (when only loading).
    #[error("no stored result for {trial} (expected {path}{}); run `cargo xtask reproduce` with the same chapter, scale and seed first",
        if *others > 0 { format!("; {others} record(s) of other behaviour versions or builds exist") } else { String::new() })]
    Missing {
        /// The trial's id.
        trial: String,
        /// Where it was looked for.
        path: PathBuf,
        /// How many records of other identities exist for the trial.
        others: usize,
    },
    /// A stored record of the trial's identity cannot be read (when only loading or verifying).
    #[error(
        "the stored record of {trial} cannot be read ({path}: {reason}); rerun `cargo xtask reproduce` to recompute it"
    )]
    Unreadable {
        /// The trial's id.
        trial: String,
        /// The file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
    /// A recomputed trial differs from its stored record.
    #[error("verification failed: {trial} recomputed differs from its stored record {path}")]
    Diverges {
        /// The trial's id.
        trial: String,
        /// The stored record.
        path: PathBuf,
    },
    /// A worker pool could not be built.
    #[error("cannot start {jobs} worker threads: {message}")]
    Pool {
        /// Requested threads.
        jobs: usize,
        /// Why.
        message: String,
    },
}
