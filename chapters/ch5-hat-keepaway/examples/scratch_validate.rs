//! Scratch: mechanism statistics of the benchmark policies (temporary).
use ch5_hat_keepaway::benchmarks::BenchmarkPolicy;
use ch5_hat_keepaway::keepaway::{EndCause, Keepaway, KeepawayParams, MAX_STATE_VARS};
use rlfd_rl::random::seeded;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(2000);
    let kk: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(3);
    let tt: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(2);
    let side: f64 = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(20.0);
    for policy in BenchmarkPolicy::ALL {
        let mut game = Keepaway::new(KeepawayParams::configuration(kk, tt, side)).unwrap();
        let len = game.params().state_len();
        let mut rng = seeded(42);
        let mut d = Vec::new();
        let (mut out, mut kks, mut tks, mut passes, mut strong) = (0, 0u64, 0u64, 0u64, 0u64);
        let (mut o_keeper, mut t_taker) = (0, 0);
        let mut ends = std::collections::BTreeMap::new();
        let mut state = [0.0; MAX_STATE_VARS];
        let t0 = std::time::Instant::now();
        game.record_kicks(true);
        game.record_trace(true);
        let mut coll = std::collections::BTreeMap::new();
        let (mut dbl, mut tonly) = (Vec::new(), Vec::new());
        let mut pst = std::collections::BTreeMap::new();
        let mut cycles = 0u64;
        for _ in 0..n {
            let (c, cause) = game.play_episode(&mut rng, |g, _, rng| {
                g.state_vars_into(&mut state[..len]);
                policy.choose_in(&state[..len], kk, tt, rng)
            });
            cycles += c as u64;
            d.push(c as f64 / 10.0);
            for snap in game.trace() {
                let ps: Vec<(bool, ch5_hat_keepaway::keepaway::Vec2)> = snap.keepers[..kk].iter().map(|p| (true, *p)).chain(snap.takers[..tt].iter().map(|p| (false, *p))).collect();
                for (i, (ki, p)) in ps.iter().enumerate() {
                    if (p.dist(snap.ball) - 0.385).abs() < 0.0015 { *coll.entry(if *ki { "ball-K" } else { "ball-T" }).or_insert(0usize) += 1; }
                    for (kj, q) in &ps[i + 1..] {
                        if (p.dist(*q) - 0.6).abs() < 0.0015 { *coll.entry(match (ki, kj) { (true, true) => "KK", (true, false) => "KT", (false, true) => "KT", _ => "TT" }).or_insert(0usize) += 1; }
                    }
                }
            }
            {
                let tr = game.trace();
                let ks = game.kicks();
                let mut c = 0;
                while c < ks.len() {
                    let cyc = ks[c].cycle;
                    let (mut k, mut tk) = (false, false);
                    while c < ks.len() && ks[c].cycle == cyc { if (ks[c].player as usize) < kk { k = true } else { tk = true }; c += 1; }
                    if let Some(sn) = tr.iter().find(|s| s.cycle == cyc + 1) {
                        let v = sn.ball_vel.norm() / 0.94;
                        if k && tk { dbl.push(v) } else if tk { tonly.push(v) }
                    }
                }
            }
            let t = game.tally();
            let ks = game.kicks();
            for a in 0..ks.len() {
                let e = ks[a];
                if e.player as usize >= kk || e.power < 50.0 { continue; }
                if a > 0 && ks[a-1].player == e.player && ks[a-1].cycle + 1 == e.cycle && ks[a-1].power >= 50.0 { continue; }
                let mut nxt = None;
                for b in a+1..ks.len() { if ks[b].player == e.player && ks[b].cycle <= e.cycle + 2 { continue; } nxt = Some(ks[b]); break; }
                let key = match nxt { None => if cause == EndCause::Out { "end_o" } else { "end_t" }, Some(x) if x.player as usize >= kk => "taker", Some(x) if x.player == e.player => "same", _ => "other_keeper" };
                *pst.entry(key).or_insert(0usize) += 1;
            }
            let kind = match (t.last_by_keeper, t.last_strong) { (Some(true), true) => "KS", (Some(true), false) => "Kw", (Some(false), _) => "T", _ => "none" };
            *ends.entry(format!("{}_{}", if cause == EndCause::Out { "o" } else { "t" }, kind)).or_insert(0usize) += 1;
            if cause == EndCause::Out { out += 1; if t.last_by_keeper == Some(true) { o_keeper += 1; } }
            else if t.last_by_keeper == Some(false) { t_taker += 1; }
            kks += t.keeper_kicks as u64;
            tks += t.taker_kicks as u64;
            passes += t.passes as u64;
            strong += t.strong_keeper_kicks as u64;
        }
        let secs = t0.elapsed().as_secs_f64();
        let mean = d.iter().sum::<f64>() / n as f64;
        let sd = (d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
        let mut s = d.clone();
        s.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let med = (s[(n - 1) / 2] + s[n / 2]) / 2.0;
        println!("{:<11} mean {:6.3} sd {:6.3} med {:5.2} out {:4.1}% (last keeper {:3.0}%) t-last-taker {:3.0}% passes {:5.2} kk {:5.1} strong {:4.1} tk {:4.1}  [{:.2} Mcyc/s]",
            policy.label(), mean, sd, med, 100.0 * out as f64 / n as f64, 100.0*o_keeper as f64/out.max(1) as f64, 100.0*t_taker as f64/(n-out).max(1) as f64,
            passes as f64 / n as f64, kks as f64 / n as f64, strong as f64 / n as f64, tks as f64 / n as f64, cycles as f64 / secs / 1e6);
        let tot: usize = pst.values().sum();
        println!("   strong first kicks {:.2}/ep: {}", tot as f64 / n as f64, pst.iter().map(|(k, v)| format!("{k} {:.1}%", 100.0 * *v as f64 / tot as f64)).collect::<Vec<_>>().join(" "));
        let q = |a: &mut Vec<f64>| { a.sort_by(|x, y| x.partial_cmp(y).unwrap()); if a.is_empty() { String::new() } else { [0.1, 0.25, 0.5, 0.75, 0.9].iter().map(|&x| format!("{:.2}", a[((a.len() - 1) as f64 * x) as usize])).collect::<Vec<_>>().join(" ") } };
        println!("   double kicks {} [{}]  taker-only {} [{}]", dbl.len(), q(&mut dbl), tonly.len(), q(&mut tonly));
        println!("   collisions/ep: {}", coll.iter().map(|(k, v)| format!("{k} {:.2}", *v as f64 / n as f64)).collect::<Vec<_>>().join(" "));
        println!("   ends: {}", ends.iter().map(|(k, v)| format!("{k} {:.1}%", 100.0 * *v as f64 / n as f64)).collect::<Vec<_>>().join("  "));
    }
}

#[allow(dead_code)]
fn debug_episode() {}
