//! How the RE-IRL fit went, for both domains: θ over the scaled and the raw
//! features, whether the ascent converged, how far θ still moves, and the
//! dual objective's curve.

use rlfd_lfd::irl::{IrlFit, STABILITY_WINDOW};
use rlfd_report::figure::{LegendPosition, LineChart, Series, SeriesStyle};
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, Provenance};

use crate::shaping::IrlSettings;
use crate::shaping::inputs::IrlDraws;

/// The most points the objective's curve is drawn with.
const CURVE_POINTS: usize = 400;

/// One sentence on the fit: convergence, θ's size before normalisation and
/// its stability, and the settings.
pub fn fit_sentence(fit: &IrlFit, settings: &IrlSettings) -> String {
    let outcome = if fit.converged {
        format!(
            "the ascent converged after {} iterations (optimality residual {:.1e}, below the stopping tolerance {:.0e}); continuing it {STABILITY_WINDOW} more iterations moves no normalised weight by more than {:.1e}",
            fit.iterations, fit.residual, settings.tolerance, fit.stability
        )
    } else {
        format!(
            "the ascent did NOT converge within {} iterations (optimality residual {:.1e}, tolerance {:.0e}); over its last iterates a normalised weight still moved by {:.1e}",
            fit.iterations, fit.residual, settings.tolerance, fit.stability
        )
    };
    let bound = if fit.on_bound {
        format!(
            "The maximiser lies on the bound ‖θ‖ = {} (the expert's counts, relaxed by ε, lie outside what reweighting the baseline reaches, so the unbounded dual's direction is what is learned)",
            settings.norm_bound
        )
    } else {
        format!("The maximiser lies inside the bound ‖θ‖ ≤ {} (‖θ‖ = {:.4})", settings.norm_bound, fit.fitted_norm)
    };
    format!(
        "{}; {outcome}. The dual objective g rose from {:.4} at θ = 0 to {:.4}.",
        bound, fit.objective[0], fit.objective[fit.iterations]
    )
}

/// θ per feature: over the features scaled to their ranges (unit length) and
/// over the raw features (what R_IRL multiplies).
pub fn weights_table(id: &str, title: &str, names: &[&str], fit: &IrlFit) -> rlfd_report::Result<Table> {
    let mut t = Table::new(id, title, "Feature");
    t.columns = vec![ColumnGroup::new("θ (scaled features)"), ColumnGroup::new("Weight (raw feature)")];
    for ((name, scaled), raw) in names.iter().zip(&fit.scaled_weights).zip(&fit.weights) {
        t.rows.push(Row::new(
            *name,
            vec![
                Cell::ours_only(Num::new(*scaled, NumFormat::fixed(4))),
                Cell::ours_only(Num::new(*raw, NumFormat::fixed(4))),
            ],
        ));
    }
    t.notes = vec![
        "Features are divided by their ranges before the fit; θ is set to unit length over the scaled features, and the weight over a raw feature is θ divided by its range. Hoeffding's ε is scaled with the features.".into(),
    ];
    t.check()?;
    Ok(t)
}

/// θ per feature under the run's baseline draw and its spread over the
/// other draws (mean, SD, range).
pub fn draws_table(
    id: &str,
    title: &str,
    names: &[&str],
    fit: &IrlFit,
    draws: &IrlDraws,
) -> rlfd_report::Result<Table> {
    let n = draws.scaled_weights.len();
    let mut t = Table::new(id, title, "Feature");
    t.columns = ["θ (this run's draw)", "Mean", "SD", "Min", "Max"].into_iter().map(ColumnGroup::new).collect();
    for (j, name) in names.iter().enumerate() {
        let values: Vec<f64> = draws.scaled_weights.iter().map(|w| w[j]).collect();
        let mean = values.iter().sum::<f64>() / n as f64;
        let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0)).sqrt();
        let min = values.iter().copied().fold(f64::INFINITY, f64::min);
        let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let cell = |v: f64| Cell::Num(Num::new(v, NumFormat::fixed(4)));
        t.rows.push(Row::new(*name, vec![cell(fit.scaled_weights[j]), cell(mean), cell(sd), cell(min), cell(max)]));
    }
    t.notes = vec![format!(
        "θ over the scaled features at unit length. The other columns refit RE-IRL on the same demonstrations with {n} other draws of the uniform-policy baseline (each its own seed); no agent learns from them. SD with n − 1."
    )];
    t.check()?;
    Ok(t)
}

/// One sentence on the other draws: how many maximisers lie on the bound,
/// and what that says about the paper's (unbounded) dual.
pub fn draws_sentence(fit: &IrlFit, draws: &IrlDraws, settings: &IrlSettings) -> String {
    let n = draws.scaled_weights.len();
    let bound = if draws.on_bound == n {
        format!(
            "Under every one of the {n} other baseline draws the maximiser lies on the bound ‖θ‖ = {}{}: on these data the paper's dual, which has no bound, has no maximiser (g grows without limit along θ's direction), so the bounded maximiser's direction is what RE-IRL gives here.",
            settings.norm_bound,
            if fit.on_bound { ", as under the run's own" } else { " (under the run's own it lies inside)" }
        )
    } else {
        format!(
            "Under {} of the {n} other baseline draws the maximiser lies on the bound ‖θ‖ = {} (there the paper's unbounded dual has no maximiser); under the rest it lies inside.",
            draws.on_bound, settings.norm_bound
        )
    };
    let converged = if draws.converged == n {
        String::new()
    } else {
        format!(" {} of the {n} ascents did not converge.", n - draws.converged)
    };
    format!("{bound}{converged}")
}

/// The dual objective per iteration.
pub fn objective_figure(file: &str, title: &str, fit: &IrlFit, provenance: &Provenance) -> rlfd_report::Result<Block> {
    let n = fit.objective.len();
    let stride = n.div_ceil(CURVE_POINTS).max(1);
    let mut points: Vec<(f64, f64)> = (0..n).step_by(stride).map(|k| (k as f64, fit.objective[k])).collect();
    if !(n - 1).is_multiple_of(stride) {
        points.push(((n - 1) as f64, fit.objective[n - 1]));
    }
    let mut chart = LineChart::new(title, "Iteration", "Dual objective g(θ)");
    chart.series.push(Series { name: "g(θ_k)".into(), points, band: None, style: SeriesStyle::Line });
    chart.legend = LegendPosition::Auto;
    Ok(Block::Figure {
        file: file.into(),
        caption: format!("{title}: the dual objective of RE-IRL at each iteration of the ascent."),
        svg: chart.to_svg(provenance)?,
    })
}
