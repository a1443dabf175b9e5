//! Robustness of the verdicts: how each claim fares over independent
//! replications (other master seeds) and over the readings of the thesis's
//! open choices, one axis at a time around the default (a multiverse, or
//! specification-curve, analysis: Steegen et al. 2016; Simonsohn et al.
//! 2020). The harness runs the replications and readings; this module only
//! holds their verdicts and renders them: a section for the chapter report
//! and a line per claim for the scorecard.

use serde::{Deserialize, Serialize};

use crate::claims::{Claim, Direction, Estimate, Verdict};
use crate::figure::{ForestPlot, ForestPoint, ForestRow};
use crate::page::{Block, ChapterReport, Section};
use crate::table::{Cell, ColumnGroup, Row, Table};
use rlfd_stats::clopper_pearson;

/// The tallest specification curve drawn as one figure (pixels: the bound
/// every figure is checked against); a taller one is cut into parts.
const MAX_FIGURE_HEIGHT: u32 = 4000;

/// One level of an axis, as the report shows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LevelInfo {
    pub name: String,
    pub meaning: String,
    pub source: String,
}

/// An open choice, as the report shows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AxisInfo {
    pub name: String,
    pub question: String,
    pub default: String,
    pub why_default: String,
    pub levels: Vec<LevelInfo>,
}

/// One component of a claim pooled over replications (the analysis plan's
/// rule: a one-sample t-test on the replication-level estimates).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PooledComponent {
    pub label: String,
    /// Replications with a defined estimate.
    pub replications: usize,
    /// The mean estimate over them (NaN, written as `null`, when none is defined).
    #[serde(deserialize_with = "nan_if_null")]
    pub mean: f64,
    /// Its 95 % interval (90 % for an equivalence component).
    #[serde(deserialize_with = "nan_if_null")]
    pub lower: f64,
    #[serde(deserialize_with = "nan_if_null")]
    pub upper: f64,
    /// The power of the pooled test at the thesis's effect (`None`: not recoverable).
    pub power: Option<f64>,
    pub verdict: Verdict,
    /// The mean within-replication SD of the estimates (`None`: they have
    /// none, e.g. a yes/no property): the unit of the specification curve.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sd_within: Option<f64>,
    /// The thesis's effect in our units (`None`: not recoverable).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thesis: Option<f64>,
    /// What the component asks (above 0, within a margin, a yes/no property).
    #[serde(default = "above")]
    pub direction: Direction,
}

fn above() -> Direction {
    Direction::Above
}

/// JSON has no NaN: serde_json writes a not-evaluable component's NaN mean
/// and bounds as `null`, so `null` reads back as NaN.
fn nan_if_null<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

/// A claim decided on all replications together.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pooled {
    pub verdict: Verdict,
    pub components: Vec<PooledComponent>,
}

impl Pooled {
    /// "inconclusive: SIS vs SAR +12.1 [−3.0, 27.2], power 0.41; …".
    pub fn text(&self) -> String {
        let parts: Vec<String> = self
            .components
            .iter()
            .map(|c| {
                let power = c.power.map_or(String::new(), |p| format!(", power {p:.2}"));
                format!(
                    "{} {} [{}, {}] over {}{power}: {}",
                    c.label,
                    sig(c.mean),
                    sig(c.lower),
                    sig(c.upper),
                    c.replications,
                    c.verdict.label()
                )
            })
            .collect();
        format!("{} ({})", self.verdict.label(), parts.join("; "))
    }
}

/// A number with four significant digits, a true minus sign.
fn sig(x: f64) -> String {
    if !x.is_finite() {
        return "–".into();
    }
    let digits = if x == 0.0 { 0 } else { (3 - libm::floor(libm::log10(x.abs())) as i32).max(0) as usize };
    format!("{x:.digits$}").replace('-', "−")
}

/// A claim at one non-default level of one axis.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(from = "ReadingWire")]
pub struct ReadingVerdict {
    pub axis: String,
    pub level: String,
    /// Pooled over the level's replications when the claim has estimates,
    /// else the verdict at the master seed.
    pub verdict: Verdict,
    /// The pooled verdict with each component's effect and interval.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pooled: Option<Pooled>,
    /// The claim's estimates at each of the level's replications (its
    /// index), from which `pooled` is recomputed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub estimates: Vec<(usize, Estimate)>,
    /// The default reading pooled over the same replications as this level
    /// (the plan's v2 rule: a level is compared with the default at matched
    /// replications, so that a difference is the reading's, not the number
    /// of replications').
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub matched: Option<Pooled>,
}

/// A reading as stored: the struct, or the `[axis, level, verdict]` triple
/// of summaries written before readings were pooled with their effects.
#[derive(Deserialize)]
#[serde(untagged)]
enum ReadingWire {
    Triple(String, String, Verdict),
    Full {
        axis: String,
        level: String,
        verdict: Verdict,
        #[serde(default)]
        pooled: Option<Pooled>,
        #[serde(default)]
        estimates: Vec<(usize, Estimate)>,
        #[serde(default)]
        matched: Option<Pooled>,
    },
}

impl From<ReadingWire> for ReadingVerdict {
    fn from(w: ReadingWire) -> ReadingVerdict {
        match w {
            ReadingWire::Triple(axis, level, verdict) => {
                ReadingVerdict { axis, level, verdict, pooled: None, estimates: Vec::new(), matched: None }
            }
            ReadingWire::Full { axis, level, verdict, pooled, estimates, matched } => {
                ReadingVerdict { axis, level, verdict, pooled, estimates, matched }
            }
        }
    }
}

impl ReadingVerdict {
    /// `axis = level`.
    pub fn name(&self) -> String {
        format!("{} = {}", self.axis, self.level)
    }

    /// What this level is compared with: the default pooled over the same
    /// replications where there is one, else `headline`.
    pub fn baseline(&self, headline: Verdict) -> Verdict {
        self.matched.as_ref().map_or(headline, |m| m.verdict)
    }

    /// Whether this level flips the claim: its verdict differs from the
    /// default's at matched replications (plan v2), or from `headline` where
    /// the default was not pooled at the level's replications.
    pub fn flips(&self, headline: Verdict) -> bool {
        self.verdict != self.baseline(headline)
    }
}

/// How two crossed axes (and their levels) are joined in a reading's name:
/// `irl-scale × tile-width = 0.1 × 0.2`.
pub const CROSSED: &str = " × ";

/// How the axes were varied, for the scorecard's lines and the section:
/// one at a time, and the crossed pairs where there are any.
fn varied(crossed: bool) -> &'static str {
    if crossed {
        "axes varied one at a time, and the pairs joined by × crossed in full"
    } else {
        "axes varied one at a time"
    }
}

/// One claim's verdicts across replications and readings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ClaimRobustness {
    pub id: String,
    /// The verdict at each replication seed (the master seed first).
    pub seeds: Vec<Verdict>,
    /// The claim at each non-default level of each axis.
    pub readings: Vec<ReadingVerdict>,
    /// The verdict on all replications together, where the claim has
    /// replication-level estimates.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pooled: Option<Pooled>,
    /// The Clopper–Pearson 95 % interval of "holds in k of K".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub held_interval: Option<(f64, f64)>,
    /// The claim's estimates at each replication (its index, the master
    /// seed's 0), from which the pooled verdict is recomputed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub estimates: Vec<(usize, Estimate)>,
}

impl ClaimRobustness {
    /// (reproduced, evaluable) over the replications.
    pub fn held(&self) -> (usize, usize) {
        let evaluable = self.seeds.iter().filter(|v| **v != Verdict::NotEvaluable).count();
        (self.seeds.iter().filter(|v| **v == Verdict::Reproduced).count(), evaluable)
    }

    /// The axes with a level that flips the claim ([`ReadingVerdict::flips`]), in order, once each.
    pub fn flipped_by(&self, headline: Verdict) -> Vec<&str> {
        let mut axes: Vec<&str> = Vec::new();
        for r in &self.readings {
            if r.flips(headline) && !axes.contains(&r.axis.as_str()) {
                axes.push(&r.axis);
            }
        }
        axes
    }

    /// Whether any of its readings crosses two axes.
    fn crossed(&self) -> bool {
        self.readings.iter().any(|r| r.axis.contains(CROSSED))
    }

    /// One line for the scorecard, e.g. "pooled over 10 replications:
    /// inconclusive (…); holds in 7 of 10 seeds (95 % CI 0.35–0.93);
    /// flipped by terminal-potential".
    pub fn line(&self, headline: Verdict) -> String {
        // A reading flips the claim when its verdict differs from the
        // default's decided the same way: pooled over the same replications
        // where there is one (plan v2), else the pooled one over all.
        let headline = self.pooled.as_ref().map_or(headline, |p| p.verdict);
        let (held, evaluable) = self.held();
        let mut line = String::new();
        if let Some(p) = &self.pooled {
            line.push_str(&format!("pooled over {} replications: {}; ", self.seeds.len(), p.text()));
        }
        line.push_str(&format!("holds in {held} of {} seeds", self.seeds.len()));
        if let Some((lo, hi)) = self.held_interval {
            line.push_str(&format!(" (95 % CI {lo:.2}–{hi:.2})"));
        }
        if evaluable < self.seeds.len() {
            line.push_str(&format!(" ({} not evaluable)", self.seeds.len() - evaluable));
        }
        if !self.readings.is_empty() {
            let flips = self.flipped_by(headline);
            if flips.is_empty() {
                line.push_str(&format!("; no reading flips it ({})", varied(self.crossed())));
            } else {
                // Each flipping level with its verdict and, where pooled,
                // every component's effect and interval (the direction in
                // which the reading moves the claim).
                let flipped: Vec<String> = self
                    .readings
                    .iter()
                    .filter(|r| r.flips(headline))
                    .map(|r| match (&r.pooled, &r.matched) {
                        (Some(p), Some(m)) => {
                            format!("{} ({}; the default over the same replications: {})", r.name(), p.text(), m.text())
                        }
                        (Some(p), None) => format!("{} ({})", r.name(), p.text()),
                        _ => format!("{} ({})", r.name(), r.verdict.label()),
                    })
                    .collect();
                line.push_str(&format!(
                    "; flipped by {} ({})",
                    if self.pooled.is_some() { flipped.join(", ") } else { flips.join(", ") },
                    varied(self.crossed())
                ));
            }
        }
        line
    }
}

/// A chapter's robustness run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Robustness {
    /// The replication seeds, the master seed first.
    pub seeds: Vec<u64>,
    /// The axes varied.
    pub axes: Vec<AxisInfo>,
    /// Per claim of the chapter, in report order.
    pub claims: Vec<ClaimRobustness>,
}

/// One run of a claim, as the data files list it.
type Run<'a> = (&'a str, &'a str, &'a str, Option<&'a Pooled>, &'a [(usize, Estimate)], Option<&'a Pooled>);

fn mark(v: Verdict) -> &'static str {
    match v {
        Verdict::Reproduced => "✓",
        Verdict::NotReproduced => "✗",
        Verdict::NotEvaluable => "–",
        Verdict::Inconclusive => "?",
    }
}

impl Robustness {
    /// Decides `report`'s claims on all replications together, as the
    /// analysis plan says the headline is decided: every claim with a pooled
    /// verdict takes it, its reason saying so and keeping the master seed's
    /// verdict and reason beside it. Claims without estimates keep the
    /// master seed's verdict (their robustness line gives k of K).
    pub fn decide(&self, report: &mut ChapterReport) {
        let plan = crate::plan::analysis_plan();
        for section in &mut report.sections {
            for block in &mut section.blocks {
                let Block::Claims(claims) = block else { continue };
                for claim in claims.iter_mut() {
                    let Some(pooled) = self.claim(&claim.id).and_then(|c| c.pooled.as_ref()) else { continue };
                    claim.reason = format!(
                        "Decided on all {} replications by the {}: {}. At the master seed alone: {}. {}",
                        self.seeds.len(),
                        plan.line(),
                        pooled.text(),
                        claim.verdict.label(),
                        claim.reason
                    );
                    claim.verdict = pooled.verdict;
                }
            }
        }
    }

    /// The claim `id`'s robustness.
    pub fn claim(&self, id: &str) -> Option<&ClaimRobustness> {
        self.claims.iter().find(|c| c.id == id)
    }

    /// The report section: how it was run, the axes with their levels and
    /// sources, and a table of verdicts per claim (✓ reproduced, ✗ not,
    /// – not evaluable).
    pub fn section(&self, headline: &[Claim], provenance: &crate::Provenance) -> crate::Result<Section> {
        let crossed: Vec<&str> = self.claims.first().map_or(Vec::new(), |c| {
            let mut axes: Vec<&str> = Vec::new();
            for r in c.readings.iter().filter(|r| r.axis.contains(CROSSED)) {
                if !axes.contains(&r.axis.as_str()) {
                    axes.push(&r.axis);
                }
            }
            axes
        });
        let crossed = if crossed.is_empty() {
            String::new()
        } else {
            format!(
                " Beside them, {} crossed in full: every pair of their non-default levels, at the readings' replications.",
                crossed.join(" and ")
            )
        };
        let mut blocks = vec![Block::Paragraph(format!(
            "Each verdict of this chapter recomputed over {} independent replications (master seeds {}, derived from the master seed) and at every other level of each open choice, one axis at a time with the others at their defaults.{crossed} ✓ reproduced, ✗ not reproduced, ? inconclusive, – not evaluable. *Pooled*: the claim decided on all replications together by the analysis plan's rule (a one-sample t-test on one estimate per replication; blank where the claim has no replication-level estimates yet). Each other level is pooled over its own replications, which run at the first replication seeds; an asterisk marks a level that flips the claim, that is whose verdict differs from the default's pooled over the same replications (the plan's rule since v2: the default at all replications can differ from a level at fewer by the number of replications alone).",
            self.seeds.len(),
            self.seeds.iter().map(u64::to_string).collect::<Vec<_>>().join(", ")
        ))];
        if let Some(n) = self.undecidable_yes_no() {
            blocks.push(Block::Paragraph(format!(
                "A yes/no component (an order, a first-to-cross, a property) pooled over {n} replications cannot be decided either way: the exact binomial test cannot reach α = 0.05 (even {n} of {n} gives a Clopper–Pearson 95 % lower bound of {:.3}, not above one half), so at such a level it reads inconclusive, as does the default over the same replications, and no level flips it.",
                clopper_pearson(n, n, 0.95).map_or(f64::NAN, |(lo, _)| lo)
            )));
        }
        for axis in &self.axes {
            let levels: Vec<String> = axis
                .levels
                .iter()
                .map(|l| {
                    let default = if l.name == axis.default { " (default)" } else { "" };
                    format!("`{}`{default}: {} ({})", l.name, l.meaning, l.source)
                })
                .collect();
            blocks.push(Block::Paragraph(format!(
                "*{}*: {} Levels: {}. Default: `{}`, because {}.",
                axis.name,
                axis.question,
                levels.join("; "),
                axis.default,
                axis.why_default
            )));
        }
        let mut table = Table::new(
            "robustness",
            "Verdicts per claim: the headline (default reading, master seed), over the replication seeds, and at each other level of each axis",
            "Claim",
        );
        table.columns.push(ColumnGroup::new("Headline"));
        table.columns.push(ColumnGroup::new("Pooled"));
        table.columns.push(ColumnGroup::new("Seeds"));
        let columns: Vec<String> =
            self.claims.first().map(|c| c.readings.iter().map(ReadingVerdict::name).collect()).unwrap_or_default();
        table.columns.extend(columns.iter().map(|h| ColumnGroup::new(h.clone())));
        for c in &self.claims {
            let head = headline.iter().find(|h| h.id == c.id).map_or(Verdict::NotEvaluable, |h| h.verdict);
            let (held, _) = c.held();
            let mut cells = vec![
                Cell::text(mark(head)),
                Cell::text(c.pooled.as_ref().map_or("", |p| mark(p.verdict))),
                Cell::text(format!(
                    "{held}/{} {}",
                    c.seeds.len(),
                    c.seeds.iter().map(|v| mark(*v)).collect::<String>()
                )),
            ];
            // A level that flips the claim (against the default at matched
            // replications) carries an asterisk.
            let default = c.pooled.as_ref().map_or(head, |p| p.verdict);
            cells.extend(
                c.readings
                    .iter()
                    .map(|r| Cell::text(format!("{}{}", mark(r.verdict), if r.flips(default) { "*" } else { "" }))),
            );
            table.rows.push(Row::new(c.id.clone(), cells));
        }
        table.check()?;
        blocks.push(Block::Table(table));
        if let Some((plot, left_out)) = self.specification_curve() {
            let left_out = if left_out.is_empty() {
                String::new()
            } else {
                format!(
                    " Yes/no components and those without a within-replication SD are in the table only: {}.",
                    left_out.join(", ")
                )
            };
            let parts = plot.parts(MAX_FIGURE_HEIGHT);
            let n = parts.len();
            for (i, part) in parts.iter().enumerate() {
                let file = if i == 0 {
                    "specification_curve.svg".to_string()
                } else {
                    format!("specification_curve_{}.svg", i + 1)
                };
                let which = if n > 1 { format!(" (part {} of {n}, by claim component)", i + 1) } else { String::new() };
                blocks.push(Block::Figure {
                    file,
                    caption: format!(
                        "Specification curve{which}: each claim component's effect pooled over replications, at the default reading ({} replications) and at each other level of each axis (its own replications), in units of the component's within-replication SD (estimate and interval divided by the mean SD of its replications), with its interval (95 %; 90 % for an equivalence component); the diamond marks the thesis's effect in the same units where it is recoverable. Positive is the thesis's direction.{left_out}",
                        self.seeds.len()
                    ),
                    svg: part.to_svg(provenance)?,
                });
            }
        }
        if self.claims.iter().any(|c| !c.estimates.is_empty()) {
            blocks.push(Block::DataFile {
                file: "robustness_estimates.csv".into(),
                description: "Every claim component's estimate at every replication (the replication's index and master seed; the estimate oriented so the thesis's direction is positive, or the difference with its equivalence margin, or 1/0 for a yes/no property; the within-replication SD; the thesis's effect in our units), from which the pooled verdicts are recomputed (`checks/recompute_statistics.py`).".into(),
                bytes: self.estimates_csv(),
            });
            blocks.push(Block::DataFile {
                file: "robustness_pooled.csv".into(),
                description: "Each claim component pooled over the replications: how many had an estimate, the mean, its interval (95 %; 90 % for equivalence; Clopper–Pearson for a yes/no property), the power at the thesis's effect, the component's verdict and the claim's.".into(),
                bytes: self.pooled_csv(),
            });
        }
        Ok(Section::new("Robustness: seeds and readings", blocks))
    }

    /// The largest number of replications at which some reading's yes/no
    /// component was pooled and which is too few for the exact binomial
    /// rule to decide it (`None`: none such).
    fn undecidable_yes_no(&self) -> Option<usize> {
        self.claims
            .iter()
            .flat_map(|c| &c.readings)
            .filter_map(|r| r.pooled.as_ref())
            .flat_map(|p| &p.components)
            .filter(|k| k.direction == Direction::Holds && k.replications >= 2)
            .map(|k| k.replications)
            .filter(|&n| clopper_pearson(n, n, 0.95).is_ok_and(|(lo, _)| lo <= 0.5))
            .max()
    }

    /// The chapter's specification curve (`None` when no component can be
    /// drawn), with the components left out of it.
    fn specification_curve(&self) -> Option<(ForestPlot, Vec<String>)> {
        let mut series = vec!["default".to_string()];
        for c in &self.claims {
            for r in &c.readings {
                if !series.contains(&r.name()) {
                    series.push(r.name());
                }
            }
        }
        let mut plot =
            ForestPlot::new("Specification curve: effects at every reading", "effect in within-replication SDs");
        plot.reference_label = "thesis".into();
        let mut left_out = Vec::new();
        for c in &self.claims {
            let Some(pooled) = &c.pooled else { continue };
            for k in &pooled.components {
                let label = format!("{} {}", c.id, k.label);
                let Some(sd) = k.sd_within.filter(|s| *s > 0.0 && k.direction != Direction::Holds) else {
                    left_out.push(label);
                    continue;
                };
                let point = |series: usize, p: &PooledComponent| {
                    [p.mean, p.lower, p.upper].iter().all(|v| v.is_finite()).then(|| ForestPoint {
                        series,
                        estimate: p.mean / sd,
                        lower: p.lower / sd,
                        upper: p.upper / sd,
                    })
                };
                let mut points: Vec<ForestPoint> = point(0, k).into_iter().collect();
                for r in &c.readings {
                    let at = r.pooled.as_ref().and_then(|p| p.components.iter().find(|x| x.label == k.label));
                    let s = series.iter().position(|n| *n == r.name()).expect("listed above");
                    points.extend(at.and_then(|p| point(s, p)));
                }
                if points.is_empty() {
                    left_out.push(label);
                    continue;
                }
                plot.rows.push(ForestRow {
                    label,
                    points,
                    reference: k.thesis.map(|t| t / sd).filter(|t| t.is_finite()),
                });
            }
        }
        plot.series = series;
        (!plot.rows.is_empty()).then_some((plot, left_out))
    }

    /// Per claim: the default reading's pooled verdict and estimates
    /// (axis and level empty), then each other level's.
    /// Each run's claim, axis, level, pooled verdict, estimates, and the
    /// default pooled over the same replications (a level's only).
    fn runs(&self) -> Vec<Run<'_>> {
        let mut out = Vec::new();
        for c in &self.claims {
            out.push((c.id.as_str(), "", "", c.pooled.as_ref(), c.estimates.as_slice(), None));
            for r in &c.readings {
                out.push((
                    c.id.as_str(),
                    r.axis.as_str(),
                    r.level.as_str(),
                    r.pooled.as_ref(),
                    r.estimates.as_slice(),
                    r.matched.as_ref(),
                ));
            }
        }
        out
    }

    fn estimates_csv(&self) -> Vec<u8> {
        let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
        let opt = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
        w.write_record([
            "claim",
            "axis",
            "level",
            "component",
            "kind",
            "margin",
            "replication",
            "seed",
            "value",
            "sd",
            "thesis",
        ])
        .expect("writing to memory");
        for (id, axis, level, _, estimates, _) in self.runs() {
            for (k, e) in estimates {
                let (kind, margin) = match e.direction {
                    Direction::Above => ("above", None),
                    Direction::Equivalent { margin } => ("equivalent", Some(margin)),
                    Direction::Holds => ("holds", None),
                };
                // A reading's replication k runs at the k-th replication seed too.
                w.write_record([
                    id.to_string(),
                    axis.to_string(),
                    level.to_string(),
                    e.label.clone(),
                    kind.to_string(),
                    opt(margin),
                    k.to_string(),
                    self.seeds.get(*k).map_or(String::new(), u64::to_string),
                    opt(e.value),
                    opt(e.sd),
                    opt(e.thesis),
                ])
                .expect("writing to memory");
            }
        }
        w.into_inner().expect("writing to memory")
    }

    fn pooled_csv(&self) -> Vec<u8> {
        let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
        let num = |x: f64| if x.is_finite() { x.to_string() } else { String::new() };
        w.write_record([
            "claim",
            "axis",
            "level",
            "component",
            "replications",
            "mean",
            "lower",
            "upper",
            "power",
            "verdict",
            "claim_verdict",
            "default_matched",
            "flips",
        ])
        .expect("writing to memory");
        for (id, axis, level, pooled, _, matched) in self.runs() {
            let Some(p) = pooled else { continue };
            // A level's row: the default's claim verdict over the same
            // replications, and whether the level flips the claim.
            let (default_matched, flips) = match matched {
                Some(m) => (m.verdict.label(), if m.verdict != p.verdict { "yes" } else { "no" }),
                None => ("", ""),
            };
            for k in &p.components {
                w.write_record([
                    id.to_string(),
                    axis.to_string(),
                    level.to_string(),
                    k.label.clone(),
                    k.replications.to_string(),
                    num(k.mean),
                    num(k.lower),
                    num(k.upper),
                    k.power.map_or(String::new(), num),
                    k.verdict.label().to_string(),
                    p.verdict.label().to_string(),
                    default_matched.to_string(),
                    flips.to_string(),
                ])
                .expect("writing to memory");
            }
        }
        w.into_inner().expect("writing to memory")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn component(mean: f64, verdict: Verdict) -> PooledComponent {
        PooledComponent {
            label: "VB vs NP".into(),
            replications: 5,
            mean,
            lower: mean - 1.0,
            upper: mean + 1.0,
            power: Some(0.9),
            verdict,
            sd_within: Some(2.0),
            thesis: Some(4.0),
            direction: Direction::Above,
        }
    }

    #[test]
    fn a_not_evaluable_component_reads_back_from_its_json() {
        let mut c = component(f64::NAN, Verdict::NotEvaluable);
        c.replications = 0;
        let json = serde_json::to_string(&c).unwrap();
        assert!(json.contains("\"mean\":null"), "{json}");
        let back: PooledComponent = serde_json::from_str(&json).unwrap();
        assert!(back.mean.is_nan() && back.lower.is_nan() && back.upper.is_nan());
        assert_eq!((back.replications, back.verdict), (0, Verdict::NotEvaluable));
    }

    fn robustness() -> Robustness {
        let pooled = |mean, verdict| Some(Pooled { verdict, components: vec![component(mean, verdict)] });
        Robustness {
            seeds: vec![1, 2],
            axes: Vec::new(),
            claims: vec![ClaimRobustness {
                id: "C5.1".into(),
                seeds: vec![Verdict::Reproduced, Verdict::Reproduced],
                readings: vec![ReadingVerdict {
                    axis: "epsilon".into(),
                    level: "0.01".into(),
                    verdict: Verdict::Inconclusive,
                    pooled: pooled(0.5, Verdict::Inconclusive),
                    estimates: vec![(0, Estimate::above("VB vs NP", 0.5, 2.0, Some(4.0)))],
                    matched: None,
                }],
                pooled: pooled(3.0, Verdict::Reproduced),
                held_interval: None,
                estimates: vec![(0, Estimate::above("VB vs NP", 3.0, 2.0, Some(4.0)))],
            }],
        }
    }

    #[test]
    fn readings_stored_as_triples_still_load() {
        let old: ReadingVerdict = serde_json::from_str(r#"["epsilon", "0.01", "inconclusive"]"#).unwrap();
        assert_eq!((old.name(), old.verdict, old.pooled), ("epsilon = 0.01".into(), Verdict::Inconclusive, None));
        let r = robustness();
        let back: Robustness = serde_json::from_str(&serde_json::to_string(&r).unwrap()).unwrap();
        assert_eq!(back, r);
    }

    #[test]
    fn a_flipping_reading_is_named_with_its_effect_and_drawn_on_the_curve() {
        let r = robustness();
        let line = r.claims[0].line(Verdict::Reproduced);
        assert!(line.contains("flipped by epsilon = 0.01 (inconclusive (VB vs NP 0.5000 [−0.5000, 1.500]"), "{line}");
        let (plot, left_out) = r.specification_curve().unwrap();
        assert!(left_out.is_empty());
        assert_eq!(plot.series, vec!["default".to_string(), "epsilon = 0.01".into()]);
        // In within-replication SDs (2.0): the default's 3 ± 1 and the thesis's 4.
        let row = &plot.rows[0];
        assert_eq!((row.points[0].estimate, row.points[0].lower, row.points[0].upper), (1.5, 1.0, 2.0));
        assert_eq!((row.points[1].series, row.reference), (1, Some(2.0)));
        let csv = String::from_utf8(r.pooled_csv()).unwrap();
        assert!(csv.contains("\nC5.1,,,VB vs NP,5,3,2,4,0.9,reproduced,reproduced,,\n"), "{csv}");
        assert!(csv.contains("\nC5.1,epsilon,0.01,VB vs NP,5,0.5,"), "{csv}");
        let est = String::from_utf8(r.estimates_csv()).unwrap();
        assert!(est.contains("\nC5.1,epsilon,0.01,VB vs NP,above,,0,1,0.5,2,4\n"), "{est}");
    }

    #[test]
    fn a_crossed_pair_says_it_was_crossed_and_one_at_a_time_says_so_alone() {
        let mut r = robustness();
        assert!(r.claims[0].line(Verdict::Reproduced).ends_with("(axes varied one at a time)"));
        r.claims[0].readings[0].axis = format!("irl-scale{CROSSED}tile-width");
        r.claims[0].readings[0].level = format!("0.1{CROSSED}0.2");
        let line = r.claims[0].line(Verdict::Reproduced);
        assert!(line.contains("flipped by irl-scale × tile-width = 0.1 × 0.2 (inconclusive"), "{line}");
        assert!(line.ends_with("(axes varied one at a time, and the pairs joined by × crossed in full)"), "{line}");
        let est = String::from_utf8(r.estimates_csv()).unwrap();
        assert!(est.contains("\nC5.1,irl-scale × tile-width,0.1 × 0.2,VB vs NP,"), "{est}");
    }

    #[test]
    fn a_level_flips_only_against_the_default_at_the_same_replications() {
        let mut r = robustness();
        let at_five = |verdict| Some(Pooled { verdict, components: vec![component(0.7, verdict)] });
        // The default over all replications reproduces; over the level's
        // own replications it is inconclusive, as the level is: no flip.
        r.claims[0].readings[0].matched = at_five(Verdict::Inconclusive);
        let line = r.claims[0].line(Verdict::Reproduced);
        assert!(line.ends_with("; no reading flips it (axes varied one at a time)"), "{line}");
        let csv = String::from_utf8(r.pooled_csv()).unwrap();
        assert!(csv.contains(",inconclusive,inconclusive,inconclusive,no\n"), "{csv}");
        // Over the same replications the default reproduces: the level flips it.
        r.claims[0].readings[0].matched = at_five(Verdict::Reproduced);
        let line = r.claims[0].line(Verdict::Reproduced);
        assert!(
            line.contains("flipped by epsilon = 0.01 (inconclusive (VB vs NP 0.5000 [−0.5000, 1.500] over 5, power 0.90: inconclusive); the default over the same replications: reproduced (VB vs NP 0.7000"),
            "{line}"
        );
        let csv = String::from_utf8(r.pooled_csv()).unwrap();
        assert!(csv.contains(",inconclusive,inconclusive,reproduced,yes\n"), "{csv}");
        let section = r.section(&[], &crate::Provenance::new("test", "0")).unwrap();
        let Some(Block::Table(t)) = section.blocks.iter().find(|b| matches!(b, Block::Table(_))) else { panic!() };
        assert_eq!(t.rows[0].cells.last(), Some(&Cell::text("?*")));
    }

    #[test]
    fn a_yes_no_component_at_five_replications_is_said_to_be_undecidable() {
        let mut r = robustness();
        assert_eq!(r.undecidable_yes_no(), None);
        let reading = &mut r.claims[0].readings[0];
        let pooled = reading.pooled.as_mut().unwrap();
        pooled.components[0].direction = Direction::Holds;
        // 5 of 5: lower bound 0.478 (scipy.stats.binomtest(5, 5).proportion_ci(method="exact").low = 0.4782).
        assert_eq!(r.undecidable_yes_no(), Some(5));
        let Block::Paragraph(text) = &r.section(&[], &crate::Provenance::new("test", "0")).unwrap().blocks[1] else {
            panic!()
        };
        assert!(text.contains("lower bound of 0.478, not above one half"), "{text}");
        // 6 of 6 can be decided (lower bound 0.541).
        r.claims[0].readings[0].pooled.as_mut().unwrap().components[0].replications = 6;
        assert_eq!(r.undecidable_yes_no(), None);
    }
}
