//! Where each of the ten Mario demonstrations ends: its outcome, how far
//! right Mario got (cells), and how many of its last ticks made no new
//! progress (a stall shows as a long tail at one place). For the review's
//! question whether a timeout is slowness or a trap.
//!
//! ```text
//! cargo run --release -p ch6-irl-shaping --example demo_ends [-- SEED]
//! ```

use ch6_irl_shaping::mario::experiment::demonstrations;
use ch6_irl_shaping::mario::params::MarioParams;

fn main() {
    let seed = match std::env::args().nth(1).map_or(Ok(rlfd_harness::THESIS_MASTER_SEED), |s| s.parse::<u64>()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("demo_ends: the seed must be a whole number ({e})");
            std::process::exit(2);
        }
    };
    let demos = demonstrations(seed, &MarioParams::paper());
    println!("demo,outcome,timed_out,ticks,score,farthest_cell,final_cell,ticks_since_farthest,stuck");
    for (k, d) in demos.episodes.iter().enumerate() {
        let cell = |x: f32| (x / 16.0) as i32;
        let (mut best, mut at) = (f32::MIN, 0);
        for (t, &(x, _)) in d.path.iter().enumerate() {
            if x >= best + 16.0 {
                best = x;
                at = t;
            }
        }
        let last = d.path.last().map_or(0.0, |p| p.0);
        println!(
            "{},{:?},{},{},{},{},{},{},{}",
            k + 1,
            d.outcome,
            d.timed_out(),
            d.len(),
            d.score,
            cell(best),
            cell(last),
            d.path.len() - 1 - at,
            d.stuck
        );
    }
}
