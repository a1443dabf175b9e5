//! Estimates the paper-scale Mario experiment's cost from a fraction of it:
//! one trial of each agent at the paper's parameters for `episodes` episodes
//! (default 2,000), timed on one core each, with the ticks per episode by
//! bins of 500 episodes, and a digest of each trial's record (to check that
//! a speed-up leaves the trial bit for bit). With `AGENT` (`sbs`, `hat`, …,
//! or the baseline's `q-lambda`), only that agent runs.
//! `cargo run --release -p ch6-irl-shaping --example mario_estimate [episodes] [AGENT]`.

use ch6_irl_shaping::mario::experiment::demonstrations;
use ch6_irl_shaping::mario::inputs::prepare;
use ch6_irl_shaping::mario::params::{BASELINE, MarioParams, run_trial};
use ch6_irl_shaping::shaping::Agent;

fn main() {
    let episodes: usize = std::env::args().nth(1).map_or(2000, |s| s.parse().expect("a number of episodes"));
    let only = std::env::args().nth(2);
    let params = MarioParams { episodes, ..MarioParams::paper() };
    let demos = demonstrations(20160501, &params);
    let inputs = prepare(20160501, &params, &demos.set).expect("inputs");
    for agent in Agent::ALL.into_iter().filter(|a| only.as_deref().is_none_or(|o| o == a.slug(BASELINE))) {
        let t = std::time::Instant::now();
        let trial = run_trial(agent, &params, Some(&inputs.agents), 11);
        let s = t.elapsed().as_secs_f64();
        let bins: Vec<String> = trial
            .steps
            .chunks(500)
            .zip(trial.returns.chunks(500))
            .map(|(c, r)| {
                format!(
                    "{:.0} ticks / {:.0} pts",
                    c.iter().map(|&x| f64::from(x)).sum::<f64>() / c.len() as f64,
                    r.iter().map(|&x| f64::from(x)).sum::<f64>() / r.len() as f64
                )
            })
            .collect();
        // FNV-1a over every episode's return and ticks, and the wins.
        let digest = trial
            .returns
            .iter()
            .flat_map(|r| r.to_le_bytes())
            .chain(trial.steps.iter().flat_map(|t| t.to_le_bytes()))
            .chain(trial.ends.wins.to_le_bytes())
            .fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
        println!(
            "{}: {} steps in {s:.1} s = {:.2} M steps/s; {:.0} ticks per episode; digest {digest:016x}; per 500 episodes: {}",
            agent.label(BASELINE),
            trial.total_steps(),
            trial.total_steps() as f64 / s / 1e6,
            trial.total_steps() as f64 / episodes as f64,
            bins.join(", ")
        );
    }
}
