//! Maps over a camera image, in image coordinates with the origin top left
//! and y growing down (e.g. Figures 4.3 and 4.7: a policy drawn over the
//! 320 × 240 image). Layers, bottom to top: outlined regions (the zones,
//! lightly tinted), filled cells (a grid policy), glyphs (the thesis's
//! triangles for untied states), ellipses (a Gaussian's 1σ and 2σ contours)
//! and points (demonstrations). Every item names a category; categories take
//! the Okabe–Ito colours by index and make the legend.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{
    AXIS, Area, LABEL_FONT, LegendEntry, SMALL_FONT, Sample, TEXT, draw_legend, figure_error, font, legend_size,
    render_svg, series_colour, titled,
};
use crate::{Provenance, Result};

/// A rectangle `[x0, x1) × [y0, y1)` in image coordinates.
pub type ImageRect = (f64, f64, f64, f64);

/// A labelled region, outlined and lightly tinted in its category's colour.
#[derive(Debug, Clone, PartialEq)]
pub struct MapRegion {
    pub rect: ImageRect,
    pub label: String,
    pub category: usize,
}

/// A cell filled in its category's colour.
#[derive(Debug, Clone, PartialEq)]
pub struct MapCell {
    pub rect: ImageRect,
    pub category: usize,
}

/// A triangle glyph (pointing up) at a point.
#[derive(Debug, Clone, PartialEq)]
pub struct MapGlyph {
    pub at: (f64, f64),
    pub category: usize,
}

/// An ellipse: centre, semi-axes and the first axis's angle (radians, image frame).
#[derive(Debug, Clone, PartialEq)]
pub struct MapEllipse {
    pub centre: (f64, f64),
    pub radii: (f64, f64),
    pub angle: f64,
    pub category: usize,
    pub dashed: bool,
}

/// A small dot.
#[derive(Debug, Clone, PartialEq)]
pub struct MapPoint {
    pub at: (f64, f64),
    pub category: usize,
}

/// A map over an image.
#[derive(Debug, Clone, PartialEq)]
pub struct ImageMap {
    pub title: String,
    /// Image size in pixels, e.g. 320 × 240.
    pub image: (f64, f64),
    /// Names of the categories (the legend), coloured by index.
    pub categories: Vec<String>,
    pub regions: Vec<MapRegion>,
    pub cells: Vec<MapCell>,
    pub glyphs: Vec<MapGlyph>,
    pub ellipses: Vec<MapEllipse>,
    pub points: Vec<MapPoint>,
    /// Screen pixels per image pixel.
    pub scale: f64,
    /// An optional note under the legend.
    pub note: Option<String>,
}

const LEFT: i32 = 56;
const BOTTOM: i32 = 44;
const MARGIN: i32 = 12;

impl ImageMap {
    /// An empty map of an image, drawn at 2 screen pixels per image pixel.
    pub fn new(title: impl Into<String>, image: (f64, f64)) -> ImageMap {
        ImageMap {
            title: title.into(),
            image,
            categories: Vec::new(),
            regions: Vec::new(),
            cells: Vec::new(),
            glyphs: Vec::new(),
            ellipses: Vec::new(),
            points: Vec::new(),
            scale: 2.0,
            note: None,
        }
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        if !(self.image.0 > 0.0 && self.image.1 > 0.0 && self.scale > 0.0) {
            return Err(figure_error(f, "image size and scale must be positive"));
        }
        let n = self.categories.len();
        let cats = self
            .regions
            .iter()
            .map(|r| r.category)
            .chain(self.cells.iter().map(|c| c.category))
            .chain(self.glyphs.iter().map(|g| g.category))
            .chain(self.ellipses.iter().map(|e| e.category))
            .chain(self.points.iter().map(|p| p.category));
        if let Some(c) = cats.into_iter().find(|&c| c >= n) {
            return Err(figure_error(f, format!("category {c} of {n}")));
        }
        if self.ellipses.iter().any(|e| !(e.radii.0.is_finite() && e.radii.1.is_finite() && e.angle.is_finite())) {
            return Err(figure_error(f, "an ellipse is not finite"));
        }
        Ok(())
    }

    fn legend_entries(&self) -> Vec<LegendEntry> {
        self.categories
            .iter()
            .enumerate()
            .map(|(i, c)| LegendEntry {
                label: c.clone(),
                sample: Sample::Swatch { colour: series_colour(i), opacity: 0.6 },
            })
            .collect()
    }

    fn plot_size(&self) -> (i32, i32) {
        ((self.image.0 * self.scale).round() as i32, (self.image.1 * self.scale).round() as i32)
    }

    /// The map as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        let (w, h) = self.plot_size();
        let (lw, lh) = legend_size(&self.legend_entries());
        let width = LEFT + w + 2 * MARGIN + lw.max(super::text_width(self.note.as_deref().unwrap_or(""), 11).min(260));
        let height = super::TITLE_HEIGHT as i32 + MARGIN + h.max(lh + 60) + BOTTOM;
        render_svg((width as u32, height as u32), provenance, &self.title, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        titled(root, &self.title, f)?;
        let (w, h) = self.plot_size();
        let ox = LEFT;
        let oy = super::TITLE_HEIGHT as i32 + MARGIN;
        // Everything is kept inside the frame (an ellipse reaching past the image is cut at its edge).
        let sx = |x: f64| ox + (x.clamp(0.0, self.image.0) * self.scale).round() as i32;
        let sy = |y: f64| oy + (y.clamp(0.0, self.image.1) * self.scale).round() as i32;
        let rect = |r: &ImageRect| [(sx(r.0), sy(r.2)), (sx(r.1), sy(r.3))];
        root.draw(&Rectangle::new([(ox, oy), (ox + w, oy + h)], RGBColor(0xF7, 0xF7, 0xF7).filled())).map_err(&err)?;
        for r in &self.regions {
            let c = series_colour(r.category);
            root.draw(&Rectangle::new(rect(&r.rect), c.mix(0.10).filled())).map_err(&err)?;
            root.draw(&Rectangle::new(rect(&r.rect), c.stroke_width(2))).map_err(&err)?;
            root.draw(&Text::new(
                r.label.clone(),
                (sx(r.rect.0) + 4, sy(r.rect.2) + 3),
                font(SMALL_FONT, HPos::Left, VPos::Top),
            ))
            .map_err(&err)?;
        }
        for c in &self.cells {
            root.draw(&Rectangle::new(rect(&c.rect), series_colour(c.category).mix(0.45).filled())).map_err(&err)?;
        }
        for g in &self.glyphs {
            let (cx, cy) = (sx(g.at.0), sy(g.at.1));
            let tri = vec![(cx, cy - 7), (cx + 7, cy + 6), (cx - 7, cy + 6)];
            root.draw(&Polygon::new(tri.clone(), series_colour(g.category).filled())).map_err(&err)?;
            let mut outline = tri;
            outline.push((cx, cy - 7));
            root.draw(&PathElement::new(outline, AXIS.stroke_width(1))).map_err(&err)?;
        }
        for e in &self.ellipses {
            let (ca, sa) = (libm::cos(e.angle), libm::sin(e.angle));
            let pts: Vec<(i32, i32)> = (0..=72)
                .map(|k| {
                    let t = 2.0 * std::f64::consts::PI * f64::from(k) / 72.0;
                    let (u, v) = (e.radii.0 * libm::cos(t), e.radii.1 * libm::sin(t));
                    (sx(e.centre.0 + u * ca - v * sa), sy(e.centre.1 + u * sa + v * ca))
                })
                .collect();
            let colour = series_colour(e.category);
            if e.dashed {
                for chunk in pts.chunks(3).step_by(2) {
                    if chunk.len() > 1 {
                        root.draw(&PathElement::new(chunk.to_vec(), colour.stroke_width(2))).map_err(&err)?;
                    }
                }
            } else {
                root.draw(&PathElement::new(pts, colour.stroke_width(2))).map_err(&err)?;
            }
            root.draw(&Circle::new((sx(e.centre.0), sy(e.centre.1)), 3, colour.filled())).map_err(&err)?;
        }
        for p in &self.points {
            root.draw(&Circle::new((sx(p.at.0), sy(p.at.1)), 2, series_colour(p.category).filled())).map_err(&err)?;
        }
        // Frame, ticks every 40 px, axis names.
        root.draw(&Rectangle::new([(ox, oy), (ox + w, oy + h)], AXIS.stroke_width(1))).map_err(&err)?;
        let mut x = 0.0;
        while x <= self.image.0 + 1e-9 {
            root.draw(&PathElement::new(vec![(sx(x), oy + h), (sx(x), oy + h + 5)], AXIS.stroke_width(1)))
                .map_err(&err)?;
            root.draw(&Text::new(format!("{x:.0}"), (sx(x), oy + h + 7), font(LABEL_FONT, HPos::Center, VPos::Top)))
                .map_err(&err)?;
            x += 40.0;
        }
        let mut y = 0.0;
        while y <= self.image.1 + 1e-9 {
            root.draw(&PathElement::new(vec![(ox - 5, sy(y)), (ox, sy(y))], AXIS.stroke_width(1))).map_err(&err)?;
            root.draw(&Text::new(format!("{y:.0}"), (ox - 7, sy(y)), font(LABEL_FONT, HPos::Right, VPos::Center)))
                .map_err(&err)?;
            y += 40.0;
        }
        root.draw(&Text::new(
            "x (pixels)".to_string(),
            (ox + w / 2, oy + h + 26),
            font(LABEL_FONT, HPos::Center, VPos::Top),
        ))
        .map_err(&err)?;
        root.draw(&Text::new("y (pixels, down)".to_string(), (ox, oy - 2), font(LABEL_FONT, HPos::Left, VPos::Bottom)))
            .map_err(&err)?;
        let lx = ox + w + 2 * MARGIN;
        let entries = self.legend_entries();
        draw_legend(root, (lx, oy), &entries, f)?;
        if let Some(note) = &self.note {
            let (_, lh) = legend_size(&entries);
            for (k, line) in note.lines().enumerate() {
                root.draw(&Text::new(
                    line.to_string(),
                    (lx, oy + lh + 12 + 14 * k as i32),
                    (super::FONT_STACK, SMALL_FONT)
                        .into_font()
                        .color(&TEXT)
                        .pos(plotters::style::text_anchor::Pos::new(HPos::Left, VPos::Top)),
                ))
                .map_err(&err)?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_policy_over_the_image() {
        let mut m = ImageMap::new("Figure 4.3(a): a policy", (320.0, 240.0));
        m.categories = vec!["pick-up".into(), "sweep".into(), "wait".into()];
        m.regions.push(MapRegion { rect: (120.0, 220.0, 160.0, 240.0), label: "pick-up zone".into(), category: 0 });
        m.cells.push(MapCell { rect: (0.0, 32.0, 0.0, 24.0), category: 2 });
        m.glyphs.push(MapGlyph { at: (16.0, 12.0), category: 2 });
        m.ellipses.push(MapEllipse {
            centre: (170.0, 200.0),
            radii: (30.0, 10.0),
            angle: 0.3,
            category: 0,
            dashed: false,
        });
        m.ellipses.push(MapEllipse {
            centre: (60.0, 200.0),
            radii: (20.0, 10.0),
            angle: 0.0,
            category: 1,
            dashed: true,
        });
        m.points.push(MapPoint { at: (100.0, 100.0), category: 1 });
        m.note = Some("two lines\nof note".into());
        let p = Provenance::new("cmd", "0.1.0");
        let a = m.to_svg(&p).unwrap();
        assert_eq!(a, m.to_svg(&p).unwrap());
        assert!(a.contains(">\npick-up zone\n</text>") && a.contains(">\nof note\n</text>"));
        // The y axis points down: the region at y 160–240 is drawn in the lower part.
        assert!(a.contains("y (pixels, down)"));
        m.points.push(MapPoint { at: (1.0, 1.0), category: 3 });
        assert!(m.to_svg(&p).is_err());
    }
}
