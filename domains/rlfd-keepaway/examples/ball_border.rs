//! Where the ball is when episodes are played, measured as the distance from
//! the region's nearest border (issue 28's question about 4 vs 3 25 m: do our
//! takers hold the ball in other places than the real ones?). Prints the
//! share of cycles, of keeper kicks and of taker kicks with the ball 0–1,
//! 1–2, 2–3, 3–5, 5–8, 8–13 and over 13 m from the border, and the same for
//! the last kicking cycle of the episodes that end out after a cycle in which
//! only takers kicked. `data/oracle_ball_border.py` prints the same lines from
//! a real server's game log.
//!
//! The episodes are split between ten games (seeds `1000 · SEED + g`), each
//! with its own draw of the see phases, or with the keepers' and takers'
//! phases given.
//!
//! usage: `cargo run --release -p rlfd-keepaway --example ball_border -- [EPISODES] [SEED] [KEEPERS] [TAKERS] [SIDE] [KEEPER_PHASE TAKER_PHASE]`
//! (default 1000 episodes, seed 1, Hand-coded 4 vs 3 on 25 m, phases drawn per game).

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, EndCause, Keepaway, KeepawayParams, MAX_STATE_VARS, SeePhases, Vec2};

/// Lower edges of the distance bins (m).
const BINS: [f64; 7] = [0.0, 1.0, 2.0, 3.0, 5.0, 8.0, 13.0];

/// Shares of `xs` per bin.
fn shares(xs: &[f64]) -> String {
    let mut c = [0usize; BINS.len()];
    for &x in xs {
        c[BINS.iter().rposition(|&b| x >= b).unwrap_or(0)] += 1;
    }
    let n = xs.len().max(1) as f64;
    c.iter().map(|&v| format!("{:.3}", v as f64 / n)).collect::<Vec<_>>().join(" ")
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize| a.get(i).and_then(|x| x.parse::<f64>().ok());
    let episodes = arg(1).map_or(1000, |x| x as u32);
    let seed = arg(2).map_or(1, |x| x as u64);
    let (nk, nt, side) = (arg(3).map_or(4, |x| x as usize), arg(4).map_or(3, |x| x as usize), arg(5).unwrap_or(25.0));
    let phases = match (arg(6), arg(7)) {
        (Some(k), Some(t)) => SeePhases::Teams { keepers: k as u8, takers: t as u8 },
        _ => SeePhases::KEEPAWAY_SH,
    };
    let half = side / 2.0;
    let border = |p: Vec2| (half - p.x.abs()).min(half - p.y.abs());
    let (mut cycles, mut keeper_kicks, mut taker_kicks, mut takers_only_outs) = (vec![], vec![], vec![], vec![]);
    for g in 0..10 {
        let mut params = KeepawayParams::configuration(nk, nt, side);
        params.see_phases = phases;
        let mut game = Keepaway::new(params).expect("a benchmark configuration");
        game.record_trace(true);
        game.record_kicks(true);
        let len = game.params().state_len();
        let mut rng = seeded(seed * 1000 + g);
        let mut state = [0.0; MAX_STATE_VARS];
        for _ in 0..episodes / 10 + u32::from(g < u64::from(episodes % 10)) {
            let (_, cause) = game.play_episode(&mut rng, |g, _, rng| {
                g.state_vars_into(&mut state[..len]);
                BenchmarkPolicy::HandCoded.choose_in(&state[..len], nk, nt, rng)
            });
            let trace = game.trace();
            let ball_at = |c: u32| trace.iter().find(|s| s.cycle == c).map(|s| s.ball);
            cycles.extend(trace.iter().map(|s| border(s.ball)));
            // The last cycle with a kick: (cycle, a keeper kicked, a taker kicked).
            let mut last: Option<(u32, bool, bool)> = None;
            for k in game.kicks() {
                let keeper = usize::from(k.player) < nk;
                if let Some(b) = ball_at(k.cycle) {
                    if keeper { &mut keeper_kicks } else { &mut taker_kicks }.push(border(b));
                }
                last = match last {
                    Some((c, ke, ta)) if c == k.cycle => Some((c, ke || keeper, ta || !keeper)),
                    _ => Some((k.cycle, keeper, !keeper)),
                };
            }
            if cause == EndCause::Out
                && let Some((c, false, true)) = last
                && let Some(b) = ball_at(c)
            {
                takers_only_outs.push(border(b));
            }
        }
    }
    println!("bins (m from the border, lower edges) {BINS:?}");
    println!("cycles {}", cycles.len());
    println!("all cycles       {}", shares(&cycles));
    println!("keeper kicks     {} {}", keeper_kicks.len(), shares(&keeper_kicks));
    println!("taker kicks      {} {}", taker_kicks.len(), shares(&taker_kicks));
    println!("takers-only outs {} {}", takers_only_outs.len(), shares(&takers_only_outs));
}
