//! What the see phases do to the benchmark policies' episodes (issue 28):
//! for each [`SeePhases`] setting (the keepers' and takers' phases fixed, the
//! takers 0, 1 or 2 cycles after the keepers; every player on its own; and
//! keepaway.sh's default, drawn per game), the mean duration with its
//! standard error over `episodes` episodes, and passes per second.
//!
//! usage: `cargo run --release -p rlfd-keepaway --example see_phases -- [EPISODES] [SEED] [POLICY] [SIDE] [KEEPERS] [TAKERS]`
//! (POLICY: hand | hold | rand; default 2000 episodes, seed 1, hand, 3 vs 2 on 20 m).

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, Keepaway, KeepawayParams, MAX_STATE_VARS, SeePhases};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let episodes: u32 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(2000);
    let seed: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    let policy = match args.get(3).map_or("hand", String::as_str) {
        "hold" => BenchmarkPolicy::AlwaysHold,
        "rand" => BenchmarkPolicy::Random,
        _ => BenchmarkPolicy::HandCoded,
    };
    let side: f64 = args.get(4).and_then(|a| a.parse().ok()).unwrap_or(20.0);
    let nk: usize = args.get(5).and_then(|a| a.parse().ok()).unwrap_or(3);
    let nt: usize = args.get(6).and_then(|a| a.parse().ok()).unwrap_or(2);
    let settings = [
        ("teams 0/0", SeePhases::Teams { keepers: 0, takers: 0 }),
        ("teams 0/1", SeePhases::Teams { keepers: 0, takers: 1 }),
        ("teams 0/2", SeePhases::Teams { keepers: 0, takers: 2 }),
        ("independent", SeePhases::Independent),
        ("keepaway.sh", SeePhases::KEEPAWAY_SH),
    ];
    println!("phases policy config n mean_s se_s passes/s");
    for (name, phases) in settings {
        let params = KeepawayParams { see_phases: phases, ..KeepawayParams::configuration(nk, nt, side) };
        let mut game = Keepaway::new(params).expect("valid configuration");
        let len = game.params().state_len();
        let mut rng = seeded(seed);
        let mut state = [0.0; MAX_STATE_VARS];
        let (mut cycles, mut sum2, mut passes) = (0u64, 0.0, 0u64);
        for _ in 0..episodes {
            let (d, _) = game.play_episode(&mut rng, |g, _, rng| {
                g.state_vars_into(&mut state[..len]);
                policy.choose_in(&state[..len], nk, nt, rng)
            });
            cycles += u64::from(d);
            sum2 += (f64::from(d) / 10.0).powi(2);
            passes += u64::from(game.tally().passes);
        }
        let n = f64::from(episodes);
        let secs = cycles as f64 / 10.0;
        let mean = secs / n;
        let se = ((sum2 - n * mean * mean) / (n - 1.0) / n).sqrt();
        println!("{name} {} {nk}v{nt}-{side} {episodes} {mean:.3} {se:.3} {:.3}", policy.slug(), passes as f64 / secs);
    }
}
