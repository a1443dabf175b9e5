//! Layered graphs drawn top to bottom: nodes as labelled ellipses in rows,
//! edges as solid, dashed or dotted arrows (e.g. Figure 4.5: a behaviour
//! network, its behaviours in the order they were taught, solid permanent,
//! dashed enabling and dotted ordering links). An edge between adjacent rows
//! is straight; a longer one bows to the side, alternately right and left,
//! so it does not run through the nodes between. The layout is the
//! caller's (the row of each node); nothing here reorders.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::{AXIS, Area, LABEL_FONT, LABEL_PX, TEXT, figure_error, font, render_svg, text_width, titled};
use crate::{Provenance, Result};

/// A node: its label, its row (0 at the top) and its lane (column, from 0
/// at the left; fractional lanes sit between columns).
#[derive(Debug, Clone, PartialEq)]
pub struct GraphNode {
    pub label: String,
    pub row: usize,
    pub lane: f64,
}

/// How an edge is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EdgeStyle {
    Solid,
    Dashed,
    Dotted,
}

/// An edge between node indices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GraphEdge {
    pub from: usize,
    pub to: usize,
    pub style: EdgeStyle,
}

/// A graph with a legend for its edge styles.
#[derive(Debug, Clone, PartialEq)]
pub struct Graph {
    pub title: String,
    pub nodes: Vec<GraphNode>,
    pub edges: Vec<GraphEdge>,
    /// What each edge style means, in legend order.
    pub legend: Vec<(EdgeStyle, String)>,
    /// Canvas width in pixels (the height follows the rows).
    pub width: u32,
}

const ROW: i32 = 64;
const TOP: i32 = 24;
const RY: i32 = 16;
const LEGEND_W: i32 = 200;

impl Graph {
    /// An empty graph 560 px wide.
    pub fn new(title: impl Into<String>) -> Graph {
        Graph { title: title.into(), nodes: Vec::new(), edges: Vec::new(), legend: Vec::new(), width: 560 }
    }

    fn rows(&self) -> usize {
        self.nodes.iter().map(|n| n.row + 1).max().unwrap_or(0)
    }

    fn check(&self) -> Result<()> {
        let f = &self.title;
        if self.nodes.is_empty() {
            return Err(figure_error(f, "no nodes"));
        }
        for e in &self.edges {
            if e.from >= self.nodes.len() || e.to >= self.nodes.len() || e.from == e.to {
                return Err(figure_error(
                    f,
                    format!("edge {}→{} does not join two of the {} nodes", e.from, e.to, self.nodes.len()),
                ));
            }
        }
        if self.rows() > 55 {
            return Err(figure_error(f, "more than 55 rows do not fit"));
        }
        if self.nodes.iter().any(|n| !(n.lane.is_finite() && n.lane >= 0.0 && n.lane <= 20.0)) {
            return Err(figure_error(f, "a lane is outside 0..=20"));
        }
        Ok(())
    }

    /// Node centres in pixels.
    fn positions(&self) -> Vec<(i32, i32)> {
        let plot_w = f64::from(self.width as i32 - LEGEND_W);
        let lanes = self.nodes.iter().map(|n| n.lane).fold(0.0, f64::max).floor() + 1.0;
        self.nodes
            .iter()
            .map(|n| {
                let x = plot_w * (n.lane + 0.5) / lanes;
                (x.round() as i32, super::TITLE_HEIGHT as i32 + TOP + RY + ROW * n.row as i32)
            })
            .collect()
    }

    /// The graph as an SVG document opening with the provenance comment.
    pub fn to_svg(&self, provenance: &Provenance) -> Result<String> {
        self.check()?;
        let h = super::TITLE_HEIGHT as i32 + TOP + ROW * self.rows() as i32 + 16;
        let legend_h: i32 = super::TITLE_HEIGHT as i32 + TOP + 24 * self.legend.len() as i32 + 16;
        render_svg((self.width, h.max(legend_h).max(150) as u32), provenance, &self.title, |root| self.draw(root))
    }

    fn draw(&self, root: &Area<'_>) -> Result<()> {
        let f = self.title.as_str();
        let err = super::drawing_error(f);
        titled(root, &self.title, f)?;
        let pos = self.positions();
        let rx = |i: usize| (text_width(&self.nodes[i].label, LABEL_PX) / 2 + 12).max(28);
        let mut side = 1;
        for e in &self.edges {
            let (a, b) = (pos[e.from], pos[e.to]);
            let (top, bottom) = if a.1 <= b.1 { (a, b) } else { (b, a) };
            let span = (self.nodes[e.to].row as i32 - self.nodes[e.from].row as i32).abs();
            let start = (top.0, top.1 + RY);
            let end = (bottom.0, bottom.1 - RY);
            let points: Vec<(i32, i32)> = if span <= 1 {
                vec![start, end]
            } else {
                side = -side;
                let bow = side * (rx(e.from).max(rx(e.to)) + 10 + 8 * span);
                (0..=24)
                    .map(|k| {
                        let t = f64::from(k) / 24.0;
                        let x = f64::from(start.0) * (1.0 - t)
                            + f64::from(end.0) * t
                            + f64::from(bow) * 4.0 * t * (1.0 - t);
                        let y = f64::from(start.1) * (1.0 - t) + f64::from(end.1) * t;
                        (x.round() as i32, y.round() as i32)
                    })
                    .collect()
            };
            stroke(root, &points, e.style, &err)?;
            // Arrowhead at the lower end (edges point down the rows).
            let (p, q) = (points[points.len() - 2], points[points.len() - 1]);
            let (dx, dy) = (f64::from(q.0 - p.0), f64::from(q.1 - p.1));
            let len = (dx * dx + dy * dy).sqrt().max(1e-9);
            let (ux, uy) = (dx / len, dy / len);
            let wing = |s: f64| {
                (
                    (f64::from(q.0) - 8.0 * ux + s * 4.0 * uy).round() as i32,
                    (f64::from(q.1) - 8.0 * uy - s * 4.0 * ux).round() as i32,
                )
            };
            root.draw(&Polygon::new(vec![q, wing(1.0), wing(-1.0)], AXIS.filled())).map_err(&err)?;
        }
        for (i, n) in self.nodes.iter().enumerate() {
            let (cx, cy) = pos[i];
            let r = rx(i);
            let ellipse: Vec<(i32, i32)> = (0..=48)
                .map(|k| {
                    let t = 2.0 * std::f64::consts::PI * f64::from(k) / 48.0;
                    (
                        (f64::from(cx) + f64::from(r) * libm::cos(t)).round() as i32,
                        (f64::from(cy) + f64::from(RY) * libm::sin(t)).round() as i32,
                    )
                })
                .collect();
            root.draw(&Polygon::new(ellipse.clone(), WHITE.filled())).map_err(&err)?;
            root.draw(&PathElement::new(ellipse, AXIS.stroke_width(1))).map_err(&err)?;
            root.draw(&Text::new(n.label.clone(), (cx, cy), font(LABEL_FONT, HPos::Center, VPos::Center)))
                .map_err(&err)?;
        }
        let x0 = self.width as i32 - LEGEND_W + 16;
        for (k, (style, label)) in self.legend.iter().enumerate() {
            let y = super::TITLE_HEIGHT as i32 + TOP + 24 * k as i32;
            stroke(root, &[(x0, y), (x0 + 36, y)], *style, &err)?;
            root.draw(&Text::new(
                label.clone(),
                (x0 + 44, y),
                (super::FONT_STACK, LABEL_FONT)
                    .into_font()
                    .color(&TEXT)
                    .pos(plotters::style::text_anchor::Pos::new(HPos::Left, VPos::Center)),
            ))
            .map_err(&err)?;
        }
        Ok(())
    }
}

/// Strokes a polyline solid, dashed (8 on, 5 off) or dotted (2 on, 4 off).
fn stroke(
    root: &Area<'_>,
    points: &[(i32, i32)],
    style: EdgeStyle,
    err: &impl Fn(DrawingAreaErrorKind<std::io::Error>) -> crate::Error,
) -> Result<()> {
    let (on, off): (f64, f64) = match style {
        EdgeStyle::Solid => return root.draw(&PathElement::new(points.to_vec(), AXIS.stroke_width(2))).map_err(err),
        EdgeStyle::Dashed => (8.0, 5.0),
        EdgeStyle::Dotted => (2.0, 4.0),
    };
    let mut drawing = true;
    let mut left = on;
    let mut run: Vec<(f64, f64)> = vec![(f64::from(points[0].0), f64::from(points[0].1))];
    let flush = |run: &mut Vec<(f64, f64)>| -> Result<()> {
        if run.len() > 1 {
            let px: Vec<(i32, i32)> = run.iter().map(|&(x, y)| (x.round() as i32, y.round() as i32)).collect();
            root.draw(&PathElement::new(px, AXIS.stroke_width(2))).map_err(err)?;
        }
        run.clear();
        Ok(())
    };
    for w in points.windows(2) {
        let (mut x, mut y) = (f64::from(w[0].0), f64::from(w[0].1));
        let (x1, y1) = (f64::from(w[1].0), f64::from(w[1].1));
        let mut seg = ((x1 - x).powi(2) + (y1 - y).powi(2)).sqrt();
        while seg > 1e-9 {
            let step = left.min(seg);
            x += (x1 - x) * step / seg;
            y += (y1 - y) * step / seg;
            seg -= step;
            left -= step;
            if drawing {
                run.push((x, y));
            }
            if left <= 1e-9 {
                if drawing {
                    flush(&mut run)?;
                } else {
                    run.push((x, y));
                }
                drawing = !drawing;
                left = if drawing { on } else { off };
            }
        }
    }
    if drawing {
        flush(&mut run)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_behaviour_network_draws() {
        let mut g = Graph::new("Figure 4.5(a): a simple network");
        for (k, l) in ["START", "FBIPZ_1", "P-UP_2", "DONE"].iter().enumerate() {
            g.nodes.push(GraphNode { label: (*l).into(), row: k, lane: 0.0 });
        }
        g.edges = vec![
            GraphEdge { from: 0, to: 1, style: EdgeStyle::Dotted },
            GraphEdge { from: 1, to: 2, style: EdgeStyle::Dashed },
            GraphEdge { from: 2, to: 3, style: EdgeStyle::Dotted },
            GraphEdge { from: 0, to: 3, style: EdgeStyle::Solid },
        ];
        g.legend = vec![
            (EdgeStyle::Solid, "permanent".into()),
            (EdgeStyle::Dashed, "enabling".into()),
            (EdgeStyle::Dotted, "ordering".into()),
        ];
        let p = Provenance::new("cmd", "0.1.0");
        let a = g.to_svg(&p).unwrap();
        assert_eq!(a, g.to_svg(&p).unwrap());
        assert!(a.contains(">\nP-UP_2\n</text>") && a.contains(">\nenabling\n</text>"));
        assert!(a.matches("<polygon").count() >= 8, "4 ellipses and 4 arrowheads");
        g.edges.push(GraphEdge { from: 2, to: 9, style: EdgeStyle::Solid });
        assert!(g.to_svg(&p).is_err());
    }
}
