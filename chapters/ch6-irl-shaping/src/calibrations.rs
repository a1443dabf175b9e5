//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the Maze
//! demonstrator's slip (on the thesis's mean demonstration length) and the
//! Mario demonstrator's slip and pause (on the thesis's demonstrator score
//! and observation count). Neither looks at a learner.

use std::fmt::Write;

use rlfd_harness::Calibration;
use rlfd_rl::random::seeded;

use crate::mario::LevelParams;
use crate::mario::demonstrator::{CALIBRATION_DEMOS, calibrate};
use crate::maze::demonstrator::{CALIBRATION_SEED, MazeDemonstrator, calibrate_slip, measure};

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![
        Calibration {
            model: "maze-demonstrator",
            what: "the Maze demonstrator's slip probability, fitted on the thesis's mean demonstration length of 337.5 steps",
            run: maze_demonstrator,
        },
        Calibration {
            model: "mario-demonstrator",
            what: "the Mario demonstrator's slip and pause, fitted jointly on the thesis's demonstrator score (1,224) and 953 observations",
            run: mario_demonstrator,
        },
    ]
}

/// For a range of slip probabilities, the statistics of 2,000 simulated
/// demonstrations, then the slip the calibration picks.
fn maze_demonstrator() -> String {
    let mut out = String::from("slip    mean length  sd      longer than optimal  suboptimal actions  wall touches\n");
    for slip in [0.0, 0.03, 0.05, 0.06, 0.065, 0.07, 0.08, 0.1] {
        let model = MazeDemonstrator::with_slip(slip);
        let mut rng = seeded(CALIBRATION_SEED);
        let demos: Vec<_> = (0..2000).map(|_| model.demonstrate(&mut rng)).collect();
        let s = measure(&demos);
        let _ = writeln!(
            out,
            "{slip:<7} {:<12.1} {:<7.2} {:<20} {:<19} {}",
            s.mean_length,
            s.sd_length,
            format!("{:.1} %", s.longer_than_optimal_pct),
            format!("{:.2} %", s.suboptimal_actions_pct),
            s.wall_touches
        );
    }
    let _ =
        writeln!(out, "calibrated slip (closest mean to 337.5 over 4,000 demonstrations): {}", calibrate_slip(4000));
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
