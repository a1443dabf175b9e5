//! Chapter 3's report content: Table 3.2 beside the thesis's (three trials
//! per condition, and 100), t-tests, the reductions with guidance beside the
//! thesis's sentences, Figure 3.4, claims C3.1–C3.5, the noise study, the
//! domain, the parameters, the decisions and the raw data, built from stored
//! results only.

mod claims;
mod figures;
mod metrics;

use rlfd_report::data_file::csv_of;
use rlfd_report::figure::{LegendPosition, LineChart, Series, SeriesStyle};
use rlfd_report::parameters::Parameters;
use rlfd_report::prose::DataFile;
use rlfd_report::published::published;
use rlfd_report::table::statistics::{self, IqmRow, TestRow};
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, ChapterReport, Deviation, Provenance, Section};
use rlfd_stats::TwoSample;
use serde::Serialize;

use crate::experiment::{Condition, Experiment, SortingParams, SortingResults};
use crate::guidance::GuidanceRegion;
use crate::nao::timing::{THESIS_MEAN_ACTION_SECONDS, UNIT_SECONDS};
use crate::nao::{Action, CATALOGUE, Durations, StateSpace, state_count};
use crate::session::SessionRecord;
use crate::{CHAPTER, Results};

pub use claims::{ALPHA, BIN_MINUTES, MIN_TRIALS_FOR_TESTS, chapter_claims};
pub use metrics::{Involvement, Metric, involvement, reduction_pct};

/// The chapter's title.
pub const TITLE: &str = "Chapter 3: Human guidance and state-space size in Interactive RL (Nao sorting)";

const TABLE: &str = "ch3.table_3_2";

fn thesis(metric: Metric, c: Condition) -> f64 {
    published().table_value(TABLE, metric.key(), c.published_key()).unwrap_or(f64::NAN)
}

fn thesis_text(path: &str) -> f64 {
    published().number(&format!("ch3.text.{path}")).unwrap_or(f64::NAN)
}

fn trials(r: &SortingResults, c: Condition) -> &[SessionRecord] {
    r.trials.get(&c).map_or(&[], Vec::as_slice)
}

fn minus(s: String) -> String {
    s.replace('-', "−")
}

/// The chapter's claims C3.1–C3.5, from its results alone.
pub fn claims(results: &Results) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
    chapter_claims(results.sorting.as_ref(), results.powered.as_ref())
}

/// One level of the `perception-noise` sweep: the 100-trial experiment
/// run with the large space's readings shifting at `rate`.
#[derive(Clone, Copy, Debug)]
pub struct NoiseLevel<'a> {
    /// The level's shift probability.
    pub rate: f64,
    /// Whether it is the run's own level (its results are the headline's).
    pub own: bool,
    /// The experiment's results there.
    pub results: &'a SortingResults,
}

/// Builds the chapter's report from its results and the noise sweep's
/// levels (empty when the 100-trial experiment did not run).
pub fn chapter_report(
    results: &Results,
    noise: &[NoiseLevel<'_>],
    provenance: &Provenance,
) -> rlfd_report::Result<ChapterReport> {
    let sorting = results.sorting.as_ref();
    let powered = results.powered.as_ref();
    let mut sections = vec![Section::new("What was run", vec![Block::paragraph(summary(results))])];
    if let Some(r) = sorting {
        sections.push(Section::new(
            "Table 3.2: experiment statistics, three trials per condition (as the thesis)",
            vec![Block::Table(table_3_2(r, "table_3_2")?), Block::Table(iqm_table(r, "table_3_2_iqm")?)],
        ));
    }
    if let Some(r) = powered {
        sections.push(Section::new(
            format!("Table 3.2 with {} trials per condition, and t-tests", r.params.trials),
            vec![
                Block::Table(table_3_2(r, "table_3_2_powered")?),
                Block::Table(iqm_table(r, "table_3_2_powered_iqm")?),
                Block::Table(tests_table(r)?),
                Block::Table(full_tests_table(r)?),
            ],
        ));
    }
    if sorting.is_some() || powered.is_some() {
        sections.push(Section::new(
            "Reductions with guidance: ours beside the thesis's sentences",
            vec![Block::paragraph(REDUCTIONS_TEXT), Block::Table(reductions_table(sorting, powered)?)],
        ));
    }
    for r in [sorting, powered].into_iter().flatten() {
        sections.push(figure_section(r, provenance)?);
    }
    if sorting.is_some() || powered.is_some() {
        let mut blocks = vec![Block::Claims(chapter_claims(sorting, powered)?)];
        if let Some(r) = powered.or(sorting) {
            blocks.push(Block::paragraph(reward_balance(r)));
        }
        sections.push(Section::new("Claims C3.1–C3.5", blocks));
    }
    if noise.len() > 1 {
        sections.push(noise_section(noise, provenance)?);
    }
    let params = sorting.or(powered).map(|r| r.params.clone()).unwrap_or_else(SortingParams::paper);
    sections.push(domain_section(sorting.or(powered))?);
    sections.push(Section::new("Parameters", vec![Block::Parameters(parameters_table(&params, results)?)]));
    sections.push(Section::new("Decisions and deviations", vec![Block::Deviations(deviations()?)]));
    sections.push(data_section(results, noise));
    Ok(ChapterReport { slug: CHAPTER.into(), title: TITLE.into(), provenance: provenance.clone(), sections })
}

const REDUCTIONS_TEXT: &str = "The thesis's text says guidance cuts learning time by 28 % (small space) and 44 % (large) and the states explored by 51.5 % and 38 %; its own Table 3.2 gives 22.2 %, 43.6 %, 48.5 % and 37.9 %. Ours are computed from our tables as `1 − mean(guided) / mean(unguided)`.";

fn summary(results: &Results) -> String {
    let mut parts = Vec::new();
    for r in [results.sorting.as_ref(), results.powered.as_ref()].into_iter().flatten() {
        let sessions: Vec<&SessionRecord> = r.trials.values().flatten().collect();
        let unfinished = sessions.iter().filter(|s| !s.finished).count();
        let actions: u64 = sessions.iter().map(|s| u64::from(s.actions)).sum();
        let seconds: f64 = sessions.iter().map(|s| s.training_seconds).sum();
        parts.push(format!(
            "*{}*: the four conditions × {} trials ({} sessions, {} actions in all, {:.2} s per action on average against the thesis's 9.8 s; {} session(s) hit the cap of {} actions unfinished)",
            r.experiment.name(),
            r.params.trials,
            sessions.len(),
            rlfd_stats::format::thousands(actions as f64, 0),
            seconds / actions.max(1) as f64,
            unfinished,
            rlfd_stats::format::thousands(f64::from(r.params.max_actions), 0)
        ));
    }
    let (scale, seed) = match results.sorting.as_ref().or(results.powered.as_ref()) {
        Some(r) => (r.scale, r.seed),
        None => (rlfd_harness::Scale::Paper, 0),
    };
    format!(
        "A scripted expert teacher trains a simulated seated Nao to sort six objects (three plain, three patterned) into two cups with Interactive Q-learning (Algorithm 1), with and without guidance, in the small (360 states) and the large (6,480 states) state space, at the *{scale}* scale with master seed {seed}. Experiments: {}. Every number below is computed from the stored sessions; the thesis's value stands beside ours in every cell where it has one.",
        parts.join("; ")
    )
}

fn table_3_2(r: &SortingResults, id: &str) -> rlfd_report::Result<Table> {
    let n = r.params.trials;
    let mut t = Table::new(
        id,
        format!("Table 3.2: experiment statistics, mean ± sd over {n} trials per condition"),
        "Statistic",
    );
    t.caption = format!(
        "Ours (mean ± sd over {n} trials) beside the thesis's mean over 3 trials. #States: states in the Q-table at the end; #Actions: actions performed; Cumul. Rew.: sum of the teacher's rewards (±1); Total #G.: actions guided; training time: the simulated durations of the actions."
    );
    t.columns = Condition::ALL
        .iter()
        .map(|c| ColumnGroup::new(format!("Fig. {}: {}", c.figure(), c.label())).with_key(c.published_key()))
        .collect();
    for m in Metric::ALL {
        let format = NumFormat::fixed(2);
        let cells = Condition::ALL
            .iter()
            .map(|&c| {
                let (mean, sd) = metrics::summary(trials(r, c), m);
                let ours = if sd.is_finite() { Num::new(mean, format).with_spread(sd) } else { Num::new(mean, format) };
                Cell::compare(ours, thesis(m, c))
            })
            .collect();
        t.rows.push(Row::new(m.label(), cells));
    }
    t.notes = vec![
        "Training time uses the per-action durations of the time model (see the domain section), calibrated so that a correct sorting averages the thesis's 9.8 s per action; the thesis's minutes were measured on the robot.".into(),
    ];
    t.check()?;
    Ok(t)
}

fn tests_table(r: &SortingResults) -> rlfd_report::Result<Table> {
    let mut t = Table::new(
        "table_3_2_tests",
        format!("Guided vs unguided: p-values of two-sample t-tests ({} trials per condition)", r.params.trials),
        "Statistic",
    );
    t.caption = "Pooled-variance Student t-tests (MATLAB `ttest2`'s default) and Welch's test, two-sided, guided against unguided in each space. The thesis ran three trials and no test.".into();
    t.columns = vec![
        ColumnGroup::new("Small: pooled").with_key("small_pooled"),
        ColumnGroup::new("Small: Welch").with_key("small_welch"),
        ColumnGroup::new("Large: pooled").with_key("large_pooled"),
        ColumnGroup::new("Large: Welch").with_key("large_welch"),
    ];
    for m in [Metric::States, Metric::Actions, Metric::CumulativeReward, Metric::Minutes] {
        let mut cells = Vec::new();
        for small in [true, false] {
            let (g, u) = metrics::pair(small);
            let (pooled, welch) = metrics::tests(trials(r, g), trials(r, u), m);
            cells.push(Cell::Num(Num::p_value(pooled.map_or(f64::NAN, |x| x.p))));
            cells.push(Cell::Num(Num::p_value(welch.map_or(f64::NAN, |x| x.p))));
        }
        t.rows.push(Row::new(m.label(), cells));
    }
    t.notes = vec!["* p ≤ 0.05, ** p ≤ 0.01, *** p ≤ 0.001, **** p ≤ 0.0001. A dash: the test is undefined (both samples constant). Total #G. is not tested: it is 0 without guidance by design.".into()];
    t.check()?;
    Ok(t)
}

/// Table 3.2's statistics per condition as interquartile means with 95 %
/// stratified-bootstrap intervals, beside the thesis's means.
fn iqm_table(r: &SortingResults, id: &str) -> rlfd_report::Result<Table> {
    let rows: Vec<IqmRow> = Condition::ALL
        .iter()
        .map(|&c| IqmRow {
            label: format!("Fig. {}: {}", c.figure(), c.label()),
            iqm: Metric::ALL
                .iter()
                .map(|&m| rlfd_stats::headline_iqm(&metrics::values(trials(r, c), m)).ok())
                .collect(),
            thesis_mean: Metric::ALL.iter().map(|&m| Some(thesis(m, c)).filter(|v| v.is_finite())).collect(),
            sample: Some(format!("{}/{}", r.experiment.name(), c.slug())),
        })
        .collect();
    let measures: Vec<(&str, &str)> = Metric::ALL.iter().map(|m| (m.label(), m.key())).collect();
    let t = statistics::iqm_table(
        id,
        &format!("Table 3.2 as interquartile means, {} trials per condition", r.params.trials),
        "The interquartile mean of each statistic over the trials (with three trials it is their mean: a quarter of three rounds down to none trimmed) beside the thesis's mean over its 3 trials. Sample: experiment/condition of sessions.csv.",
        "Condition",
        &measures,
        &rows,
        2,
    );
    t.check()?;
    Ok(t)
}

/// The t-tests of [`tests_table`] in full.
fn full_tests_table(r: &SortingResults) -> rlfd_report::Result<Table> {
    let mut rows = Vec::new();
    for small in [true, false] {
        let (g, u) = metrics::pair(small);
        for m in [Metric::States, Metric::Actions, Metric::CumulativeReward, Metric::Minutes] {
            rows.push(TestRow {
                pair: format!("{} vs {}", g.label(), u.label()),
                measure: m.label().into(),
                two: TwoSample::of(&metrics::values(trials(r, g), m), &metrics::values(trials(r, u), m), 0.95).ok(),
                holm: None,
                samples: Some([g, u].map(|c| format!("{}/{}", r.experiment.name(), c.slug()))),
            });
        }
    }
    let t = statistics::full_tests(
        "table_3_2_powered_tests_full",
        "Guided vs unguided: every test in full",
        "The tests whose p-values the table above prints, with the guided mean minus the unguided one. Samples: experiment/condition of sessions.csv (columns states, actions, cumulative_reward, training_minutes).",
        &rows,
        2,
        true,
    );
    t.check()?;
    Ok(t)
}

fn reductions_table(sorting: Option<&SortingResults>, powered: Option<&SortingResults>) -> rlfd_report::Result<Table> {
    let mut t = Table::new("reductions", "Reductions with guidance (percent)", "Reduction");
    t.caption = "`1 − mean(guided) / mean(unguided)`. The thesis column is its text's sentence; the next column recomputes it from the thesis's own Table 3.2.".into();
    let mut columns = Vec::new();
    for r in [sorting, powered].into_iter().flatten() {
        columns.push(
            ColumnGroup::new(format!("Ours, {} trials (vs the thesis's text)", r.params.trials))
                .with_key(format!("trials_{}", r.params.trials)),
        );
    }
    columns.push(ColumnGroup::new("From the thesis's Table 3.2").with_key("thesis_table"));
    t.columns = columns;
    let pct = NumFormat::Percent { decimals: 1 };
    let rows = [
        ("Training time, small space", Metric::Minutes, true, "time_reduction_pct.small"),
        ("Training time, large space", Metric::Minutes, false, "time_reduction_pct.large"),
        ("States explored, small space", Metric::States, true, "states_reduction_pct.small"),
        ("States explored, large space", Metric::States, false, "states_reduction_pct.large"),
    ];
    for (label, m, small, text_key) in rows {
        let (g, u) = metrics::pair(small);
        let mut cells = Vec::new();
        for r in [sorting, powered].into_iter().flatten() {
            let ours = reduction_pct(metrics::mean(trials(r, g), m), metrics::mean(trials(r, u), m));
            cells.push(Cell::compare(Num::new(ours, pct), thesis_text(text_key)));
        }
        cells.push(Cell::Num(Num::new(reduction_pct(thesis(m, g), thesis(m, u)), pct)));
        t.rows.push(Row::new(label, cells));
    }
    t.check()?;
    Ok(t)
}

fn figure_section(r: &SortingResults, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let curves = figures::curves(r);
    let min_running = figures::min_running(r.params.trials as usize);
    let x_max = figures::common_x_max(&curves, min_running);
    let suffix = if r.experiment == Experiment::Sorting { String::new() } else { format!("_{}", r.params.trials) };
    let mut blocks = vec![Block::paragraph(format!(
        "Per condition, the share of actions the teacher rewarded and guided in each {BIN_MINUTES:.0}-minute bin of training time, pooled over the sessions still training (dashed: their share of the {} sessions). The first 20 actions (about three minutes) are all rewarded, and guided in the guidance condition; afterwards the teacher speaks only after a mistake and for the five actions that follow. Panels share their axes, as the thesis's.{}",
        r.params.trials,
        if min_running > 1 {
            format!(
                " Curves stop where fewer than {min_running} sessions are still training (the tail of a few long sessions is in `involvement.csv`)."
            )
        } else {
            String::new()
        }
    ))];
    let below: Vec<String> = curves
        .iter()
        .map(|(c, inv)| {
            format!(
                "({}) {}: {}",
                &c.figure()[3..],
                c.label(),
                inv.first_below_half().map_or("never".to_string(), |m| format!("minute {m:.0}"))
            )
        })
        .collect();
    blocks.push(Block::Figure {
        file: format!("figure_3_4{suffix}.svg"),
        caption: format!(
            "Figure 3.4, {} trials per condition: the share of actions rewarded and guided per minute, and of sessions still training (dashed). The pooled share first falls below 50 % by {}.",
            r.params.trials,
            below.join("; ")
        ),
        svg: figures::figure_3_4(
            &format!("Figure 3.4: teacher involvement over training time, {} trials per condition", r.params.trials),
            &curves,
            x_max,
            min_running,
            provenance,
        )?,
    });
    let title = if r.experiment == Experiment::Sorting {
        "Figure 3.4: teacher involvement over training time (three trials per condition)".to_string()
    } else {
        format!("Figure 3.4 with {} trials per condition", r.params.trials)
    };
    Ok(Section::new(title, blocks))
}

/// Where the cumulative reward comes from: −1 per mistake, +1 per rewarded
/// correct action, split into the first 20 actions and the rest.
fn reward_balance(r: &SortingResults) -> String {
    let first = r.params.protocol.initial_actions as usize;
    let mut parts = Vec::new();
    for c in Condition::ALL {
        let ts = trials(r, c);
        let n = ts.len().max(1) as f64;
        let (mut early, mut later, mut mistakes) = (0usize, 0usize, 0usize);
        for t in ts {
            for (i, &f) in t.flags.iter().enumerate() {
                let rewarded = f & crate::session::flag::REWARDED != 0;
                if f & crate::session::flag::CORRECT == 0 {
                    mistakes += 1;
                } else if rewarded && i < first {
                    early += 1;
                } else if rewarded {
                    later += 1;
                }
            }
        }
        parts.push(format!(
            "{}: {} mistakes (−1 each) against {} rewarded correct actions in the first {first} and {} after (+1 each)",
            c.label(),
            metrics::num(mistakes as f64 / n, 1),
            metrics::num(early as f64 / n, 1),
            metrics::num(later as f64 / n, 1)
        ));
    }
    format!(
        "Where the cumulative reward comes from (means over the {} trials per condition of *{}*): {}. Under the protocol as stated, every mistake (−1) opens five attended actions, each +1 when it is correct, so with rewards of equal size the sum turns negative only when the robot's attended actions are wrong more often than right. The thesis's clearly negative sums without guidance imply more punished than praised actions (or punishments larger than praise); the thesis does not report its reward magnitudes, and our expert's ±1 is not tuned to reach them; the `reward-sizes` reading runs praise at 0.5 and 0.9 of punishment (and punishment at half of praise), and the robustness section gives C3.4 at each.",
        r.params.trials,
        r.experiment.name(),
        parts.join("; ")
    )
}

fn noise_section(levels: &[NoiseLevel<'_>], provenance: &Provenance) -> rlfd_report::Result<Section> {
    let trials_per = levels.first().map_or(0, |l| l.results.params.trials);
    let mut t = Table::new(
        "noise_sensitivity",
        "Sensitivity: the large space at each reading-noise level (not in the thesis)",
        "Condition, shift probability",
    );
    t.caption = format!(
        "Mean ± sd over {trials_per} trials of *sorting-100* at each level of the `perception-noise` reading, the master seed's replication. The run's own level ({}) is the headline's.",
        levels.iter().find(|l| l.own).map_or(String::new(), |l| l.rate.to_string())
    );
    let shown = [Metric::States, Metric::Actions, Metric::CumulativeReward, Metric::Minutes];
    t.columns = shown.iter().map(|m| ColumnGroup::new(m.label()).with_key(m.key())).collect();
    for condition in [Condition::LargeGuidance, Condition::LargeNoGuidance] {
        for l in levels {
            let ts = trials(l.results, condition);
            let cells = shown
                .iter()
                .map(|&m| {
                    let (mean, sd) = metrics::summary(ts, m);
                    let num = Num::new(mean, NumFormat::fixed(2));
                    Cell::Num(if sd.is_finite() { num.with_spread(sd) } else { num })
                })
                .collect();
            t.rows.push(Row::new(format!("{}, {}", condition.label(), l.rate), cells));
        }
    }
    t.check()?;
    let mut cuts = Table::new("noise_reductions", "Sensitivity: C3.3 at each reading-noise level", "Shift probability");
    cuts.caption = format!(
        "Cuts are `1 − mean(guided) / mean(unguided)`; the small space has no reading noise, so its sessions are the same at every level. The last two columns are C3.3's statistic and its 95 % bootstrap interval ({} resamples) exactly as the claim computes them, on this one replication; the robustness section's cell for the same level pools it with four more replications, whose master-seed estimate is this row's (checked by `checks/recompute_statistics.py`).",
        claims::BOOTSTRAP_RESAMPLES
    );
    cuts.columns = vec![
        ColumnGroup::new("Large: time cut").with_key("time"),
        ColumnGroup::new("Large: states cut").with_key("states"),
        ColumnGroup::new("Small: time cut").with_key("small_time"),
        ColumnGroup::new("C3.3: large − small [points]").with_key("c33"),
        ColumnGroup::new("95 % interval").with_key("c33_interval"),
    ];
    let pct = NumFormat::Percent { decimals: 1 };
    let cut = |g: &[SessionRecord], u: &[SessionRecord], m| {
        Cell::Num(Num::new(reduction_pct(metrics::mean(g, m), metrics::mean(u, m)), pct))
    };
    for l in levels {
        let of = |c: Condition| trials(l.results, c);
        let (lg, lu) = (of(Condition::LargeGuidance), of(Condition::LargeNoGuidance));
        let (sg, su) = (of(Condition::SmallGuidance), of(Condition::SmallNoGuidance));
        let (diff, interval) = match claims::time_cut_difference(l.results) {
            Some((e, lo, hi)) => (
                Cell::Num(Num::new(e, NumFormat::fixed(1))),
                Cell::Text(minus(format!("[{}, {}]", metrics::num(lo, 1), metrics::num(hi, 1)))),
            ),
            None => (Cell::Empty, Cell::Empty),
        };
        cuts.rows.push(Row::new(
            l.rate.to_string(),
            vec![
                cut(lg, lu, Metric::Minutes),
                cut(lg, lu, Metric::States),
                cut(sg, su, Metric::Minutes),
                diff,
                interval,
            ],
        ));
    }
    cuts.check()?;
    let mut chart = LineChart::new(
        "Sensitivity: mean training time against the reading-noise level (large space)",
        "Probability that a reading shifts one feature",
        "Training time [min]",
    );
    for condition in [Condition::LargeGuidance, Condition::LargeNoGuidance] {
        let at: Vec<(f64, f64, f64)> = levels
            .iter()
            .map(|l| {
                let ts = trials(l.results, condition);
                let (mean, sd) = metrics::summary(ts, Metric::Minutes);
                (l.rate, mean, sd / (ts.len().max(1) as f64).sqrt())
            })
            .collect();
        chart.series.push(Series {
            name: format!("{} (± 1 standard error)", condition.label()),
            points: at.iter().map(|&(x, m, _)| (x, m)).collect(),
            band: Some(at.iter().map(|&(_, m, se)| if se.is_finite() { (m - se, m + se) } else { (m, m) }).collect()),
            style: SeriesStyle::LineAndMarkers,
        });
    }
    chart.legend = LegendPosition::Outside;
    Ok(Section::new(
        "Sensitivity to the large space's reading noise (not in the thesis)",
        vec![
            Block::paragraph(
                "The thesis says the large space's readings are \"non-deterministic\" and give \"slightly different state representations\", without a rate. Ours, one reading in five with one feature off by one category, is an input-side choice made before any learner ran and the `perception-noise` reading's default. This section is *sorting-100* swept over that reading's levels at the master seed: the same trials a run of each reading makes, so its rows are the robustness run's first replication at each level, not a separate experiment.",
            ),
            Block::Table(t),
            Block::Table(cuts),
            Block::Figure {
                file: "figure_noise_sensitivity.svg".into(),
                caption: "Mean training time in the large space at each reading-noise level, with a band of ± 1 standard error of the mean.".into(),
                svg: chart.to_svg(provenance)?,
            },
        ],
    ))
}

fn domain_section(r: Option<&SortingResults>) -> rlfd_report::Result<Section> {
    let text = format!(
        "The robot's state is the thesis's `(z_lh, z_rh, hand_o | I, o_z, o_p)`: left hand in z1 or z2, right hand in z2 or z3, the object in neither or one hand, the descriptor `I`, the object's zone and its placement (z1, z2, z3, right cup, left cup). Enumerated from the types, the small space has {} states and the large {} (the thesis: 360 and 6,480). Legal actions: TakePicture always; xPickUp when the hand is free, in the object's zone and the object has been photographed; xPutDown when holding; xDrop when holding above the hand's own cup (left hand in z1, right in z3); xLeft/xRight within the hand's reach. A sort from rest is five actions: TakePicture, move in, pick up, move out, drop.",
        rlfd_stats::format::thousands(state_count(StateSpace::Small) as f64, 0),
        rlfd_stats::format::thousands(state_count(StateSpace::Large) as f64, 0)
    );
    let mut regions = Table::new("table_3_1", "Table 3.1: guidance regions and the actions they allow", "Guidance");
    regions.caption =
        "Generated from the code (`guidance::GuidanceRegion::actions`); a test checks it against the thesis's table."
            .into();
    regions.columns = vec![ColumnGroup::new("Action set").with_key("actions")];
    for g in GuidanceRegion::ALL {
        regions.rows.push(Row::new(g.name(), vec![Cell::text(g.actions().names())]));
    }
    regions.check()?;

    let mut objects = Table::new("objects", "The objects and their true large-space categories", "Object");
    objects.caption = "Our choice (the thesis does not list its objects); see the decisions below. A large-space reading shifts one feature by one category with probability 0.2.".into();
    objects.columns = vec![
        ColumnGroup::new("Class").with_key("class"),
        ColumnGroup::new("Cup").with_key("cup"),
        ColumnGroup::new("SURF, smoothness, entropy, area").with_key("features"),
    ];
    for o in &CATALOGUE {
        let cup = match o.class.cup() {
            crate::nao::Cup::Left => "left",
            crate::nao::Cup::Right => "right",
        };
        objects
            .rows
            .push(Row::new(o.name, vec![Cell::text(o.class.name()), Cell::text(cup), Cell::text(o.features.label())]));
    }
    objects.check()?;

    let d = r.map_or_else(Durations::thesis, |r| r.params.durations);
    let mut timing = Table::new("action_durations", "Seconds per action (the time model)", "Action");
    timing.caption = format!(
        "Each step is the two waiting windows of Algorithm 1 ({} unit) plus the action's own motion, in units of {:.3} s, a length calibrated so that a correct sort averages the thesis's {THESIS_MEAN_ACTION_SECONDS} s per action.",
        d.wait_units, UNIT_SECONDS
    );
    timing.columns = vec![ColumnGroup::new("Units").with_key("units"), ColumnGroup::new("Seconds").with_key("seconds")];
    for a in [Action::TakePicture, Action::LLeft, Action::LPickUp, Action::LPutDown, Action::LDrop] {
        let name = match a {
            Action::TakePicture => "TakePicture",
            Action::LLeft => "xLeft, xRight",
            Action::LPickUp => "xPickUp",
            Action::LPutDown => "xPutDown",
            _ => "xDrop",
        };
        timing.rows.push(Row::new(
            name,
            vec![
                Cell::Num(Num::new(d.units(a), NumFormat::fixed(1))),
                Cell::Num(Num::new(d.seconds(a), NumFormat::fixed(2))),
            ],
        ));
    }
    timing.check()?;

    let mut blocks = vec![Block::paragraph(text), Block::Table(regions), Block::Table(objects), Block::Table(timing)];
    if let Some(r) = r {
        let mut pace = Table::new("seconds_per_action", "Mean seconds per action in our sessions", "Condition");
        pace.caption = "Training time over actions, per condition: an outcome of the learner's mix of actions, shown beside the thesis's 9.8 s (which it reports for the large space with guidance).".into();
        pace.columns = vec![ColumnGroup::new("Seconds per action").with_key("seconds")];
        for c in Condition::ALL {
            let ts = trials(r, c);
            let secs: f64 = ts.iter().map(|s| s.training_seconds).sum();
            let acts: f64 = ts.iter().map(|s| f64::from(s.actions)).sum();
            let cell = Num::new(secs / acts, NumFormat::fixed(2));
            pace.rows.push(Row::new(
                c.label(),
                vec![if c == Condition::LargeGuidance {
                    Cell::compare(cell, THESIS_MEAN_ACTION_SECONDS)
                } else {
                    Cell::ours_only(cell)
                }],
            ));
        }
        pace.check()?;
        blocks.push(Block::Table(pace));
    }
    Ok(Section::new("The domain: the Nao sorting table", blocks))
}

fn parameters_table(p: &SortingParams, results: &Results) -> rlfd_report::Result<Table> {
    let mut rows = Parameters::new("parameters", "Parameters");
    let trials = |r: Option<&SortingResults>| r.map_or("not run".to_string(), |r| r.params.trials.to_string());
    rows.thesis_says("Trials per condition (sorting)", trials(results.sorting.as_ref()), "{ch3.table_3_2.trials}");
    rows.row(
        "Trials per condition (sorting-100)",
        trials(results.powered.as_ref()),
        "ours: 100 at paper scale, for t-tests",
    );
    rows.thesis("α", p.learner_small.alpha);
    rows.thesis("γ", p.learner_small.gamma);
    rows.thesis("Initial Q of a new state", p.learner_small.initial_q);
    rows.thesis("ε", p.learner_small.epsilon);
    rows.thesis("δε small / large", format!("{} / {}", p.learner_small.epsilon_decay, p.learner_large.epsilon_decay));
    rows.thesis("Actions attended from the start", p.protocol.initial_actions);
    rows.thesis("Actions attended after a mistake", p.protocol.follow_up_actions);
    rows.row(
        "Rewards: correct / incorrect",
        minus(format!("{} / {}", p.protocol.correct_reward, p.protocol.wrong_reward)),
        "ours, within the interface's [−1, 1]",
    );
    rows.thesis("Clean objects into each cup to finish", p.objects_per_cup);
    rows.row("Objects", format!("{} (3 plain, 3 patterned), in shuffled rounds", CATALOGUE.len()), "ours");
    rows.row("Large-space reading shift probability", p.shift_probability, "ours, fixed before any learner ran");
    rows.calibrated("Unit of the time model", format!("{UNIT_SECONDS:.4} s"), "the thesis's 9.8 s per action");
    rows.row("Action cap per session", p.max_actions, "ours");
    rows.row("Involvement bins", format!("{BIN_MINUTES} min"), "ours");
    rows.row("Tests", format!("pooled t-test at p < {ALPHA}; ≥ {MIN_TRIALS_FOR_TESTS} trials per condition"), "ours");
    rows.table()
}

/// The chapter's decisions and deviations, kept as data in `data/deviations.toml`.
const DEVIATIONS: DataFile = DataFile {
    path: "chapters/ch3-interactive-rl/data/deviations.toml",
    text: include_str!("../../data/deviations.toml"),
};

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    DEVIATIONS.deviations("deviation")
}

/// One row of `sessions.csv`.
#[derive(Serialize)]
struct SessionRow {
    experiment: &'static str,
    condition: String,
    /// The `perception-noise` level of a sweep row (empty: the run's own reading).
    sweep_level: String,
    trial: usize,
    finished: bool,
    states: u32,
    actions: u32,
    cumulative_reward: f64,
    guidance: u32,
    rewards: u32,
    mistakes: u32,
    training_minutes: f64,
    objects_sorted: u32,
    objects_missorted: u32,
    descriptors_read: u32,
    rewarded_correct_initial: u32,
    rewarded_correct_after: u32,
    below_half_minute: f64,
    below_half_censored: bool,
}

fn sessions_csv(results: &Results, noise: &[NoiseLevel<'_>]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut rows = |experiment: &'static str,
                    condition: String,
                    sweep_level: String,
                    ts: &[SessionRecord],
                    params: &SortingParams| {
        let initial = params.protocol.initial_actions as usize;
        let crossings = metrics::first_below_half_per_session(ts, &params.durations, BIN_MINUTES);
        for (k, (t, crossing)) in ts.iter().zip(crossings).enumerate() {
            // C3.4's split of the reward and C3.5's time to the crossing
            // (censored: the session ended before it), so both can be
            // recomputed from this file.
            let (mut initial_rewarded, mut after_rewarded) = (0u32, 0u32);
            for (i, &f) in t.flags.iter().enumerate() {
                if f & crate::session::flag::CORRECT != 0 && f & crate::session::flag::REWARDED != 0 {
                    if i < initial { initial_rewarded += 1 } else { after_rewarded += 1 }
                }
            }
            out.push(SessionRow {
                experiment,
                condition: condition.clone(),
                sweep_level: sweep_level.clone(),
                trial: k,
                finished: t.finished,
                states: t.states_discovered,
                actions: t.actions,
                cumulative_reward: t.cumulative_reward,
                guidance: t.guidance_given,
                rewards: t.rewards_given,
                mistakes: t.mistakes,
                training_minutes: t.training_minutes(),
                objects_sorted: t.objects_sorted,
                objects_missorted: t.objects_missorted,
                descriptors_read: t.descriptors_read,
                rewarded_correct_initial: initial_rewarded,
                rewarded_correct_after: after_rewarded,
                below_half_minute: crossing.time,
                below_half_censored: !crossing.observed,
            });
        }
    };
    for r in [results.sorting.as_ref(), results.powered.as_ref()].into_iter().flatten() {
        for (c, ts) in &r.trials {
            rows(r.experiment.name(), c.slug().to_string(), String::new(), ts, &r.params);
        }
    }
    for l in noise.iter().filter(|l| !l.own) {
        for (c, ts) in &l.results.trials {
            rows(l.results.experiment.name(), c.slug().to_string(), l.rate.to_string(), ts, &l.results.params);
        }
    }
    csv_of(out)
}

/// One row of `involvement.csv`.
#[derive(Serialize)]
struct InvolvementRow<'a> {
    experiment: &'a str,
    condition: &'a str,
    minute_from: f64,
    actions: u32,
    rewarded: u32,
    guided: u32,
    attended: u32,
    sessions_training: u32,
}

fn involvement_csv(results: &Results) -> Vec<u8> {
    let mut rows = Vec::new();
    for r in [results.sorting.as_ref(), results.powered.as_ref()].into_iter().flatten() {
        for (c, inv) in figures::curves(r) {
            for b in 0..inv.actions.len() {
                rows.push(InvolvementRow {
                    experiment: r.experiment.name(),
                    condition: c.slug(),
                    minute_from: b as f64 * inv.bin_minutes,
                    actions: inv.actions[b],
                    rewarded: inv.rewarded[b],
                    guided: inv.guided[b],
                    attended: inv.attended[b],
                    sessions_training: inv.running[b],
                });
            }
        }
    }
    csv_of(rows)
}

/// One row of `sorting_actions.csv`.
#[derive(Serialize)]
struct ActionRow<'a> {
    condition: &'a str,
    trial: usize,
    step: usize,
    action: &'a str,
    rewarded: u8,
    guided: u8,
    correct: u8,
}

fn actions_csv(r: &SortingResults) -> Vec<u8> {
    let mut rows = Vec::new();
    for (c, ts) in &r.trials {
        for (k, t) in ts.iter().enumerate() {
            for (i, (&a, &f)) in t.action_log.iter().zip(&t.flags).enumerate() {
                rows.push(ActionRow {
                    condition: c.slug(),
                    trial: k,
                    step: i + 1,
                    action: Action::from_index(a as usize).name(),
                    rewarded: u8::from(f & crate::session::flag::REWARDED != 0),
                    guided: u8::from(f & crate::session::flag::GUIDED != 0),
                    correct: u8::from(f & crate::session::flag::CORRECT != 0),
                });
            }
        }
    }
    csv_of(rows)
}

fn data_section(results: &Results, noise: &[NoiseLevel<'_>]) -> Section {
    let mut blocks = vec![
        Block::DataFile {
            file: "sessions.csv".into(),
            description: "Every session of every experiment: Table 3.2's numbers and more (rewards given, mistakes, objects sorted, descriptors read), the rewarded correct actions in the protocol's initial actions and after them (C3.4), and the end of the first minute in which fewer than half of the actions drew reward or guidance, or the session's end where it never did (`below_half_censored`: C3.5). Rows with a `sweep_level` are *sorting-100* at that `perception-noise` level (the noise sweep); the others are the run's own reading.".into(),
            bytes: sessions_csv(results, noise),
        },
        Block::DataFile {
            file: "involvement.csv".into(),
            description: format!("Figure 3.4's data: per experiment, condition and {BIN_MINUTES:.0}-minute bin, the actions starting in it and how many the teacher rewarded, guided, or either, with the sessions still training."),
            bytes: involvement_csv(results),
        },
    ];
    if let Some(r) = &results.sorting {
        blocks.push(Block::DataFile {
            file: "sorting_actions.csv".into(),
            description: "Every action of the three-trial experiment: condition, trial, step, action, and whether it was rewarded, guided and correct.".into(),
            bytes: actions_csv(r),
        });
    }
    Section::new("Data", blocks)
}
