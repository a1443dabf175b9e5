//! Prints the Maze demonstrator's calibration: for a range of slip
//! probabilities, the statistics of 2,000 simulated demonstrations (mean and
//! sd of the length, path ratio, suboptimal share, wall touches), then the
//! slip the calibration picks. `cargo run --release -p ch6-irl-shaping --example calibrate_maze_demonstrator`.

use ch6_irl_shaping::maze::demonstrator::{CALIBRATION_SEED, MazeDemonstrator, calibrate_slip, measure};
use rlfd_rl::random::seeded;

fn main() {
    println!("slip    mean length  sd      longer than optimal  suboptimal actions  wall touches");
    for slip in [0.0, 0.03, 0.05, 0.06, 0.065, 0.07, 0.08, 0.1] {
        let model = MazeDemonstrator::with_slip(slip);
        let mut rng = seeded(CALIBRATION_SEED);
        let demos: Vec<_> = (0..2000).map(|_| model.demonstrate(&mut rng)).collect();
        let s = measure(&demos);
        println!(
            "{slip:<7} {:<12.1} {:<7.2} {:<20} {:<19} {}",
            s.mean_length,
            s.sd_length,
            format!("{:.1} %", s.longer_than_optimal_pct),
            format!("{:.2} %", s.suboptimal_actions_pct),
            s.wall_touches
        );
    }
    println!("calibrated slip (closest mean to 337.5 over 4,000 demonstrations): {}", calibrate_slip(4000));
}
