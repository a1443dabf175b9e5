//! The chapter's figures: learning curves over simulated hours (Figures
//! 5.3–5.6: trial mean with a standard-error band; each teacher's mean
//! demonstration as a dashed line of its own colour; the thesis's 14 s
//! threshold; the thesis's final value of each condition as a short tick in
//! the condition's colour right of the last hour), the greedy evaluations
//! beside them, and one traced episode.

use rlfd_report::Provenance;
use rlfd_report::figure::{HLine, LegendPosition, LineChart, Series, SeriesStyle, Stroke};

use super::metrics::mean_curve;
use crate::experiment::{Ch5Results, Condition, TracedEpisode};
use crate::keepaway::{CYCLES_PER_SECOND, KEEPERS, TAKERS, Vec2};

/// Points per curve (one every `hours / 60`).
const POINTS: usize = 60;

/// Where the thesis's final-value ticks sit, as fractions of the trial's
/// hours: from `hours · TICK.0` to `hours · TICK.1`.
const TICK: (f64, f64) = (1.015, 1.055);

/// One curve of a learning figure: its label, its condition and the thesis's
/// final value for it (if the thesis gives one).
pub struct Curve<'a> {
    /// Legend label.
    pub label: &'a str,
    /// The condition.
    pub condition: Condition,
    /// The thesis's final reward (s).
    pub thesis_final: Option<f64>,
}

/// A learning-curve figure: each condition's online curve (mean ± s.e.),
/// the teachers' means (`references`: label, seconds) dashed, the
/// threshold as a solid grey line.
pub fn learning_curves(
    title: &str,
    results: &Ch5Results,
    curves: &[Curve],
    references: &[(String, f64)],
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let p = &results.params;
    let times: Vec<f64> = (0..=POINTS).map(|k| p.hours * k as f64 / POINTS as f64).collect();
    let mut chart = LineChart::new(
        format!("{title} (mean ± s.e. over {} trials)", p.trials),
        "Simulated hours",
        format!("Episode duration (s), sliding mean of {} episodes", p.window),
    );
    let mut any_tick = false;
    for curve in curves {
        let Some(trials) = results.trials(&curve.condition) else { continue };
        let (mean, se) = mean_curve(trials, p.window, &times);
        let mut points: Vec<(f64, f64)> = times.iter().copied().zip(mean.iter().copied()).collect();
        let mut band: Vec<(f64, f64)> = mean.iter().zip(&se).map(|(m, s)| (m - s, m + s)).collect();
        if let Some(v) = curve.thesis_final {
            // A break, then the tick (no band under it).
            points.extend([(f64::NAN, f64::NAN), (p.hours * TICK.0, v), (p.hours * TICK.1, v)]);
            band.extend([(f64::NAN, f64::NAN); 3]);
            any_tick = true;
        }
        chart.series.push(Series { name: curve.label.into(), points, band: Some(band), style: SeriesStyle::Line });
    }
    for (name, y) in references {
        chart.series.push(Series {
            name: name.clone(),
            points: vec![(0.0, *y), (p.hours, *y)],
            band: None,
            style: SeriesStyle::Dashed,
        });
    }
    chart.reference_lines.push(HLine {
        name: format!("{} s (the thesis's threshold)", p.threshold_seconds),
        y: p.threshold_seconds,
        stroke: Stroke::Solid,
    });
    if any_tick {
        chart.x_range = Some((0.0, p.hours * (TICK.1 + 0.01)));
    }
    chart.legend = LegendPosition::Auto;
    chart.size = (760, 500);
    chart.to_svg(provenance)
}

/// The greedy evaluations of `curves`' conditions: at hour 0 and every
/// integral hour, the mean duration of episodes played with learning and
/// exploration off (mean ± s.e. over trials).
pub fn greedy_curves(
    title: &str,
    results: &Ch5Results,
    curves: &[Curve],
    provenance: &Provenance,
) -> rlfd_report::Result<Option<String>> {
    let p = &results.params;
    let mut chart = LineChart::new(
        format!("{title}, greedy (mean ± s.e. over {} trials)", p.trials),
        "Simulated hours",
        format!("Episode duration (s), mean of {} greedy episodes", p.greedy_episodes),
    );
    for curve in curves {
        let Some(trials) = results.trials(&curve.condition) else { continue };
        let hours = trials.iter().map(|t| t.greedy_cycles.len()).min().unwrap_or(0);
        if hours == 0 {
            continue;
        }
        let mut points = Vec::with_capacity(hours);
        let mut band = Vec::with_capacity(hours);
        for h in 0..hours {
            let v: Vec<f64> = trials.iter().map(|t| t.greedy_cycles[h] / CYCLES_PER_SECOND).collect();
            let (m, se) = match rlfd_stats::Summary::of(&v) {
                Ok(s) => (s.mean, s.se),
                Err(_) => (v[0], 0.0),
            };
            points.push((h as f64, m));
            band.push((m - se, m + se));
        }
        chart.series.push(Series {
            name: curve.label.into(),
            points,
            band: Some(band),
            style: SeriesStyle::LineAndMarkers,
        });
    }
    if chart.series.is_empty() {
        return Ok(None);
    }
    chart.reference_lines.push(HLine {
        name: format!("{} s (the thesis's threshold)", p.threshold_seconds),
        y: p.threshold_seconds,
        stroke: Stroke::Solid,
    });
    chart.size = (760, 500);
    chart.to_svg(provenance).map(Some)
}

/// One traced episode: the paths of the ball and the keepers (solid) and
/// of the takers (dashed), each with a `+` where it starts; the plot
/// is the 20 m × 20 m region.
pub fn episode_picture(traced: &TracedEpisode, provenance: &Provenance) -> rlfd_report::Result<String> {
    let duration = traced.cycles.last().map_or(0, |s| s.cycle);
    let mut chart = LineChart::new(
        format!(
            "A demonstration episode of {} ({:.1} s): paths of the keepers, takers and ball",
            traced.player,
            f64::from(duration) / CYCLES_PER_SECOND
        ),
        "x (m)",
        "y (m)",
    );
    // A path with a plus sign at its start (after a break, in its colour).
    let path = |at: &dyn Fn(&crate::keepaway::Snapshot) -> Vec2| -> Vec<(f64, f64)> {
        let mut points: Vec<(f64, f64)> = traced.cycles.iter().map(at).map(|v| (v.x, v.y)).collect();
        if let Some(first) = traced.cycles.first() {
            let o = at(first);
            let arm = 0.5;
            points.extend([
                (f64::NAN, f64::NAN),
                (o.x - arm, o.y),
                (o.x + arm, o.y),
                (f64::NAN, f64::NAN),
                (o.x, o.y - arm),
                (o.x, o.y + arm),
            ]);
        }
        points
    };
    // The traced episode is the thesis's 3 vs 2. Palette order: the ball
    // blue; keepers vermillion, green, purple; takers orange, sky blue.
    chart.series.push(Series { name: "ball".into(), points: path(&|s| s.ball), band: None, style: SeriesStyle::Line });
    for k in 0..KEEPERS {
        chart.series.push(Series {
            name: format!("keeper {}", k + 1),
            points: path(&|s| s.keepers[k]),
            band: None,
            style: SeriesStyle::Line,
        });
    }
    for t in 0..TAKERS {
        chart.series.push(Series {
            name: format!("taker {}", t + 1),
            points: path(&|s| s.takers[t]),
            band: None,
            style: SeriesStyle::Dashed,
        });
    }
    let half = 10.0;
    chart.x_range = Some((-half, half));
    chart.y_range = Some((-half, half));
    chart.legend = LegendPosition::Outside;
    chart.size = (700, 560);
    chart.to_svg(provenance)
}
