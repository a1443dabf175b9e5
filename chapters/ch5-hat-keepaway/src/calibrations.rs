//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the
//! teachers' perception noise (and how much longer Subject A holds in the middle of the field), fitted on what
//! the thesis reports of their demonstrations only.

use std::fmt::Write;

use rlfd_harness::Calibration;

use crate::teachers::Teacher;
use crate::teachers::calibration::{CALIBRATION_EPISODES, calibrate, model_mean_seconds, rule_properties};

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![Calibration {
        model: "keepaway-teachers",
        what: "Subjects A, B and C's perception noise and how much longer A holds in the middle of the field, fitted on the thesis's mean demonstration durations and A's rule list (four rules, 87 % CV); B Fast and B Limited shown as out-of-sample checks",
        run: teachers,
    }]
}

/// The fitted values and each model's demonstrations beside the thesis's
/// (the shipped constants are what this prints; an ignored test checks it).
fn teachers() -> String {
    let c = calibrate();
    let mut out = format!(
        "perception noise A {} m, B {} m, C {} m; A's threshold rise in the middle {}\n",
        c.noise[0], c.noise[1], c.noise[2], c.a_centre_extra
    );
    for teacher in Teacher::ALL {
        let m = c.model(teacher);
        let _ = write!(
            out,
            "{:<18} model {:>6.2} s   thesis {:>5.1} s",
            teacher.label(),
            model_mean_seconds(&m, CALIBRATION_EPISODES),
            teacher.thesis_mean_seconds()
        );
        if teacher == Teacher::A {
            let (cv, rules, field) = rule_properties(&m);
            let _ = write!(
                out,
                "   JRip: {rules:.2} rules ({field:.2} on state_0), CV {:.1} % (thesis: 3 rules, over 87 %)",
                100.0 * cv
            );
        }
        if matches!(teacher, Teacher::BFast | Teacher::BLimited) {
            out.push_str("   (not fitted)");
        }
        out.push('\n');
    }
    out
}
