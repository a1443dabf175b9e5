//! The tables both halves of the chapter print for their five agents:
//! mean ± sd per metric with the demonstrator's row (Tables 6.1 and 6.3),
//! pooled and Welch p-values for the thesis's ten pairs (Tables 6.2 and 6.4),
//! those tests in full and the interquartile means beside the thesis's
//! means ([`full_tests_table`], [`iqm_table`]), and the episodes from which
//! each agent stays above the demonstrator and at which it first rises
//! above it.
//! The Maze and Mario differ only in their data, keys and wording, which the
//! callers pass in.

use rlfd_report::published::published;
use rlfd_report::table::statistics::{self, IqmRow, TestRow};
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_stats::{Summary, TwoSample, student_t_test, welch_t_test};

use super::metrics::{Metric, MetricTable, Scored, pair_label, thesis_pairs};
use crate::shaping::{Agent, Baseline};

/// A metric column: its header and its key in `thesis-numbers.toml`.
#[derive(Clone, Copy, Debug)]
pub struct MetricColumn {
    pub header: &'static str,
    pub key: &'static str,
}

/// A table's identity and wording.
pub struct TableText<'a> {
    pub id: &'a str,
    pub title: &'a str,
    pub caption: String,
    /// The table's key in `thesis-numbers.toml` (e.g. `ch6.maze.table_6_1`).
    pub thesis_key: &'a str,
    pub notes: Vec<String>,
}

fn thesis(table: &str, column: &str, row: &str) -> f64 {
    published().table_value(table, column, row).unwrap_or(f64::NAN)
}

pub(super) fn table(text: TableText<'_>, stub: &str) -> Table {
    let mut t = Table::new(text.id, text.title, stub);
    t.caption = text.caption;
    t.notes = text.notes;
    t
}

/// Mean ± sd of every agent's per-trial values (`rows`: label, one sample
/// per column), then the demonstrator's `hmn` under the first two columns.
pub fn means_table(
    text: TableText<'_>,
    columns: &[MetricColumn],
    rows: &[(&str, Vec<Vec<f64>>)],
    hmn: f64,
    format: NumFormat,
) -> rlfd_report::Result<Table> {
    let key = text.thesis_key.to_string();
    let mut t = table(text, "Agent");
    t.columns = columns.iter().map(|c| ColumnGroup::new(c.header).with_key(c.key)).collect();
    for (label, samples) in rows {
        let cells = columns
            .iter()
            .zip(samples)
            .map(|(c, xs)| {
                let ours =
                    Summary::of(xs).map_or(Num::new(f64::NAN, format), |s| Num::new(s.mean, format).with_spread(s.sd));
                Cell::compare(ours, thesis(&key, c.key, label))
            })
            .collect();
        t.rows.push(Row::new(*label, cells));
    }
    let hmn_cells = columns
        .iter()
        .enumerate()
        .map(
            |(i, c)| if i < 2 { Cell::compare(Num::new(hmn, format), thesis(&key, c.key, "HMN")) } else { Cell::Empty },
        )
        .collect();
    t.rows.push(Row::new("HMN", hmn_cells));
    t.check()?;
    Ok(t)
}

/// Pooled-variance p-values beside the thesis's, then Welch's, for each
/// pair (`pairs`: label, then per column the two samples).
pub fn p_value_table(
    text: TableText<'_>,
    columns: &[MetricColumn],
    pairs: &[(String, Vec<(Vec<f64>, Vec<f64>)>)],
) -> rlfd_report::Result<Table> {
    let key = text.thesis_key.to_string();
    let mut t = table(text, "Pair");
    t.columns = columns
        .iter()
        .map(|c| ColumnGroup::new(c.header).with_key(c.key))
        .chain(
            columns
                .iter()
                .map(|c| ColumnGroup::new(format!("{} (Welch)", c.header)).with_key(format!("{}_welch", c.key))),
        )
        .collect();
    for (label, samples) in pairs {
        let p = |test: Result<rlfd_stats::TTest, _>| test.map_or(f64::NAN, |t| t.p);
        let mut cells: Vec<Cell> = columns
            .iter()
            .zip(samples)
            .map(|(c, (a, b))| Cell::compare(Num::p_value(p(student_t_test(a, b))), thesis(&key, c.key, label)))
            .collect();
        cells.extend(samples.iter().map(|(a, b)| Cell::Num(Num::p_value(p(welch_t_test(a, b))))));
        t.rows.push(Row::new(label.clone(), cells));
    }
    t.check()?;
    Ok(t)
}

/// Each agent's episode to surpass the demonstrator beside the thesis's
/// (`thesis_prefix.<label>` in `thesis-numbers.toml`; absent = never): the
/// episode from which it stays above (the verdicts' reading), then the
/// first episode above it (`rows`: label, stays above from, first above).
pub fn surpass_table(text: TableText<'_>, rows: &[(&str, Option<usize>, Option<usize>)]) -> rlfd_report::Result<Table> {
    let prefix = text.thesis_key.to_string();
    let mut t = table(text, "Agent");
    t.columns = vec![ColumnGroup::new("Stays above from"), ColumnGroup::new("First above")];
    let p = published();
    for &(label, e, first) in rows {
        let theirs = p.number(&format!("{prefix}.{label}")).unwrap_or(f64::NAN);
        let cell = match (e, theirs.is_nan()) {
            (Some(e), false) => Cell::compare(Num::new(e as f64, NumFormat::Integer), theirs),
            (Some(e), true) => Cell::text(format!("{e} (thesis: never)")),
            (None, false) => Cell::text(format!("never (thesis: {theirs})")),
            (None, true) => Cell::text("never (thesis: never)"),
        };
        let first = match first {
            Some(f) => Cell::ours_only(Num::new(f as f64, NumFormat::Integer)),
            None => Cell::text("never"),
        };
        t.rows.push(Row::new(label, vec![cell, first]));
    }
    t.check()?;
    Ok(t)
}

/// The metric columns of `T`'s half, in the thesis's order.
pub fn metric_columns<T: Scored>() -> Vec<MetricColumn> {
    Metric::ALL.iter().map(|m| MetricColumn { header: m.header::<T>(), key: m.key() }).collect()
}

/// The rows of [`means_table`]: each of `agents` with its values per metric.
pub fn means_rows(table: &MetricTable, agents: &[Agent], baseline: Baseline) -> Vec<(&'static str, Vec<Vec<f64>>)> {
    agents
        .iter()
        .map(|&a| (a.label(baseline), Metric::ALL.iter().map(|&m| table.values(a, m).to_vec()).collect()))
        .collect()
}

/// The rows of [`p_value_table`]: the thesis's ten pairs with their samples per metric.
pub fn pair_rows(table: &MetricTable, baseline: Baseline) -> Vec<(String, Vec<(Vec<f64>, Vec<f64>)>)> {
    thesis_pairs()
        .iter()
        .map(|&(a, b)| {
            let samples = Metric::ALL.iter().map(|&m| (table.values(a, m).to_vec(), table.values(b, m).to_vec()));
            (pair_label(a, b, baseline), samples.collect())
        })
        .collect()
}

/// The t-tests of the thesis's ten pairs ([`p_value_table`]) in full: per
/// pair and metric the sizes, the difference with its 95 % interval, t, df,
/// p and Hedges' g, Student's and Welch's rows. `sample` names an agent's
/// runs in the report's data files, for a reader to recompute them.
pub fn full_tests_table(
    text: TableText<'_>,
    table: &MetricTable,
    baseline: Baseline,
    sample: impl Fn(Agent) -> String,
    decimals: usize,
) -> rlfd_report::Result<Table> {
    let mut rows = Vec::new();
    for (a, b) in thesis_pairs() {
        for m in Metric::ALL {
            rows.push(TestRow {
                pair: pair_label(a, b, baseline),
                measure: m.key().into(),
                two: TwoSample::of(table.values(a, m), table.values(b, m), 0.95).ok(),
                holm: None,
                samples: Some([sample(a), sample(b)]),
            });
        }
    }
    let mut t = statistics::full_tests(text.id, text.title, &text.caption, &rows, decimals, true);
    t.notes.extend(text.notes);
    t.check()?;
    Ok(t)
}

/// Each of `agents`' interquartile mean per metric with its 95 %
/// stratified-bootstrap interval, beside the thesis's mean
/// (`text.thesis_key`'s table); `sample` names an agent's runs as in
/// [`full_tests_table`].
pub fn iqm_table<T: Scored>(
    text: TableText<'_>,
    table: &MetricTable,
    agents: &[Agent],
    baseline: Baseline,
    sample: impl Fn(Agent) -> String,
    decimals: usize,
) -> rlfd_report::Result<Table> {
    let key = text.thesis_key;
    let rows: Vec<IqmRow> = agents
        .iter()
        .map(|&a| {
            let label = a.label(baseline);
            IqmRow {
                label: label.into(),
                iqm: Metric::ALL.iter().map(|&m| rlfd_stats::headline_iqm(table.values(a, m)).ok()).collect(),
                thesis_mean: Metric::ALL
                    .iter()
                    .map(|m| Some(thesis(key, m.key(), label)).filter(|v| v.is_finite()))
                    .collect(),
                sample: Some(sample(a)),
            }
        })
        .collect();
    let measures: Vec<(&str, &str)> = Metric::ALL.iter().map(|&m| (m.header::<T>(), m.key())).collect();
    let mut t = statistics::iqm_table(text.id, text.title, &text.caption, "Agent", &measures, &rows, decimals);
    t.notes.extend(text.notes);
    t.check()?;
    Ok(t)
}
