//! The simulator's trajectories, hashed bit for bit: a speed-up of the
//! simulator must leave every one of these hashes unchanged (issue 30: a pure
//! speed-up keeps every result). The constants were recorded on the code
//! before the speed work (commit 810b689) and re-recorded when issue 27 put
//! the tick in the benchmark 0.2.0's order; a change that alters a trajectory
//! fails here and must be declared (behaviour version, docs) and re-recorded
//! on purpose.
//!
//! Each hash covers, tick by tick, the 27 variables (their `f64` bits), the
//! reward, the episode's end, Mario's position, speed and mode, and every
//! sprite on screen (kind, position, in order); at each episode's end, the
//! level's tile counts (blocks bumped, coins taken). Episodes draw their level
//! seed and start mode from the seeded generator as [`MarioEnv::reset`] does.

use rlfd_env::Environment;
use rlfd_env::random::{below, seeded};
use rlfd_mario::level::HiddenBlocks;
use rlfd_mario::observation::Shoot;
use rlfd_mario::{ACTIONS, LevelParams, MarioEnv};

/// FNV-1a over 64-bit words: small, fixed and dependency-free.
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }

    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0100_0000_01b3);
        }
    }
}

#[derive(Clone, Copy)]
enum Policy {
    Random,
    ForwardJump,
}

/// The hash of `episodes` episodes of `policy` from `seed`, and the ticks played.
fn trajectories(policy: Policy, params: LevelParams, shoot: Shoot, seed: u64, episodes: usize) -> (u64, u64) {
    let mut env = MarioEnv::new(params).with_shoot(shoot);
    let mut rng = seeded(seed);
    let mut keys = seeded(seed ^ 0x9e37_79b9_7f4a_7c15);
    let mut h = Fnv::new();
    let mut ticks = 0u64;
    let record = |h: &mut Fnv, env: &MarioEnv| {
        for &v in env.state() {
            h.word(v.to_bits());
        }
        let w = env.world();
        let m = w.mario();
        for v in [m.x, m.y, m.xa, m.ya] {
            h.word(u64::from(v.to_bits()));
        }
        h.word(m.mode as u64);
        h.word(w.sprites().len() as u64);
        for s in w.sprites() {
            h.word(s.kind as u64);
            h.word(u64::from(s.x.to_bits()) << 32 | u64::from(s.y.to_bits()));
        }
    };
    for _ in 0..episodes {
        env.reset(&mut rng);
        h.word(env.world().level().seed());
        record(&mut h, &env);
        loop {
            let s = env.state();
            let a = match policy {
                Policy::Random => below(&mut keys, ACTIONS),
                // The oracle's policy (b): right + speed, jump when able or in the air.
                Policy::ForwardJump => {
                    if s[0] == 1.0 || s[1] == 0.0 {
                        11
                    } else {
                        8
                    }
                }
            };
            let step = env.step(a, &mut rng);
            ticks += 1;
            h.word(step.reward.to_bits());
            h.word(u64::from(step.terminal));
            record(&mut h, &env);
            if step.terminal {
                break;
            }
        }
        for c in env.world().level().tile_counts() {
            h.word(c as u64);
        }
        h.word(u64::from(env.world().stomps()) << 32 | u64::from(env.world().coins()));
    }
    (h.0, ticks)
}

const HIDDEN: LevelParams = LevelParams { hidden_blocks: HiddenBlocks::On, ..LevelParams::EXPERIMENT };
const HARD: LevelParams = LevelParams { difficulty: 3, ..LevelParams::EXPERIMENT };

#[test]
fn random_keys_trajectories_are_unchanged() {
    let got: Vec<_> = [11, 12, 13, 14]
        .into_iter()
        .map(|seed| trajectories(Policy::Random, LevelParams::EXPERIMENT, Shoot::Api, seed, 6))
        .collect();
    assert_eq!(got, EXPECTED_RANDOM, "{got:#x?}");
}

#[test]
fn forward_jumping_trajectories_are_unchanged() {
    let got: Vec<_> = [21, 22, 23, 24]
        .into_iter()
        .map(|seed| trajectories(Policy::ForwardJump, LevelParams::EXPERIMENT, Shoot::Api, seed, 30))
        .collect();
    assert_eq!(got, EXPECTED_FORWARD, "{got:#x?}");
}

#[test]
fn other_levels_and_readings_are_unchanged() {
    let got = vec![
        trajectories(Policy::ForwardJump, HIDDEN, Shoot::Strict, 31, 10),
        trajectories(Policy::Random, HIDDEN, Shoot::Strict, 32, 4),
        trajectories(Policy::ForwardJump, HARD, Shoot::Api, 33, 10),
        trajectories(Policy::Random, HARD, Shoot::Api, 34, 4),
    ];
    assert_eq!(got, EXPECTED_OTHER, "{got:#x?}");
}

/// (hash, ticks) per seed, re-recorded for issue 27's benchmark tick order
/// (Mario behaviour version 6; first recorded at 810b689).
const EXPECTED_RANDOM: [(u64, u64); 4] =
    [(0x5d35bf240f4abf7, 17994), (0xa7136a3e089dc13d, 17994), (0x2da3fd8df6caded3, 16940), (0x5f83567ff2ec7e87, 17994)];
const EXPECTED_FORWARD: [(u64, u64); 4] =
    [(0xec3c9a81c674bc1e, 8945), (0x529d38ba5e10a931, 10368), (0x5d12ac897fe92503, 10927), (0x1c2e682a68d848d9, 13623)];
const EXPECTED_OTHER: [(u64, u64); 4] =
    [(0x24a41643d11e5ef2, 3312), (0xd728aa81b43ddf8c, 11996), (0x34a4e4d834604b64, 638), (0xececdaccd314c34, 3283)];
