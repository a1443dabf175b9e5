//! Q(λ) with 32 hashed tilings learning `episodes` episodes at the paper's
//! parameters from a new learner (the `cargo xtask bench` `q-lambda`
//! workload, one trial), and prints its agent steps, for profiling:
//! `valgrind --tool=callgrind target/release/examples/q_lambda_steps 3 20`.

use ch6_irl_shaping::mario::params::{MarioParams, run_trial};
use ch6_irl_shaping::shaping::Agent;

fn main() {
    let mut args = std::env::args().skip(1);
    let mut number = |default: u64| -> Result<u64, String> {
        args.next().map_or(Ok(default), |s| s.parse::<u64>().map_err(|_| format!("not a whole number: {s}")))
    };
    let (seed, episodes) = match (number(3), number(20)) {
        (Ok(s), Ok(e)) => (s, e),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("error: {e} (usage: q_lambda_steps [SEED] [EPISODES])");
            std::process::exit(2);
        }
    };
    let params = MarioParams { episodes: episodes as usize, ..MarioParams::paper() };
    println!("{} steps", run_trial(Agent::Baseline, &params, None, seed).total_steps());
}
