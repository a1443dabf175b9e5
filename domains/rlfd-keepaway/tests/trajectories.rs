//! Bit-identity of the simulator's trajectories: a regression test that any
//! change meant as a pure speed-up must leave passing.
//!
//! For every benchmark policy (Always Hold, Random, Hand-coded) on 3 vs 2 and
//! 4 vs 3 at 20 m and 25 m it plays seeded episodes through the interface the
//! learners and teachers use (`run`, `state_vars_into`, `last_action_cycle`
//! as the SMDP reward, `act`, `believed_ball`, `pass_receiver`,
//! `snapshot_ago`) and hashes, bit for bit, everything observable: every
//! cycle's positions and the ball's velocity (the trace), every kick command
//! with its power, the kick tally, each decision's keeper, state variables,
//! reward, belief and chosen action, the episodes' durations, causes and
//! final rewards. The same episodes played without the trace must give the
//! same decisions (recording is not allowed to change the game).
//!
//! The expected digests were recorded on the simulator of commit 810b689
//! (issue 28's world model, before the issue 30 speed-up), and re-recorded
//! when issue 28's collision sensing (`updateBallForCollision`) and see
//! phases (`SeePhases::KEEPAWAY_SH`) changed behaviour on purpose, and again
//! when sees of a far ball left out its velocity (issue 28; the digests
//! before, with [`KeepawayParams::drop_far_ball_velocity`] off, are kept and
//! still checked). A change that
//! alters any of them alters results: it is not a speed-up, and needs a
//! behaviour-version bump and a declaration instead of new digests here.

use rlfd_env::random::seeded;
use rlfd_keepaway::{BenchmarkPolicy, Keepaway, KeepawayParams, KeeperAction, MAX_STATE_VARS, STATE_VARS, Status};

/// FNV-1a over 64-bit words: a stable digest (no platform hasher).
struct Digest(u64);

impl Digest {
    fn new() -> Digest {
        Digest(0xcbf2_9ce4_8422_2325)
    }

    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    fn f(&mut self, x: f64) {
        self.word(x.to_bits());
    }
}

/// Episodes per configuration and policy.
const EPISODES: usize = 100;

/// Plays the episodes; returns (the decisions' digest, the full digest).
fn play(params: KeepawayParams, policy: BenchmarkPolicy, seed: u64, traced: bool) -> (u64, u64) {
    let (nk, nt) = (params.keepers, params.takers);
    let mut game = Keepaway::new(params).expect("valid configuration");
    if traced {
        game.record_trace(true);
        game.record_kicks(true);
        game.record_beliefs(true);
        game.keep_history(8);
    }
    let mut rng = seeded(seed);
    let (mut dec, mut full) = (Digest::new(), Digest::new());
    let len = game.params().state_len();
    let mut state = [0.0; MAX_STATE_VARS];
    for _ in 0..EPISODES {
        game.reset(&mut rng);
        let mut status = game.run(&mut rng);
        let cause = loop {
            match status {
                Status::Decision(k) => {
                    if nk == 3 && nt == 2 {
                        // The learners' call.
                        let mut s13 = [0.0; STATE_VARS];
                        game.state_vars(k, &mut s13);
                        state[..STATE_VARS].copy_from_slice(&s13);
                    } else {
                        game.state_vars_into(&mut state[..len]);
                    }
                    let reward = game.last_action_cycle(k).map_or(0.0, |c| f64::from(game.cycle() - c));
                    let action = policy.choose_in(&state[..len], nk, nt, &mut rng);
                    dec.word(u64::from(game.cycle()));
                    dec.word(k as u64);
                    for &v in &state[..len] {
                        dec.f(v);
                    }
                    dec.f(reward);
                    dec.word(action.index() as u64);
                    let (bp, bv) = game.believed_ball(k).expect("a deciding keeper has seen the ball");
                    for v in [bp.x, bp.y, bv.x, bv.y] {
                        dec.f(v);
                    }
                    for a in 1..nk {
                        dec.word(game.pass_receiver(k, KeeperAction(a as u8)).map_or(99, |r| r as u64));
                    }
                    if traced {
                        let s = game.snapshot_ago(2).expect("history kept");
                        full.word(u64::from(s.cycle));
                        full.f(s.ball.x);
                        full.f(s.ball.y);
                    }
                    status = game.act(action, &mut rng);
                }
                Status::Ended(cause) => break cause,
            }
        };
        let end = game.cycle();
        dec.word(u64::from(end));
        dec.word(cause as u64);
        for k in 0..nk {
            dec.word(game.last_action_cycle(k).map_or(u64::MAX, |c| u64::from(end - c)));
        }
        if traced {
            for s in game.trace() {
                full.word(u64::from(s.cycle));
                for v in [s.ball, s.ball_vel].into_iter().chain(s.keepers).chain(s.takers) {
                    full.f(v.x);
                    full.f(v.y);
                }
            }
            for e in game.kicks() {
                full.word(u64::from(e.cycle));
                full.word(u64::from(e.player));
                full.f(e.power);
            }
            let t = game.tally();
            for w in [t.keeper_kicks, t.strong_keeper_kicks, t.taker_kicks, t.passes] {
                full.word(u64::from(w));
            }
            full.word(t.last_by_keeper.map_or(2, u64::from));
            full.word(u64::from(t.last_strong));
            full.word(t.last_strong_keeper_kick.map_or(u64::MAX, u64::from));
            for b in game.keepers().iter().chain(game.takers()) {
                for v in [b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.angle, b.dir.x, b.dir.y] {
                    full.f(v);
                }
            }
        }
    }
    full.word(dec.0);
    (dec.0, full.0)
}

/// (keepers, takers, side, policy, full digest) of the simulator as it is.
const EXPECTED: [(usize, usize, f64, BenchmarkPolicy, u64); 12] = [
    (3, 2, 20.0, BenchmarkPolicy::AlwaysHold, 0x8b3c988208f89f31),
    (3, 2, 20.0, BenchmarkPolicy::Random, 0x2e32f5a4213aa8f5),
    (3, 2, 20.0, BenchmarkPolicy::HandCoded, 0x1da466cab1e17a28),
    (3, 2, 25.0, BenchmarkPolicy::AlwaysHold, 0x597fe2854f175edc),
    (3, 2, 25.0, BenchmarkPolicy::Random, 0x8cc1e4636fda8ea7),
    (3, 2, 25.0, BenchmarkPolicy::HandCoded, 0x072fba2f820e3c77),
    (4, 3, 20.0, BenchmarkPolicy::AlwaysHold, 0xf5aef8e9a5d8e7fc),
    (4, 3, 20.0, BenchmarkPolicy::Random, 0x11f9e4edc1c39c12),
    (4, 3, 20.0, BenchmarkPolicy::HandCoded, 0x82389413838550d7),
    (4, 3, 25.0, BenchmarkPolicy::AlwaysHold, 0x5b9889823991f0f5),
    (4, 3, 25.0, BenchmarkPolicy::Random, 0x3457c00377eeb9e9),
    (4, 3, 25.0, BenchmarkPolicy::HandCoded, 0xf30c2877d88c4e3a),
];

/// With every see carrying the ball's velocity, as before the far sees
/// dropped it (`drop_far_ball_velocity` off): the digests recorded before
/// that mechanism, so the change is that mechanism and nothing else.
const EXPECTED_WITH_EVERY_BALL_VELOCITY: [(usize, usize, f64, BenchmarkPolicy, u64); 12] = [
    (3, 2, 20.0, BenchmarkPolicy::AlwaysHold, 0xb83b64fe9a25a1cd),
    (3, 2, 20.0, BenchmarkPolicy::Random, 0x28db826ca01e7f5c),
    (3, 2, 20.0, BenchmarkPolicy::HandCoded, 0xe5b116702147a5d3),
    (3, 2, 25.0, BenchmarkPolicy::AlwaysHold, 0x8ad6ce06c428a3ef),
    (3, 2, 25.0, BenchmarkPolicy::Random, 0x992a3d2c5b30f022),
    (3, 2, 25.0, BenchmarkPolicy::HandCoded, 0x3220dd09711859a3),
    (4, 3, 20.0, BenchmarkPolicy::AlwaysHold, 0x51f182f9586852c9),
    (4, 3, 20.0, BenchmarkPolicy::Random, 0x68deefd42c9955fd),
    (4, 3, 20.0, BenchmarkPolicy::HandCoded, 0x9eebd6cb2f194fcd),
    (4, 3, 25.0, BenchmarkPolicy::AlwaysHold, 0xf71253ce9e710b02),
    (4, 3, 25.0, BenchmarkPolicy::Random, 0x8a3f7eb5a0908449),
    (4, 3, 25.0, BenchmarkPolicy::HandCoded, 0xb8b6df1ee2763f25),
];

#[test]
fn trajectories_are_bit_identical_to_the_recorded_ones() {
    check(&EXPECTED, true);
}

#[test]
fn without_the_far_ball_velocity_drop_they_are_the_earlier_ones() {
    check(&EXPECTED_WITH_EVERY_BALL_VELOCITY, false);
}

fn check(expected: &[(usize, usize, f64, BenchmarkPolicy, u64)], drop_far_ball_velocity: bool) {
    let mut wrong = Vec::new();
    for (i, &(nk, nt, side, policy, expected)) in expected.iter().enumerate() {
        let seed = 1000 + i as u64;
        let params = KeepawayParams { drop_far_ball_velocity, ..KeepawayParams::configuration(nk, nt, side) };
        let (dec, full) = play(params.clone(), policy, seed, true);
        let (untraced, _) = play(params, policy, seed, false);
        assert_eq!(dec, untraced, "{nk} vs {nt} {side} m {}: recording changed the game", policy.label());
        println!("    ({nk}, {nt}, {side:.1}, BenchmarkPolicy::{policy:?}, {full:#018x}),");
        if full != expected {
            wrong.push(format!("{nk} vs {nt} {side} m {}: {full:#018x}, recorded {expected:#018x}", policy.label()));
        }
    }
    assert!(wrong.is_empty(), "trajectories differ from the recorded ones:\n{}", wrong.join("\n"));
}
