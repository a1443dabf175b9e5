//! Criterion benches of the Nao sorting domain: the simulator alone (random
//! legal actions), the teacher's judgement and guidance with the simulator,
//! and whole training sessions of each condition (actions per second).
//! `cargo bench -p ch3-interactive-rl`; `cargo xtask bench` prints the same
//! rates as one line per workload.

use ch3_interactive_rl::nao::{NaoSorting, Perception, SHIFT_PROBABILITY, StateSpace, random_walk_steps};
use ch3_interactive_rl::session::run_session;
use ch3_interactive_rl::teacher::{ExpertTeacher, TeacherProtocol};
use ch3_interactive_rl::{Condition, SortingParams};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rlfd_rl::random::seeded;

fn simulator(c: &mut Criterion) {
    let mut g = c.benchmark_group("nao");
    g.throughput(Throughput::Elements(100_000));
    g.bench_function("simulator, random legal actions", |b| b.iter(|| random_walk_steps(7, 100_000)));
    g.finish();
}

fn teacher(c: &mut Criterion) {
    let mut g = c.benchmark_group("nao teacher");
    g.throughput(Throughput::Elements(10_000));
    g.bench_function("correct actions and guidance, 10,000 states", |b| {
        let mut rng = seeded(3);
        let mut world = NaoSorting::new(Perception::new(StateSpace::Large, SHIFT_PROBABILITY));
        world.reset(&mut rng);
        let t = ExpertTeacher::new(TeacherProtocol::thesis(), true);
        b.iter(|| {
            let mut n = 0usize;
            for _ in 0..10_000 {
                let a = t.correct_actions(&world).iter().next().unwrap();
                n += usize::from(t.guidance(&world).is_some());
                world.act(a, &mut rng);
            }
            n
        })
    });
    g.finish();
}

fn sessions(c: &mut Criterion) {
    let params = SortingParams::paper();
    let mut g = c.benchmark_group("nao sessions");
    g.sample_size(20);
    for condition in Condition::ALL {
        let setup = params.setup(condition);
        // The same seed every iteration: the same session, so the action count is fixed.
        let actions = run_session(&setup, &mut seeded(11)).actions;
        g.throughput(Throughput::Elements(u64::from(actions)));
        g.bench_function(format!("{} session ({actions} actions)", condition.slug()), |b| {
            b.iter(|| run_session(&setup, &mut seeded(11)))
        });
    }
    g.finish();
}

criterion_group!(benches, simulator, teacher, sessions);
criterion_main!(benches);
