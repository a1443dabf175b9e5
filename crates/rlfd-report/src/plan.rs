//! The analysis plan: how every claim is decided, as data
//! (`data/analysis-plan.toml`), frozen and dated before the runs it decides.
//!
//! The plan names, per claim, the estimand, the thesis's direction and
//! effect, the test, the equivalence margin where the thesis says "no
//! difference" (derived from the thesis's own data), and the thesis's sample
//! size that sets the smallest effect of interest (Simonsohn's small
//! telescopes, d33); its conventions say how replications are pooled, the
//! sidedness, α, the power threshold and the four outcomes. A change after
//! results have been seen is a new version with a new date. Every report
//! prints the plan's version, date and digest ([`AnalysisPlan::line`]); a
//! test fails when a committed report names another digest.

use std::sync::OnceLock;

use serde::Deserialize;
use sha2::{Digest, Sha256};

use crate::{Error, Result};

const PLAN_TOML: &str = include_str!("../data/analysis-plan.toml");

/// The plan's header: which version decides, and since when.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct PlanHeader {
    pub version: u32,
    /// ISO date, `2026-12-05`.
    pub date: String,
    pub status: String,
}

/// One entry of the plan's history.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct PlanVersion {
    pub version: u32,
    pub date: String,
    pub change: String,
}

/// The d33 values the plan uses (from the thesis's sample sizes).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct D33 {
    pub n3: f64,
    pub n10: f64,
    pub n25: f64,
    pub r31: f64,
}

/// The rules every claim shares.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct Conventions {
    pub alpha: f64,
    pub sidedness: String,
    pub unit: String,
    pub pooling: String,
    /// K at paper scale.
    pub replications: usize,
    /// Replications per non-default reading level.
    pub reading_replications: usize,
    pub smallest_effect: String,
    pub d33: D33,
    pub d33_source: String,
    pub power_threshold: f64,
    pub power: String,
    pub outcomes: String,
    pub conjunction: String,
    pub ordinal: String,
    pub secondary: String,
    pub readings: String,
}

/// How one claim is decided.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct ClaimPlan {
    pub id: String,
    pub estimand: String,
    pub direction: String,
    pub thesis_effect: String,
    pub test: String,
    /// The equivalence margin of a "no difference" component.
    pub margin: Option<f64>,
    /// What the margin is relative to (absent: in the claim's own units).
    pub margin_kind: Option<String>,
    /// Why that margin, from the thesis's data.
    pub margin_why: Option<String>,
    /// The thesis's sample size per condition (0: no sample).
    pub thesis_n: u32,
}

impl ClaimPlan {
    /// The smallest effect of interest in within-replication SD units: d33
    /// of the thesis's design (`None` where the thesis has no sample to set it).
    pub fn d33(&self, c: &Conventions) -> Option<f64> {
        match self.thesis_n {
            3 => Some(c.d33.n3),
            10 => Some(c.d33.n10),
            25 => Some(c.d33.n25),
            31 => Some(c.d33.r31),
            _ => None,
        }
    }
}

/// The whole plan.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct AnalysisPlan {
    pub plan: PlanHeader,
    #[serde(rename = "version")]
    pub versions: Vec<PlanVersion>,
    pub conventions: Conventions,
    #[serde(rename = "claim")]
    pub claims: Vec<ClaimPlan>,
    /// The first 16 hex digits of the file's SHA-256.
    #[serde(skip)]
    pub digest: String,
}

/// The embedded plan, parsed once. Panics only if the embedded file is
/// broken, which the tests below rule out.
pub fn analysis_plan() -> &'static AnalysisPlan {
    static PLAN: OnceLock<AnalysisPlan> = OnceLock::new();
    PLAN.get_or_init(|| AnalysisPlan::parse(PLAN_TOML).expect("the embedded analysis-plan.toml parses (tested)"))
}

impl AnalysisPlan {
    /// Parses a plan and checks that it is consistent: its header names the
    /// latest version of its history, dates never go back, margins are
    /// positive and no claim appears twice.
    pub fn parse(text: &str) -> Result<AnalysisPlan> {
        let bad = |reason: String| Error::Published { path: "analysis-plan.toml".into(), reason };
        let mut plan: AnalysisPlan = toml::from_str(text).map_err(|e| bad(e.to_string()))?;
        let last = plan.versions.last().ok_or_else(|| bad("no [[version]] entry".into()))?;
        if (last.version, last.date.as_str()) != (plan.plan.version, plan.plan.date.as_str()) {
            return Err(bad(format!(
                "[plan] names version {} of {} but the latest [[version]] is {} of {}",
                plan.plan.version, plan.plan.date, last.version, last.date
            )));
        }
        for w in plan.versions.windows(2) {
            if w[1].version != w[0].version + 1 || w[1].date < w[0].date {
                return Err(bad(format!("version {} follows version {} out of order", w[1].version, w[0].version)));
            }
        }
        for (k, c) in plan.claims.iter().enumerate() {
            if plan.claims[..k].iter().any(|d| d.id == c.id) {
                return Err(bad(format!("claim {} appears twice", c.id)));
            }
            if c.margin.is_some_and(|m| m.is_nan() || m <= 0.0) || c.margin.is_some() != c.margin_why.is_some() {
                return Err(bad(format!("claim {}: a margin must be positive and say why", c.id)));
            }
        }
        plan.digest = digest(text);
        Ok(plan)
    }

    /// How the claim `id` is decided.
    pub fn claim(&self, id: &str) -> Option<&ClaimPlan> {
        self.claims.iter().find(|c| c.id == id)
    }

    /// `analysis plan v1 of 2026-12-05 (sha256 0123456789abcdef)`: what
    /// every report prints, and what the committed-report test reads.
    pub fn line(&self) -> String {
        format!("analysis plan v{} of {} (sha256 {})", self.plan.version, self.plan.date, self.digest)
    }
}

/// The first 16 hex digits of the SHA-256 of `text`.
fn digest(text: &str) -> String {
    Sha256::digest(text.as_bytes()).iter().take(8).map(|b| format!("{b:02x}")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::published::published;

    #[test]
    fn the_embedded_plan_parses_and_covers_every_claim_once() {
        let plan = analysis_plan();
        let spec: Vec<&str> = published().claims().iter().map(|c| c.id.as_str()).collect();
        let planned: Vec<&str> = plan.claims.iter().map(|c| c.id.as_str()).collect();
        assert_eq!(planned, spec, "the plan lists every claim of claims.md, in its order");
        assert_eq!(plan.conventions.replications, 10);
        assert!(plan.conventions.reading_replications >= 5);
        assert_eq!(plan.digest.len(), 16);
        assert!(
            plan.line().starts_with(&format!("analysis plan v{} of {} (sha256 ", plan.plan.version, plan.plan.date))
        );
    }

    #[test]
    fn the_digest_is_sha256_of_the_file() {
        // `printf 'abc' | sha256sum`: ba7816bf8f01cfea414140de5dae2223…
        assert_eq!(digest("abc"), "ba7816bf8f01cfea");
    }

    #[test]
    fn an_inconsistent_plan_is_refused_with_its_reason() {
        let good = PLAN_TOML;
        let later = good.replacen(
            "version = 2\ndate = \"2026-12-06\"\nstatus",
            "version = 3\ndate = \"2026-12-06\"\nstatus",
            1,
        );
        let e = AnalysisPlan::parse(&later).unwrap_err().to_string();
        assert!(e.contains("[plan] names version 3 of 2026-12-06 but the latest [[version]] is 2"), "{e}");
        let twice = format!(
            "{good}\n[[claim]]\nid = \"C3.1\"\nestimand = \"\"\ndirection = \"\"\nthesis_effect = \"\"\ntest = \"\"\nthesis_n = 3\n"
        );
        assert!(AnalysisPlan::parse(&twice).unwrap_err().to_string().contains("claim C3.1 appears twice"));
        let unjustified = good.replacen("margin_why = \"|r| < 0.2", "margin_note = \"|r| < 0.2", 1);
        assert!(AnalysisPlan::parse(&unjustified).is_err());
    }
}
