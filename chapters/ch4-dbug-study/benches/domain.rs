//! Criterion benches of chapter 4: the table alone, one ten-minute session
//! of each algorithm with a drawn novice, a GMM fit, and scoring a CBA
//! classifier over the 76,800 states. `cargo bench -p ch4-dbug-study`;
//! `cargo xtask bench` prints the session rates as simulated ticks per second.

use ch4_dbug_study::LearnerParams;
use ch4_dbug_study::cba::gmm::fit_bic;
use ch4_dbug_study::cba::{Cba, CbaParams};
use ch4_dbug_study::dbug::{Action, Pixel, busy_table_ticks};
use ch4_dbug_study::session::{SessionParams, Teacher, run_session};
use ch4_dbug_study::users::{Algorithm, Expertise, UserModel};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

fn simulator(c: &mut Criterion) {
    let mut g = c.benchmark_group("dbug");
    g.throughput(Throughput::Elements(60_000));
    g.bench_function("table, 100 simulated minutes", |b| b.iter(|| busy_table_ticks(3, 60_000)));
    g.finish();
}

fn sessions(c: &mut Criterion) {
    let model = UserModel::thesis();
    let params = SessionParams::thesis();
    let mut g = c.benchmark_group("dbug sessions");
    g.sample_size(10);
    g.throughput(Throughput::Elements(6000));
    for a in Algorithm::ALL {
        g.bench_function(format!("{} session, 10 simulated minutes", a.key()), |b| {
            b.iter(|| {
                let mut rng = rlfd_rl::random::seeded(5);
                let traits = model.traits.draw(Expertise::Novice, &mut rng);
                let t = Teacher { traits, session: 0, ideal: false };
                run_session(a, &t, &model, &params, &LearnerParams::thesis(), &mut rng)
            })
        });
    }
    g.finish();
}

fn cba(c: &mut Criterion) {
    let points: Vec<[f64; 2]> = (0..120).map(|i| [f64::from(i * 37 % 320), f64::from(i * 53 % 240)]).collect();
    let mut learner = Cba::new(CbaParams::thesis());
    for (i, p) in points.iter().enumerate() {
        learner.add(Pixel::new(p[0] as u16, p[1] as u16), Action::from_index(i % 3));
    }
    let mut g = c.benchmark_group("dbug cba");
    g.bench_function("GMM fit with BIC, 120 points", |b| b.iter(|| fit_bic(&points, 4, &CbaParams::thesis().em)));
    g.throughput(Throughput::Elements(76_800));
    g.bench_function("score a classifier over 76,800 states", |b| b.iter(|| learner.accuracy()));
    g.finish();
}

criterion_group!(benches, simulator, sessions, cba);
criterion_main!(benches);
