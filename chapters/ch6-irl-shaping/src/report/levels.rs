//! The sensitivity sections of both halves: agents rerun at every level of
//! a reading (the Maze's irl-scale, Mario's dis-beta) beside the baseline,
//! as a table of mean ± sd per metric and a figure of their mean curves.
//! Nothing is chosen from these runs; the sections say so in their text.

use rlfd_report::figure::{LegendPosition, LineChart, Series, SeriesStyle};
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row};
use rlfd_report::{Block, Provenance, Section};
use rlfd_stats::Summary;

use super::agent_tables::{TableText, table};
use super::metrics::{Metric, Scored, values};
use crate::shaping::trials::{LevelRun, LevelRuns};

/// What a half's sensitivity section says and draws.
pub struct LevelText<'a, T> {
    /// The section's title.
    pub title: &'a str,
    /// The paragraph before the table.
    pub text: &'a str,
    /// The table's identity and wording (its notes are made here).
    pub table: TableText<'a>,
    /// What follows "Diverged and left out: …." in the table's note.
    pub diverged_tail: &'a str,
    /// How a mean is shown.
    pub format: NumFormat,
    /// A run's row label.
    pub label: &'a dyn Fn(&LevelRun<T>) -> String,
    /// The figure's file, title, y-axis label, y-range and caption.
    pub figure: (&'a str, String, &'a str, Option<(f64, f64)>, &'a str),
    /// The points of a row's mean curve (episode, value).
    pub curve: &'a dyn Fn(&[T]) -> Vec<(f64, f64)>,
}

/// The section: the baseline's trials (`baseline`, when it has any) then
/// each run of `levels`; `trials` per condition.
pub fn section<T: Scored>(
    text: LevelText<'_, T>,
    baseline: Option<(&str, &[T])>,
    levels: &LevelRuns<T>,
    trials: u32,
    provenance: &Provenance,
) -> rlfd_report::Result<Section> {
    let mut rows: Vec<(String, &[T])> = baseline.map(|(l, ts)| (l.to_string(), ts)).into_iter().collect();
    let mut diverged = Vec::new();
    for run in &levels.runs {
        let label = (text.label)(run);
        if !run.diverged.is_empty() {
            diverged.push(format!("{label} {}", super::diverged_phrase(&run.diverged, trials)));
        }
        rows.push((label, run.trials.as_slice()));
    }
    let mut t = table(text.table, "Agent");
    t.columns = Metric::ALL.iter().map(|m| ColumnGroup::new(m.header::<T>())).collect();
    if !diverged.is_empty() {
        t.notes = vec![format!("Diverged and left out: {}.{}", diverged.join("; "), text.diverged_tail)];
    }
    for (label, ts) in &rows {
        let cells = Metric::ALL
            .iter()
            .map(|&m| match Summary::of(&values(ts, m)) {
                Ok(s) => Cell::Num(Num::new(s.mean, text.format).with_spread(s.sd)),
                Err(_) => Cell::Empty,
            })
            .collect();
        t.rows.push(Row::new(label.clone(), cells));
    }
    t.check()?;
    let (file, title, y_label, y_range, caption) = text.figure;
    let mut chart = LineChart::new(title, "Episode", y_label);
    for (label, ts) in &rows {
        chart.series.push(Series {
            name: label.clone(),
            points: (text.curve)(ts),
            band: None,
            style: SeriesStyle::Line,
        });
    }
    chart.y_range = y_range;
    chart.legend = LegendPosition::Outside;
    Ok(Section::new(
        text.title,
        vec![
            Block::paragraph(text.text),
            Block::Table(t),
            Block::Figure { file: file.into(), caption: caption.into(), svg: chart.to_svg(provenance)? },
        ],
    ))
}
