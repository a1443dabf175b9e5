//! The oracle's two fixed policies on our simulator against the real Mario
//! AI Benchmark 0.2.0, 1,000 episodes each at the same options (difficulty
//! 0, overground, length 256, 200 s, no hidden blocks, random start mode).
//!
//! The benchmark's numbers are pasted from `../shared/oracle/mario/README.md`
//! §4.1 (the table "Benchmark defaults", the events table) and §6 (P(1)
//! under policy (b)), measured with `run_policies.sh` (`oracle.Oracle
//! --policy fwdjump|random --episodes 1000 --seed 1`). Ours: `cargo run
//! --release -p rlfd-mario --example oracle_policies -- fwdjump 1000 1`.
//! Our levels are not the benchmark's (other random numbers), so these are
//! comparisons of distributions: the criterion is 10 % on returns,
//! outcome shares and ticks, 0.03 absolute on P(1).

use rlfd_mario::LevelParams;
use rlfd_mario::baseline::{FixedPolicy, Outcome, PolicySummary, play};
use rlfd_mario::observation::{CLOSE, MID, OBSTACLE};

/// One policy's figures on the real benchmark.
struct Oracle {
    ret: f64,
    ticks: f64,
    won: f64,
    died: f64,
    timed_out: f64,
    coins: f64,
    hurts: f64,
    distance: f64,
}

const FORWARD_JUMP: Oracle = Oracle {
    ret: 593.2,
    ticks: 382.0,
    won: 0.359,
    died: 0.623,
    timed_out: 0.018,
    coins: 36.0,
    hurts: 1.44,
    distance: 166.1,
};

const RANDOM: Oracle = Oracle {
    ret: -444.7,
    ticks: 2676.0,
    won: 0.0,
    died: 0.147,
    timed_out: 0.853,
    coins: 3.8,
    hurts: 0.27,
    distance: 12.5,
};

/// P(1) under policy (b) on the real benchmark (README §6): jump, ground,
/// shoot (API), x-dir +1, y-dir +1, the 8 close and 8 mid directions from
/// up clockwise, the 4 obstacles; and P(no enemy in the grid).
const P_ONE_FORWARD_JUMP: [(usize, f64); 25] = [
    (0, 0.065),
    (1, 0.125),
    (2, 0.0026),
    (3, 0.807),
    (4, 0.412),
    (CLOSE, 0.002),
    (CLOSE + 1, 0.009),
    (CLOSE + 2, 0.010),
    (CLOSE + 3, 0.013),
    (CLOSE + 4, 0.013),
    (CLOSE + 5, 0.014),
    (CLOSE + 6, 0.011),
    (CLOSE + 7, 0.001),
    (MID, 0.001),
    (MID + 1, 0.027),
    (MID + 2, 0.013),
    (MID + 3, 0.045),
    (MID + 4, 0.014),
    (MID + 5, 0.049),
    (MID + 6, 0.012),
    (MID + 7, 0.002),
    (OBSTACLE, 0.347),
    (OBSTACLE + 1, 0.193),
    (OBSTACLE + 2, 0.146),
    (OBSTACLE + 3, 0.102),
];
const P_NO_ENEMY_FORWARD_JUMP: f64 = 0.034;

fn relative(got: f64, want: f64) -> f64 {
    (got / want - 1.0).abs()
}

/// Checks what holds within the 10 %; the timeout share, a rare
/// outcome, is held to three binomial standard errors of the benchmark's
/// share at 1,000 episodes instead.
fn check(name: &str, s: &PolicySummary, o: &Oracle) {
    let n = s.episodes.len() as f64;
    let ret = s.mean(|e| e.ret);
    assert!(relative(ret, o.ret) <= 0.10, "{name}: mean return {ret:.1} against {}", o.ret);
    let ticks = s.mean(|e| f64::from(e.ticks));
    assert!(relative(ticks, o.ticks) <= 0.10, "{name}: ticks {ticks:.0} against {}", o.ticks);
    for (what, got, want) in [("won", s.share(Outcome::Won), o.won), ("died", s.share(Outcome::Died), o.died)] {
        if want == 0.0 {
            assert_eq!(got, 0.0, "{name}: {what}");
        } else {
            assert!(relative(got, want) <= 0.10, "{name}: {what} {got:.3} against {want}");
        }
    }
    let timed_out = s.share(Outcome::TimedOut);
    let se = (o.timed_out * (1.0 - o.timed_out) / n).sqrt();
    assert!((timed_out - o.timed_out).abs() <= 3.0 * se, "{name}: timed out {timed_out:.3} against {}", o.timed_out);
    // Events per episode: within 10 %, or within three standard errors of
    // the difference of two means of 1,000 episodes (ours and the
    // benchmark's, its sd taken as ours). Since issue 27 our engine replays
    // the benchmark's own episodes tick for tick (`examples/replay_oracle.rs`),
    // so what remains is sampling: other levels, other key draws; for a rare
    // event (random play is hurt 0.27 times an episode) 10 % is tighter than
    // that noise.
    for (what, get, want) in [
        ("coins", (|e| f64::from(e.coins)) as fn(&rlfd_mario::baseline::EpisodeRecord) -> f64, o.coins),
        ("hurts", |e| f64::from(e.hurts), o.hurts),
        ("distance", |e| f64::from(e.distance_cells), o.distance),
    ] {
        let got = s.mean(get);
        let sd = (s.episodes.iter().map(|e| (get(e) - got).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        let se = sd * (2.0 / n).sqrt();
        assert!(
            relative(got, want) <= 0.10 || (got - want).abs() <= 3.0 * se,
            "{name}: {what} {got:.2} against {want} (3 SE {:.3})",
            3.0 * se
        );
    }
}

#[test]
fn the_forward_jumping_policy_plays_as_on_the_real_benchmark() {
    let s = play(FixedPolicy::ForwardJump, LevelParams::EXPERIMENT, 1000, 1);
    check("forward-jumping", &s, &FORWARD_JUMP);
    for (k, want) in P_ONE_FORWARD_JUMP {
        assert!((s.p_one[k] - want).abs() <= 0.03, "P(1) of variable {k}: {:.4} against {want}", s.p_one[k]);
    }
    assert!((s.p_no_enemy - P_NO_ENEMY_FORWARD_JUMP).abs() <= 0.03, "no enemy {:.3}", s.p_no_enemy);
}

#[test]
fn random_play_plays_as_on_the_real_benchmark() {
    let s = play(FixedPolicy::Random, LevelParams::EXPERIMENT, 1000, 1);
    check("random", &s, &RANDOM);
    // The API's shoot is about a coin flip under random play (0.501 on the benchmark).
    assert!((s.p_one[2] - 0.501).abs() <= 0.03, "shoot {:.3}", s.p_one[2]);
    assert!((s.p_no_enemy - 0.700).abs() <= 0.03, "no enemy {:.3}", s.p_no_enemy);
}
