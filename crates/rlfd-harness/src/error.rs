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
    #[error(
        "no stored result for {trial} (expected {path}); run `cargo xtask reproduce` with the same chapter, scale and seed first"
    )]
    Missing {
        /// The trial's id.
        trial: String,
        /// Where it was looked for.
        path: PathBuf,
    },
    /// A stored result was made by other code or other parameters (when only loading).
    #[error(
        "the stored result {path} was made by other code or parameters (fingerprint {found}, expected {expected}); rerun `cargo xtask reproduce`"
    )]
    Stale {
        /// The file.
        path: PathBuf,
        /// Its fingerprint.
        found: String,
        /// The current fingerprint.
        expected: String,
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
