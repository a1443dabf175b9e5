//! Times `n` studies of 31 users (paper-scale sessions) through the harness
//! with 2 threads into a scratch store, and extrapolates to the paper
//! scale's 100 studies: `cargo run --release -p ch4-dbug-study --example time_studies [n]`.

use ch4_dbug_study::experiment::{IdealParams, StudyParams, plan_ideal, plan_study, run_ideal, run_study};
use rlfd_harness::{ResultStore, RunContext, RunOptions, Scale};

fn main() {
    let n: u32 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(10);
    let dir = std::env::temp_dir().join(format!("rlfd-ch4-timing-{}", std::process::id()));
    let options = RunOptions::new(ResultStore::new(&dir), 2);
    let ctx = RunContext::new(20160501, Scale::Paper);
    let started = std::time::Instant::now();
    run_study(&plan_study(&ctx, &StudyParams { studies: n, ..StudyParams::paper() }).unwrap(), &options).unwrap();
    let study = started.elapsed().as_secs_f64();
    let trials = options.tally.totals().0;
    let started = std::time::Instant::now();
    run_ideal(&plan_ideal(&ctx, &IdealParams::paper()).unwrap(), &options).unwrap();
    let ideal = started.elapsed().as_secs_f64();
    println!(
        "{n} studies ({} trials): {study:.1} s wall on 2 threads; ideal teacher (30 sessions): {ideal:.1} s; paper scale (100 studies) ≈ {:.0} s",
        trials,
        study * 100.0 / f64::from(n) + ideal
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
