//! Forest plots: one row per labelled quantity, and in each row one
//! horizontal interval with a dot at its estimate per series (e.g. per
//! reading of an open choice), a vertical line at zero and an optional
//! reference marker per row (e.g. the thesis's effect). The specification
//! curve of a chapter's claims is drawn with it. Estimates and intervals are
//! computed by the caller; this module only draws them.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{
    AXIS, Area, GRID, LABEL_FONT, LABEL_PX, LegendEntry, Sample, TEXT, draw_legend_grid, extent, figure_error, font,
    legend_grid_size, marker_shape, pad, render_svg, series_colour, text_width, tick_decimals, tick_text, titled,
    x_tick_count,
};
use crate::{Provenance, Result};

/// One interval of a row.
#[derive(Debug, Clone, PartialEq)]
pub struct ForestPoint {
    /// The series (its index in [`ForestPlot::series`]).
    pub series: usize,
    pub estimate: f64,
    pub lower: f64,
    pub upper: f64,
}

/// One row: a label, its intervals, and an optional reference value.
#[derive(Debug, Clone, PartialEq)]
pub struct ForestRow {
    pub label: String,
    pub points: Vec<ForestPoint>,
    /// Drawn as a black diamond (e.g. the thesis's effect).
    pub reference: Option<f64>,
}

/// A forest plot.
#[derive(Debug, Clone, PartialEq)]
pub struct ForestPlot {
    pub title: String,
    pub x_label: String,
    /// The series' names, in legend order (series 0 is drawn on top of its row).
    pub series: Vec<String>,
    /// The reference marker's legend entry (e.g. "thesis").
    pub reference_label: String,
    pub rows: Vec<ForestRow>,
    /// The figure's width; the height follows from the rows and the legend.
    pub width: u32,
}

const MARGIN: i32 = 12;
const BOTTOM: i32 = 48;
/// Vertical pixels per interval within a row, and the gap between rows.
const STEP: i32 = 7;
const ROW_GAP: i32 = 10;
/// The widest row label in pixels (longer ones are cut with an ellipsis).
const LABEL_MAX: i32 = 330;

impl ForestPlot {
    /// An empty plot 900 pixels wide.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>) -> ForestPlot {
        ForestPlot {
            title: title.into(),
            x_label: x_label.into(),
            series: Vec::new(),
            reference_label: "reference".into(),
            rows: Vec::new(),
            width: 900,
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        if self.rows.is_empty() || self.series.is_empty() {
            return Err(figure_error(f, "no rows or no series"));
        }
        for r in &self.rows {
            for p in &r.points {
                if p.series >= self.series.len() {
                    return Err(figure_error(f, format!("row `{}`: series {} does not exist", r.label, p.series)));
                }
                if !(p.lower.is_finite() && p.upper.is_finite() && p.estimate.is_finite()) || p.lower > p.upper {
                    return Err(figure_error(f, format!("row `{}`: an interval is not finite and ordered", r.label)));
                }
            }
        }
        Ok(())
    }

    fn row_height(&self) -> i32 {
        STEP * self.series.len() as i32 + ROW_GAP
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let mut e: Vec<LegendEntry> = self
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| LegendEntry {
                label: s.clone(),
                sample: Sample::Line { colour: series_colour(i), width: 2, dash: None, band: false },
            })
            .collect();
        if self.rows.iter().any(|r| r.reference.is_some()) {
            e.push(LegendEntry {
                label: self.reference_label.clone(),
                sample: Sample::Shape { colour: BLACK, kind: 0 },
            });
        }
        e
    }

    fn height(&self) -> u32 {
        let (_, legend_h, _) = legend_grid_size(&self.legend(), self.width as i32 - 2 * MARGIN);
        (super::TITLE_HEIGHT as i32 + MARGIN + self.row_height() * self.rows.len() as i32 + BOTTOM + legend_h + MARGIN)
            as u32
    }

    /// The plot cut into consecutive parts of whole rows, each at most
    /// `max_height` pixels tall (one part, the plot itself, when it fits;
    /// else each titled "(part i of n)"). A chapter with many claim
    /// components and many readings would otherwise draw one figure taller
    /// than any page or screen.
    pub fn parts(&self, max_height: u32) -> Vec<ForestPlot> {
        if self.height() <= max_height || self.rows.len() < 2 {
            return vec![self.clone()];
        }
        let fixed = self.height() as i32 - self.row_height() * self.rows.len() as i32;
        let per_part = ((max_height as i32 - fixed) / self.row_height()).max(1) as usize;
        let n = self.rows.len().div_ceil(per_part);
        self.rows
            .chunks(per_part)
            .enumerate()
            .map(|(i, rows)| ForestPlot {
                title: format!("{} (part {} of {n})", self.title, i + 1),
                rows: rows.to_vec(),
                ..self.clone()
            })
            .collect()
    }

    /// The plot as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        render_svg((self.width, self.height()), provenance, &self.title, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        let body = titled(root, &self.title, f)?;
        let label_w =
            self.rows.iter().map(|r| text_width(&r.label, LABEL_PX)).max().unwrap_or(0).min(LABEL_MAX) + 2 * MARGIN;
        let values = self
            .rows
            .iter()
            .flat_map(|r| r.points.iter().flat_map(|p| [p.lower, p.upper]).chain(r.reference))
            .chain([0.0]);
        let (x0, x1) = pad(extent(values).expect("zero is finite"), 0.04);
        let n = self.rows.len() as i32;
        let plot_h = self.row_height() * n;
        let (plot, _) = body.split_vertically((MARGIN + plot_h + BOTTOM) as u32);
        let mut chart = ChartBuilder::on(&plot)
            .margin_top(MARGIN as u32)
            .margin_right(MARGIN as u32)
            .x_label_area_size(BOTTOM as u32)
            .y_label_area_size(label_w as u32)
            .build_cartesian_2d(x0..x1, 0.0..f64::from(plot_h))
            .map_err(&err)?;
        let xd = tick_decimals(x1 - x0, 8);
        let x_fmt = move |v: &f64| tick_text(*v, xd);
        let (w, _) = plot.dim_in_pixel();
        chart
            .configure_mesh()
            .x_labels(x_tick_count(w as i32 - label_w - MARGIN, (x0, x1), 10))
            .y_labels(0)
            .disable_y_mesh()
            .max_light_lines(0)
            .bold_line_style(GRID)
            .axis_style(AXIS)
            .label_style((super::FONT_STACK, LABEL_FONT).into_font().color(&TEXT))
            .axis_desc_style((super::FONT_STACK, super::DESC_FONT).into_font().color(&TEXT))
            .x_desc(self.x_label.as_str())
            .x_label_formatter(&x_fmt)
            .draw()
            .map_err(&err)?;
        // Row y in data units counts down from the top: row i's series s at
        // plot_h - (i · row_height + ROW_GAP/2 + (s + 0.5) · STEP).
        let y_of = |i: usize, s: usize| {
            f64::from(plot_h)
                - f64::from(self.row_height() * i as i32 + ROW_GAP / 2)
                - (s as f64 + 0.5) * f64::from(STEP)
        };
        chart
            .draw_series([PathElement::new(vec![(0.0, 0.0), (0.0, f64::from(plot_h))], AXIS.stroke_width(1))])
            .map_err(&err)?;
        for (i, row) in self.rows.iter().enumerate() {
            if i > 0 {
                let y = f64::from(plot_h - self.row_height() * i as i32);
                chart.draw_series([PathElement::new(vec![(x0, y), (x1, y)], GRID.stroke_width(1))]).map_err(&err)?;
            }
            for p in &row.points {
                let colour = series_colour(p.series);
                let y = y_of(i, p.series);
                chart
                    .draw_series([PathElement::new(vec![(p.lower, y), (p.upper, y)], colour.stroke_width(2))])
                    .map_err(&err)?;
                chart.draw_series([Circle::new((p.estimate, y), 3, colour.filled())]).map_err(&err)?;
            }
            let middle = f64::from(plot_h) - f64::from(self.row_height()) * (i as f64 + 0.5);
            if let Some(r) = row.reference {
                let at = chart.backend_coord(&(r, middle));
                root.draw(&PathElement::new(marker_shape(0, at), BLACK.stroke_width(2))).map_err(&err)?;
            }
            let (_, py) = chart.backend_coord(&(x0, middle));
            root.draw(&Text::new(
                clipped(&row.label),
                (label_w - MARGIN, py),
                font(LABEL_FONT, HPos::Right, VPos::Center),
            ))
            .map_err(&err)?;
        }
        let entries = self.legend();
        let (_, _, columns) = legend_grid_size(&entries, self.width as i32 - 2 * MARGIN);
        let top = super::TITLE_HEIGHT as i32 + MARGIN + plot_h + BOTTOM;
        draw_legend_grid(root, (MARGIN, top), &entries, columns, f)
    }
}

/// A row label cut to the label column's width, with an ellipsis.
fn clipped(label: &str) -> String {
    if text_width(label, LABEL_PX) <= LABEL_MAX {
        return label.to_string();
    }
    let mut out = String::new();
    for c in label.chars() {
        if text_width(&format!("{out}{c}…"), LABEL_PX) > LABEL_MAX {
            break;
        }
        out.push(c);
    }
    out.push('…');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plot() -> ForestPlot {
        let mut p = ForestPlot::new("Specification curve", "effect (SD)");
        p.series = vec!["default".into(), "noise = 0.1".into()];
        p.reference_label = "thesis".into();
        p.rows.push(ForestRow {
            label: "C3.1 #States".into(),
            points: vec![
                ForestPoint { series: 0, estimate: 1.0, lower: 0.5, upper: 1.5 },
                ForestPoint { series: 1, estimate: -0.2, lower: -0.9, upper: 0.4 },
            ],
            reference: Some(2.0),
        });
        p.rows.push(ForestRow {
            label: "a very long label that the label column cannot hold in full, so it is cut".into(),
            points: vec![ForestPoint { series: 0, estimate: 0.1, lower: 0.0, upper: 0.2 }],
            reference: None,
        });
        p
    }

    #[test]
    fn rows_intervals_reference_and_checks() {
        let prov = Provenance::new("cmd", "0.1.0");
        let p = plot();
        let a = p.to_svg(&prov).unwrap();
        assert_eq!(a, p.to_svg(&prov).unwrap());
        assert!(a.starts_with("<!-- generated by cmd"));
        assert!(a.contains(">\nC3.1 #States\n</text>") && a.contains(">\nthesis\n</text>"));
        assert!(a.contains("…"), "the long label is cut");
        // Three intervals, each a dot.
        assert_eq!(a.matches("<circle").count(), 3);
        let mut bad = p.clone();
        bad.rows[0].points[0].lower = 2.0;
        assert!(bad.to_svg(&prov).unwrap_err().to_string().contains("not finite and ordered"));
        let mut bad = p;
        bad.rows[0].points[0].series = 5;
        assert!(bad.to_svg(&prov).unwrap_err().to_string().contains("series 5"));
    }

    #[test]
    fn a_tall_plot_is_cut_into_parts_of_whole_rows_that_render() {
        let prov = Provenance::new("cmd", "0.1.0");
        let mut p = plot();
        assert_eq!(p.parts(4000), vec![p.clone()], "a plot that fits stays whole");
        p.series = (0..40).map(|i| format!("level {i}")).collect();
        let row = p.rows[0].clone();
        p.rows = (0..30).map(|i| ForestRow { label: format!("row {i}"), ..row.clone() }).collect();
        assert!(p.height() > 4000, "{}", p.height());
        let parts = p.parts(4000);
        assert!(parts.len() >= 2);
        let rows: Vec<String> = parts.iter().flat_map(|q| q.rows.iter().map(|r| r.label.clone())).collect();
        assert_eq!(rows, p.rows.iter().map(|r| r.label.clone()).collect::<Vec<_>>(), "every row once, in order");
        for (i, q) in parts.iter().enumerate() {
            assert!(q.height() <= 4000, "part {i}: {}", q.height());
            assert!(q.title.ends_with(&format!("(part {} of {})", i + 1, parts.len())));
            q.to_svg(&prov).unwrap();
        }
        assert!(p.to_svg(&prov).unwrap_err().to_string().contains("outside"), "whole, it is too tall to draw");
    }
}
