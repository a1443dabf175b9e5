//! Criterion benches of Mario: one world tick, the simulator alone (random
//! actions, the 27-variable observation included), packing the 27 variables
//! into a key, the tile lookup of the 27 variables (the hashed coder, and the
//! agents' map: renumbered and memoised) and Q(λ) with hashed tile coding
//! learning on it (agent steps per second over whole episodes).
//! `cargo bench -p ch6-irl-shaping --bench mario`; `cargo xtask bench`
//! prints the same rates as one line each.

use std::hint::black_box;

use ch6_irl_shaping::mario::env::ACTION_KEYS;
use ch6_irl_shaping::mario::observation::pack;
use ch6_irl_shaping::mario::params::{MarioFeatures, MarioParams, MemoFeatures, run_trial};
use ch6_irl_shaping::mario::{ACTIONS, Level, LevelParams, MarioEnv, Mode, Status, World, random_ticks};
use ch6_irl_shaping::shaping::Agent;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rlfd_rl::Environment;
use rlfd_rl::features::{ActiveFeatures, FeatureMap, FirstTouch};
use rlfd_rl::random::{below, seeded};

fn world_tick(c: &mut Criterion) {
    // 1,000 random keys replayed on one level; a finished game restarts.
    let mut rng = seeded(11);
    let keys: Vec<usize> = (0..1000).map(|_| below(&mut rng, ACTIONS)).collect();
    let mut world = World::new(Level::generate(LevelParams::EXPERIMENT, 5), Mode::Large);
    let mut g = c.benchmark_group("mario");
    g.throughput(Throughput::Elements(keys.len() as u64));
    g.bench_function("world tick, random keys", |b| {
        b.iter(|| {
            let mut points = 0;
            for &a in &keys {
                if world.status() != Status::Running {
                    world.restart(Mode::Large);
                }
                points += world.tick(ACTION_KEYS[a]);
            }
            points
        })
    });
    g.finish();
}

fn tile_lookup(c: &mut Criterion) {
    // The 27 variables of 1,000 ticks of random play.
    let params = MarioParams::paper();
    let mut rng = seeded(12);
    let mut env = MarioEnv::new(params.level);
    env.reset(&mut rng);
    let states: Vec<Vec<f64>> = (0..1000)
        .map(|_| {
            if env.step(below(&mut rng, ACTIONS), &mut rng).terminal {
                env.reset(&mut rng);
            }
            env.state().to_vec()
        })
        .collect();
    let coder = params.tile_coder();
    let memo: MarioFeatures = MemoFeatures::new(FirstTouch::new(params.tile_coder()));
    let mut out = ActiveFeatures::with_capacity(32);
    let mut g = c.benchmark_group("mario tiles");
    g.throughput(Throughput::Elements(states.len() as u64));
    g.bench_function("pack 27 variables", |b| {
        b.iter(|| states.iter().fold(0u64, |k, s| k ^ pack(black_box(s)).unwrap_or(0)))
    });
    g.bench_function("hashed 27 variables, 32 tilings", |b| {
        b.iter(|| {
            for s in &states {
                coder.features(black_box(s), &mut out);
            }
            out.indices[0]
        })
    });
    g.bench_function("renumbered and memoised, 27 variables, 32 tilings", |b| {
        b.iter(|| {
            for s in &states {
                memo.features(black_box(s), &mut out);
            }
            out.indices[0]
        })
    });
    g.finish();
}

fn simulator(c: &mut Criterion) {
    let mut g = c.benchmark_group("mario");
    g.throughput(Throughput::Elements(200_000));
    g.bench_function("simulator, random actions", |b| b.iter(|| random_ticks(7, 200_000)));
    g.finish();
}

fn q_lambda(c: &mut Criterion) {
    let params = MarioParams { episodes: 20, ..MarioParams::paper() };
    // The same seed every iteration: the same episodes, so the step count is fixed.
    let steps = run_trial(Agent::Baseline, &params, None, 3).total_steps();
    let mut g = c.benchmark_group("mario agents");
    g.sample_size(10);
    g.throughput(Throughput::Elements(steps));
    g.bench_function("q-lambda learning, 20 episodes", |b| b.iter(|| run_trial(Agent::Baseline, &params, None, 3)));
    g.finish();
}

criterion_group!(benches, world_tick, simulator, tile_lookup, q_lambda);
criterion_main!(benches);
