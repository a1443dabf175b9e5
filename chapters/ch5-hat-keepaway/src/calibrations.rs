//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the
//! how much longer Subject A holds in the middle of the field, fitted on
//! what the thesis reports of its demonstrations only, and, as a diagnostic
//! feeding no run, each teacher's mean duration against a perception noise
//! (the noise is declared, not fitted: [`crate::teachers::calibration`]).

use std::fmt::Write;

use rlfd_harness::{Calibration, Reading};

use crate::readings;
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

/// The fitted value and each model's demonstrations beside the thesis's,
/// under each level of the `bc-styles` reading, with B's handicapped
/// durations as fractions of B's (the inputs behind that reading's
/// default), and the noise diagnostic (the shipped constant is what this
/// prints; an ignored test checks it).
fn teachers() -> String {
    let c = calibrate();
    let mut out = format!(
        "A's threshold rise in the middle {} (fitted); perception noise {PERCEPTION_NOISE} m for every teacher (declared)\n",
        c.a_centre_extra
    );
    let default = readings::frequent_passer(&Reading::defaults());
    for level in readings::BC_STYLES.levels {
        let passer = level.value;
        let _ = writeln!(out, "bc-styles = {}{}", level.name, if passer == default { " (default)" } else { "" });
        let mut means = [0.0; 5];
        for (i, teacher) in Teacher::ALL.into_iter().enumerate() {
            let m = c.model(teacher, passer);
            means[i] = model_mean_seconds(&m, CALIBRATION_EPISODES);
            let _ = write!(
                out,
                "  {:<18} model {:>6.2} s   thesis {:>5.1} s",
                teacher.label(),
                means[i],
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
                let _ = write!(
                    out,
                    "   of B's: {:.2} (thesis {:.2}; not fitted)",
                    means[i] / means[1],
                    teacher.thesis_mean_seconds() / Teacher::B.thesis_mean_seconds()
                );
            }
            out.push('\n');
        }
    }
    let _ = writeln!(
        out,
        "diagnostic, feeding no run: mean duration (s) against perception noise (m), bc-styles at its default"
    );
    for teacher in [Teacher::A, Teacher::B, Teacher::C] {
        let _ = write!(out, "  {:<18}", teacher.label());
        for (noise, seconds) in noise_curve(teacher, default) {
            let _ = write!(out, " {noise:.1}:{seconds:.2}");
        }
        out.push('\n');
    }
    out
}
