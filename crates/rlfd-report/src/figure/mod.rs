//! SVG figures drawn with plotters' SVG backend, returned as `String`s that
//! are byte-identical across runs: line charts with bands and reference
//! lines ([`LineChart`]), scenes in data coordinates such as the maze
//! ([`Scene`]), bar charts with significance brackets ([`BarChart`]),
//! scatter plots with a fitted line ([`ScatterPlot`]), box plots with
//! markers ([`BoxPlot`]), intervals per row and series ([`ForestPlot`], the
//! specification curve), layered graphs with styled edges ([`Graph`]) and
//! maps over a camera image with cells, glyphs and ellipses ([`ImageMap`]).
//!
//! Determinism: plotters maps every coordinate to whole pixels and writes
//! them as integers; text goes out as `<text>` elements in an explicit
//! font stack, DejaVu Sans first ([`FONT_STACK`]), never as glyph outlines.
//! Legends and labels are laid out here with DejaVu Sans's own advance
//! widths ([`text_width`], from the font the `dejavu` crate ships), so no
//! system font is read and layout cannot vary between machines; legends are
//! placed where they cover the fewest data (or outside the plot). Each
//! figure also converts to PDF ([`svg_to_pdf`]) with that font embedded.
//!
//! Every SVG starts with an XML comment carrying the caller's provenance
//! line, and holds the exact line again in a `<desc>` element: XML comments
//! may not contain `--`, so in the comment each `--` of the command is
//! written `- -` (see [`provenance_comment`]).
//!
//! Colours: series take the Okabe–Ito palette ([`PALETTE`], colour-blind
//! safe) by index; the maze's demonstrations take the lighter [`LIGHT`].

mod bar_chart;
mod box_plot;
mod clip;
mod font;
mod forest;
mod graph;
mod image_map;
mod line_chart;
mod scatter;
mod scene;

pub use bar_chart::{BarChart, Bracket};
pub use box_plot::{BoxMarker, BoxPlot, BoxSeries, BoxStats};
pub(crate) use clip::Window;
pub use font::{FONT_STACK, svg_to_pdf, text_width};
pub use forest::{ForestPlot, ForestPoint, ForestRow};
pub use graph::{EdgeStyle, Graph, GraphEdge, GraphNode};
pub use image_map::{ImageMap, ImageRect, MapCell, MapEllipse, MapGlyph, MapPoint, MapRegion};
pub use line_chart::{HLine, LineChart, Series, SeriesStyle, Stroke};
pub use scatter::{Fit, ScatterGroup, ScatterPlot};
pub use scene::{Marker, PathEmphasis, Rect, Scene, ScenePath};

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::{Error, Provenance, Result};

/// The Okabe–Ito palette (Okabe & Ito 2008), ordered so the first colours
/// differ most: blue, vermillion, bluish green, reddish purple, orange, sky
/// blue, yellow, black. Series `i` takes `PALETTE[i % 8]`.
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0x00, 0x72, 0xB2),
    (0xD5, 0x5E, 0x00),
    (0x00, 0x9E, 0x73),
    (0xCC, 0x79, 0xA7),
    (0xE6, 0x9F, 0x00),
    (0x56, 0xB4, 0xE9),
    (0xF0, 0xE4, 0x42),
    (0x00, 0x00, 0x00),
];

/// Ten light, distinct colours for secondary paths (Paul Tol's "light"
/// scheme without its grey, plus two): `LIGHT[i % 10]`.
pub const LIGHT: [(u8, u8, u8); 10] = [
    (0x77, 0xAA, 0xDD),
    (0xEE, 0x88, 0x66),
    (0x44, 0xBB, 0x99),
    (0xFF, 0xAA, 0xBB),
    (0x99, 0xDD, 0xFF),
    (0xBB, 0xCC, 0x33),
    (0xEE, 0xDD, 0x88),
    (0xAA, 0xAA, 0x00),
    (0xCC, 0x99, 0xCC),
    (0x88, 0xCC, 0xAA),
];

/// Where a legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LegendPosition {
    /// The inner corner that covers the fewest data (ties: upper right,
    /// upper left, lower right, lower left).
    Auto,
    UpperLeft,
    UpperRight,
    LowerLeft,
    LowerRight,
    /// No legend (a panel of a grid whose legend is shared, see [`LineChart::grid`]).
    Hidden,
    /// Outside the plot, never covering data: in a column at its right, or
    /// under it in as many columns as fit when a column would take more than
    /// a quarter of the figure's width.
    Outside,
}

// Font sizes are given to plotters times 1.24 (its SVG backend divides by
// 1.24), chosen so the written `font-size` is a whole number.
pub(crate) const TITLE_FONT: f64 = 19.84; // 16 px
pub(crate) const DESC_FONT: f64 = 17.36; // 14 px
pub(crate) const LABEL_FONT: f64 = 14.88; // 12 px
pub(crate) const SMALL_FONT: f64 = 13.64; // 11 px
/// Pixel size of legend and label text (LABEL_FONT as written).
pub(crate) const LABEL_PX: i32 = 12;
pub(crate) const TITLE_HEIGHT: u32 = 36;

pub(crate) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
pub(crate) type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

pub(crate) fn rgb((r, g, b): (u8, u8, u8)) -> RGBColor {
    RGBColor(r, g, b)
}

pub(crate) fn series_colour(i: usize) -> RGBColor {
    rgb(PALETTE[i % PALETTE.len()])
}

pub(crate) const GRID: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
pub(crate) const AXIS: RGBColor = RGBColor(0x44, 0x44, 0x44);
pub(crate) const TEXT: RGBColor = RGBColor(0x22, 0x22, 0x22);

/// The first line of every SVG: `<!-- generated by … -->`, with `--` written
/// `- -` because XML comments cannot hold it.
pub fn provenance_comment(provenance: &Provenance) -> String {
    let mut line = provenance.line();
    while line.contains("--") {
        line = line.replace("--", "- -");
    }
    if line.ends_with('-') {
        line.push(' ');
    }
    format!("<!-- {line} -->")
}

/// Puts the provenance comment first and the exact line in a `<desc>`
/// right after the opening `<svg …>` tag.
pub(crate) fn finish_svg(svg: String, provenance: &Provenance) -> String {
    let desc = format!("<desc>{}</desc>\n", crate::markup::escape_html(&provenance.line()));
    let mut out = String::with_capacity(svg.len() + 256);
    out.push_str(&provenance_comment(provenance));
    out.push('\n');
    match svg.find(">\n") {
        Some(i) if svg.starts_with("<svg") => {
            out.push_str(&svg[..i + 2]);
            out.push_str(&desc);
            out.push_str(&svg[i + 2..]);
        }
        _ => out.push_str(&svg),
    }
    out
}

pub(crate) fn drawing_error(figure: &str) -> impl Fn(DrawingAreaErrorKind<std::io::Error>) -> Error + '_ {
    move |e| Error::Drawing { figure: figure.to_owned(), reason: e.to_string() }
}

pub(crate) fn figure_error(figure: &str, reason: impl Into<String>) -> Error {
    Error::Figure { figure: figure.to_owned(), reason: reason.into() }
}

/// A text style: the font stack at `size` (a plotters size, see the constants),
/// anchored at `pos`.
pub(crate) fn font(size: f64, h: HPos, v: VPos) -> TextStyle<'static> {
    (FONT_STACK, size).into_font().color(&TEXT).pos(Pos::new(h, v))
}

/// Fills the canvas white, writes the title centred on top and returns the
/// area below it.
pub(crate) fn titled<'a>(root: &Area<'a>, title: &str, figure: &str) -> Result<Area<'a>> {
    root.fill(&WHITE).map_err(drawing_error(figure))?;
    let (w, _) = root.dim_in_pixel();
    root.draw(&Text::new(title.to_owned(), (w as i32 / 2, 10), font(TITLE_FONT, HPos::Center, VPos::Top)))
        .map_err(drawing_error(figure))?;
    let (_, body) = root.split_vertically(TITLE_HEIGHT);
    Ok(body)
}

/// `(lo, hi)` of finite values, or `None` if there is none.
pub(crate) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values.into_iter().filter(|v| v.is_finite()).fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// Widens `(lo, hi)` by `fraction` of its span on each side (a degenerate
/// range becomes `lo - 1 .. hi + 1`).
pub(crate) fn pad((lo, hi): (f64, f64), fraction: f64) -> (f64, f64) {
    let span = hi - lo;
    if span <= 0.0 { (lo - 1.0, hi + 1.0) } else { (lo - span * fraction, hi + span * fraction) }
}

/// Checks a user-given range.
pub(crate) fn check_range(figure: &str, axis: &str, (lo, hi): (f64, f64)) -> Result<()> {
    if lo.is_finite() && hi.is_finite() && lo < hi {
        Ok(())
    } else {
        Err(figure_error(figure, format!("{axis} range {lo}..{hi} is not finite and increasing")))
    }
}

/// Decimals for tick labels of an axis spanning `span` with about `ticks`
/// ticks: one more than the step's leading digit needs (trailing zeros are
/// trimmed by [`tick_text`]).
pub(crate) fn tick_decimals(span: f64, ticks: usize) -> usize {
    let step = span / ticks.max(1) as f64;
    let sci = format!("{step:e}");
    let exponent: i32 = sci.split_once('e').and_then(|(_, e)| e.parse().ok()).unwrap_or(0);
    (1 - exponent).max(0) as usize
}

/// A tick label: thousands grouped, trailing zeros trimmed, true minus sign.
pub(crate) fn tick_text(v: f64, decimals: usize) -> String {
    let mut s = crate::format::thousands(v, decimals);
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    s.replace('-', "−")
}

/// How many x tick labels fit side by side in `plot_width` pixels without
/// touching, at most `max`: the widest label (the axis end with more
/// digits) at about 0.6 em a character, plus a gap of one em.
pub(crate) fn x_tick_count(plot_width: i32, (x0, x1): (f64, f64), max: usize) -> usize {
    let decimals = tick_decimals(x1 - x0, max);
    let chars = tick_text(x0, decimals).chars().count().max(tick_text(x1, decimals).chars().count());
    let em = LABEL_FONT * 12.0 / 14.88;
    let per_label = chars as f64 * 0.6 * em + em;
    ((f64::from(plot_width.max(0)) / per_label) as usize).clamp(2, max)
}

/// Draws the light grid, axes, tick labels and axis descriptions.
pub(crate) fn draw_mesh(
    chart: &mut Chart<'_, '_>,
    x_label: &str,
    y_label: &str,
    (x_span, y_span): (f64, f64),
    (x_ticks, y_ticks): (usize, usize),
    figure: &str,
) -> Result<()> {
    let xd = tick_decimals(x_span, x_ticks);
    let yd = tick_decimals(y_span, y_ticks);
    let x_fmt = move |v: &f64| tick_text(*v, xd);
    let y_fmt = move |v: &f64| tick_text(*v, yd);
    chart
        .configure_mesh()
        .x_labels(x_ticks)
        .y_labels(y_ticks)
        .max_light_lines(0)
        .bold_line_style(GRID)
        .axis_style(AXIS)
        .label_style((FONT_STACK, LABEL_FONT).into_font().color(&TEXT))
        .axis_desc_style((FONT_STACK, DESC_FONT).into_font().color(&TEXT))
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .draw()
        .map_err(drawing_error(figure))
}

/// What a legend entry shows left of its label.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Sample {
    /// A line; `band` adds a translucent box behind it.
    /// `dash`: `(on, off)` pixels, or solid.
    Line { colour: RGBColor, width: u32, dash: Option<(i32, i32)>, band: bool },
    /// A filled circle.
    Marker { colour: RGBColor },
    /// A filled box.
    Swatch { colour: RGBColor, opacity: f64 },
    /// The stroked shape a box plot's marker of this kind draws (see [`marker_shape`]).
    Shape { colour: RGBColor, kind: usize },
}

/// The outline of marker shape `kind` at `(px, py)`: a diamond, a cross or a
/// bar (`kind % 3`), as one polyline.
pub(crate) fn marker_shape(kind: usize, (px, py): (i32, i32)) -> Vec<(i32, i32)> {
    match kind % 3 {
        0 => vec![(px, py - 6), (px + 6, py), (px, py + 6), (px - 6, py), (px, py - 6)],
        1 => vec![(px - 5, py - 5), (px + 5, py + 5), (px, py), (px + 5, py - 5), (px - 5, py + 5)],
        _ => vec![(px - 6, py), (px + 6, py)],
    }
}

#[derive(Debug, Clone)]
pub(crate) struct LegendEntry {
    pub label: String,
    pub sample: Sample,
}

const LEGEND_ROW: i32 = 18;
const LEGEND_PAD: i32 = 8;
const LEGEND_SAMPLE: i32 = 26;

/// The legend box's size in pixels.
pub(crate) fn legend_size(entries: &[LegendEntry]) -> (i32, i32) {
    let text = entries.iter().map(|e| text_width(&e.label, LABEL_PX)).max().unwrap_or(0);
    (2 * LEGEND_PAD + LEGEND_SAMPLE + 6 + text, 2 * LEGEND_PAD + LEGEND_ROW * entries.len() as i32 - 4)
}

/// The legend laid out in columns across `width` pixels: `(width, height,
/// columns)` of the box.
pub(crate) fn legend_grid_size(entries: &[LegendEntry], width: i32) -> (i32, i32, usize) {
    let cell = entries.iter().map(|e| text_width(&e.label, LABEL_PX)).max().unwrap_or(0) + LEGEND_SAMPLE + 6 + 16;
    let columns = ((width - 2 * LEGEND_PAD) / cell.max(1)).clamp(1, entries.len().max(1) as i32) as usize;
    let rows = entries.len().div_ceil(columns) as i32;
    (2 * LEGEND_PAD + cell * columns as i32 - 16, 2 * LEGEND_PAD + LEGEND_ROW * rows - 4, columns)
}

/// Draws the legend in `columns` columns (entries row by row) with its
/// upper-left corner at `(x, y)`.
pub(crate) fn draw_legend_grid(
    root: &Area<'_>,
    (x, y): (i32, i32),
    entries: &[LegendEntry],
    columns: usize,
    figure: &str,
) -> Result<()> {
    let cell = entries.iter().map(|e| text_width(&e.label, LABEL_PX)).max().unwrap_or(0) + LEGEND_SAMPLE + 6 + 16;
    for (k, chunk) in entries.chunks(columns).enumerate() {
        for (j, entry) in chunk.iter().enumerate() {
            // Each entry drawn as a one-entry legend without its own frame.
            draw_entry(root, (x + cell * j as i32, y + LEGEND_ROW * k as i32), entry, figure)?;
        }
    }
    Ok(())
}

/// Draws the legend with its upper-left corner at `(x, y)` (root pixels).
pub(crate) fn draw_legend(root: &Area<'_>, (x, y): (i32, i32), entries: &[LegendEntry], figure: &str) -> Result<()> {
    if entries.is_empty() {
        return Ok(());
    }
    let err = drawing_error(figure);
    let (w, h) = legend_size(entries);
    root.draw(&Rectangle::new([(x, y), (x + w, y + h)], WHITE.mix(0.9).filled())).map_err(&err)?;
    root.draw(&Rectangle::new([(x, y), (x + w, y + h)], GRID.stroke_width(1))).map_err(&err)?;
    for (i, entry) in entries.iter().enumerate() {
        draw_entry(root, (x, y + LEGEND_ROW * i as i32), entry, figure)?;
    }
    Ok(())
}

/// One legend entry whose row starts at `(x, y)` (the legend's padding included).
fn draw_entry(root: &Area<'_>, (x, y): (i32, i32), entry: &LegendEntry, figure: &str) -> Result<()> {
    let err = drawing_error(figure);
    let cy = y + LEGEND_PAD + LEGEND_ROW / 2 - 2;
    let (sx0, sx1) = (x + LEGEND_PAD, x + LEGEND_PAD + LEGEND_SAMPLE);
    match entry.sample {
        Sample::Line { colour, width, dash, band } => {
            if band {
                root.draw(&Rectangle::new([(sx0, cy - 6), (sx1, cy + 6)], colour.mix(BAND_OPACITY).filled()))
                    .map_err(&err)?;
            }
            let style = colour.stroke_width(width);
            if let Some((on, off)) = dash {
                for (a, b) in dash_pattern(sx0, sx1, on, off) {
                    root.draw(&PathElement::new(vec![(a, cy), (b, cy)], style)).map_err(&err)?;
                }
            } else {
                root.draw(&PathElement::new(vec![(sx0, cy), (sx1, cy)], style)).map_err(&err)?;
            }
        }
        Sample::Marker { colour } => {
            root.draw(&Circle::new(((sx0 + sx1) / 2, cy), 4, colour.filled())).map_err(&err)?;
        }
        Sample::Swatch { colour, opacity } => {
            root.draw(&Rectangle::new([(sx0 + 4, cy - 6), (sx1 - 4, cy + 6)], colour.mix(opacity).filled()))
                .map_err(&err)?;
        }
        Sample::Shape { colour, kind } => {
            root.draw(&PathElement::new(marker_shape(kind, ((sx0 + sx1) / 2, cy)), colour.stroke_width(2)))
                .map_err(&err)?;
        }
    }
    root.draw(&Text::new(entry.label.clone(), (sx1 + 6, cy), font(LABEL_FONT, HPos::Left, VPos::Center)))
        .map_err(&err)?;
    Ok(())
}

/// Opacity of error bands.
pub(crate) const BAND_OPACITY: f64 = 0.2;

/// Dash segments `[a, b]` covering `x0..x1`: `on` px drawn, `off` px left out.
pub(crate) fn dash_pattern(x0: i32, x1: i32, on: i32, off: i32) -> Vec<(i32, i32)> {
    let mut out = Vec::new();
    let mut a = x0;
    while a < x1 {
        out.push((a, (a + on).min(x1)));
        a += on + off;
    }
    out
}

/// The dash patterns of dashed reference lines, in order, so several of
/// them in one chart stay apart: long, dotted, long-short.
pub(crate) const REFERENCE_DASHES: [(i32, i32); 3] = [(8, 5), (2, 3), (14, 4)];

/// Picks the legend's upper-left corner inside the plot `(x, y)` pixel
/// ranges: a fixed corner, or for `Auto` the corner whose box covers the
/// fewest of `occupied` pixels. `Outside` is handled by the caller.
pub(crate) fn legend_corner(
    position: LegendPosition,
    plot: &(std::ops::Range<i32>, std::ops::Range<i32>),
    size: (i32, i32),
    occupied: &[(i32, i32)],
) -> (i32, i32) {
    const INSET: i32 = 8;
    let (xr, yr) = plot;
    let corner = |p: LegendPosition| match p {
        LegendPosition::UpperLeft => (xr.start + INSET, yr.start + INSET),
        LegendPosition::LowerLeft => (xr.start + INSET, yr.end - INSET - size.1),
        LegendPosition::LowerRight => (xr.end - INSET - size.0, yr.end - INSET - size.1),
        _ => (xr.end - INSET - size.0, yr.start + INSET),
    };
    if position != LegendPosition::Auto {
        return corner(position);
    }
    let candidates =
        [LegendPosition::UpperRight, LegendPosition::UpperLeft, LegendPosition::LowerRight, LegendPosition::LowerLeft];
    let covered = |(x, y): (i32, i32)| {
        occupied
            .iter()
            .filter(|(px, py)| (x - 4..=x + size.0 + 4).contains(px) && (y - 4..=y + size.1 + 4).contains(py))
            .count()
    };
    let mut best = corner(candidates[0]);
    let mut best_count = covered(best);
    for p in &candidates[1..] {
        let c = corner(*p);
        let n = covered(c);
        if n < best_count {
            best = c;
            best_count = n;
        }
    }
    best
}

/// Pixels along a polyline, every few pixels, for legend placement.
pub(crate) fn trace(points: &[(i32, i32)], out: &mut Vec<(i32, i32)>) {
    for w in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        let steps = ((x1 - x0).abs().max((y1 - y0).abs()) / 3).max(1);
        for k in 0..steps {
            out.push((x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps));
        }
    }
    if let Some(last) = points.last() {
        out.push(*last);
    }
}

/// Splits a series at non-finite points into runs of finite ones.
pub(crate) fn finite_runs(points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut runs = Vec::new();
    let mut run = Vec::new();
    for &(x, y) in points {
        if x.is_finite() && y.is_finite() {
            run.push((x, y));
        } else if !run.is_empty() {
            runs.push(std::mem::take(&mut run));
        }
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs
}

/// Renders with a fresh SVG backend of `size` and finishes the document.
pub(crate) fn render_svg(
    size: (u32, u32),
    provenance: &Provenance,
    figure: &str,
    draw: impl FnOnce(&Area<'_>) -> Result<()>,
) -> Result<String> {
    if size.0 < 200 || size.1 < 150 || size.0 > 4000 || size.1 > 4000 {
        return Err(figure_error(figure, format!("size {}x{} outside 200x150..4000x4000", size.0, size.1)));
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw(&root)?;
        root.present().map_err(drawing_error(figure))?;
    }
    Ok(finish_svg(svg, provenance))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn provenance_comment_has_no_double_hyphen() {
        let p = Provenance::new("cargo xtask reproduce --chapter ch6 --seed 7 ---x-", "0.1.0");
        let c = provenance_comment(&p);
        assert_eq!(
            c,
            format!(
                "<!-- generated by cargo xtask reproduce - -chapter ch6 - -seed 7 - - -x- (rlfd 0.1.0), decided by the {}; do not edit -->",
                crate::plan::analysis_plan().line()
            )
        );
        assert!(!c[4..c.len() - 3].contains("--"));
    }

    #[test]
    fn ticks() {
        assert_eq!(tick_decimals(1.0, 5), 2);
        assert_eq!(tick_decimals(8000.0, 6), 0);
        assert_eq!(tick_text(-150000.0, 0), "−150,000");
        assert_eq!(tick_text(0.2, 2), "0.2");
        assert_eq!(tick_text(1.0, 2), "1");
        assert_eq!(tick_text(-0.0001, 2), "0");
    }

    #[test]
    fn x_ticks_fit_the_plot_width() {
        // "20,000": 6 characters of about 7.2 px and a 12 px gap, 55 px a label.
        assert_eq!(x_tick_count(396, (1.0, 20000.0), 10), 7);
        // Short labels: the cap.
        assert_eq!(x_tick_count(396, (1.0, 150.0), 10), 10);
        // Never fewer than two, whatever the width.
        assert_eq!(x_tick_count(10, (0.0, 1.0e9), 10), 2);
        assert_eq!(x_tick_count(-5, (0.0, 1.0), 10), 2);
    }

    #[test]
    fn runs_split_at_nan() {
        let runs = finite_runs(&[(0.0, 1.0), (1.0, f64::NAN), (2.0, 2.0), (3.0, 3.0)]);
        assert_eq!(runs, vec![vec![(0.0, 1.0)], vec![(2.0, 2.0), (3.0, 3.0)]]);
    }
}
