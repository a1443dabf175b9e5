//! Figure 3.4: the teacher's involvement over training time, one panel per
//! condition, with common axes ("The y-axis and legend are common for all
//! graphs"); and the noise study's figure.

use rlfd_report::Provenance;
use rlfd_report::figure::{LegendPosition, LineChart, Series, SeriesStyle};

use super::claims::BIN_MINUTES;
use super::metrics::{Involvement, involvement};
use crate::experiment::{Condition, SortingResults};

/// The involvement curves of every condition of `r`.
pub fn curves(r: &SortingResults) -> Vec<(Condition, Involvement)> {
    Condition::ALL
        .iter()
        .filter_map(|&c| r.trials.get(&c).map(|ts| (c, involvement(ts, &r.params.durations, BIN_MINUTES))))
        .collect()
}

/// Figure 3.4: the four conditions' panels in a 2 × 2 grid with common
/// axes and one legend, as the thesis lays them out.
pub fn figure_3_4(
    title: &str,
    curves: &[(Condition, Involvement)],
    x_max: f64,
    min_running: usize,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let panels: Vec<LineChart> = curves.iter().map(|(c, inv)| figure_3_4_panel(*c, inv, x_max, min_running)).collect();
    LineChart::grid(title, &panels, 2, provenance)
}

/// One panel of Figure 3.4: the share of actions rewarded and guided per
/// minute, and the share of sessions still training (dashed).
fn figure_3_4_panel(condition: Condition, inv: &Involvement, x_max: f64, min_running: usize) -> LineChart {
    let centre = |b: usize| (b as f64 + 0.5) * inv.bin_minutes;
    let shown = shown_bins(inv, min_running);
    let series = |name: &str, counts: &[u32], style| Series {
        name: name.into(),
        points: (0..shown).map(|b| (centre(b), inv.share(counts, b))).collect(),
        band: None,
        style,
    };
    let mut chart = LineChart::new(
        format!("({}) {}, {} sessions", &condition.figure()[3..], condition.label(), inv.sessions),
        "Training time [min]",
        "Actions / sessions [%]",
    );
    chart.series.push(series("Reward", &inv.rewarded, SeriesStyle::Line));
    chart.series.push(series("Guidance", &inv.guided, SeriesStyle::Line));
    chart.series.push(Series {
        name: "Sessions still training".into(),
        points: (0..shown)
            .map(|b| (centre(b), 100.0 * f64::from(inv.running[b]) / inv.sessions.max(1) as f64))
            .collect(),
        band: None,
        style: SeriesStyle::Dashed,
    });
    chart.x_range = Some((0.0, x_max));
    chart.y_range = Some((0.0, 105.0));
    chart.legend = LegendPosition::Hidden;
    chart.size = (480, 330);
    chart
}

/// Sessions that must still be training for a bin to be drawn: one for
/// three trials (every session is shown), 5 % of them for more, so the
/// pooled share of the last few long sessions does not dominate the panel.
pub fn min_running(sessions: usize) -> usize {
    if sessions <= 10 { 1 } else { sessions.div_ceil(20) }
}

/// Number of leading bins with at least `min_running` sessions training.
fn shown_bins(inv: &Involvement, min_running: usize) -> usize {
    inv.running.iter().take_while(|&&r| r as usize >= min_running).count()
}

/// The common x-axis end: the last drawn bin of any panel, rounded up to 5 minutes.
pub fn common_x_max(curves: &[(Condition, Involvement)], min_running: usize) -> f64 {
    let longest =
        curves.iter().map(|(_, inv)| shown_bins(inv, min_running) as f64 * inv.bin_minutes).fold(0.0, f64::max);
    ((longest / 5.0).ceil() * 5.0).max(5.0)
}
