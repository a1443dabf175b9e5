//! Scenes drawn in data coordinates with the aspect ratio kept (a unit
//! square stays square): grey walls, an optional goal region, paths (a
//! primary one in black, secondary ones such as demonstrations in light
//! distinct colours) and labelled markers (S, G). The legend sits in a
//! column right of the plot so it never hides the scene.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{
    Area, LIGHT, LegendEntry, Sample, TITLE_HEIGHT, Window, check_range, draw_legend, draw_mesh, figure_error,
    finite_runs, font, legend_size, render_svg, rgb, titled,
};
use crate::{Provenance, Result};

/// An axis-aligned rectangle in data coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

impl Rect {
    pub const fn new(x0: f64, y0: f64, x1: f64, y1: f64) -> Rect {
        Rect { x0, y0, x1, y1 }
    }

    /// The unit square.
    pub const UNIT: Rect = Rect::new(0.0, 0.0, 1.0, 1.0);
}

/// A path through the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenePath {
    /// Shown in the legend when named (name one demonstration
    /// "demonstrations (10)" and leave the others unnamed).
    pub name: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub emphasis: PathEmphasis,
}

/// How a path is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathEmphasis {
    /// Black, 2 px (the optimal path).
    Primary,
    /// A light colour of [`LIGHT`](super::LIGHT), one per light path in order, 1 px.
    Light,
}

/// A labelled point (start, goal).
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    pub label: String,
    pub at: (f64, f64),
}

/// A scene (e.g. Figure 6.1: the maze with the optimal path and the ten
/// demonstrations).
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    /// The visible region, e.g. [`Rect::UNIT`].
    pub bounds: Rect,
    pub walls: Vec<Rect>,
    pub goal: Option<Rect>,
    pub paths: Vec<ScenePath>,
    pub markers: Vec<Marker>,
    /// Width of the plot in pixels; its height follows the bounds' aspect.
    pub plot_width: u32,
    /// Ticks per axis (6 gives 0, 0.2, …, 1 on the unit square).
    pub ticks: usize,
    /// Strips the x range is cut into, drawn one under another (a long
    /// level reads at a legible scale in rows); 1 draws the scene whole.
    pub rows: usize,
    /// The legend's names for the walls and the goal region (`wall`,
    /// `goal region`; a level has blocks and an exit).
    pub wall_label: String,
    pub goal_label: String,
}

const WALL: RGBColor = RGBColor(0x99, 0x99, 0x99);
const GOAL: RGBColor = RGBColor(0x00, 0x9E, 0x73);
const GOAL_OPACITY: f64 = 0.25;
const LEFT: u32 = 64;
const BOTTOM: u32 = 52;
const MARGIN: u32 = 12;

impl Scene {
    /// An empty scene on `bounds` with a 480 px wide plot and 6 ticks.
    pub fn new(title: impl Into<String>, bounds: Rect) -> Scene {
        Scene {
            title: title.into(),
            x_label: "x".into(),
            y_label: "y".into(),
            bounds,
            walls: Vec::new(),
            goal: None,
            paths: Vec::new(),
            markers: Vec::new(),
            plot_width: 480,
            ticks: 6,
            rows: 1,
            wall_label: "wall".into(),
            goal_label: "goal region".into(),
        }
    }

    fn legend_entries(&self) -> Vec<LegendEntry> {
        let mut entries = Vec::new();
        if !self.walls.is_empty() {
            entries.push(LegendEntry {
                label: self.wall_label.clone(),
                sample: Sample::Swatch { colour: WALL, opacity: 1.0 },
            });
        }
        if self.goal.is_some() {
            entries.push(LegendEntry {
                label: self.goal_label.clone(),
                sample: Sample::Swatch { colour: GOAL, opacity: GOAL_OPACITY },
            });
        }
        for (path, colour) in self.paths.iter().zip(self.path_colours()) {
            if let Some(name) = &path.name {
                entries.push(LegendEntry {
                    label: name.clone(),
                    sample: Sample::Line { colour: colour.0, width: colour.1, dash: None, band: false },
                });
            }
        }
        entries
    }

    /// Colour and width per path: black for primary paths, the light
    /// palette in order for the others.
    fn path_colours(&self) -> Vec<(RGBColor, u32)> {
        let mut light = 0;
        self.paths
            .iter()
            .map(|p| match p.emphasis {
                PathEmphasis::Primary => (BLACK, 2),
                PathEmphasis::Light => {
                    light += 1;
                    (rgb(LIGHT[(light - 1) % LIGHT.len()]), 1)
                }
            })
            .collect()
    }

    /// The canvas size: the plot keeps the bounds' aspect ratio.
    fn size(&self) -> (u32, u32) {
        let (legend_w, _) = legend_size(&self.legend_entries());
        let legend = if legend_w > 0 { legend_w as u32 + 2 * MARGIN } else { MARGIN };
        (LEFT + self.plot_width + MARGIN + legend, TITLE_HEIGHT + self.rows.max(1) as u32 * self.row_height())
    }

    /// One strip's height: its plot (keeping the aspect ratio), the margin and the x axis.
    fn row_height(&self) -> u32 {
        let b = self.bounds;
        let span = (b.x1 - b.x0) / self.rows.max(1) as f64;
        MARGIN + (self.plot_width as f64 * (b.y1 - b.y0) / span).round() as u32 + BOTTOM
    }

    /// The scene as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        let f = &self.title;
        let b = self.bounds;
        check_range(f, "x", (b.x0, b.x1))?;
        check_range(f, "y", (b.y0, b.y1))?;
        if self.plot_width < 100 {
            return Err(figure_error(f, "plot_width below 100 px"));
        }
        render_svg(self.size(), provenance, f, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let body = titled(root, &self.title, f)?;
        let b = self.bounds;
        let entries = self.legend_entries();
        let (legend_w, _) = legend_size(&entries);
        let chart_w = LEFT + self.plot_width + MARGIN;
        let chart_area = if legend_w > 0 { body.split_horizontally(chart_w).0 } else { body.clone() };
        let full = Window { x: (b.x0, b.x1), y: (b.y0, b.y1) };
        if let Some(m) = self.markers.iter().find(|m| !full.contains(m.at)) {
            return Err(figure_error(f, format!("marker `{}` is outside the scene", m.label)));
        }
        let rows = self.rows.max(1);
        let span = (b.x1 - b.x0) / rows as f64;
        let strips = chart_area.split_evenly((rows, 1));
        let mut top = None;
        for (k, strip) in strips.iter().enumerate() {
            let (x0, x1) = (b.x0 + span * k as f64, if k + 1 == rows { b.x1 } else { b.x0 + span * (k + 1) as f64 });
            let y = self.draw_strip(root, strip, (x0, x1), f)?;
            top.get_or_insert(y);
        }
        draw_legend(root, ((chart_w + MARGIN) as i32, top.unwrap_or(0)), &entries, f)
    }

    /// Draws the part of the scene between `x0` and `x1` in `area`; returns
    /// the plot's top pixel row.
    fn draw_strip(&self, root: &Area<'_>, area: &Area<'_>, (x0, x1): (f64, f64), f: &str) -> Result<i32> {
        let err = super::drawing_error(f);
        let b = Rect { x0, x1, ..self.bounds };
        let mut chart = ChartBuilder::on(area)
            .margin_top(MARGIN)
            .margin_right(MARGIN)
            .x_label_area_size(BOTTOM)
            .y_label_area_size(LEFT)
            .build_cartesian_2d(b.x0..b.x1, b.y0..b.y1)
            .map_err(&err)?;
        let x_ticks = if self.rows > 1 { self.ticks.div_ceil(self.rows).max(2) * 2 } else { self.ticks };
        draw_mesh(&mut chart, &self.x_label, &self.y_label, (b.x1 - b.x0, b.y1 - b.y0), (x_ticks, self.ticks), f)?;
        // Rectangles are cut to the scene, and dropped if outside it.
        let clamp = |r: &Rect| {
            let (x0, x1) = (r.x0.min(r.x1).max(b.x0), r.x0.max(r.x1).min(b.x1));
            let (y0, y1) = (r.y0.min(r.y1).max(b.y0), r.y0.max(r.y1).min(b.y1));
            (x0 < x1 && y0 < y1).then_some([(x0, y0), (x1, y1)])
        };
        if let Some(g) = self.goal.as_ref().and_then(clamp) {
            chart.draw_series(std::iter::once(Rectangle::new(g, GOAL.mix(GOAL_OPACITY).filled()))).map_err(&err)?;
        }
        chart
            .draw_series(self.walls.iter().filter_map(clamp).map(|r| Rectangle::new(r, WALL.filled())))
            .map_err(&err)?;
        // Light paths under primary ones.
        let colours = self.path_colours();
        let window = Window { x: (b.x0, b.x1), y: (b.y0, b.y1) };
        for emphasis in [PathEmphasis::Light, PathEmphasis::Primary] {
            for (path, (colour, width)) in self.paths.iter().zip(&colours) {
                if path.emphasis != emphasis {
                    continue;
                }
                for run in finite_runs(&path.points).iter().flat_map(|r| window.polyline(r)) {
                    chart.draw_series(LineSeries::new(run, colour.stroke_width(*width))).map_err(&err)?;
                }
            }
        }
        for m in &self.markers {
            if !window.contains(m.at) {
                continue;
            }
            let (px, py) = chart.backend_coord(&m.at);
            root.draw(&Circle::new((px, py), 5, BLACK.filled())).map_err(&err)?;
            root.draw(&Circle::new((px, py), 5, WHITE.stroke_width(1))).map_err(&err)?;
            root.draw(&Text::new(m.label.clone(), (px + 8, py - 4), font(super::DESC_FONT, HPos::Left, VPos::Bottom)))
                .map_err(&err)?;
        }
        let (_, yr) = chart.plotting_area().get_pixel_range();
        Ok(yr.start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) fn sample() -> Scene {
        let mut s = Scene::new("Maze: optimal path and demonstrations", Rect::UNIT);
        s.walls = vec![Rect::new(0.3, 0.0, 0.35, 0.7), Rect::new(0.6, 0.3, 0.65, 1.0)];
        s.goal = Some(Rect::new(0.9, 0.9, 1.0, 1.0));
        s.paths.push(ScenePath {
            name: Some("optimal path".into()),
            points: vec![(0.08, 0.6), (0.2, 0.8), (0.45, 0.8), (0.5, 0.2), (0.8, 0.2), (0.95, 0.95)],
            emphasis: PathEmphasis::Primary,
        });
        for k in 0..10 {
            let d = 0.004 * k as f64;
            s.paths.push(ScenePath {
                name: (k == 0).then(|| "demonstrations (10)".into()),
                points: vec![
                    (0.08, 0.6),
                    (0.2 + d, 0.82 + d),
                    (0.45 + d, 0.82),
                    (0.5, 0.18 + d),
                    (0.8, 0.22),
                    (0.93, 0.93 + d),
                ],
                emphasis: PathEmphasis::Light,
            });
        }
        s.markers = vec![Marker { label: "S".into(), at: (0.08, 0.6) }, Marker { label: "G".into(), at: (0.95, 0.95) }];
        s
    }

    #[test]
    fn scene_keeps_aspect_and_draws_everything() {
        let p = Provenance::new("cmd", "0.1.0");
        let s = sample();
        let a = s.to_svg(&p).unwrap();
        assert_eq!(a, s.to_svg(&p).unwrap());
        assert!(a.starts_with(&format!(
            "<!-- generated by cmd (rlfd 0.1.0), decided by the {}; do not edit -->\n<svg ",
            crate::plan::analysis_plan().line()
        )));
        // 2 walls + goal + legend swatches/box; 11 paths + 2 legend samples.
        let polylines = a.lines().filter(|l| l.starts_with("<polyline")).count();
        assert!(polylines >= 13, "{polylines}");
        for colour in super::super::LIGHT {
            let (r, g, b) = colour;
            assert!(a.contains(&format!("stroke=\"#{r:02X}{g:02X}{b:02X}\"")));
        }
        assert!(a.contains(">\nS\n</text>") && a.contains(">\nG\n</text>"));
        assert!(a.contains(">\ngoal region\n</text>"));
        // The plot is square: 480 px wide, so 480 px high.
        let (w, h) = s.size();
        assert_eq!(h, TITLE_HEIGHT + MARGIN + 480 + BOTTOM);
        assert!(a.contains(&format!("<svg width=\"{w}\" height=\"{h}\"")));
    }
}
