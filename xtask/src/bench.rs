//! `bench`: whole-domain speed, one line per domain and agent, measured on
//! one thread (`criterion` benches in each crate measure the kernels).

use std::time::Instant;

use anyhow::Result;
use ch6_irl_shaping::agents::{MazeAgent, MazeParams, run_trial};
use ch6_irl_shaping::experiment::{DemonstrationSource, demonstrations};
use ch6_irl_shaping::inputs::prepare;
use ch6_irl_shaping::maze::random_walk_steps;

use crate::cli::DEFAULT_SEED;

fn line(domain: &str, what: &str, count: u64, seconds: f64, unit: &str) {
    println!("{domain:<6} {what:<14} {:>7.2}M {unit}/s  ({count} in {seconds:.2} s)", count as f64 / seconds / 1e6);
}

pub fn run(quick: bool) -> Result<()> {
    let budget = if quick { 0.2 } else { 2.0 };

    // The simulator alone, uniformly random moves.
    let (mut steps, mut seed, start) = (0u64, 0u64, Instant::now());
    while start.elapsed().as_secs_f64() < budget {
        steps += random_walk_steps(seed, 100_000);
        seed += 1;
    }
    line("maze", "simulator", steps, start.elapsed().as_secs_f64(), "steps");

    // Each agent learning: whole trials of the paper's parameters, as often as the budget allows.
    let demos = demonstrations(DEFAULT_SEED, &DemonstrationSource::Synthetic)?;
    let params = MazeParams::paper();
    let inputs = prepare(DEFAULT_SEED, &params, &demos.set)?;
    for agent in MazeAgent::ALL {
        let (mut steps, mut seed, start) = (0u64, 0u64, Instant::now());
        while start.elapsed().as_secs_f64() < budget {
            let trial = run_trial(agent, &params, &inputs.agents, seed);
            steps += trial.steps.iter().map(|&s| u64::from(s)).sum::<u64>();
            seed += 1;
        }
        let name = match agent {
            MazeAgent::Sarsa => "sarsa-lambda".to_string(),
            other => other.slug().to_string(),
        };
        line("maze", &name, steps, start.elapsed().as_secs_f64(), "steps");
    }
    Ok(())
}
