//! Line charts: learning curves with translucent bands (e.g. ± standard
//! error) and horizontal reference lines (e.g. the demonstrator's mean,
//! dashed). Series take the Okabe–Ito colours by index; bands are drawn
//! first, then lines, then reference lines and the legend.

use plotters::prelude::*;

use super::{
    Area, BAND_OPACITY, LegendEntry, LegendPosition, Sample, Window, check_range, draw_legend, draw_mesh, extent,
    figure_error, finite_runs, legend_corner, legend_size, pad, render_svg, series_colour, titled, trace,
};
use crate::{Provenance, Result};

/// A line chart (e.g. Figure 6.4: five agents' reward per episode).
#[derive(Debug, Clone, PartialEq)]
pub struct LineChart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub reference_lines: Vec<HLine>,
    /// Fixed ranges; `None`: the data's extent (x exact, y padded by 5 %).
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    pub legend: LegendPosition,
    /// Canvas size in pixels, `(width, height)`.
    pub size: (u32, u32),
}

/// One curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    /// `(x, y)`; a non-finite point breaks the line.
    pub points: Vec<(f64, f64)>,
    /// `(low, high)` per point, drawn as a translucent area (e.g. mean ± se).
    pub band: Option<Vec<(f64, f64)>>,
    pub style: SeriesStyle,
}

/// How a series is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesStyle {
    Line,
    Dashed,
    /// A line with a dot at every point (for few points).
    LineAndMarkers,
}

/// A horizontal reference line across the plot, e.g. the demonstrator's mean.
#[derive(Debug, Clone, PartialEq)]
pub struct HLine {
    pub name: String,
    pub y: f64,
    pub stroke: Stroke,
}

/// Solid or dashed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stroke {
    Solid,
    Dashed,
}

/// Reference lines are drawn in this dark grey.
const REFERENCE: RGBColor = RGBColor(0x33, 0x33, 0x33);

impl LineChart {
    /// An empty chart of the default size (720 × 440) with the legend placed
    /// automatically.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> LineChart {
        LineChart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            reference_lines: Vec::new(),
            x_range: None,
            y_range: None,
            legend: LegendPosition::Auto,
            size: (720, 440),
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        if self.series.iter().all(|s| finite_runs(&s.points).is_empty()) {
            return Err(figure_error(f, "no series has a finite point"));
        }
        for s in &self.series {
            if let Some(band) = &s.band
                && band.len() != s.points.len()
            {
                return Err(figure_error(
                    f,
                    format!("series `{}` has {} band values for {} points", s.name, band.len(), s.points.len()),
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

    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let xs = self.series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
        let x = self.x_range.unwrap_or_else(|| {
            let (lo, hi) = extent(xs).expect("checked: some finite point");
            if lo < hi { (lo, hi) } else { pad((lo, hi), 0.0) }
        });
        let y = self.y_range.unwrap_or_else(|| {
            let ys = self.series.iter().flat_map(|s| {
                let points = s.points.iter().map(|p| p.1);
                let band = s.band.iter().flatten().flat_map(|b| [b.0, b.1]);
                points.chain(band)
            });
            let refs = self.reference_lines.iter().map(|r| r.y);
            pad(extent(ys.chain(refs)).expect("checked: some finite point"), 0.05)
        });
        (x, y)
    }

    fn legend_entries(&self) -> Vec<LegendEntry> {
        if self.legend == LegendPosition::Hidden {
            return Vec::new();
        }
        let mut entries: Vec<LegendEntry> = self
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| LegendEntry {
                label: s.name.clone(),
                sample: Sample::Line {
                    colour: series_colour(i),
                    width: 2,
                    dash: (s.style == SeriesStyle::Dashed).then_some((8, 5)),
                    band: s.band.is_some(),
                },
            })
            .collect();
        entries.extend(self.reference_lines.iter().enumerate().map(|(i, r)| LegendEntry {
            label: r.name.clone(),
            sample: Sample::Line { colour: REFERENCE, width: 2, dash: self.reference_dash(i), band: false },
        }));
        entries
    }

    /// Reference line `i`'s dash pattern: the k-th dashed line takes the
    /// k-th of [`REFERENCE_DASHES`](super::REFERENCE_DASHES).
    fn reference_dash(&self, i: usize) -> Option<(i32, i32)> {
        let r = &self.reference_lines[i];
        (r.stroke == Stroke::Dashed).then(|| {
            let k = self.reference_lines[..i].iter().filter(|r| r.stroke == Stroke::Dashed).count();
            super::REFERENCE_DASHES[k % super::REFERENCE_DASHES.len()]
        })
    }

    /// The chart as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        render_svg(self.size, provenance, &self.title, |root| self.draw(root))
    }

    /// Panels side by side in `columns` columns, each at its own size (the
    /// first panel's), under one title and one legend (the first panel's,
    /// under the grid), as one SVG document: e.g. Figure 3.4's four
    /// conditions in a 2 × 2 grid with common axes.
    pub fn grid(title: &str, panels: &[LineChart], columns: usize, provenance: &Provenance) -> Result<String> {
        let Some(first) = panels.first() else {
            return Err(figure_error(title, "a grid needs at least one panel"));
        };
        for p in panels {
            p.check()?;
        }
        let columns = columns.clamp(1, panels.len());
        let rows = panels.len().div_ceil(columns) as u32;
        let (pw, ph) = first.size;
        let width = pw * columns as u32;
        let mut shared = first.clone();
        shared.legend = LegendPosition::Auto;
        let entries = shared.legend_entries();
        let grid = super::legend_grid_size(&entries, width as i32 - 20);
        let height = super::TITLE_HEIGHT + rows * ph + grid.1 as u32 + 8;
        render_svg((width, height), provenance, title, |root| {
            let body = titled(root, title, title)?;
            let (area, _) = body.split_vertically(rows * ph);
            for (panel, cell) in panels.iter().zip(area.split_evenly((rows as usize, columns))) {
                let mut p = panel.clone();
                p.legend = LegendPosition::Hidden;
                p.draw(&cell)?;
            }
            let x = ((width as i32 - grid.0) / 2).max(0);
            super::draw_legend_grid(root, (x, height as i32 - grid.1 - 4), &entries, grid.2, title)
        })
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        let body = titled(root, &self.title, f)?;
        let entries = self.legend_entries();
        let (legend_w, legend_h) = legend_size(&entries);
        let outside = self.legend == LegendPosition::Outside && !entries.is_empty();
        // A legend column wider than a quarter of the figure goes under the plot instead.
        let (body_w, body_h) = body.dim_in_pixel();
        let below = outside && legend_w * 4 > body_w as i32;
        let grid = super::legend_grid_size(&entries, body_w as i32 - 20);
        let chart_area = if below {
            body.split_vertically(body_h as i32 - grid.1 - 6).0
        } else if outside {
            body.split_horizontally(body_w as i32 - legend_w - 16).0
        } else {
            body.clone()
        };
        let ((x0, x1), (y0, y1)) = self.ranges();
        let (margin, margin_right, y_label_area) = (10, 24, 84);
        let plot_width = chart_area.dim_in_pixel().0 as i32 - margin - margin_right - y_label_area;
        let x_ticks = super::x_tick_count(plot_width, (x0, x1), 10);
        let mut chart = ChartBuilder::on(&chart_area)
            .margin(margin)
            .margin_right(margin_right)
            .x_label_area_size(48)
            .y_label_area_size(y_label_area)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(&err)?;
        draw_mesh(&mut chart, &self.x_label, &self.y_label, (x1 - x0, y1 - y0), (x_ticks, 8), f)?;
        let window = Window { x: (x0, x1), y: (y0, y1) };

        // Bands first, so every line stays visible on top of every band.
        for (i, s) in self.series.iter().enumerate() {
            let Some(band) = &s.band else { continue };
            let colour = series_colour(i);
            let lows: Vec<(f64, f64)> = s.points.iter().zip(band).map(|(p, b)| (p.0, b.0)).collect();
            let highs: Vec<(f64, f64)> = s.points.iter().zip(band).map(|(p, b)| (p.0, b.1)).collect();
            // A band breaks where either bound or the point is not finite.
            let mut start = 0;
            while start < lows.len() {
                let ok = |k: usize| lows[k].0.is_finite() && lows[k].1.is_finite() && highs[k].1.is_finite();
                if !ok(start) {
                    start += 1;
                    continue;
                }
                let mut end = start;
                while end < lows.len() && ok(end) {
                    end += 1;
                }
                let mut polygon: Vec<(f64, f64)> = highs[start..end].to_vec();
                polygon.extend(lows[start..end].iter().rev());
                let polygon = window.polygon(&polygon);
                start = end;
                if polygon.len() < 3 {
                    continue;
                }
                chart
                    .draw_series(std::iter::once(Polygon::new(polygon, colour.mix(BAND_OPACITY).filled())))
                    .map_err(&err)?;
            }
        }

        let mut occupied = Vec::new();
        for (i, s) in self.series.iter().enumerate() {
            let style = series_colour(i).stroke_width(2);
            for run in finite_runs(&s.points).iter().flat_map(|r| window.polyline(r)) {
                let pixels: Vec<(i32, i32)> = run.iter().map(|p| chart.backend_coord(p)).collect();
                trace(&pixels, &mut occupied);
                match s.style {
                    SeriesStyle::Line => {
                        chart.draw_series(LineSeries::new(run, style)).map_err(&err)?;
                    }
                    SeriesStyle::Dashed => {
                        chart.draw_series(DashedLineSeries::new(run, 8, 5, style)).map_err(&err)?;
                    }
                    SeriesStyle::LineAndMarkers => {
                        chart.draw_series(LineSeries::new(run.iter().copied(), style)).map_err(&err)?;
                        chart
                            .draw_series(
                                run.iter()
                                    .filter(|p| s.points.contains(p))
                                    .map(|p| Circle::new(*p, 3, series_colour(i).filled())),
                            )
                            .map_err(&err)?;
                    }
                }
            }
            if let Some(band) = &s.band {
                for (p, b) in s.points.iter().zip(band) {
                    for y in [b.0, b.1] {
                        if window.contains((p.0, y)) {
                            occupied.push(chart.backend_coord(&(p.0, y)));
                        }
                    }
                }
            }
        }

        let (xr, yr) = chart.plotting_area().get_pixel_range();
        for (i, r) in self.reference_lines.iter().enumerate() {
            if !(y0..=y1).contains(&r.y) {
                continue;
            }
            let py = chart.backend_coord(&(x0, r.y)).1;
            let style = REFERENCE.stroke_width(2);
            let segments = match self.reference_dash(i) {
                Some((on, off)) => super::dash_pattern(xr.start, xr.end, on, off),
                None => vec![(xr.start, xr.end)],
            };
            for (a, b) in segments {
                root.draw(&PathElement::new(vec![(a, py), (b, py)], style)).map_err(&err)?;
            }
            trace(&[(xr.start, py), (xr.end, py)], &mut occupied);
        }

        if below {
            let (w, h) = root.dim_in_pixel();
            let x = ((w as i32 - grid.0) / 2).max(0);
            return super::draw_legend_grid(root, (x, h as i32 - grid.1 - 4), &entries, grid.2, f);
        }
        let corner = if outside {
            let (w, _) = root.dim_in_pixel();
            (w as i32 - legend_w - 12, yr.start)
        } else {
            legend_corner(self.legend, &(xr, yr), (legend_w, legend_h), &occupied)
        };
        draw_legend(root, corner, &entries, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Five learning curves of 150 episodes with bands and the demonstrator.
    pub(crate) fn sample() -> LineChart {
        let mut c = LineChart::new("Maze: reward per episode", "Episode", "Reward");
        for (i, name) in ["SAR", "SIS", "DIS", "HAT", "SBS"].iter().enumerate() {
            let points: Vec<(f64, f64)> = (0..150)
                .map(|e| {
                    let e = e as f64;
                    (e, -200.0 - 6000.0 / (1.0 + e * (0.1 + 0.05 * i as f64)))
                })
                .collect();
            let band = points.iter().map(|p| (p.1 - 150.0, p.1 + 150.0)).collect();
            c.series.push(Series { name: (*name).into(), points, band: Some(band), style: SeriesStyle::Line });
        }
        c.reference_lines.push(HLine { name: "HMN (demonstrator)".into(), y: -327.5, stroke: Stroke::Dashed });
        c
    }

    fn prov() -> Provenance {
        Provenance::new("cargo xtask reproduce --chapter ch6-irl-shaping --scale quick --seed 1", "0.1.0")
    }

    #[test]
    fn renders_identically_with_every_part() {
        let c = sample();
        let a = c.to_svg(&prov()).unwrap();
        let b = c.to_svg(&prov()).unwrap();
        assert_eq!(a, b);
        let first = a.lines().next().unwrap();
        assert_eq!(
            first,
            format!(
                "<!-- generated by cargo xtask reproduce - -chapter ch6-irl-shaping - -scale quick - -seed 1 (rlfd 0.1.0), decided by the {}; do not edit -->",
                crate::plan::analysis_plan().line()
            )
        );
        assert!(a.contains(&format!(
            "<desc>generated by cargo xtask reproduce --chapter ch6-irl-shaping --scale quick --seed 1 (rlfd 0.1.0), decided by the {}; do not edit</desc>",
            crate::plan::analysis_plan().line()
        )));
        // One band polygon per series, one line per series in its colour.
        assert_eq!(a.matches("<polygon").count(), 5);
        for (r, g, b) in &super::super::PALETTE[..5] {
            let stroke = format!("stroke=\"#{r:02X}{g:02X}{b:02X}\"");
            let lines = a.lines().filter(|l| l.starts_with("<polyline") && l.contains(&stroke));
            // The curve and the legend's sample.
            assert_eq!(lines.count(), 2, "{stroke}");
        }
        // Legend entries: each name once, as text.
        for name in ["SAR", "SIS", "DIS", "HAT", "SBS", "HMN (demonstrator)"] {
            assert_eq!(a.matches(&format!(">\n{name}\n</text>")).count(), 1, "{name}");
        }
        // The dashed reference line: many short dark segments on one row.
        let dash_lines = a.lines().filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#333333\"")).count();
        assert!(dash_lines > 20, "{dash_lines}");
        assert!(a.ends_with("</svg>\n"));
    }

    #[test]
    fn bad_input_is_an_error() {
        let mut c = sample();
        c.series[0].band.as_mut().unwrap().pop();
        assert!(c.to_svg(&prov()).is_err());
        let mut c = sample();
        c.y_range = Some((1.0, 0.0));
        assert!(c.to_svg(&prov()).is_err());
        let c = LineChart::new("empty", "x", "y");
        assert!(c.to_svg(&prov()).is_err());
    }
}
