//! The chapter's figures: Figure 4.2 (box plots), 4.3 and 4.7 (policies
//! over the image), 4.4, 4.6 and 4.8 (scatter plots with r), 4.5 (behaviour
//! networks) and the spread of the correlations over studies.

use rlfd_report::Provenance;
use rlfd_report::figure::{
    BoxMarker, BoxPlot, BoxSeries, EdgeStyle, Fit, Graph, GraphEdge, GraphNode, ImageMap, LegendPosition, MapCell,
    MapEllipse, MapGlyph, MapRegion, ScatterGroup, ScatterPlot,
};

use super::stats::{Pair, box_stats, correlation, fit_line, zone_values};
use crate::bnets::{Branch, LinkKind};
use crate::cba::classifier::GmmClassifier;
use crate::dbug::{Action, IMAGE_HEIGHT, IMAGE_WIDTH, Pixel, Zone};
use crate::experiment::ParticipantRecord;
use crate::intrl::{CELL, cell_origin};
use crate::users::Algorithm;

/// Whiskers at 1.5 IQR (the thesis's Figure 4.2 used 3 IQR, with dots between 3 and 5 IQR).
pub const WHISKER_IQR: f64 = 1.5;

/// Figure 4.2: % correct per action, one box per algorithm.
pub fn figure_4_2(study: &[ParticipantRecord], provenance: &Provenance) -> rlfd_report::Result<String> {
    let mut p = BoxPlot::new(
        format!("Figure 4.2: states with the correct action, per action ({} users)", study.len()),
        "Action (its zone)",
        "Correct (% of the zone's states)",
    );
    p.categories = Zone::ALL.iter().map(|z| z.correct_action().label().to_string()).collect();
    for a in Algorithm::ALL {
        p.series.push(BoxSeries {
            name: a.label().into(),
            boxes: Zone::ALL.iter().map(|&z| box_stats(&zone_values(study, a, z), WHISKER_IQR)).collect(),
        });
    }
    p.y_range = Some((-3.0, 103.0));
    p.to_svg(provenance)
}

/// Figures 4.4, 4.6 and 4.8, (a) or (b): accuracy against interactions or satisfaction.
pub fn scatter(
    study: &[ParticipantRecord],
    a: Algorithm,
    pair: Pair,
    thesis_r: f64,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let number = match a {
        Algorithm::IntRl => "4.4",
        Algorithm::BNets => "4.6",
        Algorithm::Cba => "4.8",
    };
    let part = if pair == Pair::Interactions { "a" } else { "b" };
    let x_label = match (pair, a) {
        (Pair::Satisfaction, _) => "Satisfaction (1 not at all … 4 very well)",
        (Pair::Interactions, Algorithm::IntRl) => "Rewards given",
        (Pair::Interactions, Algorithm::BNets) => "Demonstrations (START…DONE)",
        (Pair::Interactions, Algorithm::Cba) => "Demonstrations and corrections",
    };
    let points: Vec<(f64, f64)> = study.iter().map(|p| (pair.x(p, a), p.session(a).accuracy.overall)).collect();
    let r = correlation(study, a, pair);
    let r_text = r.map_or("r undefined".to_string(), |c| format!("r = {:.2}", c.r));
    let mut plot = ScatterPlot::new(
        format!("Figure {number}({part}): {} — {} ({r_text}; thesis {thesis_r})", a.label(), pair.label()),
        x_label,
        "Accuracy (% of all states)",
    );
    plot.groups.push(ScatterGroup {
        name: "users".into(),
        fit: fit_line(&points).map(|(slope, intercept)| Fit { slope, intercept, label: r_text.clone() }),
        points,
        labels: Vec::new(),
    });
    plot.y_range = Some((-3.0, 103.0));
    if pair == Pair::Satisfaction {
        plot.x_range = Some((0.5, 4.5));
    }
    // Ratings and counts are whole numbers and many users share them: each
    // point is spread sideways (at most a tenth of a rating, or a third of a
    // count) so ties show; the fit and r use the exact values.
    plot.jitter = (if pair == Pair::Satisfaction { 0.1 } else { 0.33 }, 0.0);
    plot.legend = LegendPosition::Auto;
    plot.to_svg(provenance)
}

/// The three zones as outlined regions.
fn zone_regions() -> Vec<MapRegion> {
    vec![
        MapRegion { rect: (0.0, 320.0, 0.0, 160.0), label: "wait zone".into(), category: 2 },
        MapRegion { rect: (220.0, 320.0, 160.0, 240.0), label: "wait".into(), category: 2 },
        MapRegion { rect: (120.0, 220.0, 160.0, 240.0), label: "pick-up zone".into(), category: 0 },
        MapRegion { rect: (0.0, 120.0, 160.0, 240.0), label: "sweep zone".into(), category: 1 },
    ]
}

fn action_categories() -> Vec<String> {
    Action::ALL.iter().map(|a| a.label().to_string()).collect()
}

/// Figure 4.3: an Int-RL policy: each untied cell's action as a triangle (tied cells left empty).
pub fn figure_4_3(
    part: &str,
    what: &str,
    p: &ParticipantRecord,
    policy: &[Option<Action>],
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let s = p.session(Algorithm::IntRl);
    let untied = policy.iter().filter(|a| a.is_some()).count();
    let mut m = ImageMap::new(
        format!(
            "Figure 4.3({part}): {what} Int-RL policy ({:.1} % correct, {untied} of 100 cells untied)",
            s.accuracy.overall
        ),
        (f64::from(IMAGE_WIDTH), f64::from(IMAGE_HEIGHT)),
    );
    m.categories = action_categories();
    m.regions = zone_regions();
    for (cell, a) in policy.iter().enumerate() {
        if let Some(a) = a {
            let o = cell_origin(cell);
            let (x, y) = (f64::from(o.x), f64::from(o.y));
            m.cells.push(MapCell { rect: (x, x + f64::from(CELL.0), y, y + f64::from(CELL.1)), category: a.index() });
            m.glyphs
                .push(MapGlyph { at: (x + f64::from(CELL.0) / 2.0, y + f64::from(CELL.1) / 2.0), category: a.index() });
        }
    }
    m.note = Some(format!(
        "study {}, user {} ({}):\n{} rewards, satisfaction {}",
        p.study,
        p.participant,
        p.traits.expertise.label(),
        s.interactions,
        s.satisfaction
    ));
    m.to_svg(provenance)
}

/// Figure 4.7: a CBA policy: the classifier's action on a 16-pixel lattice
/// (light cells) and every Gaussian's 2σ ellipse (1σ dashed).
pub fn figure_4_7(
    part: &str,
    what: &str,
    p: &ParticipantRecord,
    classifier: Option<&GmmClassifier>,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let s = p.session(Algorithm::Cba);
    let components: usize = classifier.map_or(0, |c| c.models.iter().map(|g| g.components.len()).sum());
    let mut m = ImageMap::new(
        format!("Figure 4.7({part}): {what} CBA policy ({:.1} % correct, {components} Gaussians)", s.accuracy.overall),
        (f64::from(IMAGE_WIDTH), f64::from(IMAGE_HEIGHT)),
    );
    m.categories = action_categories();
    m.regions = zone_regions();
    if let Some(c) = classifier {
        let c = c.refreshed();
        for y in (0..IMAGE_HEIGHT as u16).step_by(16) {
            for x in (0..IMAGE_WIDTH as u16).step_by(16) {
                let a = c.classify(Pixel::new(x + 8, y + 8).as_f64()).action;
                let (x, y) = (f64::from(x), f64::from(y));
                m.cells.push(MapCell { rect: (x, x + 16.0, y, y + 16.0), category: a.index() });
            }
        }
        for (a, g) in c.models.iter().enumerate() {
            for comp in &g.components {
                for (k, dashed) in [(2.0, false), (1.0, true)] {
                    let (radii, angle) = comp.ellipse(k);
                    m.ellipses.push(MapEllipse {
                        centre: (comp.mean[0], comp.mean[1]),
                        radii,
                        angle,
                        category: a,
                        dashed,
                    });
                }
            }
        }
    }
    let counts = match &s.details {
        crate::session::Details::Cba { counts, .. } => *counts,
        _ => [0; 3],
    };
    m.note = Some(format!(
        "study {}, user {} ({}): demonstrations\npick-up {}, sweep {}, wait {};\nsatisfaction {}{}",
        p.study,
        p.participant,
        p.traits.expertise.label(),
        counts[0],
        counts[1],
        counts[2],
        s.satisfaction,
        if classifier.is_none() { "\nno classifier: < 3 of an action" } else { "" }
    ));
    m.to_svg(provenance)
}

/// Figure 4.5: a behaviour network, one column per kept demonstration, from START to DONE.
pub fn figure_4_5(part: &str, what: &str, branches: &[Branch], provenance: &Provenance) -> rlfd_report::Result<String> {
    const MAX_ROWS: usize = 40;
    let mut g = Graph::new(format!("Figure 4.5({part}): {what}"));
    let middle = (branches.len().max(1) - 1) as f64 / 2.0;
    g.nodes.push(GraphNode { label: "START".into(), row: 0, lane: middle });
    let mut last_row = 0;
    let mut tails = Vec::new();
    let mut cut = false;
    for (lane, b) in branches.iter().enumerate() {
        let base = g.nodes.len();
        let shown = b.nodes.len().min(MAX_ROWS);
        cut |= shown < b.nodes.len();
        for (k, n) in b.nodes.iter().take(shown).enumerate() {
            g.nodes.push(GraphNode {
                label: format!("{}_{}", n.behavior.abbreviation(), n.id),
                row: k + 1,
                lane: lane as f64,
            });
            last_row = last_row.max(k + 1);
        }
        if shown > 0 {
            g.edges.push(GraphEdge { from: 0, to: base, style: EdgeStyle::Dotted });
            tails.push(base + shown - 1);
        }
        for l in b.drawn_links() {
            if l.from < shown && l.to < shown {
                let style = match l.kind {
                    LinkKind::Permanent => EdgeStyle::Solid,
                    LinkKind::Enabling => EdgeStyle::Dashed,
                    LinkKind::Ordering => EdgeStyle::Dotted,
                };
                g.edges.push(GraphEdge { from: base + l.from, to: base + l.to, style });
            }
        }
    }
    let done = g.nodes.len();
    g.nodes.push(GraphNode {
        label: if cut { "… DONE".into() } else { "DONE".into() },
        row: last_row + 1,
        lane: middle,
    });
    for t in tails {
        g.edges.push(GraphEdge { from: t, to: done, style: EdgeStyle::Dotted });
    }
    g.legend = vec![
        (EdgeStyle::Solid, "permanent".into()),
        (EdgeStyle::Dashed, "enabling".into()),
        (EdgeStyle::Dotted, "ordering".into()),
    ];
    g.width = 640;
    g.to_svg(provenance)
}

/// The six correlations over all studies, with the thesis's value and study 0's.
pub fn correlation_spread(
    values: &[[Vec<f64>; 2]; 3],
    thesis: &[[f64; 2]; 3],
    studies: usize,
    provenance: &Provenance,
) -> rlfd_report::Result<String> {
    let mut p = BoxPlot::new(
        format!("The six correlations over {studies} independent studies of 31 users"),
        "Algorithm",
        "Pearson's r (accuracy with …)",
    );
    p.categories = Algorithm::ALL.iter().map(|a| a.label().to_string()).collect();
    for (k, pair) in Pair::ALL.iter().enumerate() {
        p.series.push(BoxSeries {
            name: match pair {
                Pair::Interactions => "r with interactions".into(),
                Pair::Satisfaction => "r with satisfaction".into(),
            },
            boxes: (0..3)
                .map(|a| {
                    let v: Vec<f64> = values[a][k].iter().copied().filter(|x| x.is_finite()).collect();
                    box_stats(&v, WHISKER_IQR)
                })
                .collect(),
        });
        for a in 0..3 {
            p.markers.push(BoxMarker { category: a, series: k, value: thesis[a][k], label: "thesis".into() });
            if let Some(&v0) = values[a][k].first().filter(|v| v.is_finite()) {
                p.markers.push(BoxMarker { category: a, series: k, value: v0, label: "study 0".into() });
            }
        }
    }
    p.y_range = Some((-1.0, 1.0));
    p.to_svg(provenance)
}
