//! The simulator's cost alone, as `cargo xtask bench` measures it (keepers
//! choosing uniformly at random, whole episodes of 3 vs 2 on 20 m): runs at
//! least CYCLES cycles from SEED and prints the cycles run, the wall time
//! and the rate. Small enough to profile under callgrind, where the count of
//! instructions per cycle is the machine-independent measure.
//!
//! usage: `cargo run --release -p rlfd-keepaway --example cycles -- [CYCLES] [SEED] [far-velocity-always]`
//! (default 360 000 cycles, ten simulated hours, seed 7; `far-velocity-always`
//! gives every see the ball's velocity, as before
//! `KeepawayParams::drop_far_ball_velocity`, to measure what that costs).

use rlfd_env::random::{below, seeded};
use rlfd_keepaway::{Keepaway, KeepawayParams, KeeperAction};

fn main() {
    let mut args = std::env::args().skip(1);
    let cycles: u64 = args.next().map_or(Ok(360_000), |a| a.parse()).unwrap_or_else(|_| {
        eprintln!("error: CYCLES must be a whole number");
        std::process::exit(2)
    });
    let seed: u64 = args.next().map_or(Ok(7), |a| a.parse()).unwrap_or_else(|_| {
        eprintln!("error: SEED must be a whole number");
        std::process::exit(2)
    });
    let far_velocity_always = args.next().is_some_and(|a| a == "far-velocity-always");
    let start = std::time::Instant::now();
    let params = KeepawayParams { drop_far_ball_velocity: !far_velocity_always, ..KeepawayParams::benchmark() };
    let mut game = Keepaway::new(params).expect("the benchmark parameters are valid");
    let mut rng = seeded(seed);
    let (mut done, mut episodes) = (0u64, 0u64);
    while done < cycles {
        let (d, _) = game.play_episode(&mut rng, |_, _, rng| KeeperAction::ALL[below(rng, 3)]);
        done += u64::from(d);
        episodes += 1;
    }
    let secs = start.elapsed().as_secs_f64();
    println!("{done} cycles, {episodes} episodes, {secs:.3} s, {:.3} M cycles/s", done as f64 / secs / 1e6);
}
