//! Prints the time model's calibration: the nominal units of each action,
//! the mean units per action of a correct sorting (the scripted expert's
//! plan over many objects), the unit length that makes that mean 9.8 s, and
//! the resulting seconds per action. Nothing here looks at a learner.
//! `cargo run --release -p ch3-interactive-rl --example calibrate_action_durations`.

use ch3_interactive_rl::nao::timing::{
    CALIBRATION_OBJECTS, CALIBRATION_SEED, THESIS_MEAN_ACTION_SECONDS, UNIT_SECONDS, calibrate_unit, expert_mean_units,
};
use ch3_interactive_rl::nao::{Action, Durations};
use rlfd_rl::random::seeded;

fn main() {
    let nominal = Durations::nominal();
    let mean = expert_mean_units(&nominal, CALIBRATION_OBJECTS, &mut seeded(CALIBRATION_SEED));
    println!("mean units per action of a correct sorting ({CALIBRATION_OBJECTS} objects): {mean:.4}");
    let unit = calibrate_unit(CALIBRATION_OBJECTS);
    println!("unit = {THESIS_MEAN_ACTION_SECONDS} s / {mean:.4} = {unit:.6} s (shipped: {UNIT_SECONDS:.6} s)");
    let d = Durations { unit_seconds: unit, ..nominal };
    for a in Action::ALL {
        println!("{:<12} {:>4.1} units {:>6.2} s", a.name(), d.units(a), d.seconds(a));
    }
}
