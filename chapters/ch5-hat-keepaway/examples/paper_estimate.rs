//! Estimates the paper scale's cost from a fraction of it: one trial of
//! every learning condition at the thesis's length (30 simulated hours,
//! 1,000 evaluation episodes), timed on this machine, then scaled to the
//! paper's 10 trials per condition on `--jobs` cores. Also prints each
//! trial's final reward, as a preview (one trial, not a result).
//! `cargo run --release -p ch5-hat-keepaway --example paper_estimate [jobs]`.

use std::time::Instant;

use ch5_hat_keepaway::experiment::Condition;
use ch5_hat_keepaway::inputs::prepare;
use ch5_hat_keepaway::learners::{TrialParams, run_learning_trial};
use ch5_hat_keepaway::report::metrics::trial_metrics;
use ch5_hat_keepaway::{Ch5Params, Experiment};

fn main() {
    let jobs: f64 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(2.0);
    let params = Ch5Params::paper();
    let start = Instant::now();
    let passer = ch5_hat_keepaway::readings::frequent_passer(&rlfd_harness::Reading::defaults());
    let demos = prepare(20160501, passer).expect("demonstrations");
    let setup = start.elapsed().as_secs_f64();
    let mut conditions: Vec<Condition> = Vec::new();
    for e in Experiment::ALL {
        for c in Condition::of(e) {
            if !conditions.iter().any(|d| d.slug() == c.slug()) {
                conditions.push(c);
            }
        }
    }
    let mut total = 0.0;
    for c in &conditions {
        let trial = TrialParams {
            hours: params.hours,
            eval_episodes: params.eval_episodes,
            greedy_episodes: params.greedy_episodes,
            learner: params.learner.clone(),
            method: c.method,
        };
        let rules = c.set.map(|s| &demos.get(s).rules);
        let t = Instant::now();
        let result = run_learning_trial(&trial, rules, 1).expect("valid");
        let secs = t.elapsed().as_secs_f64();
        total += secs;
        let m = trial_metrics(&result, params.window, params.hours);
        println!(
            "{:<28} {:>6.2} s  ({} episodes; initial {:.2} s, final {:.2} s, total {:.0})",
            c.slug(),
            secs,
            result.durations.len(),
            m.initial,
            m.final_reward,
            m.total
        );
    }
    let trials = f64::from(params.trials);
    println!(
        "setup {setup:.1} s; one trial of each of {} conditions {total:.1} s; paper scale ≈ {:.0} s of CPU, ≈ {:.0} s wall on {jobs} cores",
        conditions.len(),
        setup + trials * total,
        setup + trials * total / jobs
    );
}
