//! What varies from run to run: written to `run.json` beside a report and
//! left out of every golden and determinism comparison.

use serde::{Deserialize, Serialize};

/// Run metadata.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunMetadata {
    /// The command line as typed.
    pub command: Vec<String>,
    /// The semantic command: what determines the output (no `--jobs`, no `--out`).
    pub semantic_command: String,
    /// The master seed.
    pub seed: u64,
    /// `quick` or `paper`.
    pub scale: String,
    /// Worker threads.
    pub jobs: usize,
    /// `git rev-parse HEAD`, with `-dirty` when the tree had changes, if known.
    pub commit: Option<String>,
    /// The host name, if known.
    pub host: Option<String>,
    /// Seconds since the Unix epoch when the run started.
    pub started_unix: u64,
    /// Wall time of the whole run, in seconds.
    pub wall_seconds: f64,
    /// Trials computed in this run.
    pub trials_computed: usize,
    /// Trials reused from the result store.
    pub trials_reused: usize,
    /// The package version.
    pub version: String,
    /// Each chapter's part of the run, in run order (absent from the
    /// `run.json` of earlier versions).
    #[serde(default)]
    pub chapters: Vec<ChapterTime>,
    /// The analysis plan that decided the verdicts: `analysis plan v1 of
    /// 2026-12-05 (sha256 …)` (absent from the `run.json` of earlier versions).
    #[serde(default)]
    pub analysis_plan: Option<String>,
}

/// One chapter's part of a run: its trials (computed or read), its
/// robustness run when asked for, and its rendering.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ChapterTime {
    /// The chapter's slug, e.g. `ch6-irl-shaping`.
    pub chapter: String,
    /// Wall time, in seconds.
    pub wall_seconds: f64,
    /// The chapter's trials computed (the headline reading's, as in
    /// [`RunMetadata::trials_computed`]).
    pub trials_computed: usize,
    /// The chapter's trials read from the result store.
    pub trials_reused: usize,
    /// CPU seconds of the chapter's trials computed by this run, at every
    /// run point (its replications and readings too), set-ups included, as
    /// the workers timed them: the chapter's share of a run's cost.
    #[serde(default)]
    pub trial_cpu_seconds: f64,
}
