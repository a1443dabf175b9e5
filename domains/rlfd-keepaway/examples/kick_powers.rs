//! Keeper kick powers of Hand-coded 3 vs 2 on 20 m as a histogram (tenths of
//! the maximum), to set beside the real server's log (issue 28).
//!
//! usage: `cargo run --release -p rlfd-keepaway --example kick_powers -- [EPISODES]`

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, Keepaway, MAX_STATE_VARS};

fn main() {
    let episodes: u32 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(1000);
    let mut game = Keepaway::benchmark();
    game.record_kicks(true);
    let mut rng = seeded(1);
    let mut state = [0.0; MAX_STATE_VARS];
    let mut hist = [0u64; 11];
    let (mut strong, mut sum) = (0u64, 0.0);
    for _ in 0..episodes {
        game.play_episode(&mut rng, |g, _, rng| {
            g.state_vars_into(&mut state[..13]);
            BenchmarkPolicy::HandCoded.choose_in(&state[..13], 3, 2, rng)
        });
        for k in game.kicks().iter().filter(|k| k.player < 3) {
            hist[((k.power / 10.0) as usize).min(10)] += 1;
            if k.power >= 50.0 {
                strong += 1;
                sum += k.power;
            }
        }
    }
    let total: u64 = hist.iter().sum();
    let shares: Vec<String> =
        hist.iter().enumerate().map(|(i, h)| format!("({}, {:.3})", i * 10, *h as f64 / total as f64)).collect();
    println!("{total} keeper kicks: {}", shares.join(" "));
    println!("strong {strong} mean power {:.2}", sum / strong as f64);
}
