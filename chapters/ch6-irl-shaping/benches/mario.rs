//! Criterion benches of Mario: the simulator alone (random actions, the
//! 27-variable observation included) and Q(λ) with hashed tile coding
//! learning on it (agent steps per second over whole episodes).
//! `cargo bench -p ch6-irl-shaping --bench mario`; `cargo xtask bench`
//! prints the same rates as one line each.

use ch6_irl_shaping::mario::random_ticks;
use ch6_irl_shaping::mario_agents::{MarioAgent, MarioParams, run_trial_episodes};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

fn simulator(c: &mut Criterion) {
    let mut g = c.benchmark_group("mario");
    g.throughput(Throughput::Elements(200_000));
    g.bench_function("simulator, random actions", |b| b.iter(|| random_ticks(7, 200_000)));
    g.finish();
}

fn q_lambda(c: &mut Criterion) {
    let params = MarioParams { episodes: 20, ..MarioParams::paper() };
    // The same seed every iteration: the same episodes, so the step count is fixed.
    let steps = run_trial_episodes(MarioAgent::QLambda, &params, None, 3).total_steps();
    let mut g = c.benchmark_group("mario agents");
    g.sample_size(10);
    g.throughput(Throughput::Elements(steps));
    g.bench_function("q-lambda learning, 20 episodes", |b| {
        b.iter(|| run_trial_episodes(MarioAgent::QLambda, &params, None, 3))
    });
    g.finish();
}

criterion_group!(benches, simulator, q_lambda);
criterion_main!(benches);
