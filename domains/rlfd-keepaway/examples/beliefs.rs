//! How well the players know the ball (issue 28): plays Hand-coded episodes
//! with every player's belief recorded ([`Keepaway::record_beliefs`]) and
//! the true ball traced, and prints, for keepers and takers apart, the mean
//! error of the believed position and velocity by the player's distance
//! from the ball, with the share of player-cycles that saw the ball, took a
//! teammate's message or sensed a collision. The real players can log the
//! same belief (`keepaway_player -l 101..102`), for a side-by-side reading.
//!
//! usage: `cargo run --release -p rlfd-keepaway --example beliefs -- [EPISODES] [SEED]`
//! (default 500 episodes, seed 1; 3 vs 2 on 20 m).

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, Keepaway, KeepawayParams, MAX_STATE_VARS};

/// The distance bands, m.
const BANDS: [f64; 5] = [0.0, 2.0, 5.0, 10.0, 30.0];

#[derive(Default, Clone, Copy)]
struct Cell {
    n: u64,
    pos_err: f64,
    vel_err: f64,
    saw: u64,
    heard: u64,
    collided: u64,
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let episodes: u32 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(500);
    let seed: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    let mut game = Keepaway::new(KeepawayParams::benchmark()).expect("valid configuration");
    game.record_trace(true);
    game.record_beliefs(true);
    let len = game.params().state_len();
    let nk = game.params().keepers;
    let mut rng = seeded(seed);
    let mut state = [0.0; MAX_STATE_VARS];
    // [keepers, takers] × band
    let mut cells = [[Cell::default(); BANDS.len() - 1]; 2];
    for _ in 0..episodes {
        game.play_episode(&mut rng, |g, _, rng| {
            g.state_vars_into(&mut state[..len]);
            BenchmarkPolicy::HandCoded.choose_in(&state[..len], 3, 2, rng)
        });
        let trace = game.trace();
        for b in game.beliefs() {
            let Some(s) = trace.iter().find(|s| s.cycle == b.cycle) else { continue };
            let p = usize::from(b.player);
            let (team, me) = if p < nk { (0, s.keepers[p]) } else { (1, s.takers[p - nk]) };
            let d = me.dist(s.ball);
            let Some(band) = BANDS.windows(2).position(|w| d >= w[0] && d < w[1]) else { continue };
            let c = &mut cells[team][band];
            c.n += 1;
            c.pos_err += b.pos.dist(s.ball);
            c.vel_err += b.vel.dist(s.ball_vel);
            c.saw += u64::from(b.saw);
            c.heard += u64::from(b.heard);
            c.collided += u64::from(b.collided);
        }
    }
    println!("team band_m player_cycles pos_err_m vel_err_m_per_cycle saw heard collided");
    for (team, name) in [(0, "keepers"), (1, "takers")] {
        for (band, c) in cells[team].iter().enumerate() {
            let n = c.n.max(1) as f64;
            println!(
                "{name} {}-{} {} {:.3} {:.3} {:.3} {:.3} {:.4}",
                BANDS[band],
                BANDS[band + 1],
                c.n,
                c.pos_err / n,
                c.vel_err / n,
                c.saw as f64 / n,
                c.heard as f64 / n,
                c.collided as f64 / n
            );
        }
    }
}
