//! `bench`: whole-domain speed, one line per domain and agent, measured on
//! one thread (`criterion` benches in each crate measure the kernels).
//!
//! Each line runs the work in five windows and prints the best window's rate
//! and the median: on a shared or virtual machine the best window is the
//! closest to what the code does, the median to what a run will see.

use std::time::Instant;

use anyhow::Result;
use ch6_irl_shaping::agents::{MazeAgent, MazeParams, run_trial};
use ch6_irl_shaping::experiment::{DemonstrationSource, demonstrations};
use ch6_irl_shaping::inputs::prepare;
use ch6_irl_shaping::maze::random_walk_steps;

use crate::cli::DEFAULT_SEED;

const WINDOWS: usize = 5;

/// Runs `work` (returning steps done) repeatedly for `budget` seconds per
/// window, `WINDOWS` times; returns the rates (steps/s) sorted.
fn measure(budget: f64, mut work: impl FnMut(u64) -> u64) -> Vec<f64> {
    let mut seed = 0;
    let mut rates: Vec<f64> = (0..WINDOWS)
        .map(|_| {
            let (mut steps, start) = (0u64, Instant::now());
            while start.elapsed().as_secs_f64() < budget {
                steps += work(seed);
                seed += 1;
            }
            steps as f64 / start.elapsed().as_secs_f64()
        })
        .collect();
    rates.sort_by(f64::total_cmp);
    rates
}

fn line(domain: &str, what: &str, rates: &[f64]) {
    let best = rates[rates.len() - 1];
    let median = rates[rates.len() / 2];
    println!(
        "{domain:<6} {what:<14} {:>7.2}M steps/s  (median {:.2}M over {} windows)",
        best / 1e6,
        median / 1e6,
        rates.len()
    );
}

pub fn run(quick: bool) -> Result<()> {
    let budget = if quick { 0.05 } else { 0.4 };
    line("maze", "simulator", &measure(budget, |seed| random_walk_steps(seed, 100_000)));

    // Each agent learning: whole trials of the paper's parameters.
    let demos = demonstrations(DEFAULT_SEED, &DemonstrationSource::Synthetic)?;
    let params = MazeParams::paper();
    let inputs = prepare(DEFAULT_SEED, &params, &demos.set)?;
    for agent in MazeAgent::ALL {
        let rates = measure(budget, |seed| {
            run_trial(agent, &params, &inputs.agents, seed).steps.iter().map(|&s| u64::from(s)).sum()
        });
        let name = match agent {
            MazeAgent::Sarsa => "sarsa-lambda".to_string(),
            other => other.slug().to_string(),
        };
        line("maze", &name, &rates);
    }
    Ok(())
}
