//! Criterion benches of the hot kernels: tile lookups (dense 2-D and hashed
//! 27-D), one SARSA(λ) update with sparse replacing traces, one Watkins
//! Q(λ) update over 12 actions with hashed 27-D tiles (Mario's learner),
//! replacing traces kept as a list and by generation (mark, apply, decay),
//! and ε-greedy selection. `cargo bench -p rlfd-rl`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rlfd_rl::agent::TdControl;
use rlfd_rl::features::{ActiveFeatures, FeatureMap, TileCoder, TileIndexing};
use rlfd_rl::policy::epsilon_greedy;
use rlfd_rl::random::{seeded, uniform01};
use rlfd_rl::traces::GenerationTraces;
use rlfd_rl::{LinearActionValues, SarsaLambda, TdParams, TraceKind, WatkinsQLambda};

fn states(n: usize, dim: usize) -> Vec<Vec<f64>> {
    let mut rng = seeded(1);
    (0..n).map(|_| (0..dim).map(|_| uniform01(&mut rng)).collect()).collect()
}

fn tile_lookups(c: &mut Criterion) {
    let mut g = c.benchmark_group("tile coding");
    g.throughput(Throughput::Elements(1024));
    let dense =
        TileCoder::new(32, &[0.1, 0.1], TileIndexing::Dense { lower: vec![0.0; 2], upper: vec![1.0; 2] }).unwrap();
    let xs = states(1024, 2);
    let mut out = ActiveFeatures::with_capacity(32);
    g.bench_function("dense 2-D, 32 tilings", |b| {
        b.iter(|| {
            for x in &xs {
                dense.features(black_box(x), &mut out);
            }
            out.indices[0]
        })
    });
    let hashed = TileCoder::new(32, &[1.0; 27], TileIndexing::Hashed { size: 1 << 22 }).unwrap();
    let ys = states(1024, 27);
    g.bench_function("hashed 27-D, 32 tilings", |b| {
        b.iter(|| {
            for y in &ys {
                hashed.features(black_box(y), &mut out);
            }
            out.indices[0]
        })
    });
    g.finish();
}

fn sarsa_update(c: &mut Criterion) {
    let coder =
        TileCoder::new(32, &[0.1, 0.1], TileIndexing::Dense { lower: vec![0.0; 2], upper: vec![1.0; 2] }).unwrap();
    let params = TdParams { alpha: 0.25 / 32.0, gamma: 1.0, lambda: 0.25, epsilon: 0.02 };
    let mut learner = SarsaLambda::new(coder.num_features(), 4, params, TraceKind::Replacing);
    // A walk of nearby states, as an agent makes.
    let walk: Vec<ActiveFeatures> = (0..1024)
        .map(|k| {
            let mut f = ActiveFeatures::with_capacity(32);
            let t = k as f64 / 1024.0;
            coder.features(&[0.5 + 0.4 * (6.0 * t).sin(), 0.5 + 0.4 * (4.0 * t).cos()], &mut f);
            f
        })
        .collect();
    let mut q = [0.0; 4];
    let mut g = c.benchmark_group("sarsa(λ)");
    g.throughput(Throughput::Elements(1023));
    g.bench_function("update, 32 tilings, replacing traces", |b| {
        b.iter(|| {
            for k in 0..1023 {
                learner.action_values(&walk[k + 1], &mut q);
                learner.learn(&walk[k], k % 4, -1.0, Some((&q, (k + 1) % 4, (k + 1) % 4)));
            }
            learner.trace_count()
        })
    });
    g.finish();
}

fn q_lambda_update(c: &mut Criterion) {
    // Mario's learner: 32 hashed tilings of 27 variables, 2^18 weights per
    // action, 12 actions, α = 0.01/32, γ = 0.9, λ = 0.5, replacing traces by generation.
    let coder = TileCoder::new(32, &[2.0; 27], TileIndexing::Hashed { size: 1 << 18 }).unwrap();
    let params = TdParams { alpha: 0.01 / 32.0, gamma: 0.9, lambda: 0.5, epsilon: 0.05 };
    let mut learner =
        WatkinsQLambda::new(coder.num_features(), 12, params, TraceKind::Replacing).traces_by_generation();
    // A walk that flips one boolean variable per step, as Mario's states do.
    let mut rng = seeded(3);
    let mut state = [0.0f64; 27];
    let walk: Vec<ActiveFeatures> = (0..1024)
        .map(|_| {
            let i = rlfd_rl::random::below(&mut rng, 27);
            state[i] = 1.0 - state[i];
            let mut f = ActiveFeatures::with_capacity(32);
            coder.features(&state, &mut f);
            f
        })
        .collect();
    let mut q = [0.0; 12];
    let mut g = c.benchmark_group("watkins q(λ)");
    g.throughput(Throughput::Elements(1023));
    g.bench_function("update, 12 actions, 32 hashed tilings, replacing traces", |b| {
        b.iter(|| {
            for k in 0..1023 {
                learner.action_values(&walk[k + 1], &mut q);
                // Every 16th step explores (a' not greedy): Watkins's cut.
                let next = (k + 1) % 12;
                let target = if k % 16 == 0 { (k + 2) % 12 } else { next };
                learner.learn(&walk[k], k % 12, -1.0, Some((&q, target, next)));
            }
            learner.trace_count()
        })
    });
    g.finish();
}

fn replacing_traces(c: &mut Criterion) {
    // Mario's learner step without the action values of s': Q(s, a) and
    // marking s's 32 tiles, then w += α δ e and the decay (γλ = 0.45), 12
    // actions; a walk that keeps its state a third of the time and
    // otherwise flips one variable.
    let coder = TileCoder::new(32, &[2.0; 27], TileIndexing::Hashed { size: 1 << 18 }).unwrap();
    let mut rng = seeded(4);
    let mut state = [0.0f64; 27];
    let walk: Vec<ActiveFeatures> = (0..1024)
        .map(|_| {
            if uniform01(&mut rng) > 1.0 / 3.0 {
                let i = rlfd_rl::random::below(&mut rng, 27);
                state[i] = 1.0 - state[i];
            }
            let mut f = ActiveFeatures::with_capacity(32);
            coder.features(&state, &mut f);
            f
        })
        .collect();
    let (factor, a_n) = (0.45, 12);
    let mut q = LinearActionValues::new(1 << 18, a_n, 0.0);
    let mut g = c.benchmark_group("replacing traces");
    g.throughput(Throughput::Elements(walk.len() as u64));
    let mut list = q.new_traces(TraceKind::Replacing, 0.01);
    g.bench_function("listed: Q(s, a) and mark 32, apply and decay", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (k, f) in walk.iter().enumerate() {
                let v = q.value_and_mark(&mut list, f, k % a_n, TraceKind::Replacing);
                q.apply_and_decay(&mut list, 1e-6 * (1.0 - v), factor);
                sum += v;
            }
            sum
        })
    });
    let mut generations = GenerationTraces::new(1 << 18, factor, 0.01).unwrap();
    g.bench_function("by generation: Q(s, a) and mark 32, apply and decay", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (k, f) in walk.iter().enumerate() {
                let v = q.value_and_mark_generation(&mut generations, f, k % a_n).unwrap();
                generations.apply_and_decay(q.weights_mut(), 1e-6 * (1.0 - v));
                sum += v;
            }
            sum
        })
    });
    g.finish();
}

fn selection(c: &mut Criterion) {
    let mut rng = seeded(2);
    let values = [0.0, -1.0, 0.0, -3.0];
    c.bench_function("ε-greedy over 4 actions with ties", |b| {
        b.iter(|| epsilon_greedy(black_box(&values), 0.02, &mut rng))
    });
}

criterion_group!(benches, tile_lookups, sarsa_update, q_lambda_update, replacing_traces, selection);
criterion_main!(benches);
