//! Claims with verdicts, and the scorecard that shows them: each claim of
//! `claims.md` with the thesis's evidence, ours, a verdict and one sentence
//! of why. The chapter crates decide whether a claim holds; [`Check`] turns
//! that into a verdict (or "not evaluable" with its reason), and this module
//! renders the scorecard ([`to_html`], [`to_latex`]).

use crate::Result;
use crate::markup::{self, escape_html, escape_latex};
use crate::published::published;

/// Whether a finding of the thesis holds on our data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    Reproduced,
    NotReproduced,
    /// Not decidable at this scale (e.g. quick scale has too few trials).
    NotEvaluable,
}

impl Verdict {
    /// `reproduced`, `not reproduced`, `not evaluable at this scale`.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::NotReproduced => "not reproduced",
            Verdict::NotEvaluable => "not evaluable at this scale",
        }
    }

    /// The CSS class of the verdict's badge (`verdict-reproduced`, …).
    pub(crate) fn css_class(self) -> &'static str {
        match self {
            Verdict::Reproduced => "verdict-reproduced",
            Verdict::NotReproduced => "verdict-not-reproduced",
            Verdict::NotEvaluable => "verdict-not-evaluable",
        }
    }

    /// The xcolor colour of the verdict in LaTeX.
    fn latex_colour(self) -> &'static str {
        match self {
            Verdict::Reproduced => "green!45!black",
            Verdict::NotReproduced => "red!70!black",
            Verdict::NotEvaluable => "black!55",
        }
    }
}

/// Whether a chapter's data can decide a claim, and if not, why: built once
/// per set of claims with [`Check::when`], then asked for each claim's
/// verdict with [`Check::verdict`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Check {
    /// The data decide: the verdict is reproduced or not.
    Decidable,
    /// The data cannot decide (too few trials, not the paper scale); the
    /// sentence says why and is the reason of every verdict it gives.
    Undecidable(String),
}

impl Check {
    /// [`Check::Decidable`] when `decidable`, else undecidable for the
    /// reason `why_not` gives (called only then).
    pub fn when(decidable: bool, why_not: impl FnOnce() -> String) -> Check {
        if decidable { Check::Decidable } else { Check::Undecidable(why_not()) }
    }

    /// The verdict and its sentence: not evaluable with the reason when
    /// undecidable, else reproduced with `yes` when `holds` and not
    /// reproduced with `no` otherwise.
    pub fn verdict(&self, holds: bool, yes: &str, no: &str) -> (Verdict, String) {
        match self {
            Check::Undecidable(why_not) => (Verdict::NotEvaluable, why_not.clone()),
            Check::Decidable if holds => (Verdict::Reproduced, yes.into()),
            Check::Decidable => (Verdict::NotReproduced, no.into()),
        }
    }
}

/// How many trials per condition a chapter needs before its significance
/// tests count as evidence (below it, and below the paper scale, a claim
/// decided by a test is [`Verdict::NotEvaluable`]). The floors differ for
/// one reason, named here:
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TestFloor {
    /// The thesis tested its claims (10 trials per condition in Keepaway and
    /// Mario, 25 in the Maze): ours need 10, the smallest sample the thesis
    /// itself took a test on.
    ThesisTested,
    /// The thesis ran a few trials and no test (three per condition in the
    /// Nao sorting study), so no sample of its sets the bar: our own powered
    /// experiment decides, and 20 keeps a run of a handful of trials from
    /// ever deciding a claim.
    NoThesisTest,
}

impl TestFloor {
    /// The minimum trials per condition: 10 or 20.
    pub const fn trials(self) -> usize {
        match self {
            TestFloor::ThesisTested => 10,
            TestFloor::NoThesisTest => 20,
        }
    }
}

/// A claim of the thesis with our verdict on it.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Claim {
    /// `C6.1`: an id of `claims.md`.
    pub id: String,
    /// The finding (from `claims.md`).
    pub statement: String,
    /// How it is tested (from `claims.md`).
    pub test: String,
    /// What the thesis reports for it (numbers, p-values; inline markup allowed).
    pub thesis_evidence: String,
    /// What we measured (inline markup allowed).
    pub our_evidence: String,
    pub verdict: Verdict,
    /// One sentence of why.
    pub reason: String,
}

impl Claim {
    /// The claim `id` of `claims.md` (statement and test from the file) with
    /// the evidence and verdict given.
    pub fn from_spec(
        id: &str,
        thesis_evidence: impl Into<String>,
        our_evidence: impl Into<String>,
        verdict: Verdict,
        reason: impl Into<String>,
    ) -> Result<Claim> {
        let spec = published().claim(id)?;
        Ok(Claim {
            id: spec.id.clone(),
            statement: spec.statement.clone(),
            test: spec.test.clone(),
            thesis_evidence: thesis_evidence.into(),
            our_evidence: our_evidence.into(),
            verdict,
            reason: reason.into(),
        })
    }
}

/// An HTML badge for a verdict; `None` is a claim not yet run.
pub(crate) fn badge_html(verdict: Option<Verdict>) -> String {
    match verdict {
        Some(v) => format!("<span class=\"badge {}\">{}</span>", v.css_class(), v.label()),
        None => "<span class=\"badge verdict-not-run\">not yet run</span>".into(),
    }
}

/// The claims as an HTML scorecard `<table class="scorecard">`: id, claim and
/// test, the thesis's evidence, ours, and the verdict badge with its reason.
pub fn to_html(claims: &[Claim]) -> String {
    let mut h = String::from(
        "<table class=\"scorecard\">\n<thead>\n<tr><th>Claim</th><th>Finding and test</th>\
         <th>Thesis</th><th>Ours</th><th>Verdict</th></tr>\n</thead>\n<tbody>\n",
    );
    for c in claims {
        h.push_str(&format!(
            "<tr id=\"{id}\"><th scope=\"row\">{id}</th>\
             <td>{statement}<div class=\"test\">Test: {test}</div></td>\
             <td>{thesis}</td><td>{ours}</td>\
             <td>{badge}<div class=\"reason\">{reason}</div></td></tr>\n",
            id = escape_html(&c.id),
            statement = escape_html(&c.statement),
            test = escape_html(&c.test),
            thesis = markup::to_html(&c.thesis_evidence),
            ours = markup::to_html(&c.our_evidence),
            badge = badge_html(Some(c.verdict)),
            reason = markup::to_html(&c.reason),
        ));
    }
    h.push_str("</tbody>\n</table>\n");
    h
}

/// The claims as a LaTeX `longtable` (needs `longtable`, `array`, `booktabs`
/// and `xcolor`), verdicts in colour.
pub fn to_latex(claims: &[Claim]) -> String {
    let mut t = String::from(
        "\\begin{longtable}{@{}>{\\raggedright}p{0.07\\linewidth}>{\\raggedright}p{0.26\\linewidth}\
         >{\\raggedright}p{0.17\\linewidth}>{\\raggedright}p{0.17\\linewidth}\
         >{\\raggedright\\arraybackslash}p{0.21\\linewidth}@{}}\n\
         \\toprule\nClaim & Finding and test & Thesis & Ours & Verdict \\\\\n\\midrule\n\\endhead\n",
    );
    for c in claims {
        t.push_str(&format!(
            "{} & {} \\newline\\emph{{Test:}} {} & {} & {} & \\textcolor{{{}}}{{\\textbf{{{}}}}} \\newline {} \\\\\n",
            escape_latex(&c.id),
            escape_latex(&c.statement),
            escape_latex(&c.test),
            markup::to_latex(&c.thesis_evidence),
            markup::to_latex(&c.our_evidence),
            c.verdict.latex_colour(),
            escape_latex(c.verdict.label()),
            markup::to_latex(&c.reason),
        ));
    }
    // A longtable steps the table counter even without a caption.
    t.push_str("\\bottomrule\n\\end{longtable}\n\\addtocounter{table}{-1}\n");
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c61() -> Claim {
        Claim::from_spec(
            "C6.1",
            "p < 1e-17 (Table 6.2)",
            "SIS −93,600 vs SAR −151,500, p = 2.1e-40",
            Verdict::Reproduced,
            "Both shaped agents beat the three others with p < 1e-4.",
        )
        .unwrap()
    }

    #[test]
    fn checks_give_verdicts() {
        let yes = Check::when(true, || unreachable!());
        assert_eq!(yes.verdict(true, "y", "n"), (Verdict::Reproduced, "y".into()));
        assert_eq!(yes.verdict(false, "y", "n"), (Verdict::NotReproduced, "n".into()));
        let no = Check::when(false, || "too few".into());
        assert_eq!(no.verdict(true, "y", "n"), (Verdict::NotEvaluable, "too few".into()));
        assert_eq!((TestFloor::ThesisTested.trials(), TestFloor::NoThesisTest.trials()), (10, 20));
    }

    #[test]
    fn from_spec_fills_statement_and_test() {
        let c = c61();
        assert_eq!(c.test, "t-tests, p < 1e-4");
        assert!(Claim::from_spec("C9.9", "", "", Verdict::Reproduced, "").is_err());
    }

    #[test]
    fn html_scorecard_has_badges() {
        let mut c2 = c61();
        c2.id = "C6.3".into();
        c2.verdict = Verdict::NotEvaluable;
        let h = to_html(&[c61(), c2]);
        assert_eq!(h.matches("<tr id=").count(), 2);
        assert!(h.contains("<span class=\"badge verdict-reproduced\">reproduced</span>"));
        assert!(h.contains("<span class=\"badge verdict-not-evaluable\">not evaluable at this scale</span>"));
        assert!(h.contains("<div class=\"test\">Test: t-tests, p &lt; 1e-4</div>"), "{h}");
    }

    #[test]
    fn latex_scorecard_colours_verdicts() {
        let l = to_latex(&[c61()]);
        assert!(l.contains("\\textcolor{green!45!black}{\\textbf{reproduced}}"), "{l}");
        assert!(l.contains("SIS \\ensuremath{-}93,600"), "{l}");
        assert!(l.starts_with("\\begin{longtable}"));
        assert!(l.ends_with("\\end{longtable}\n\\addtocounter{table}{-1}\n"));
    }
}
