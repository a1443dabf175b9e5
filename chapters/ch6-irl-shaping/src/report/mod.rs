//! Chapter 6's report content: tables beside the thesis's, figures, claims,
//! parameters, decisions and raw data, built from stored results only.
//! The Maze's sections ([`maze`]) and Mario's ([`mario`]) are built on one
//! set of metrics ([`metrics`]), agent tables, key numbers and claim
//! families; claim C6.11 (`claims`) belongs to neither.

mod agent_tables;
mod claims;
pub mod family;
mod irl;
mod levels;
pub mod mario;
pub mod maze;
pub mod metrics;
mod scorecard;

use rlfd_report::prose::DataFile;
use rlfd_report::{Block, ChapterReport, Provenance, Section};

use crate::shaping::Baseline;
use crate::shaping::trials::Diverged;
use crate::{CHAPTER, Ch6Results};

pub use metrics::{Metric, MetricTable};

/// The chapter's title.
pub const TITLE: &str = "Chapter 6: Learning from demonstration for shaping through IRL (SIS, DIS)";

/// Random MDPs checked for claim C6.11 in the report.
const SHAPING_CHECK_MDPS: usize = 200;

/// Builds the chapter's report from its results.
pub fn chapter_report(results: &Ch6Results, provenance: &Provenance) -> rlfd_report::Result<ChapterReport> {
    let mut sections = Vec::new();
    if let Some(r) = &results.maze {
        sections.extend(maze::sections(r, provenance)?);
    }
    if let Some(v) = &results.validation {
        sections.push(mario::validation::section(v)?);
    }
    sections.extend(mario::sections(results.mario.as_ref(), results.demo_length.as_ref(), provenance)?);
    sections.push(Section::new(
        "Claim C6.11: potential-based shaping keeps the optimal policy",
        vec![Block::Claims(vec![claims::shaping_invariance_claim(SHAPING_CHECK_MDPS, terminal_reading(results))?])],
    ));
    if let (Some(maze), Some(mario)) = (&results.maze, &results.mario) {
        sections.push(Section::new(
            "Claim C6.13: SIS and DIS end above the demonstrator in both domains",
            vec![Block::Claims(vec![claims::above_demonstrator_claim(maze, mario)?])],
        ));
    }
    Ok(ChapterReport { slug: CHAPTER.into(), title: TITLE.into(), provenance: provenance.clone(), sections })
}

/// The terminal potential the chapter's runs used (the Maze's, else
/// Mario's; the axis's default when neither ran).
fn terminal_reading(results: &Ch6Results) -> rlfd_rl::shaping::TerminalPotential {
    results
        .maze
        .as_ref()
        .map(|r| r.params.terminal_potential)
        .or_else(|| results.mario.as_ref().map(|r| r.params.terminal_potential))
        .unwrap_or(rlfd_rl::shaping::TerminalPotential::Literal)
}

/// The chapter's claims, from its results alone (no figure, no bootstrap
/// table): C6.1–C6.5 with the Maze, C6.6–C6.9 with Mario, C6.10 with the
/// length study, C6.11, and C6.13 when both domains ran, in the report's order.
pub fn claims(results: &Ch6Results) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
    let mut out = Vec::new();
    if let Some(r) = &results.maze {
        out.extend(maze::claims_of(r)?);
    }
    if let Some(r) = &results.mario {
        out.extend(mario::main_claims_of(r)?);
    }
    if let Some(s) = &results.demo_length {
        out.push(mario::length_claim(s)?);
    }
    out.push(claims::shaping_invariance_claim(SHAPING_CHECK_MDPS, terminal_reading(results))?);
    if let (Some(maze), Some(mario)) = (&results.maze, &results.mario) {
        out.push(claims::above_demonstrator_claim(maze, mario)?);
    }
    Ok(out)
}

/// How the chapter's claims are tested, in one paragraph (both halves).
pub(crate) fn how_claims_are_tested() -> String {
    format!(
        "How the claims are tested: differences with the thesis's two-sided pooled-variance Student t-test (MATLAB ttest2's default); a directional claim needs the direction and p below its threshold. \"Do not differ\" is tested by equivalence, not read off a non-significant t-test: two one-sided tests (TOST, pooled variance) against a margin fixed before the run, a tenth of the thesis's demonstrator score (±{} reward in the Maze, ±{} points in Mario); equivalence holds when the TOST p is below 0.05, i.e. when the 90 % interval of the difference lies inside the margin. Where a claim rests on several tests (its family), each p is printed beside its Holm-adjusted p and the verdict uses the adjusted ones. Each comparison shows both means, the difference with its interval, t and its degrees of freedom.",
        family::num(family::MAZE_MARGIN, 2),
        family::num(family::MARIO_MARGIN, 1)
    )
}

/// The episodes of divergence as a phrase: "in 3 of 10 trials (episodes 212–340)".
pub(crate) fn diverged_phrase(episodes: &[u32], trials: u32) -> String {
    let lo = episodes.iter().min().copied().unwrap_or(0);
    let hi = episodes.iter().max().copied().unwrap_or(0);
    let when = if lo == hi { format!("episode {lo}") } else { format!("episodes {lo}–{hi}") };
    format!("in {} of {trials} trials ({when})", episodes.len())
}

/// The reason of a claim that rests on diverged learners, one part per
/// condition ("DIS in 3 of 10 trials (…)"); none when no part.
pub(crate) fn diverged_reason(parts: &[String]) -> Option<String> {
    (!parts.is_empty()).then(|| {
        format!(
            "Not evaluable: the learner diverged (a value or shaping reward became non-finite or exceeded {:e}): {}. Diverged trials are recorded, not tabulated or tested.",
            rlfd_rl::DIVERGENCE_BOUND,
            parts.join("; ")
        )
    })
}

/// The chapter's decisions and deviations, kept as data in
/// `data/deviations.toml` (`maze` and `mario` lists).
pub(crate) const DEVIATIONS: DataFile = DataFile {
    path: "chapters/ch6-irl-shaping/data/deviations.toml",
    text: include_str!("../../data/deviations.toml"),
};

/// The parameter rows of the two terminal readings (SIS's potential, HAT's
/// and SBS's advice) at `at` ("the goal", "a terminal state").
pub(crate) fn terminal_rows(
    rows: &mut rlfd_report::parameters::Parameters,
    at: &str,
    sis: rlfd_rl::shaping::TerminalPotential,
    advice: rlfd_rl::shaping::TerminalPotential,
) {
    let name = |t: rlfd_rl::shaping::TerminalPotential| format!("{t:?}").to_lowercase();
    rows.row(&format!("Φ at {at}: SIS"), name(sis), "the terminal-potential reading (default literal, eq. 6.2)");
    rows.row(
        &format!("Φ at {at}: HAT's and SBS's advice"),
        name(advice),
        "the advice-terminal reading (default zero: their Q-initialisation)",
    );
}

/// The chapter's `data/evidence.toml`: the thesis's evidence beside each claim.
const EVIDENCE: DataFile =
    DataFile { path: "chapters/ch6-irl-shaping/data/evidence.toml", text: include_str!("../../data/evidence.toml") };

/// The thesis's evidence for claim `id`.
pub(crate) fn evidence(id: &str) -> rlfd_report::Result<String> {
    EVIDENCE.evidence()?.thesis(id, &[])
}

/// Why the claims on `agents` cannot be judged, when some of their trials
/// diverged (one part per agent, in the order given).
pub(crate) fn diverged_agents(
    diverged: &Diverged,
    agents: &[crate::shaping::Agent],
    baseline: Baseline,
    trials: u32,
) -> Option<String> {
    let parts: Vec<String> = agents
        .iter()
        .filter_map(|a| diverged.get(a).map(|eps| format!("{} {}", a.label(baseline), diverged_phrase(eps, trials))))
        .collect();
    diverged_reason(&parts)
}

#[cfg(test)]
mod evidence_tests {
    use super::*;

    #[test]
    fn the_evidence_file_covers_every_claim_of_chapter_6_as_the_thesis_prints_it() {
        EVIDENCE.evidence().unwrap().check_chapter(6).unwrap();
        assert_eq!(
            evidence("C6.6").unwrap(),
            "DIS 25,725,731.6 against QLR 20,101,973.6, HAT 13,250,664.4, SBS 22,332,848.2; p = 5.5e-09, 1.7e-18, 1.9e-08."
        );
        assert_eq!(
            evidence("C6.2").unwrap(),
            "Initial: HAT −164.68, SBS −324.04 against SAR −3,730.36; p = 1.6e-13 and 1.7e-12."
        );
    }
}
