//! The chapter's figures: learning curves over simulated hours (Figures
//! 5.3–5.6: trial mean with a standard-error band, the teachers' mean
//! demonstration durations as dashed lines) and one traced episode.

use rlfd_report::Provenance;
use rlfd_report::figure::{
    HLine, LegendPosition, LineChart, Marker, PathEmphasis, Rect, Scene, ScenePath, Series, SeriesStyle, Stroke,
};

use super::metrics::mean_curve;
use crate::experiment::{Ch5Results, Condition, TracedEpisode};

/// Points per curve (one every `hours / 60`).
const POINTS: usize = 60;

/// A learning-curve figure of `conditions` (label, condition) with reference lines.
pub fn learning_curves(
    title: &str,
    results: &Ch5Results,
    conditions: &[(&str, Condition)],
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
    for (label, c) in conditions {
        let Some(trials) = results.trials(c) else { continue };
        let (mean, se) = mean_curve(trials, p.window, &times);
        chart.series.push(Series {
            name: (*label).into(),
            points: times.iter().copied().zip(mean.iter().copied()).collect(),
            band: Some(mean.iter().zip(&se).map(|(m, s)| (m - s, m + s)).collect()),
            style: SeriesStyle::Line,
        });
    }
    for (name, y) in references {
        chart.reference_lines.push(HLine { name: name.clone(), y: *y, stroke: Stroke::Dashed });
    }
    chart.legend = LegendPosition::Outside;
    chart.to_svg(provenance)
}

/// One traced episode: the ball's and every player's path over the region.
pub fn episode_picture(traced: &TracedEpisode, provenance: &Provenance) -> rlfd_report::Result<String> {
    let duration = traced.cycles.last().map_or(0, |s| s.cycle);
    let mut scene = Scene::new(
        format!(
            "A demonstration episode of {} ({:.1} s): paths of the ball, keepers and takers",
            traced.player,
            f64::from(duration) / 10.0
        ),
        Rect::new(-11.0, -11.0, 11.0, 11.0),
    );
    // Outside the 20 m × 20 m region, in grey.
    scene.walls = vec![
        Rect::new(-11.0, -11.0, 11.0, -10.0),
        Rect::new(-11.0, 10.0, 11.0, 11.0),
        Rect::new(-11.0, -10.0, -10.0, 10.0),
        Rect::new(10.0, -10.0, 11.0, 10.0),
    ];
    let inside = |x: f64, y: f64| (x.clamp(-10.95, 10.95), y.clamp(-10.95, 10.95));
    scene.x_label = "x (m)".into();
    scene.y_label = "y (m)".into();
    scene.ticks = 5;
    // Paths are cut at the scene's edge (a ball that left the region may roll on).
    let clip = |p: (f64, f64)| inside(p.0, p.1);
    let ball: Vec<(f64, f64)> = traced.cycles.iter().map(|s| clip((s.ball.x, s.ball.y))).collect();
    for k in 0..3 {
        scene.paths.push(ScenePath {
            name: Some(format!("keeper {}", k + 1)),
            points: traced.cycles.iter().map(|s| clip((s.keepers[k].x, s.keepers[k].y))).collect(),
            emphasis: PathEmphasis::Light,
        });
    }
    for t in 0..2 {
        scene.paths.push(ScenePath {
            name: Some(format!("taker {}", t + 1)),
            points: traced.cycles.iter().map(|s| clip((s.takers[t].x, s.takers[t].y))).collect(),
            emphasis: PathEmphasis::Light,
        });
    }
    scene.paths.push(ScenePath { name: Some("ball".into()), points: ball, emphasis: PathEmphasis::Primary });
    if let Some(first) = traced.cycles.first() {
        for k in 0..3 {
            scene
                .markers
                .push(Marker { label: format!("K{}", k + 1), at: inside(first.keepers[k].x, first.keepers[k].y) });
        }
        scene.markers.push(Marker { label: "T".into(), at: inside(first.takers[0].x, first.takers[0].y) });
        scene.markers.push(Marker { label: "B".into(), at: inside(first.ball.x, first.ball.y) });
    }
    if let Some(last) = traced.cycles.last() {
        scene.markers.push(Marker { label: "end".into(), at: inside(last.ball.x, last.ball.y) });
    }
    scene.to_svg(provenance)
}
