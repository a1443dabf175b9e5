//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the Maze
//! demonstrator's slip (on the thesis's mean demonstration length) and the
//! Mario demonstrator's slip and pause (on the thesis's demonstrator score
//! and observation count). Neither looks at a learner.

use std::fmt::Write;

use rlfd_harness::Calibration;

use crate::mario::LevelParams;
use crate::mario::demonstrator::{CALIBRATION_DEMOS, calibrate};
use crate::maze::demonstrator;

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![
        Calibration {
            model: "maze-demonstrator",
            what: "the Maze demonstrator's slip and drift, fitted jointly on the thesis's mean demonstration length (337.5 steps) and its 1.5 % of suboptimal actions (read as moves later undone)",
            run: maze_demonstrator,
        },
        Calibration {
            model: "mario-demonstrator",
            what: "the Mario demonstrator's slip and pause, fitted jointly on the thesis's demonstrator score (1,224) and 953 observations",
            run: mario_demonstrator,
        },
    ]
}

/// Every grid point of the joint fit of slip and drift, then the pair it picks.
fn maze_demonstrator() -> String {
    let (best, points) = demonstrator::calibrate(demonstrator::CALIBRATION_DEMOS);
    let mut out = String::from("slip    drift   mean length  undone moves  error\n");
    for p in points {
        let _ = writeln!(
            out,
            "{:<7} {:<7} {:<12.1} {:<13} {:.5}",
            p.slip,
            p.drift,
            p.mean_length,
            format!("{:.2} %", p.undone_moves_pct),
            p.error
        );
    }
    let _ = writeln!(
        out,
        "calibrated (closest to 337.5 steps and 1.5 % undone moves over 2,000 demonstrations): slip {}, drift {}",
        best.0, best.1
    );
    out
}

/// Every grid point of the joint fit, then the model it picks.
fn mario_demonstrator() -> String {
    let (model, trace) = calibrate(LevelParams::EXPERIMENT, CALIBRATION_DEMOS);
    let mut out = String::new();
    for p in trace {
        let _ = writeln!(
            out,
            "slip {:.3} pause {:.3}: mean score {:.1}, E[10th longest] {:.1}",
            p.model.slip, p.model.pause_start, p.mean_score, p.expected_tenth_longest
        );
    }
    let _ = writeln!(out, "calibrated: {model:?}");
    out
}
