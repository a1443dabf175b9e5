//! Scatter plots: groups of points in the Okabe–Ito colours, optional point
//! labels and an optional fitted line per group whose label (e.g.
//! `r = 0.64`) joins the group's legend entry. The fit is computed by the
//! caller; this module only draws it.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{
    Area, LegendEntry, LegendPosition, SMALL_FONT, Sample, Window, check_range, draw_legend, draw_mesh, extent,
    figure_error, font, legend_corner, legend_size, pad, render_svg, series_colour, titled, trace,
};
use crate::{Provenance, Result};

/// A scatter plot (e.g. Figure 4.x: interactions against accuracy, one group
/// per algorithm).
#[derive(Debug, Clone, PartialEq)]
pub struct ScatterPlot {
    /// Put the correlation here if there is one group: `… (r = 0.64)`.
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub groups: Vec<ScatterGroup>,
    /// Fixed ranges; `None`: the data's extent padded by 5 %.
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    pub legend: LegendPosition,
    pub size: (u32, u32),
    /// Half-widths `(x, y)` of a deterministic spread given to every point
    /// in data units, so integer-valued data (counts, 1–7 ratings) that
    /// coincide show as a cloud instead of one dot; zero draws exactly.
    pub jitter: (f64, f64),
}

/// A deterministic offset in [−1, 1] for point `k` of group `g` along `axis`
/// (the golden-ratio sequence: evenly spread, no generator, same everywhere).
fn spread(g: usize, k: usize, axis: usize) -> f64 {
    let phi = if axis == 0 { 0.618_033_988_749_894_9 } else { 0.754_877_666_246_692_7 };
    let x = ((k * 7 + g * 3 + 1) as f64 * phi).fract();
    2.0 * x - 1.0
}

/// Points of one kind.
#[derive(Debug, Clone, PartialEq)]
pub struct ScatterGroup {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// Empty, or one label per point, written beside it.
    pub labels: Vec<String>,
    pub fit: Option<Fit>,
}

/// A fitted line `y = slope · x + intercept`, drawn across the x range.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    pub slope: f64,
    pub intercept: f64,
    /// E.g. `r = 0.64`: shown after the group's name in the legend.
    pub label: String,
}

impl ScatterPlot {
    /// An empty plot of 560 × 440 pixels with the legend placed automatically.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> ScatterPlot {
        ScatterPlot {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            groups: Vec::new(),
            x_range: None,
            y_range: None,
            legend: LegendPosition::Auto,
            size: (560, 440),
            jitter: (0.0, 0.0),
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
        if !self.groups.iter().any(|g| g.points.iter().any(finite)) {
            return Err(figure_error(f, "no finite point"));
        }
        for g in &self.groups {
            if !g.labels.is_empty() && g.labels.len() != g.points.len() {
                return Err(figure_error(
                    f,
                    format!("group `{}` has {} labels for {} points", g.name, g.labels.len(), g.points.len()),
                ));
            }
        }
        if let Some(r) = self.x_range {
            check_range(f, "x", r)?;
        }
        if let Some(r) = self.y_range {
            check_range(f, "y", r)?;
        }
        Ok(())
    }

    /// The plot as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        render_svg(self.size, provenance, &self.title, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        let body = titled(root, &self.title, f)?;
        let points = || self.groups.iter().flat_map(|g| g.points.iter());
        let (x0, x1) = self.x_range.unwrap_or_else(|| pad(extent(points().map(|p| p.0)).expect("checked"), 0.05));
        let (y0, y1) = self.y_range.unwrap_or_else(|| pad(extent(points().map(|p| p.1)).expect("checked"), 0.05));
        let mut chart = ChartBuilder::on(&body)
            .margin(10)
            .margin_right(24)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(&err)?;
        draw_mesh(&mut chart, &self.x_label, &self.y_label, (x1 - x0, y1 - y0), (8, 8), f)?;

        let window = Window { x: (x0, x1), y: (y0, y1) };
        let mut occupied = Vec::new();
        let mut entries = Vec::new();
        for (i, g) in self.groups.iter().enumerate() {
            let colour = series_colour(i);
            if let Some(fit) = &g.fit {
                let a = (x0, fit.slope * x0 + fit.intercept);
                let b = (x1, fit.slope * x1 + fit.intercept);
                if let Some((a, b)) = window.segment(a, b).filter(|(a, b)| a != b) {
                    let px = [chart.backend_coord(&a), chart.backend_coord(&b)];
                    trace(&px, &mut occupied);
                    chart.draw_series(LineSeries::new([a, b], colour.stroke_width(2))).map_err(&err)?;
                }
            }
            let (jx, jy) = self.jitter;
            let finite: Vec<(usize, (f64, f64))> = g
                .points
                .iter()
                .enumerate()
                .map(|(k, p)| (k, (p.0 + jx * spread(i, k, 0), p.1 + jy * spread(i, k, 1))))
                .filter(|(_, p)| window.contains(*p))
                .collect();
            // Translucent fill with a solid rim: where points pile up the colour deepens.
            chart
                .draw_series(finite.iter().map(|(_, p)| Circle::new(*p, 4, colour.mix(0.45).filled())))
                .map_err(&err)?;
            chart.draw_series(finite.iter().map(|(_, p)| Circle::new(*p, 4, colour.stroke_width(1)))).map_err(&err)?;
            for (k, p) in &finite {
                let (px, py) = chart.backend_coord(p);
                occupied.push((px, py));
                if let Some(label) = g.labels.get(*k).filter(|l| !l.is_empty()) {
                    root.draw(&Text::new(label.clone(), (px + 6, py - 4), font(SMALL_FONT, HPos::Left, VPos::Bottom)))
                        .map_err(&err)?;
                }
            }
            let label = match &g.fit {
                Some(fit) => format!("{} ({})", g.name, fit.label),
                None => g.name.clone(),
            };
            entries.push(LegendEntry {
                label,
                sample: if g.fit.is_some() {
                    Sample::Line { colour, width: 2, dash: None, band: false }
                } else {
                    Sample::Marker { colour }
                },
            });
        }
        let plot = chart.plotting_area().get_pixel_range();
        let position = match self.legend {
            LegendPosition::Outside => LegendPosition::Auto,
            p => p,
        };
        let corner = legend_corner(position, &plot, legend_size(&entries), &occupied);
        draw_legend(root, corner, &entries, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_fits_and_labels() {
        let mut s = ScatterPlot::new("Interactions vs accuracy", "Interactions", "Accuracy (%)");
        for (i, name) in ["Int-RL", "BNets", "CBA"].iter().enumerate() {
            let points: Vec<(f64, f64)> =
                (0..10).map(|k| (k as f64 * 3.0 + i as f64, 10.0 * i as f64 + k as f64 * (1.0 + i as f64))).collect();
            s.groups.push(ScatterGroup {
                name: (*name).into(),
                labels: if i == 0 { (0..10).map(|k| format!("u{k}")).collect() } else { Vec::new() },
                points,
                fit: Some(Fit { slope: 0.5 + i as f64, intercept: 10.0 * i as f64, label: format!("r = 0.{}", 3 + i) }),
            });
        }
        let p = Provenance::new("cmd", "0.1.0");
        let a = s.to_svg(&p).unwrap();
        assert_eq!(a, s.to_svg(&p).unwrap());
        assert_eq!(a.matches("<circle").count(), 60, "a fill and a rim per point");
        assert!(a.contains(">\nCBA (r = 0.5)\n</text>"));
        assert!(a.contains(">\nu9\n</text>"));
        s.groups[0].labels.pop();
        assert!(s.to_svg(&p).is_err());
    }
}
