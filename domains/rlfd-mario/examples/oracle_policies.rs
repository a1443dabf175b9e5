//! The oracle's fixed policies on our simulator ([`rlfd_mario::baseline`]),
//! for a like-for-like comparison with the real Mario AI Benchmark 0.2.0
//! measured in `../shared/oracle/mario/` (its `run_policies.sh`).
//!
//! ```text
//! cargo run --release -p rlfd-mario --example oracle_policies -- random|fwdjump EPISODES SEED [CSV]
//! ```
//!
//! Writes one CSV row per episode to `CSV` if given (level seed, start mode,
//! return, ticks, outcome, stomps, coins, hurts, distance) and prints the
//! oracle's summary: return and ticks, won / died / timed out, events per
//! episode, returns by start mode, and P(1) of the 27 variables.

use std::io::Write;

use rlfd_mario::LevelParams;
use rlfd_mario::baseline::{FixedPolicy, Outcome, play};
use rlfd_mario::observation::{CLOSEST, NAMES};

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: oracle_policies random|fwdjump EPISODES SEED [CSV]";
    let policy = match args.first().map(String::as_str) {
        Some("random") => FixedPolicy::Random,
        Some("fwdjump") => FixedPolicy::ForwardJump,
        _ => panic!("{usage}"),
    };
    let episodes: usize = args.get(1).expect(usage).parse().expect("EPISODES is a number");
    let seed: u64 = args.get(2).expect(usage).parse().expect("SEED is a number");
    let s = play(policy, LevelParams::EXPERIMENT, episodes, seed);
    if let Some(path) = args.get(3) {
        let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
        writeln!(f, "policy,episode,level_seed,start_mode,return,ticks,outcome,stomps,coins,hurts,distance_cells")?;
        for (k, e) in s.episodes.iter().enumerate() {
            writeln!(
                f,
                "{},{k},{},{:?},{},{},{:?},{},{},{},{}",
                args[0],
                e.level_seed,
                e.start_mode,
                e.ret,
                e.ticks,
                e.outcome,
                e.stomps,
                e.coins,
                e.hurts,
                e.distance_cells
            )?;
        }
    }
    let ret = s.mean(|e| e.ret);
    let sd = (s.episodes.iter().map(|e| (e.ret - ret).powi(2)).sum::<f64>() / (episodes - 1) as f64).sqrt();
    println!("policy {}, {episodes} episodes, seed {seed}, levels {:?}", args[0], LevelParams::EXPERIMENT);
    println!(
        "return mean {ret:.1} sd {sd:.1}; ticks mean {:.0}; won {:.3} died {:.3} timed out {:.3}",
        s.mean(|e| f64::from(e.ticks)),
        s.share(Outcome::Won),
        s.share(Outcome::Died),
        s.share(Outcome::TimedOut)
    );
    println!(
        "per episode: stomps {:.2} coins {:.1} hurts {:.2} distance {:.1} cells",
        s.mean(|e| f64::from(e.stomps)),
        s.mean(|e| f64::from(e.coins)),
        s.mean(|e| f64::from(e.hurts)),
        s.mean(|e| f64::from(e.distance_cells))
    );
    for (k, name) in ["small", "large", "fire"].iter().enumerate() {
        let of: Vec<_> = s.episodes.iter().filter(|e| e.start_mode as usize == k).collect();
        let n = of.len() as f64;
        let won = of.iter().filter(|e| e.outcome == Outcome::Won).count() as f64;
        println!("start {name}: mean return {:.0}, won {:.2}", of.iter().map(|e| e.ret).sum::<f64>() / n, won / n);
    }
    println!(
        "P(1) over {} decision states (x-dir, y-dir: P(+1) / P(-1)); no enemy in the grid {:.3}",
        s.states, s.p_no_enemy
    );
    for k in 0..CLOSEST {
        println!("  {:<18} {:.4} / {:.4}", NAMES[k], s.p_one[k], s.p_minus_one[k]);
    }
    Ok(())
}
