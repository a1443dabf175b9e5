//! Box plots: for each category on the x axis (e.g. an action), one box per
//! series side by side (e.g. an algorithm), in the Okabe–Ito colours, with
//! optional markers at chosen values (e.g. the thesis's number, or one
//! study's value among a hundred). Summaries (quartiles, whisker ends,
//! outliers) are computed by the caller: this module only draws them.

use plotters::prelude::*;

use super::{
    AXIS, Area, GRID, LABEL_FONT, LegendEntry, Sample, TEXT, check_range, draw_legend, extent, figure_error,
    legend_size, pad, render_svg, series_colour, tick_decimals, tick_text, titled,
};
use crate::{Provenance, Result};

/// A box's five numbers and its outliers.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxStats {
    pub q1: f64,
    pub median: f64,
    pub q3: f64,
    /// Whisker ends (the caller's rule, e.g. the most extreme data within 1.5 IQR).
    pub low: f64,
    pub high: f64,
    /// Points beyond the whiskers.
    pub outliers: Vec<f64>,
}

/// One series: a box per category (`None`: no box there).
#[derive(Debug, Clone, PartialEq)]
pub struct BoxSeries {
    pub name: String,
    pub boxes: Vec<Option<BoxStats>>,
}

/// A marker at `value` over the box of (`category`, `series`); markers with
/// the same label share a legend entry and a shape.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxMarker {
    pub category: usize,
    pub series: usize,
    pub value: f64,
    pub label: String,
}

/// A box plot (e.g. Figure 4.2: % correct per action, one box per algorithm).
#[derive(Debug, Clone, PartialEq)]
pub struct BoxPlot {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub categories: Vec<String>,
    pub series: Vec<BoxSeries>,
    pub markers: Vec<BoxMarker>,
    /// A fixed value range; `None`: the data's extent padded by 5 %.
    pub y_range: Option<(f64, f64)>,
    pub size: (u32, u32),
}

const LEFT: u32 = 72;
const BOTTOM: u32 = 56;
const MARGIN: u32 = 12;
/// Marker shapes by label index: a black diamond, a red cross, a ring.
const MARKER_COLOURS: [RGBColor; 3] = [RGBColor(0, 0, 0), RGBColor(0xD5, 0x5E, 0x00), RGBColor(0x55, 0x55, 0x55)];

impl BoxPlot {
    /// An empty plot of 720 × 440 pixels.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> BoxPlot {
        BoxPlot {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            categories: Vec::new(),
            series: Vec::new(),
            markers: Vec::new(),
            y_range: None,
            size: (720, 440),
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        let n = self.categories.len();
        if n == 0 || self.series.is_empty() {
            return Err(figure_error(f, "no categories or no series"));
        }
        for s in &self.series {
            if s.boxes.len() != n {
                return Err(figure_error(
                    f,
                    format!("series `{}` has {} boxes for {n} categories", s.name, s.boxes.len()),
                ));
            }
            for b in s.boxes.iter().flatten() {
                let five = [b.low, b.q1, b.median, b.q3, b.high];
                if five.iter().any(|v| !v.is_finite()) || five.windows(2).any(|w| w[0] > w[1]) {
                    return Err(figure_error(
                        f,
                        format!("series `{}`: a box is not ordered low ≤ q1 ≤ median ≤ q3 ≤ high", s.name),
                    ));
                }
            }
        }
        for m in &self.markers {
            if m.category >= n || m.series >= self.series.len() || !m.value.is_finite() {
                return Err(figure_error(f, format!("marker `{}` is outside the plot", m.label)));
            }
        }
        if !self.series.iter().any(|s| s.boxes.iter().any(Option::is_some)) {
            return Err(figure_error(f, "no box"));
        }
        if let Some(r) = self.y_range {
            check_range(f, "y", r)?;
        }
        Ok(())
    }

    fn marker_labels(&self) -> Vec<String> {
        let mut labels: Vec<String> = Vec::new();
        for m in &self.markers {
            if !labels.contains(&m.label) {
                labels.push(m.label.clone());
            }
        }
        labels
    }

    fn legend_entries(&self) -> Vec<LegendEntry> {
        let mut e: Vec<LegendEntry> = self
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| LegendEntry {
                label: s.name.clone(),
                sample: Sample::Swatch { colour: series_colour(i), opacity: 0.35 },
            })
            .collect();
        for (k, l) in self.marker_labels().into_iter().enumerate() {
            e.push(LegendEntry { label: l, sample: Sample::Shape { colour: MARKER_COLOURS[k % 3], kind: k } });
        }
        e
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
        let entries = self.legend_entries();
        let (legend_w, _) = legend_size(&entries);
        let (w, _) = body.dim_in_pixel();
        let chart_w = w.saturating_sub(legend_w as u32 + 2 * MARGIN);
        let (chart_area, _) = body.split_horizontally(chart_w);
        let values = self
            .series
            .iter()
            .flat_map(|s| s.boxes.iter().flatten())
            .flat_map(|b| [b.low, b.high].into_iter().chain(b.outliers.iter().copied()));
        let (y0, y1) = self
            .y_range
            .unwrap_or_else(|| pad(extent(values.chain(self.markers.iter().map(|m| m.value))).expect("checked"), 0.05));
        let n = self.categories.len();
        let mut chart = ChartBuilder::on(&chart_area)
            .margin_top(MARGIN)
            .margin_right(MARGIN)
            .x_label_area_size(BOTTOM)
            .y_label_area_size(LEFT)
            .build_cartesian_2d(-0.5..(n as f64 - 0.5), y0..y1)
            .map_err(&err)?;
        let yd = tick_decimals(y1 - y0, 8);
        let y_fmt = move |v: &f64| tick_text(*v, yd);
        let cats = self.categories.clone();
        let x_fmt = move |v: &f64| {
            let i = v.round();
            if (v - i).abs() < 1e-9 && i >= 0.0 && (i as usize) < cats.len() {
                cats[i as usize].clone()
            } else {
                String::new()
            }
        };
        chart
            .configure_mesh()
            .x_labels(2 * n + 1)
            .y_labels(8)
            .disable_x_mesh()
            .max_light_lines(0)
            .bold_line_style(GRID)
            .axis_style(AXIS)
            .label_style((super::FONT_STACK, LABEL_FONT).into_font().color(&TEXT))
            .axis_desc_style((super::FONT_STACK, super::DESC_FONT).into_font().color(&TEXT))
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt)
            .draw()
            .map_err(&err)?;
        let k = self.series.len() as f64;
        let slot = 0.8 / k;
        let half = slot * 0.35;
        let centre = |c: usize, s: usize| c as f64 - 0.4 + slot * (s as f64 + 0.5);
        for (si, s) in self.series.iter().enumerate() {
            let colour = series_colour(si);
            for (ci, b) in s.boxes.iter().enumerate() {
                let Some(b) = b else { continue };
                let x = centre(ci, si);
                chart
                    .draw_series([
                        Rectangle::new([(x - half, b.q1), (x + half, b.q3)], colour.mix(0.35).filled()),
                        Rectangle::new([(x - half, b.q1), (x + half, b.q3)], colour.stroke_width(1)),
                    ])
                    .map_err(&err)?;
                chart
                    .draw_series([
                        PathElement::new(vec![(x - half, b.median), (x + half, b.median)], colour.stroke_width(3)),
                        PathElement::new(vec![(x, b.q3), (x, b.high)], colour.stroke_width(1)),
                        PathElement::new(vec![(x, b.q1), (x, b.low)], colour.stroke_width(1)),
                        PathElement::new(
                            vec![(x - half / 2.0, b.high), (x + half / 2.0, b.high)],
                            colour.stroke_width(1),
                        ),
                        PathElement::new(
                            vec![(x - half / 2.0, b.low), (x + half / 2.0, b.low)],
                            colour.stroke_width(1),
                        ),
                    ])
                    .map_err(&err)?;
                chart
                    .draw_series(
                        b.outliers
                            .iter()
                            .filter(|v| (y0..=y1).contains(*v))
                            .map(|&v| Circle::new((x, v), 3, colour.stroke_width(1))),
                    )
                    .map_err(&err)?;
            }
        }
        let labels = self.marker_labels();
        for m in &self.markers {
            if !(y0..=y1).contains(&m.value) {
                continue;
            }
            let kind = labels.iter().position(|l| *l == m.label).unwrap_or(0);
            let colour = MARKER_COLOURS[kind % 3];
            let (px, py) = chart.backend_coord(&(centre(m.category, m.series), m.value));
            let shape = super::marker_shape(kind, (px, py));
            root.draw(&PathElement::new(shape, colour.stroke_width(2))).map_err(&err)?;
        }
        let (_, yr) = chart.plotting_area().get_pixel_range();
        draw_legend(root, ((chart_w + MARGIN) as i32, yr.start), &entries, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn b(m: f64) -> Option<BoxStats> {
        Some(BoxStats { q1: m - 5.0, median: m, q3: m + 4.0, low: m - 12.0, high: m + 9.0, outliers: vec![m + 30.0] })
    }

    #[test]
    fn boxes_markers_and_checks() {
        let mut p = BoxPlot::new("Figure 4.2: correct per action", "Action", "Correct (%)");
        p.categories = vec!["pick-up".into(), "sweep".into(), "wait".into()];
        for (i, name) in ["Int-RL", "BNets", "CBA"].iter().enumerate() {
            p.series.push(BoxSeries { name: (*name).into(), boxes: vec![b(20.0 + i as f64), b(30.0), None] });
        }
        p.markers.push(BoxMarker { category: 1, series: 2, value: 64.0, label: "thesis".into() });
        p.markers.push(BoxMarker { category: 0, series: 0, value: 10.0, label: "study 0".into() });
        let prov = Provenance::new("cmd", "0.1.0");
        let a = p.to_svg(&prov).unwrap();
        assert_eq!(a, p.to_svg(&prov).unwrap());
        assert!(a.starts_with("<!-- generated by cmd"));
        assert!(a.contains(">\nsweep\n</text>") && a.contains(">\nCBA\n</text>") && a.contains(">\nthesis\n</text>"));
        // 6 boxes, each drawn as a filled and an outlined rectangle.
        assert!(a.matches("<rect").count() >= 12);
        p.series[0].boxes[0] = Some(BoxStats { q1: 5.0, median: 4.0, q3: 6.0, low: 0.0, high: 9.0, outliers: vec![] });
        assert!(p.to_svg(&prov).unwrap_err().to_string().contains("not ordered"));
    }
}
