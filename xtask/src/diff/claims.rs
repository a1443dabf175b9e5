//! Claims compared by verdict: every chapter's `summary.json` (what the
//! top-level index is rebuilt from) read into its claims, matched by id.
//! A verdict change comes first in the output; a claim whose verdict held
//! but whose text, key numbers or tests changed is named with what changed.

use std::collections::BTreeMap;

use anyhow::{Context, Result};
use rlfd_report::ChapterSummary;
use rlfd_report::claims::{Claim, Verdict};
use serde::Deserialize;

/// A chapter's `summary.json` as `reproduce` writes it (its `generated_by`
/// line is provenance and not read).
#[derive(Deserialize)]
struct Stored {
    summary: ChapterSummary,
}

/// Reads a chapter's summary.
pub fn parse(bytes: &[u8]) -> Result<ChapterSummary> {
    let stored: Stored = serde_json::from_slice(bytes).context("not a chapter summary")?;
    Ok(stored.summary)
}

/// A claim whose verdict changed (`None`: the tree has no verdict for it).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VerdictChange {
    pub id: String,
    pub old: Option<Verdict>,
    pub new: Option<Verdict>,
    /// The new verdict's one sentence of why (the old one's if the claim is gone).
    pub reason: String,
}

/// What changed in the claims of two trees.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct ClaimChanges {
    pub verdicts: Vec<VerdictChange>,
    /// Claims with the same verdict whose evidence, reason, key numbers or
    /// tests changed: `C3.1 (key numbers, tests)`.
    pub evidence: Vec<String>,
}

/// `C6.10` → (6, 10), for the thesis's order; other ids sort after.
fn order(id: &str) -> (u32, u32, String) {
    let parsed = id
        .strip_prefix('C')
        .and_then(|rest| rest.split_once('.'))
        .and_then(|(c, n)| Some((c.parse().ok()?, n.parse().ok()?)));
    let (c, n) = parsed.unwrap_or((u32::MAX, u32::MAX));
    (c, n, id.to_string())
}

/// Every claim of the summaries, by id in the thesis's order.
fn by_id(summaries: &[ChapterSummary]) -> BTreeMap<(u32, u32, String), &Claim> {
    summaries.iter().flat_map(|s| &s.claims).map(|c| (order(&c.id), c)).collect()
}

/// Compares the claims of two trees' summaries.
pub fn compare(old: &[ChapterSummary], new: &[ChapterSummary]) -> ClaimChanges {
    let (old, new) = (by_id(old), by_id(new));
    let mut ids: Vec<&(u32, u32, String)> = old.keys().chain(new.keys()).collect();
    ids.sort();
    ids.dedup();
    let mut changes = ClaimChanges::default();
    for key in ids {
        let (a, b) = (old.get(key), new.get(key));
        let (va, vb) = (a.map(|c| c.verdict), b.map(|c| c.verdict));
        if va != vb {
            let reason = b.or(a).map_or_else(String::new, |c| c.reason.clone());
            changes.verdicts.push(VerdictChange { id: key.2.clone(), old: va, new: vb, reason });
        } else if let (Some(a), Some(b)) = (a, b) {
            let parts = changed_parts(a, b);
            if !parts.is_empty() {
                changes.evidence.push(format!("{} ({})", key.2, parts.join(", ")));
            }
        }
    }
    changes
}

/// Whether two values are equal as JSON, where a missing number (NaN)
/// equals itself.
fn same<T: serde::Serialize>(a: &T, b: &T) -> bool {
    serde_json::to_value(a).ok() == serde_json::to_value(b).ok()
}

/// What differs between two versions of one claim, in words.
fn changed_parts(a: &Claim, b: &Claim) -> Vec<&'static str> {
    let mut parts = Vec::new();
    if a.statement != b.statement || a.test != b.test {
        parts.push("definition");
    }
    if a.thesis_evidence != b.thesis_evidence || a.our_evidence != b.our_evidence {
        parts.push("evidence");
    }
    if a.reason != b.reason {
        parts.push("reason");
    }
    if !same(&a.numbers, &b.numbers) {
        parts.push("key numbers");
    }
    if !same(&a.tests, &b.tests) {
        parts.push("tests");
    }
    parts
}

/// A verdict as shown: `reproduced`, …, `not run` when absent.
pub fn label(v: Option<Verdict>) -> &'static str {
    v.map_or("not run", Verdict::label)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary(claims: &[(&str, Verdict, &str)]) -> ChapterSummary {
        ChapterSummary {
            slug: "ch6-irl-shaping".into(),
            title: "Chapter 6".into(),
            claims: claims
                .iter()
                .map(|(id, v, reason)| Claim::from_spec(id, "thesis", "ours", *v, *reason).unwrap())
                .collect(),
            robustness: None,
        }
    }

    #[test]
    fn verdict_changes_in_the_thesis_order_then_evidence() {
        use Verdict::*;
        let old = summary(&[("C6.10", Reproduced, "a"), ("C6.2", NotEvaluable, "b"), ("C6.3", Reproduced, "c")]);
        let new = summary(&[
            ("C6.2", Reproduced, "now holds"),
            ("C6.10", NotReproduced, "fails"),
            ("C6.3", Reproduced, "c2"),
        ]);
        let c = compare(std::slice::from_ref(&old), &[new]);
        let got: Vec<(&str, &str, &str, &str)> =
            c.verdicts.iter().map(|v| (v.id.as_str(), label(v.old), label(v.new), v.reason.as_str())).collect();
        assert_eq!(
            got,
            [("C6.2", "not evaluable", "reproduced", "now holds"), ("C6.10", "reproduced", "not reproduced", "fails")]
        );
        assert_eq!(c.evidence, ["C6.3 (reason)"]);
        let same = std::slice::from_ref(&old);
        assert_eq!(compare(same, same), ClaimChanges::default());
        let gone = compare(&[old], &[]);
        assert_eq!(gone.verdicts.len(), 3);
        assert_eq!(label(gone.verdicts[0].new), "not run");
    }

    #[test]
    fn a_summary_is_read_without_its_provenance() {
        let json = r#"{"generated_by": "generated by x", "summary": {"slug": "s", "title": "T", "claims": []}}"#;
        assert_eq!(parse(json.as_bytes()).unwrap().title, "T");
        assert!(parse(b"{}").is_err());
    }
}
