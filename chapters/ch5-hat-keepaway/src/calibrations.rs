//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the
//! teachers' reaction delay and perception noise, fitted on their
//! demonstrations' mean durations only.

use std::fmt::Write;

use rlfd_harness::Calibration;

use crate::teachers::Teacher;
use crate::teachers::calibration::{CALIBRATION_EPISODES, calibrate, model_mean_seconds};

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![Calibration {
        model: "keepaway-teachers",
        what: "Subjects A, B and C's reaction delay and perception noise, fitted on the thesis's mean demonstration durations",
        run: teachers,
    }]
}

/// The fitted values and each model's mean demonstration duration beside the
/// thesis's (the shipped constants are what this prints; a unit test checks it).
fn teachers() -> String {
    let c = calibrate(CALIBRATION_EPISODES);
    let mut out = format!(
        "reaction delay {} s; perception noise A {} m, B {} m, C {} m\n",
        c.reaction_delay_s, c.noise[0], c.noise[1], c.noise[2]
    );
    for teacher in Teacher::ALL {
        let _ = writeln!(
            out,
            "{:<18} model {:>6.2} s   thesis {:>5.1} s",
            teacher.label(),
            model_mean_seconds(&c.model(teacher), CALIBRATION_EPISODES),
            teacher.thesis_mean_seconds()
        );
    }
    out
}
