//! Criterion benches of 3 vs 2 Keepaway: the simulator alone (keepers
//! choosing at random, cycles per second), the 13 state variables and the
//! RBF features of one decision, GetOpen, and the keepers learning (No Prior and PPR
//! on Subject A's rules) for a tenth of a simulated hour. `cargo bench -p
//! ch5-hat-keepaway`; `cargo xtask bench` prints the whole-domain rates.

use ch5_hat_keepaway::inputs::{DemoSetId, prepare};
use ch5_hat_keepaway::keepaway::players::{GetOpenGrid, least_congested_points};
use ch5_hat_keepaway::keepaway::{Keepaway, KeeperAction, STATE_VARS, Status, Vec2};
use ch5_hat_keepaway::learners::{LearnerParams, Method, RbfLayout, TrialParams, run_learning_trial};
use ch5_hat_keepaway::simulator_cycles;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rlfd_rl::features::{ActiveFeatures, FeatureMap};
use rlfd_rl::random::seeded;

fn simulator(c: &mut Criterion) {
    let cycles = simulator_cycles(7, 36_000);
    let mut g = c.benchmark_group("keepaway");
    g.throughput(Throughput::Elements(cycles));
    g.bench_function("simulator, random keepers, one hour", |b| b.iter(|| simulator_cycles(7, 36_000)));
    g.finish();
}

fn decision(c: &mut Criterion) {
    // A game paused at a decision.
    let mut game = Keepaway::benchmark();
    let mut rng = seeded(3);
    game.reset(&mut rng);
    let mut status = game.run(&mut rng);
    while status == Status::Decision(0) || status == Status::Decision(1) || status == Status::Decision(2) {
        if game.cycle() > 20 {
            break;
        }
        status = game.act(KeeperAction::HOLD, &mut rng);
    }
    let k = game.pending().unwrap_or(0);
    let features = RbfLayout::reconstruction().features();
    let mut state = [0.0; STATE_VARS];
    let mut active = ActiveFeatures::with_capacity(features.max_active());
    let mut g = c.benchmark_group("keepaway decision");
    g.bench_function("13 state variables", |b| b.iter(|| game.state_vars(k, &mut state)));
    game.state_vars(k, &mut state);
    g.bench_function("RBF features", |b| b.iter(|| features.features(&state, &mut active)));
    let grid = GetOpenGrid::new(&game.params().region());
    let players = [
        game.keepers()[0].pos,
        game.keepers()[1].pos,
        game.keepers()[2].pos,
        game.takers()[0].pos,
        game.takers()[1].pos,
    ];
    let mut out = [Vec2::ZERO; 3];
    g.bench_function("GetOpen for two keepers", |b| {
        b.iter(|| {
            least_congested_points(&grid, Vec2::ZERO, game.ball().pos, &players, 3, &[true, true, false], &mut out)
        })
    });
    g.finish();
}

fn learning(c: &mut Criterion) {
    let passer = ch5_hat_keepaway::readings::frequent_passer(&rlfd_harness::Reading::defaults());
    let rules = prepare(20160501, passer).unwrap().get(DemoSetId::A20).rules.clone();
    let mut g = c.benchmark_group("keepaway learning");
    g.sample_size(10);
    for (name, method) in [("sarsa", Method::NoPrior), ("sarsa + PPR", Method::POLICY_REUSE)] {
        let params =
            TrialParams { hours: 0.1, eval_episodes: 0, greedy_episodes: 0, learner: LearnerParams::thesis(), method };
        let r = method.uses_rules().then_some(&rules);
        let cycles: u64 = run_learning_trial(&params, r, 5).unwrap().durations.iter().map(|&d| u64::from(d)).sum();
        g.throughput(Throughput::Elements(cycles));
        g.bench_function(format!("{name}, 0.1 simulated hours"), |b| b.iter(|| run_learning_trial(&params, r, 5)));
    }
    g.finish();
}

criterion_group!(benches, simulator, decision, learning);
criterion_main!(benches);
