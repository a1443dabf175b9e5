//! Quick speed check of Mario (one core): the simulator alone (ticks per
//! second) and Q(λ) with tile coding learning on it (agent steps per second):
//! `cargo run --release -p ch6-irl-shaping --example mario_speed [episodes]`.
//! The criterion bench `mario` measures the same with statistics.

use ch6_irl_shaping::mario_agents::{MarioAgent, MarioParams, run_trial_episodes};

fn main() {
    let episodes: usize = std::env::args().nth(1).map_or(100, |s| s.parse().expect("a number of episodes"));
    let n = 5_000_000;
    let t = std::time::Instant::now();
    let ticks = ch6_irl_shaping::mario::random_ticks(1, n);
    let s = t.elapsed().as_secs_f64();
    println!("simulator: {ticks} ticks in {s:.2} s: {:.2} M ticks/s", ticks as f64 / s / 1e6);
    let params = MarioParams { episodes, ..MarioParams::paper() };
    let t = std::time::Instant::now();
    let trial = run_trial_episodes(MarioAgent::QLambda, &params, None, 1);
    let s = t.elapsed().as_secs_f64();
    let steps = trial.total_steps();
    println!(
        "q-lambda: {episodes} episodes, {steps} steps ({:.0} per episode) in {s:.2} s: {:.2} M steps/s",
        steps as f64 / episodes as f64,
        steps as f64 / s / 1e6
    );
}
