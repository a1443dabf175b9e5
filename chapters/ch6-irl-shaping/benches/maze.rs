//! Criterion benches of the Maze: the simulator alone and each agent
//! learning (steps per second over whole episodes). `cargo bench -p
//! ch6-irl-shaping`; `cargo xtask bench` prints the same rates as one line
//! per agent.

use ch6_irl_shaping::maze::experiment::{DemonstrationSource, demonstrations};
use ch6_irl_shaping::maze::inputs::prepare;
use ch6_irl_shaping::maze::params::{BASELINE, MazeParams, run_trial};
use ch6_irl_shaping::maze::random_walk_steps;
use ch6_irl_shaping::shaping::Agent;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

fn simulator(c: &mut Criterion) {
    let mut g = c.benchmark_group("maze");
    g.throughput(Throughput::Elements(100_000));
    g.bench_function("simulator, random moves", |b| b.iter(|| random_walk_steps(7, 100_000)));
    g.finish();
}

fn agents(c: &mut Criterion) {
    let demos = demonstrations(20160501, &DemonstrationSource::Synthetic, Default::default()).unwrap();
    let params = MazeParams { episodes: 30, ..MazeParams::paper() };
    let inputs = prepare(20160501, &params, &demos.set).unwrap();
    let mut g = c.benchmark_group("maze agents");
    g.sample_size(10);
    for agent in Agent::ALL {
        // The same seed every iteration: the same episodes, so the step count is fixed.
        let steps: u64 = run_trial(agent, &params, &inputs.agents, 3).steps.iter().map(|&s| u64::from(s)).sum();
        g.throughput(Throughput::Elements(steps));
        g.bench_function(format!("{} learning, 30 episodes", agent.slug(BASELINE)), |b| {
            b.iter(|| run_trial(agent, &params, &inputs.agents, 3))
        });
    }
    // The reference kernel (issue 30): the baseline's episodes as one plain loop.
    let steps: u64 = ch6_irl_shaping::maze::kernel::run_trial(&params, 3).1.iter().map(|&s| u64::from(s)).sum();
    g.throughput(Throughput::Elements(steps));
    g.bench_function("reference kernel (sarsa) learning, 30 episodes", |b| {
        b.iter(|| ch6_irl_shaping::maze::kernel::run_trial(&params, 3))
    });
    g.finish();
}

criterion_group!(benches, simulator, agents);
criterion_main!(benches);
