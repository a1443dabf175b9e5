//! Reruns the teachers' calibration (`teachers::calibration::calibrate`) and
//! prints the fitted values and each model's mean demonstration duration
//! beside the thesis's: `cargo run --release -p ch5-hat-keepaway --example calibrate_teachers`.
//! The shipped constants are what this prints; a unit test checks it.

use ch5_hat_keepaway::teachers::Teacher;
use ch5_hat_keepaway::teachers::calibration::{CALIBRATION_EPISODES, calibrate, model_mean_seconds};

fn main() {
    let c = calibrate(CALIBRATION_EPISODES);
    println!(
        "reaction delay {} s; perception noise A {} m, B {} m, C {} m",
        c.reaction_delay_s, c.noise[0], c.noise[1], c.noise[2]
    );
    for teacher in Teacher::ALL {
        println!(
            "{:<18} model {:>6.2} s   thesis {:>5.1} s",
            teacher.label(),
            model_mean_seconds(&c.model(teacher), CALIBRATION_EPISODES),
            teacher.thesis_mean_seconds()
        );
    }
}
