//! Q(λ) with 32 hashed tilings at the paper's parameters, as `cargo xtask
//! bench` runs it, for profiling. Without `WARM`: a new learner's trial of
//! `EPISODES` episodes (the `q-lambda` workload). With `WARM`: a learner that
//! has played `WARM` episodes plays `EPISODES` more (the `q-lambda-warm`
//! workload; the bench's is `WARM` = 2,000 from the thesis's master seed);
//! only those run inside `measured`, so callgrind can collect just them:
//!
//! ```text
//! valgrind --tool=callgrind target/release/examples/q_lambda_steps 3 20
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*measured*' \
//!     target/release/examples/q_lambda_steps 20160501 20 2000
//! ```

use ch6_irl_shaping::mario::params::{MarioParams, run_trial};
use ch6_irl_shaping::shaping::Agent;
use ch6_irl_shaping::shaping::agents::Continuing;

#[inline(never)]
fn measured(warm: &mut Continuing<MarioParams>, episodes: usize) -> u64 {
    warm.episodes(episodes)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mut number = |default: Option<u64>| -> Result<Option<u64>, String> {
        args.next().map_or(Ok(default), |s| s.parse::<u64>().map(Some).map_err(|_| format!("not a whole number: {s}")))
    };
    let (seed, episodes, warm) = match (number(Some(3)), number(Some(20)), number(None)) {
        (Ok(Some(s)), Ok(Some(e)), Ok(w)) => (s, e as usize, w),
        (Err(e), ..) | (_, Err(e), _) | (.., Err(e)) => {
            eprintln!("error: {e} (usage: q_lambda_steps [SEED] [EPISODES] [WARM])");
            std::process::exit(2);
        }
        _ => unreachable!("defaults are given"),
    };
    let steps = match warm {
        None => {
            let params = MarioParams { episodes, ..MarioParams::paper() };
            run_trial(Agent::Baseline, &params, None, seed).total_steps()
        }
        Some(w) => {
            let mut learner = Continuing::new(&MarioParams::paper(), seed);
            learner.episodes(w as usize);
            measured(&mut learner, episodes)
        }
    };
    println!("{steps} steps");
}
