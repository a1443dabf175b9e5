//! The Maze's figures: the layout (6.1), the demonstrations (6.2), the
//! optimal path (6.3) and the learning curves (6.4).

use rlfd_report::Provenance;
use rlfd_report::figure::{
    HLine, LegendPosition, LineChart, Marker, PathEmphasis, Rect, Scene, ScenePath, Series, SeriesStyle, Stroke,
};

use crate::maze::experiment::MazeResults;
use crate::maze::layout::{LATTICE, LayoutId, MazeLayout, START};
use crate::maze::params::BASELINE;
use crate::maze::search::{DistanceField, corners};
use crate::shaping::Agent;

use super::mean_curve;

fn unit(p: (i32, i32)) -> (f64, f64) {
    (f64::from(p.0) / f64::from(LATTICE), f64::from(p.1) / f64::from(LATTICE))
}

/// The maze `layout` with its walls, start and goal.
pub fn maze_scene(title: &str, layout: LayoutId) -> Scene {
    let mut scene = Scene::new(title, Rect::UNIT);
    scene.x_label = "x".into();
    scene.y_label = "y".into();
    scene.walls = MazeLayout::of(layout)
        .walls()
        .iter()
        .map(|w| {
            let (x0, y0, x1, y1) = w.unit_square();
            Rect::new(x0, y0, x1, y1)
        })
        .collect();
    scene.goal = Some(Rect::new(0.9, 0.9, 1.0, 1.0));
    scene.markers = vec![Marker { label: "S".into(), at: unit(START) }, Marker { label: "G".into(), at: (0.95, 0.95) }];
    scene
}

/// Figure 6.1: the modified Dyna Maze.
pub fn figure_6_1(layout: LayoutId, provenance: &Provenance) -> rlfd_report::Result<String> {
    let title = format!(
        "Figure 6.1: the modified Dyna Maze, {} layout (walls grey, goal region x ≥ 0.9, y ≥ 0.9)",
        layout.name()
    );
    maze_scene(&title, layout).to_svg(provenance)
}

/// Figure 6.2: the demonstrations, drawn as paths.
pub fn figure_6_2(results: &MazeResults, provenance: &Provenance) -> rlfd_report::Result<String> {
    let mut scene = maze_scene("Figure 6.2: the ten demonstrations", results.params.layout);
    for (k, t) in results.demonstrations.set.trajectories().iter().enumerate() {
        let points: Vec<(f64, f64)> = t.states().map(|s| (s[0], s[1])).collect();
        scene.paths.push(ScenePath {
            name: (k == 0).then(|| format!("demonstrations ({})", results.demonstrations.set.len())),
            points,
            emphasis: PathEmphasis::Light,
        });
    }
    scene.to_svg(provenance)
}

/// Figure 6.3: a shortest path, as its corners (piecewise linear).
pub fn figure_6_3(layout: LayoutId, provenance: &Provenance) -> rlfd_report::Result<String> {
    let field = DistanceField::to_goal(&MazeLayout::of(layout), 2);
    let path = field.shortest_path_from_start();
    let length = (path.len() - 1) as f64 * 0.02;
    let mut scene =
        maze_scene(&format!("Figure 6.3: an optimal path ({} steps, length {length:.2})", path.len() - 1), layout);
    scene.paths.push(ScenePath {
        name: Some("optimal path".into()),
        points: corners(&path).into_iter().map(unit).collect(),
        emphasis: PathEmphasis::Primary,
    });
    scene.to_svg(provenance)
}

/// Figure 6.4: reward per episode, mean ± standard error over trials, with
/// the demonstrator's mean; `y_range` zooms in.
pub fn figure_6_4(
    results: &MazeResults,
    hmn: f64,
    y_range: Option<(f64, f64)>,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let trials = results.params.trials;
    let title = match y_range {
        None => format!("Figure 6.4: reward per episode (mean ± s.e. over {trials} trials)"),
        Some((lo, hi)) => {
            format!("Figure 6.4, zoomed to [{lo}, {hi}]: reward per episode (mean ± s.e. over {trials} trials)")
        }
    };
    let mut chart = LineChart::new(title, "Episode", "Reward per episode");
    for agent in Agent::ALL {
        let Some(ts) = results.trials.get(&agent) else { continue };
        let (mean, se) = mean_curve(ts);
        let points: Vec<(f64, f64)> = mean.iter().enumerate().map(|(e, &y)| ((e + 1) as f64, y)).collect();
        let band = mean.iter().zip(&se).map(|(m, s)| (m - s, m + s)).collect();
        chart.series.push(Series {
            name: agent.label(BASELINE).into(),
            points,
            band: Some(band),
            style: SeriesStyle::Line,
        });
    }
    chart.reference_lines.push(HLine { name: "HMN (demonstrator mean)".into(), y: hmn, stroke: Stroke::Dashed });
    chart.y_range = y_range;
    chart.legend = LegendPosition::Outside;
    chart.to_svg(provenance)
}
