//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the
//! how much longer Subject A holds in the middle of the field, fitted on
//! what the thesis reports of its demonstrations only, and, as a diagnostic
//! feeding no run, each teacher's mean duration against a perception noise
//! (the noise is declared, not fitted: [`crate::teachers::calibration`]).

use std::fmt::Write;

use rlfd_harness::Calibration;

use crate::teachers::Teacher;
use crate::teachers::calibration::{
    CALIBRATION_EPISODES, PERCEPTION_NOISE, calibrate, model_mean_seconds, noise_curve, rule_properties,
};

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![Calibration {
        model: "keepaway-teachers",
        what: "How much longer Subject A holds in the middle of the field, fitted on A's mean demonstration duration and rule list (four rules, 87 % CV), at the declared perception noise; B Fast and B Limited shown as out-of-sample checks; a diagnostic of each teacher's duration against perception noise (feeding no run)",
        run: teachers,
    }]
}

/// The fitted values and each model's demonstrations beside the thesis's
/// (the shipped constants are what this prints; an ignored test checks it).
fn teachers() -> String {
    let c = calibrate();
    let mut out = format!(
        "A's threshold rise in the middle {} (fitted); perception noise {PERCEPTION_NOISE} m for every teacher (declared)\n",
        c.a_centre_extra
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
    out.push_str("diagnostic, feeding no run: mean duration (s) against perception noise (m)\n");
    for teacher in [Teacher::A, Teacher::B, Teacher::C] {
        let _ = write!(out, "{:<18}", teacher.label());
        for (noise, seconds) in noise_curve(teacher) {
            let _ = write!(out, " {noise:.1}:{seconds:.2}");
        }
        out.push('\n');
    }
    out
}
