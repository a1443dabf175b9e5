//! Scratch: trace episodes (temporary).
use ch5_hat_keepaway::keepaway::{Keepaway, KeeperAction, Status};
use rlfd_rl::random::seeded;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let seed: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(42);
    let eps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let mut game = Keepaway::benchmark();
    let mut rng = seeded(seed);
    for e in 0..eps {
        game.reset(&mut rng);
        let mut status = game.run(&mut rng);
        let mut lines = Vec::new();
        let mut kk = (0, 0);
        loop {
            let b = game.ball();
            let t = game.tally();
            let kicks = format!("{}{}", if t.keeper_kicks != kk.0 { "K" } else { "" }, if t.taker_kicks != kk.1 { "T" } else { "" });
            kk = (t.keeper_kicks, t.taker_kicks);
            let mut l = format!("{:4} ball ({:6.2},{:6.2}) v({:5.2},{:5.2})", game.cycle(), b.pos.x, b.pos.y, b.vel.x, b.vel.y);
            for p in game.keepers().iter().chain(game.takers()) { l += &format!(" ({:5.1},{:5.1}){:4.1}", p.pos.x, p.pos.y, p.pos.dist(b.pos)); }
            l += " "; l += &kicks;
            lines.push(l);
            match status {
                Status::Decision(_) => status = game.act(KeeperAction::HOLD, &mut rng),
                Status::Ended(c) => { println!("=== ep {e} ended {c:?} at {}", game.cycle()); break; }
            }
        }
        lines.dedup();
        for l in lines.iter().rev().take(14).rev() { println!("{l}"); }
    }
}
