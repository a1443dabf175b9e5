//! The chapter's calibrations, rerun by `cargo xtask calibrate`: the Nao's
//! action durations, fitted on the thesis's 9.8 s per action only.

use std::fmt::Write;

use rlfd_harness::Calibration;
use rlfd_rl::random::seeded;

use crate::nao::timing::{
    CALIBRATION_OBJECTS, CALIBRATION_SEED, THESIS_MEAN_ACTION_SECONDS, UNIT_SECONDS, calibrate_unit, expert_mean_units,
};
use crate::nao::{Action, Durations};

/// Every calibration of the chapter.
pub fn all() -> Vec<Calibration> {
    vec![Calibration {
        model: "nao-durations",
        what: "the unit length of the Nao's action durations, fitted so that a correct sorting averages the thesis's 9.8 s per action",
        run: action_durations,
    }]
}

/// The nominal units of each action, the mean units per action of a
/// correct sorting (the scripted expert's plan over many objects), the unit
/// length that makes that mean 9.8 s, and the seconds per action.
fn action_durations() -> String {
    let nominal = Durations::nominal();
    let mean = expert_mean_units(&nominal, CALIBRATION_OBJECTS, &mut seeded(CALIBRATION_SEED));
    let mut out = format!("mean units per action of a correct sorting ({CALIBRATION_OBJECTS} objects): {mean:.4}\n");
    let unit = calibrate_unit(CALIBRATION_OBJECTS);
    let _ =
        writeln!(out, "unit = {THESIS_MEAN_ACTION_SECONDS} s / {mean:.4} = {unit:.6} s (shipped: {UNIT_SECONDS:.6} s)");
    let d = Durations { unit_seconds: unit, ..nominal };
    for a in Action::ALL {
        let _ = writeln!(out, "{:<12} {:>4.1} units {:>6.2} s", a.name(), d.units(a), d.seconds(a));
    }
    out
}
