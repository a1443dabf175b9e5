//! The oracle's fixed policies on our simulator: the two the real Mario AI
//! Benchmark 0.2.0 was measured with (`../shared/oracle/mario/`, its
//! `Oracle.java`), played episode by episode and summed up as the oracle
//! sums them, so the two can be put side by side.
//!
//! - [`FixedPolicy::Random`]: one of the 12 actions uniformly per tick.
//! - [`FixedPolicy::ForwardJump`]: right and speed held, jump whenever able
//!   and held while in the air (`jump = isMarioAbleToJump() || !onGround`).
//!
//! Episodes draw their level seed and start mode as [`MarioEnv`]'s `reset`
//! does; the random policy draws from its own stream. Ticks count the
//! benchmark's way (the first tick without keys included); a hurt is every
//! creature hit, the fatal one included (the benchmark's
//! `collisionsWithCreatures`; at difficulty 0 there are no gaps, so every
//! death before the timer is a hit).
//!
//! What it is not: IO. The `oracle_policies` example writes the CSV.

use rlfd_env::Environment;
use rlfd_env::random::{below, seeded};

use super::env::{ACTIONS, MarioEnv};
use super::level::{CELL, LevelParams};
use super::observation::{CLOSEST, NO_ENEMY, STATE_VARIABLES};
use super::world::{Mode, Status};

/// A fixed policy of the oracle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FixedPolicy {
    /// Uniformly random actions.
    Random,
    /// Right + speed, jump whenever able (the oracle's policy (b)).
    ForwardJump,
}

/// How an episode ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Outcome {
    /// Reached the exit.
    Won,
    /// Hit (or fell) before the timer ran out.
    Died,
    /// The 3,000-tick timer ran out.
    TimedOut,
}

/// One episode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EpisodeRecord {
    /// The level's seed.
    pub level_seed: u64,
    /// Mario's start mode.
    pub start_mode: Mode,
    /// Points (the benchmark's intermediate reward summed).
    pub ret: f64,
    /// Ticks, the first one included.
    pub ticks: u32,
    /// How it ended.
    pub outcome: Outcome,
    /// Enemies, shells and bullet bills stomped.
    pub stomps: u32,
    /// Coins taken.
    pub coins: u32,
    /// Creature hits, the fatal one included.
    pub hurts: u32,
    /// Mario's final column.
    pub distance_cells: i32,
}

/// What the oracle's summary reports, for one policy.
#[derive(Clone, Debug, PartialEq)]
pub struct PolicySummary {
    /// Every episode, in order.
    pub episodes: Vec<EpisodeRecord>,
    /// P(variable = 1) over the decision states (for x-dir and y-dir: P(+1)).
    pub p_one: [f64; STATE_VARIABLES],
    /// P(variable = −1) over the decision states (nonzero for x-dir and y-dir only).
    pub p_minus_one: [f64; STATE_VARIABLES],
    /// Share of decision states without an enemy in the 22 × 22 grid.
    pub p_no_enemy: f64,
    /// Decision states counted.
    pub states: u64,
    /// Decision states with each variable at 1 (the counts behind `p_one`,
    /// so that summaries of several runs pool exactly).
    pub ones: [u64; STATE_VARIABLES],
    /// Decision states with each variable at −1.
    pub minus_ones: [u64; STATE_VARIABLES],
    /// Decision states without an enemy in the grid.
    pub no_enemy_states: u64,
}

impl PolicySummary {
    /// The mean of `f` over the episodes.
    pub fn mean(&self, f: impl Fn(&EpisodeRecord) -> f64) -> f64 {
        self.episodes.iter().map(f).sum::<f64>() / self.episodes.len() as f64
    }

    /// The share of episodes that ended as `outcome`.
    pub fn share(&self, outcome: Outcome) -> f64 {
        self.mean(|e| f64::from(u8::from(e.outcome == outcome)))
    }
}

/// Plays `policy` for `episodes` episodes on `params`' levels from `seed`.
pub fn play(policy: FixedPolicy, params: LevelParams, episodes: usize, seed: u64) -> PolicySummary {
    let mut env = MarioEnv::new(params);
    let mut rng = seeded(seed);
    let mut act = seeded(seed.wrapping_mul(7919).wrapping_add(17));
    let (mut ones, mut negatives) = ([0u64; STATE_VARIABLES], [0u64; STATE_VARIABLES]);
    let (mut states, mut no_enemy) = (0u64, 0u64);
    let mut records = Vec::with_capacity(episodes);
    for _ in 0..episodes {
        env.reset(&mut rng);
        let start_mode = env.world().mario().mode;
        let level_seed = env.world().level().seed();
        let (mut ret, mut ticks, mut hurts) = (0.0, 1u32, 0u32);
        loop {
            let s = env.state();
            states += 1;
            for (k, &v) in s.iter().enumerate() {
                ones[k] += u64::from(v == 1.0);
                negatives[k] += u64::from(v == -1.0);
            }
            no_enemy += u64::from(s[CLOSEST] == NO_ENEMY);
            let a = match policy {
                FixedPolicy::Random => below(&mut act, ACTIONS),
                // 11 = right+jump+speed, 8 = right+speed.
                FixedPolicy::ForwardJump => {
                    if s[0] == 1.0 || s[1] == 0.0 {
                        11
                    } else {
                        8
                    }
                }
            };
            let mode = env.world().mario().mode;
            let step = env.step(a, &mut rng);
            ret += step.reward;
            ticks += 1;
            hurts += u32::from((env.world().mario().mode as u8) < (mode as u8));
            if step.terminal {
                break;
            }
        }
        let w = env.world();
        let outcome = match w.status() {
            Status::Won => Outcome::Won,
            _ if w.time_left() <= 0 => Outcome::TimedOut,
            _ => Outcome::Died,
        };
        hurts += u32::from(outcome == Outcome::Died);
        records.push(EpisodeRecord {
            level_seed,
            start_mode,
            ret,
            ticks,
            outcome,
            stomps: w.stomps(),
            coins: w.coins(),
            hurts,
            distance_cells: (w.mario().x / CELL) as i32,
        });
    }
    let n = states as f64;
    PolicySummary {
        episodes: records,
        p_one: ones.map(|c| c as f64 / n),
        p_minus_one: negatives.map(|c| c as f64 / n),
        p_no_enemy: no_enemy as f64 / n,
        states,
        ones,
        minus_ones: negatives,
        no_enemy_states: no_enemy,
    }
}
