//! Reruns the Mario demonstrator's calibration (and, with `difficulty`, the
//! difficulty table behind the levels' difficulty), printing every grid
//! point: `cargo run --release -p ch6-irl-shaping --example mario_demonstrator [difficulty]`.

use ch6_irl_shaping::mario::LevelParams;
use ch6_irl_shaping::mario::demonstrator::{CALIBRATION_DEMOS, calibrate, difficulty_table};

fn main() {
    let params = LevelParams::EXPERIMENT;
    if std::env::args().any(|a| a == "difficulty") {
        for (d, p) in difficulty_table(params.width, 0..=4, 200) {
            println!("difficulty {d}: mean score {:.1}, E[10th longest] {:.1}", p.mean_score, p.expected_tenth_longest);
        }
    }
    let (model, trace) = calibrate(params, CALIBRATION_DEMOS);
    for p in trace {
        println!(
            "slip {:.3} pause {:.3}: mean score {:.1}, E[10th longest] {:.1}",
            p.model.slip, p.model.pause_start, p.mean_score, p.expected_tenth_longest
        );
    }
    println!("calibrated: {model:?}");
}
