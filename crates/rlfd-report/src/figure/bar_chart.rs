//! Bar charts with error bars and significance brackets between pairs of
//! bars (e.g. DIS's asymptote for demonstrations of 100, 500 and 953 steps,
//! with the pairwise p-values). Bars start at zero; brackets stack above the
//! tallest bar, one level each, in the order given.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{
    AXIS, Area, DESC_FONT, GRID, LABEL_FONT, SMALL_FONT, TEXT, check_range, extent, figure_error, font, render_svg,
    series_colour, tick_decimals, tick_text, titled,
};
use crate::{Provenance, Result};

/// A bar chart.
#[derive(Debug, Clone, PartialEq)]
pub struct BarChart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub categories: Vec<String>,
    pub values: Vec<f64>,
    /// ± per bar (say in the caption whether sd or se); `None`: no error bars.
    pub errors: Option<Vec<f64>>,
    pub brackets: Vec<Bracket>,
    /// A fixed value range; `None`: from zero (or the lowest bar) to above
    /// the highest bar and brackets.
    pub y_range: Option<(f64, f64)>,
    pub size: (u32, u32),
}

/// A bracket joining bars `from` and `to` (indices), labelled e.g. `p = 0.2338`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Bracket {
    pub from: usize,
    pub to: usize,
    pub label: String,
}

const BAR_HALF_WIDTH: f64 = 0.3;

impl BarChart {
    /// An empty chart of 560 × 420 pixels.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> BarChart {
        BarChart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            categories: Vec::new(),
            values: Vec::new(),
            errors: None,
            brackets: Vec::new(),
            y_range: None,
            size: (560, 420),
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        let n = self.categories.len();
        if n == 0 {
            return Err(figure_error(f, "no categories"));
        }
        if self.values.len() != n {
            return Err(figure_error(f, format!("{} values for {n} categories", self.values.len())));
        }
        if let Some(e) = &self.errors
            && e.len() != n
        {
            return Err(figure_error(f, format!("{} errors for {n} categories", e.len())));
        }
        if self.values.iter().any(|v| !v.is_finite()) {
            return Err(figure_error(f, "a bar value is not finite"));
        }
        for b in &self.brackets {
            if b.from >= n || b.to >= n || b.from == b.to {
                return Err(figure_error(f, format!("bracket {}–{} does not join two of the {n} bars", b.from, b.to)));
            }
        }
        if let Some(r) = self.y_range {
            check_range(f, "y", r)?;
        }
        Ok(())
    }

    fn error(&self, i: usize) -> f64 {
        self.errors.as_ref().map_or(0.0, |e| if e[i].is_finite() { e[i].abs() } else { 0.0 })
    }

    /// `(y range, level of the first bracket, step between levels)`.
    fn layout(&self) -> ((f64, f64), f64, f64) {
        let tops = (0..self.values.len()).map(|i| self.values[i] + self.error(i));
        let bottoms = (0..self.values.len()).map(|i| self.values[i] - self.error(i));
        let (lo, hi) = extent(tops.chain(bottoms).chain([0.0])).expect("0 is finite");
        let span = if hi > lo { hi - lo } else { 1.0 };
        let step = 0.09 * span;
        let first = hi + step;
        let n = self.brackets.len() as f64;
        let range = self.y_range.unwrap_or((
            if lo < 0.0 { lo - 0.05 * span } else { 0.0 },
            if n > 0.0 { first + (n - 1.0) * step + 0.7 * step } else { hi + 0.05 * span },
        ));
        (range, first, step)
    }

    /// The chart as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        render_svg(self.size, provenance, &self.title, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        let body = titled(root, &self.title, f)?;
        let n = self.categories.len();
        let x = (-0.5, n as f64 - 0.5);
        let ((y0, y1), first, step) = self.layout();
        let mut chart = ChartBuilder::on(&body)
            .margin(10)
            .margin_right(20)
            .x_label_area_size(56)
            .y_label_area_size(84)
            .build_cartesian_2d(x.0..x.1, y0..y1)
            .map_err(&err)?;
        let yd = tick_decimals(y1 - y0, 8);
        let y_fmt = move |v: &f64| tick_text(*v, yd);
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(0)
            .y_labels(8)
            .max_light_lines(0)
            .bold_line_style(GRID)
            .axis_style(AXIS)
            .label_style((super::FONT_STACK, LABEL_FONT).into_font().color(&TEXT))
            .axis_desc_style((super::FONT_STACK, DESC_FONT).into_font().color(&TEXT))
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .y_label_formatter(&y_fmt)
            .draw()
            .map_err(&err)?;
        let colour = series_colour(0);
        chart
            .draw_series(self.values.iter().enumerate().map(|(i, v)| {
                let c = i as f64;
                Rectangle::new([(c - BAR_HALF_WIDTH, 0.0), (c + BAR_HALF_WIDTH, *v)], colour.mix(0.85).filled())
            }))
            .map_err(&err)?;
        if self.errors.is_some() {
            for (i, v) in self.values.iter().enumerate() {
                let e = self.error(i);
                if e == 0.0 {
                    continue;
                }
                let c = i as f64;
                let (top, bottom) = (v + e, v - e);
                let style = BLACK.stroke_width(1);
                let cap = 0.08;
                for path in [
                    vec![(c, bottom), (c, top)],
                    vec![(c - cap, top), (c + cap, top)],
                    vec![(c - cap, bottom), (c + cap, bottom)],
                ] {
                    chart.draw_series(std::iter::once(PathElement::new(path, style))).map_err(&err)?;
                }
            }
        }
        // Category names under the axis.
        for (i, name) in self.categories.iter().enumerate() {
            let (px, _) = chart.backend_coord(&(i as f64, y0));
            let (_, yr) = chart.plotting_area().get_pixel_range();
            root.draw(&Text::new(name.clone(), (px, yr.end + 8), font(LABEL_FONT, HPos::Center, VPos::Top)))
                .map_err(&err)?;
        }
        for (k, b) in self.brackets.iter().enumerate() {
            let level = first + step * k as f64;
            let tick = step * 0.25;
            let (a, c) = (b.from.min(b.to) as f64, b.from.max(b.to) as f64);
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(a, level - tick), (a, level), (c, level), (c, level - tick)],
                    BLACK.stroke_width(1),
                )))
                .map_err(&err)?;
            let (px, py) = chart.backend_coord(&((a + c) / 2.0, level));
            root.draw(&Text::new(b.label.clone(), (px, py - 3), font(SMALL_FONT, HPos::Center, VPos::Bottom)))
                .map_err(&err)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bars_errors_and_brackets() {
        let mut c = BarChart::new("DIS asymptote by demonstration length", "Demonstration length", "Asymptotic reward");
        c.categories = vec!["100".into(), "500".into(), "953".into()];
        c.values = vec![1380.0, 1402.5, 1398.8];
        c.errors = Some(vec![40.0, 35.0, 30.0]);
        c.brackets = vec![
            Bracket { from: 0, to: 1, label: "p = 0.2338".into() },
            Bracket { from: 1, to: 2, label: "p = 0.8123".into() },
            Bracket { from: 0, to: 2, label: "p = 0.4410".into() },
        ];
        let p = Provenance::new("cmd", "0.1.0");
        let a = c.to_svg(&p).unwrap();
        assert_eq!(a, c.to_svg(&p).unwrap());
        let bar_fill = "fill=\"#0072B2\"";
        assert_eq!(a.lines().filter(|l| l.starts_with("<rect") && l.contains(bar_fill)).count(), 3);
        for label in ["p = 0.2338", "p = 0.8123", "p = 0.4410", "100", "953"] {
            assert!(a.contains(&format!(">\n{label}\n</text>")), "{label}");
        }
        // 3 error bars of 3 strokes, 3 brackets.
        let black = a.lines().filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#000000\"")).count();
        assert_eq!(black, 12);
        c.brackets.push(Bracket { from: 0, to: 3, label: "x".into() });
        assert!(c.to_svg(&p).is_err());
    }
}
