//! The Maze baseline's paper trials, by the library's SARSA(λ) or by the
//! reference kernel (`maze::kernel`), for profiling and for comparing their
//! instruction counts (issue 30): both play the same episodes bit for bit.
//!
//! ```text
//! valgrind --tool=callgrind target/release/examples/maze_sarsa library 3
//! valgrind --tool=callgrind target/release/examples/maze_sarsa kernel 3
//! ```
//!
//! Prints the agent steps played (the same for both).

use ch6_irl_shaping::maze::kernel;
use ch6_irl_shaping::maze::params::MazeParams;
use ch6_irl_shaping::shaping::{Agent, run_trial};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let which = args.first().map_or("library", String::as_str);
    let trials = match args.get(1).map_or(Ok(1), |s| s.parse::<u64>()) {
        Ok(n) => n,
        Err(_) => {
            eprintln!("maze_sarsa: the trial count must be a whole number, not {:?}", args[1]);
            std::process::exit(2);
        }
    };
    let params = MazeParams::paper();
    let mut steps = 0u64;
    for seed in 0..trials {
        let trial_steps = match which {
            "library" => run_trial(Agent::Baseline, &params, None, seed).steps,
            "kernel" => kernel::run_trial(&params, seed).1,
            other => {
                eprintln!("maze_sarsa: the learner is `library` or `kernel`, not {other:?}");
                std::process::exit(2);
            }
        };
        steps += trial_steps.iter().map(|&s| u64::from(s)).sum::<u64>();
    }
    println!("{steps}");
}
