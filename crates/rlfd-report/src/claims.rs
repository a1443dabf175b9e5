//! Claims with verdicts, and the scorecard that shows them: each claim of
//! `claims.md` with the thesis's evidence, ours, a verdict and one sentence
//! of why, and the numbers it turns on ([`KeyNumber`]: the thesis's value
//! beside ours) with the test that decided it ([`TestOutcome`]: its p or its
//! equivalence margin). The chapter crates decide whether a claim holds;
//! [`Check`] turns that into a verdict (or "not evaluable" with its reason),
//! and this module renders the scorecard ([`to_html`], [`to_latex`]).

use serde::{Deserialize, Serialize};

use crate::Result;
use crate::markup::{self, escape_html, escape_latex};
use crate::published::published;
use crate::table::{Num, NumFormat};

/// Whether a finding of the thesis holds on our data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    Reproduced,
    NotReproduced,
    /// Not decidable at this scale (e.g. quick scale has too few trials).
    NotEvaluable,
    /// The data neither show the thesis's effect nor exclude it (the
    /// analysis plan's pooled rule over replications).
    Inconclusive,
}

impl Verdict {
    /// `reproduced`, `not reproduced`, `not evaluable`, `inconclusive`.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::NotReproduced => "not reproduced",
            Verdict::NotEvaluable => "not evaluable",
            Verdict::Inconclusive => "inconclusive",
        }
    }

    /// The CSS class of the verdict's badge (`verdict-reproduced`, …).
    pub(crate) fn css_class(self) -> &'static str {
        match self {
            Verdict::Reproduced => "verdict-reproduced",
            Verdict::NotReproduced => "verdict-not-reproduced",
            Verdict::NotEvaluable => "verdict-not-evaluable",
            Verdict::Inconclusive => "verdict-inconclusive",
        }
    }

    /// The xcolor colour of the verdict in LaTeX.
    fn latex_colour(self) -> &'static str {
        match self {
            Verdict::Reproduced => "green!45!black",
            Verdict::NotReproduced => "red!70!black",
            Verdict::NotEvaluable => "black!55",
            Verdict::Inconclusive => "orange!75!black",
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

/// A number a claim turns on: what it measures, the thesis's value(s) and
/// ours (two values read "a vs b", e.g. guided vs unguided), all in one
/// format so the scorecard writes them alike (true minus sign, thousands
/// separators, `× 10ⁿ`). An empty side shows as a dash.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeyNumber {
    /// `states, small space (guided vs unguided)`.
    pub label: String,
    pub thesis: Vec<Num>,
    pub ours: Vec<Num>,
}

impl KeyNumber {
    /// A key number with both sides in `format` (NaN: no value).
    pub fn new(label: impl Into<String>, thesis: &[f64], ours: &[f64], format: NumFormat) -> KeyNumber {
        let nums = |v: &[f64]| v.iter().map(|&x| Num::new(x, format)).collect();
        KeyNumber { label: label.into(), thesis: nums(thesis), ours: nums(ours) }
    }
}

/// The test a verdict rests on, as the scorecard shows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TestOutcome {
    /// What was compared: `states, small space`.
    pub label: String,
    /// The test, in words: `pooled t-test, one-sided`, `TOST`, `95 % bootstrap interval`.
    pub test: String,
    /// Its p-value, when it has one; NaN when the test is undefined (a
    /// sample is missing, e.g. a learner that diverged). JSON has no NaN and
    /// `null` means "no p-value", so an undefined one is stored as the string
    /// `"undefined"`: the scorecard rebuilt from the stored summaries says
    /// "p undefined" exactly as the chapter's own page does.
    #[serde(default, with = "p_value_json")]
    pub p: Option<f64>,
    /// Anything else the decision needs: `margin ±5 %`, `interval [2.1, 5.3]`.
    pub note: Option<String>,
}

/// [`TestOutcome::p`] in JSON: `null` (none), a number, or `"undefined"` (NaN).
mod p_value_json {
    use serde::de::{self, Deserializer};
    use serde::{Deserialize, Serializer};

    /// How an undefined p-value (NaN) is written.
    const UNDEFINED: &str = "undefined";

    pub fn serialize<S: Serializer>(p: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        match p {
            None => s.serialize_none(),
            Some(p) if p.is_nan() => s.serialize_str(UNDEFINED),
            Some(p) => s.serialize_f64(*p),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Stored {
            Number(f64),
            Word(String),
        }
        match Option::<Stored>::deserialize(d)? {
            None => Ok(None),
            Some(Stored::Number(p)) => Ok(Some(p)),
            Some(Stored::Word(w)) if w == UNDEFINED => Ok(Some(f64::NAN)),
            Some(Stored::Word(w)) => {
                Err(de::Error::custom(format!("a p-value is a number, null or \"{UNDEFINED}\", not {w:?}")))
            }
        }
    }
}

impl TestOutcome {
    /// A test with a p-value (NaN: undefined).
    pub fn p(label: impl Into<String>, test: impl Into<String>, p: f64) -> TestOutcome {
        TestOutcome { label: label.into(), test: test.into(), p: Some(p), note: None }
    }

    /// A test decided by something other than a p-value (an interval, a margin, a count).
    pub fn note(label: impl Into<String>, test: impl Into<String>, note: impl Into<String>) -> TestOutcome {
        TestOutcome { label: label.into(), test: test.into(), p: None, note: Some(note.into()) }
    }
}

/// A claim of the thesis with our verdict on it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
    /// The numbers the claim turns on, thesis beside ours (may be empty).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub numbers: Vec<KeyNumber>,
    /// The tests that decided it (may be empty).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tests: Vec<TestOutcome>,
    /// Its components as replication-level estimates, for the analysis
    /// plan's pooled verdict over replications (empty: the claim has none yet).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub estimates: Vec<Estimate>,
}

/// What a component of a claim asks of its estimate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Direction {
    /// Above zero: the estimate is oriented so that the thesis's direction is positive.
    Above,
    /// Within ±margin of zero (a "no difference" component).
    Equivalent { margin: f64 },
    /// A yes/no property (an order, a first-to-cross, a level set): the
    /// value is 1 when it holds in the replication, 0 when not; pooled by
    /// the exact binomial rule of the analysis plan.
    Holds,
}

/// One component of a claim in one replication: the estimate the analysis
/// plan pools over replications (e.g. SIS's mean cumulative reward minus
/// SARSA's), with what the pooled rule needs beside it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Estimate {
    /// `SIS vs SAR`.
    pub label: String,
    pub direction: Direction,
    /// The estimate (`None`: undefined in this replication, e.g. a diverged learner).
    pub value: Option<f64>,
    /// The within-replication standard deviation the estimate's effect size
    /// is measured in (pooled over the conditions compared), for the
    /// smallest effect of interest; `None` when it has none.
    pub sd: Option<f64>,
    /// The thesis's effect in our units, for the power (`None`: not recoverable).
    pub thesis: Option<f64>,
}

impl Estimate {
    /// A directional component: `value` oriented so the thesis's direction is positive.
    pub fn above(label: impl Into<String>, value: f64, sd: f64, thesis: Option<f64>) -> Estimate {
        let finite = |x: f64| x.is_finite().then_some(x);
        Estimate { label: label.into(), direction: Direction::Above, value: finite(value), sd: finite(sd), thesis }
    }

    /// A yes/no component: whether the property holds in this replication.
    pub fn holds(label: impl Into<String>, holds: bool) -> Estimate {
        Estimate {
            label: label.into(),
            direction: Direction::Holds,
            value: Some(if holds { 1.0 } else { 0.0 }),
            sd: None,
            thesis: None,
        }
    }

    /// An equivalence component within ±`margin`.
    pub fn equivalent(label: impl Into<String>, value: f64, sd: f64, margin: f64) -> Estimate {
        let finite = |x: f64| x.is_finite().then_some(x);
        Estimate {
            label: label.into(),
            direction: Direction::Equivalent { margin },
            value: finite(value),
            sd: finite(sd),
            thesis: None,
        }
    }
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
            numbers: Vec::new(),
            tests: Vec::new(),
            estimates: Vec::new(),
        })
    }

    /// The claim with its components' estimates added, in order.
    pub fn with_estimates(mut self, estimates: impl IntoIterator<Item = Estimate>) -> Claim {
        self.estimates.extend(estimates);
        self
    }

    /// The claim with a key number added.
    pub fn with_number(mut self, number: KeyNumber) -> Claim {
        self.numbers.push(number);
        self
    }

    /// The claim with a test added.
    pub fn with_test(mut self, test: TestOutcome) -> Claim {
        self.tests.push(test);
        self
    }

    /// The claim with `tests` added, in order.
    pub fn with_tests(mut self, tests: impl IntoIterator<Item = TestOutcome>) -> Claim {
        self.tests.extend(tests);
        self
    }
}

/// Values joined by "vs", or a dash when there is none.
fn values_html(v: &[Num]) -> String {
    if v.is_empty() {
        return "—".into();
    }
    v.iter().map(crate::table::num_html_text).collect::<Vec<_>>().join(" vs ")
}

fn values_latex(v: &[Num]) -> String {
    if v.is_empty() {
        return "---".into();
    }
    v.iter().map(crate::table::num_latex_text).collect::<Vec<_>>().join(" vs ")
}

/// A p-value for the scorecard: `p = 0.0123`, `p = 1.4 × 10⁻¹⁰`, `p undefined`.
fn p_html(p: f64) -> String {
    if p.is_nan() {
        return "p undefined".into();
    }
    let text = crate::table::plain_html(&Num::p_value(p));
    if text.starts_with('<') { format!("p {text}") } else { format!("p = {text}") }
}

fn p_latex(p: f64) -> String {
    if p.is_nan() {
        return "$p$ undefined".into();
    }
    let text = crate::table::plain_latex(&Num::p_value(p));
    if text.starts_with('<') { format!("$p {text}$") } else { format!("$p = {text}$") }
}

/// The key numbers as an HTML table (measure, thesis, ours), or the
/// evidence texts when the chapter gave no numbers.
pub(crate) fn numbers_html(c: &Claim) -> String {
    if c.numbers.is_empty() {
        return format!(
            "<div class=\"evidence\"><b>Thesis:</b> {}</div><div class=\"evidence\"><b>Ours:</b> {}</div>",
            markup::to_html(&c.thesis_evidence),
            markup::to_html(&c.our_evidence)
        );
    }
    let mut h =
        String::from("<table class=\"numbers\"><thead><tr><th></th><th>thesis</th><th>ours</th></tr></thead><tbody>");
    for k in &c.numbers {
        h.push_str(&format!(
            "<tr><th scope=\"row\">{}</th><td class=\"thesis\">{}</td><td>{}</td></tr>",
            markup::to_html(&k.label),
            values_html(&k.thesis),
            values_html(&k.ours)
        ));
    }
    h.push_str("</tbody></table>");
    h
}

/// The tests as HTML lines: `label: test, p = …`.
pub(crate) fn tests_html(c: &Claim) -> String {
    c.tests
        .iter()
        .map(|t| {
            let mut parts = vec![markup::to_html(&t.test)];
            if let Some(p) = t.p {
                parts.push(p_html(p));
            }
            if let Some(n) = &t.note {
                parts.push(markup::to_html(n));
            }
            format!(
                "<div class=\"test-line\"><span class=\"label\">{}:</span> {}</div>",
                markup::to_html(&t.label),
                parts.join(", ")
            )
        })
        .collect()
}

/// The key numbers as LaTeX lines (`label: thesis ‖ ours`), or the evidence.
pub(crate) fn numbers_latex(c: &Claim) -> (String, String) {
    if c.numbers.is_empty() {
        return (markup::to_latex(&c.thesis_evidence), markup::to_latex(&c.our_evidence));
    }
    let line = |f: &dyn Fn(&KeyNumber) -> String| {
        c.numbers
            .iter()
            .map(|k| format!("{}: {}", markup::to_latex(&k.label), f(k)))
            .collect::<Vec<_>>()
            .join(" \\newline ")
    };
    (line(&|k| values_latex(&k.thesis)), line(&|k| values_latex(&k.ours)))
}

/// The key numbers for the LaTeX scorecard, one line each:
/// `label: thesis a vs b; ours c vs d` (or the evidence texts).
pub(crate) fn scorecard_numbers_latex(c: &Claim) -> String {
    if c.numbers.is_empty() {
        let (thesis, ours) = numbers_latex(c);
        return format!("\\emph{{Thesis:}} {thesis} \\newline \\emph{{Ours:}} {ours}");
    }
    c.numbers
        .iter()
        .map(|k| {
            format!(
                "{}: \\textcolor{{black!55}}{{{}}}; ours {}",
                markup::to_latex(&k.label),
                values_latex(&k.thesis),
                values_latex(&k.ours)
            )
        })
        .collect::<Vec<_>>()
        .join(" \\newline ")
}

/// A verdict in its colour, for LaTeX.
pub(crate) fn verdict_latex(v: Verdict) -> String {
    format!("\\textcolor{{{}}}{{\\textbf{{{}}}}}", v.latex_colour(), escape_latex(v.label()))
}

pub(crate) fn tests_latex(c: &Claim) -> String {
    c.tests
        .iter()
        .map(|t| {
            let mut parts = vec![markup::to_latex(&t.test)];
            if let Some(p) = t.p {
                parts.push(p_latex(p));
            }
            if let Some(n) = &t.note {
                parts.push(markup::to_latex(n));
            }
            format!("{}: {}", markup::to_latex(&t.label), parts.join(", "))
        })
        .collect::<Vec<_>>()
        .join(" \\newline ")
}

/// An HTML badge for a verdict; `None` is a claim not yet run.
pub(crate) fn badge_html(verdict: Option<Verdict>) -> String {
    match verdict {
        Some(v) => format!("<span class=\"badge {}\">{}</span>", v.css_class(), v.label()),
        None => "<span class=\"badge verdict-not-run\">not yet run</span>".into(),
    }
}

/// The claims as an HTML scorecard `<table class="scorecard">`: id, claim and
/// test, the thesis's evidence, ours (with the tests that decided it), and
/// the verdict badge with its reason.
pub fn to_html(claims: &[Claim]) -> String {
    let mut h = String::from(
        "<table class=\"scorecard\">\n<thead>\n<tr><th>Claim</th><th>Finding and test</th>\
         <th>Thesis</th><th>Ours</th><th>Verdict</th></tr>\n</thead>\n<tbody>\n",
    );
    for c in claims {
        h.push_str(&format!(
            "<tr id=\"{id}\"><th scope=\"row\">{id}</th>\
             <td>{statement}<div class=\"test\">Test: {test}</div></td>\
             <td>{thesis}</td><td>{ours}{tests}</td>\
             <td>{badge}<div class=\"reason\">{reason}</div></td></tr>\n",
            id = escape_html(&c.id),
            statement = escape_html(&c.statement),
            test = escape_html(&c.test),
            thesis = markup::to_html(&c.thesis_evidence),
            ours = markup::to_html(&c.our_evidence),
            tests = tests_html(c),
            badge = badge_html(Some(c.verdict)),
            reason = markup::to_html(&c.reason),
        ));
    }
    h.push_str("</tbody>\n</table>\n");
    h
}

/// The claims as a LaTeX list, one item per claim (its verdict in colour,
/// the finding and test, the thesis's evidence, ours, the tests and why):
/// prose that wraps, never a table too narrow for it. Needs `xcolor`.
pub fn to_latex(claims: &[Claim]) -> String {
    let mut t = String::from("\\begin{description}\n");
    for c in claims {
        let mut item = format!(
            "\\item[{} \\textcolor{{{}}}{{{}}}] {}\\par\n\\emph{{Test:}} {}\\par\n\\emph{{Thesis:}} {}\\par\n\\emph{{Ours:}} {}\\par\n",
            escape_latex(&c.id),
            c.verdict.latex_colour(),
            escape_latex(c.verdict.label()),
            escape_latex(&c.statement),
            escape_latex(&c.test),
            markup::to_latex(&c.thesis_evidence),
            markup::to_latex(&c.our_evidence),
        );
        if !c.tests.is_empty() {
            item.push_str(&format!("\\emph{{Decided by:}} {}\\par\n", tests_latex(c).replace(" \\newline ", "; ")));
        }
        item.push_str(&format!("\\emph{{Why:}} {}\n", markup::to_latex(&c.reason)));
        t.push_str(&item);
    }
    t.push_str("\\end{description}\n");
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_undefined_p_value_survives_the_stored_summary() {
        // The scorecard of every chapter is rebuilt from the summaries stored
        // beside the reports: a NaN p (a diverged learner's test) read back as
        // "no p-value" dropped the "p undefined" the chapter's page shows.
        let claim = c61().with_tests([
            TestOutcome::p("DIS vs QLR", "two-sided pooled t-test", f64::NAN),
            TestOutcome::p("SIS vs QLR", "two-sided pooled t-test", 0.0123),
            TestOutcome::note("interval", "95 % bootstrap interval", "[2.1, 5.3]"),
        ]);
        let json = serde_json::to_string(&claim).unwrap();
        assert!(json.contains(r#""p":"undefined""#), "{json}");
        assert!(json.contains(r#""p":0.0123"#), "{json}");
        assert!(json.contains(r#""p":null"#), "{json}");
        let back: Claim = serde_json::from_str(&json).unwrap();
        assert!(back.tests[0].p.is_some_and(f64::is_nan));
        assert_eq!(back.tests[1].p, Some(0.0123));
        assert_eq!(back.tests[2].p, None);
        let (html, latex) = (to_html(std::slice::from_ref(&claim)), to_latex(std::slice::from_ref(&claim)));
        assert!(html.contains("p undefined"));
        assert_eq!(to_html(std::slice::from_ref(&back)), html);
        assert_eq!(to_latex(std::slice::from_ref(&back)), latex);
    }

    #[test]
    fn a_p_value_in_json_is_a_number_null_or_undefined() {
        let p = |text: &str| {
            serde_json::from_str::<TestOutcome>(&format!(r#"{{"label":"a","test":"t","p":{text},"note":null}}"#))
        };
        assert_eq!(p("0.5").unwrap().p, Some(0.5));
        assert_eq!(p("1").unwrap().p, Some(1.0));
        assert_eq!(p("null").unwrap().p, None);
        assert!(p(r#""undefined""#).unwrap().p.is_some_and(f64::is_nan));
        let e = p(r#""NaN""#).unwrap_err().to_string();
        assert!(e.contains("undefined"), "{e}");
    }

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
        assert!(h.contains("<span class=\"badge verdict-not-evaluable\">not evaluable</span>"));
        assert!(h.contains("<div class=\"test\">Test: t-tests, p &lt; 1e-4</div>"), "{h}");
    }

    #[test]
    fn latex_scorecard_colours_verdicts() {
        let l = to_latex(&[c61()]);
        assert!(l.contains("\\item[C6.1 \\textcolor{green!45!black}{reproduced}] Maze: SIS and DIS"), "{l}");
        assert!(l.contains("SIS \\ensuremath{-}93,600"), "{l}");
        assert!(l.contains("p = 2.1~\\ensuremath{\\times}~10\\textsuperscript{\\ensuremath{-}}\\textsuperscript{4}\\textsuperscript{0}"), "{l}");
        assert!(l.starts_with("\\begin{description}\n"));
        assert!(l.ends_with("\\end{description}\n"));
        let with = c61()
            .with_number(KeyNumber::new(
                "cumulative, SIS vs SAR",
                &[-93_592.0, -151_526.0],
                &[-70_492.4],
                NumFormat::grouped(0),
            ))
            .with_test(TestOutcome::p("SIS vs SAR", "Welch t-test", 1.5e-10));
        let h = numbers_html(&with);
        assert!(h.contains("<td class=\"thesis\">−93,592 vs −151,526</td><td>−70,492</td>"), "{h}");
        assert_eq!(
            tests_html(&with),
            "<div class=\"test-line\"><span class=\"label\">SIS vs SAR:</span> Welch t-test, p = 1.500 × 10⁻¹⁰</div>"
        );
        let l = to_latex(std::slice::from_ref(&with));
        assert!(l.contains("\\emph{Decided by:} SIS vs SAR: Welch t-test, $p = 1.500\\times10^{-10}$"), "{l}");
        assert!(
            scorecard_numbers_latex(&with)
                .contains("\\textcolor{black!55}{$-93{,}592$ vs $-151{,}526$}; ours $-70{,}492$")
        );
        // The structured numbers survive the summary's JSON.
        let json = serde_json::to_string(&with).unwrap();
        assert_eq!(serde_json::from_str::<Claim>(&json).unwrap(), with);
    }
}
