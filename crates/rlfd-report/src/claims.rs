//! Claims with verdicts, and the scorecard that shows them: each claim of
//! `claims.md` with the thesis's evidence, ours, a verdict and one sentence
//! of why. The chapter crates decide verdicts; this module only renders them
//! ([`to_html`], [`to_latex`]).

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
