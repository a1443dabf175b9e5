//! `mario-validation`: our Mario simulator against the real Mario AI
//! Benchmark 0.2.0 (issue 27), as `keepaway-validation` puts our Keepaway
//! beside the real soccer server.
//!
//! The oracle (`../shared/oracle/mario/`) played two fixed policies on the
//! real benchmark at its defaults (difficulty 0, overground, length 256,
//! 200 s, no hidden blocks, random start mode): uniformly random actions, and
//! right + speed with jump whenever able. This experiment plays the same two
//! policies on our simulator ([`rlfd_mario::baseline`]), 1,000 episodes each
//! at the paper scale (ten trials of 100), and keeps every episode (its
//! level's seed and contents, start mode, points, ticks, outcome, stomps,
//! coins, hurts, distance) and the counts of the 27 variables' values over
//! the decision states. The report sets them beside the oracle's figures,
//! which ship as data (`data/mario-oracle.toml`), with the criteria:
//! returns, outcome shares and ticks within 10 %, level contents within
//! 15 %, every P(1) within 0.03 under the forward-jumping policy.
//!
//! Our levels are not the benchmark's (our generator draws from ChaCha8), so
//! the comparison is of distributions, not of episodes.

use std::collections::BTreeMap;

use rlfd_harness::{Batch, RunContext, RunOptions, Scale, TrialRunner};
use rlfd_mario::baseline::{FixedPolicy, Outcome, play};
use rlfd_mario::level::{EnemyKind, Level, LevelParams, tile};
use rlfd_mario::observation::{NAMES, STATE_VARIABLES};
use rlfd_report::prose::DataFile;
use serde::{Deserialize, Serialize};

use super::Mode;
use crate::{CHAPTER, Ch6Error, Experiment};

/// The two policies, in the report's order.
pub const POLICIES: [FixedPolicy; 2] = [FixedPolicy::ForwardJump, FixedPolicy::Random];

/// The policy's name in result paths and the oracle's data file.
pub fn slug(policy: FixedPolicy) -> &'static str {
    match policy {
        FixedPolicy::ForwardJump => "forward-jump",
        FixedPolicy::Random => "random",
    }
}

/// The policy for people.
pub fn label(policy: FixedPolicy) -> &'static str {
    match policy {
        FixedPolicy::ForwardJump => "right + speed, jump when able",
        FixedPolicy::Random => "uniformly random",
    }
}

/// Trials per policy and episodes per trial at `scale`: 10 × 100 (the
/// oracle's 1,000) or 2 × 20.
pub fn shape(scale: Scale) -> (u32, usize) {
    match scale {
        Scale::Paper => (10, 100),
        Scale::Quick => (2, 20),
    }
}

/// One episode of a fixed policy on our simulator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ValidationEpisode {
    /// The level's seed (ours: not the benchmark's level of that number).
    pub level_seed: u64,
    /// `small`, `large` or `fire`.
    pub start_mode: String,
    /// Points (the benchmark's intermediate reward, the thesis's table).
    pub points: f64,
    /// Ticks, the first one (without keys) included.
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
    pub distance: i32,
    /// The level's goombas, coin tiles, question blocks, bricks and piranha plants.
    pub contents: [u32; 5],
}

/// One trial: a policy's episodes and the counts of the variables' values
/// over their decision states.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ValidationChunk {
    /// The episodes, in order.
    pub episodes: Vec<ValidationEpisode>,
    /// Decision states.
    pub states: u64,
    /// States with each of the 27 variables at 1.
    pub ones: Vec<u64>,
    /// States with each variable at −1.
    pub minus_ones: Vec<u64>,
    /// States without an enemy in the 22 × 22 grid.
    pub no_enemy: u64,
}

/// A level's goombas, coin tiles, question blocks (the three kinds), bricks
/// (the three kinds) and piranha plants, as the oracle's `LevelStats` counts
/// them.
pub fn contents(level: &Level) -> [u32; 5] {
    let t = level.tile_counts();
    let count = |tiles: &[u8]| tiles.iter().map(|&k| t[k as usize] as u32).sum::<u32>();
    let kind = |k: EnemyKind| level.templates().iter().filter(|tp| tp.kind == k).count() as u32;
    [
        kind(EnemyKind::Goomba),
        count(&[tile::COIN]),
        count(&[tile::QUESTION_COIN, tile::QUESTION_POWERUP, tile::QUESTION_COINS]),
        count(&[tile::BRICK, tile::BRICK_COIN, tile::BRICK_POWERUP]),
        kind(EnemyKind::Flower),
    ]
}

fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Small => "small",
        Mode::Large => "large",
        Mode::Fire => "fire",
    }
}

/// The experiment's trials: `episodes` of a policy per trial.
#[derive(Clone, Debug, Serialize)]
pub struct ValidationTrials {
    /// Episodes per trial.
    pub episodes: usize,
}

impl TrialRunner for ValidationTrials {
    type Setup = ();
    type Params = FixedPolicy;
    type Result = ValidationChunk;
    type Error = Ch6Error;

    fn setup(&self) -> Result<(), Ch6Error> {
        Ok(())
    }

    fn run(&self, _: &(), &policy: &FixedPolicy, seed: u64) -> ValidationChunk {
        let params = LevelParams::EXPERIMENT;
        let s = play(policy, params, self.episodes, seed);
        ValidationChunk {
            episodes: s
                .episodes
                .iter()
                .map(|e| ValidationEpisode {
                    level_seed: e.level_seed,
                    start_mode: mode_name(e.start_mode).into(),
                    points: e.ret,
                    ticks: e.ticks,
                    outcome: e.outcome,
                    stomps: e.stomps,
                    coins: e.coins,
                    hurts: e.hurts,
                    distance: e.distance_cells,
                    contents: contents(&Level::generate(params, e.level_seed)),
                })
                .collect(),
            states: s.states,
            ones: s.ones.to_vec(),
            minus_ones: s.minus_ones.to_vec(),
            no_enemy: s.no_enemy_states,
        }
    }
}

/// Plans the experiment: each policy's trials at the run's scale.
pub fn plan(ctx: &RunContext) -> Batch<ValidationTrials> {
    let (trials, episodes) = shape(ctx.scale);
    let mut batch = Batch::new(ctx, CHAPTER, Experiment::MarioValidation, ValidationTrials { episodes });
    for policy in POLICIES {
        for t in 0..trials {
            batch.trial(slug(policy), t, policy);
        }
    }
    batch
}

/// A policy's episodes and counts, its trials pooled.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolicyRun {
    /// Every episode, trial after trial.
    pub episodes: Vec<ValidationEpisode>,
    /// Decision states.
    pub states: u64,
    /// States with each variable at 1.
    pub ones: [u64; STATE_VARIABLES],
    /// States without an enemy in the grid.
    pub no_enemy: u64,
    /// Per trial: its decision states and its states with each variable at 1.
    pub trials: Vec<(u64, [u64; STATE_VARIABLES])>,
}

impl PolicyRun {
    /// The standard error of [`PolicyRun::p_one`] with the trials as
    /// clusters (a ratio of sums: `√(k/(k−1) · Σᵢ (onesᵢ − p·statesᵢ)²) / Σᵢ statesᵢ`),
    /// since the states of one episode are not independent draws: a few long
    /// episodes (timeouts) carry many similar states. NaN below two trials.
    pub fn p_one_se(&self, k: usize) -> f64 {
        let m = self.trials.len();
        if m < 2 || self.states == 0 {
            return f64::NAN;
        }
        let p = self.p_one(k);
        let ss: f64 = self.trials.iter().map(|(n, ones)| (ones[k] as f64 - p * *n as f64).powi(2)).sum();
        (m as f64 / (m as f64 - 1.0) * ss).sqrt() / self.states as f64
    }

    /// The share of the decision states (counted as ticks) spent in
    /// episodes that ended as `outcome`.
    pub fn tick_share(&self, outcome: Outcome) -> f64 {
        let all: u64 = self.episodes.iter().map(|e| u64::from(e.ticks)).sum();
        let of: u64 = self.episodes.iter().filter(|e| e.outcome == outcome).map(|e| u64::from(e.ticks)).sum();
        of as f64 / all.max(1) as f64
    }

    /// The mean of `f` over the episodes.
    pub fn mean(&self, f: impl Fn(&ValidationEpisode) -> f64) -> f64 {
        self.episodes.iter().map(f).sum::<f64>() / self.episodes.len().max(1) as f64
    }

    /// The share of episodes that ended as `outcome`.
    pub fn share(&self, outcome: Outcome) -> f64 {
        self.mean(|e| f64::from(u8::from(e.outcome == outcome)))
    }

    /// P(variable `k` = 1) over the decision states.
    pub fn p_one(&self, k: usize) -> f64 {
        self.ones[k] as f64 / self.states.max(1) as f64
    }

    /// P(no enemy in the grid) over the decision states.
    pub fn p_no_enemy(&self) -> f64 {
        self.no_enemy as f64 / self.states.max(1) as f64
    }
}

/// The experiment's results.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MarioValidation {
    /// Per policy, its trials pooled.
    pub runs: BTreeMap<FixedPolicy, PolicyRun>,
}

/// Runs (or loads) the batch and pools each policy's trials.
pub fn run(batch: &Batch<ValidationTrials>, options: &RunOptions) -> Result<MarioValidation, Ch6Error> {
    let out = batch.execute(options)?;
    let mut runs: BTreeMap<FixedPolicy, PolicyRun> = BTreeMap::new();
    for (t, chunk) in batch.trials().iter().zip(out.results) {
        let run = runs.entry(t.params).or_default();
        run.states += chunk.states;
        run.no_enemy += chunk.no_enemy;
        let mut ones = [0u64; STATE_VARIABLES];
        for (k, one) in ones.iter_mut().enumerate() {
            *one = chunk.ones.get(k).copied().unwrap_or(0);
            run.ones[k] += *one;
        }
        run.trials.push((chunk.states, ones));
        run.episodes.extend(chunk.episodes);
    }
    Ok(MarioValidation { runs })
}

/// The real benchmark's figures for one policy (`data/mario-oracle.toml`).
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct OraclePolicy {
    /// Episodes measured.
    pub episodes: u32,
    /// Mean points.
    #[serde(rename = "return")]
    pub points: f64,
    /// Standard deviation of the points.
    pub return_sd: f64,
    /// Mean ticks.
    pub ticks: f64,
    /// Share won.
    pub won: f64,
    /// Share died.
    pub died: f64,
    /// Share timed out.
    pub timed_out: f64,
    /// Stomp kills per episode.
    pub stomps: f64,
    /// Coins per episode.
    pub coins: f64,
    /// Hurts per episode.
    pub hurts: f64,
    /// Final column.
    pub distance: f64,
    /// P(no enemy in the grid).
    pub p_no_enemy: f64,
    /// P(variable = 1) by the variable's name.
    pub p_one: BTreeMap<String, f64>,
}

/// The real benchmark's level contents per level.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct OracleLevels {
    pub goombas: f64,
    pub coin_tiles: f64,
    pub question_blocks: f64,
    pub bricks: f64,
    pub plants: f64,
}

/// Everything the oracle measured that the report compares.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct Oracle {
    #[serde(rename = "forward-jump")]
    pub forward_jump: OraclePolicy,
    pub random: OraclePolicy,
    pub levels: OracleLevels,
}

impl Oracle {
    /// The figures for `policy`.
    pub fn policy(&self, policy: FixedPolicy) -> &OraclePolicy {
        match policy {
            FixedPolicy::ForwardJump => &self.forward_jump,
            FixedPolicy::Random => &self.random,
        }
    }
}

/// The oracle's data file.
pub const ORACLE: DataFile = DataFile {
    path: "chapters/ch6-irl-shaping/data/mario-oracle.toml",
    text: include_str!("../../data/mario-oracle.toml"),
};

/// The oracle's figures, checked: every P(1) names one of the 27 variables.
pub fn oracle() -> Result<Oracle, String> {
    let o: Oracle = toml::from_str(ORACLE.text).map_err(|e| format!("{}: {e}", ORACLE.path))?;
    for p in [&o.forward_jump, &o.random] {
        if let Some(name) = p.p_one.keys().find(|n| !NAMES.contains(&n.as_str())) {
            return Err(format!("{}: p_one names `{name}`, not one of the 27 variables", ORACLE.path));
        }
    }
    Ok(o)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oracle_s_figures_parse_and_name_the_variables() {
        let o = oracle().unwrap();
        assert_eq!(o.forward_jump.points, 593.2);
        assert_eq!(o.random.p_one["shoot"], 0.501);
        assert_eq!(o.forward_jump.p_one.len(), 25, "every boolean and direction variable");
        assert_eq!(o.levels.goombas, 42.6);
    }

    #[test]
    fn a_trial_pools_its_episodes_counts_and_level_contents() {
        let chunk = ValidationTrials { episodes: 3 }.run(&(), &FixedPolicy::ForwardJump, 7);
        assert_eq!(chunk.episodes.len(), 3);
        let ticks: u64 = chunk.episodes.iter().map(|e| u64::from(e.ticks - 1)).sum();
        assert_eq!(chunk.states, ticks, "one decision state per tick after the first");
        let e = &chunk.episodes[0];
        assert_eq!(e.contents, contents(&Level::generate(LevelParams::EXPERIMENT, e.level_seed)));
        assert!(e.contents[0] > 10 && e.contents[1] > 50, "a 0.2.0 level: {:?}", e.contents);
    }

    #[test]
    fn p_one_has_a_cluster_standard_error_over_the_trials() {
        let mut run = PolicyRun::default();
        for (n, o) in [(100u64, 30u64), (300, 60), (200, 70)] {
            let mut ones = [0; STATE_VARIABLES];
            ones[21] = o;
            run.states += n;
            run.ones[21] += o;
            run.trials.push((n, ones));
        }
        // p = 160/600; residuals 30 − 26.67, 60 − 80, 70 − 53.33: Σ² = 11.11 + 400 + 277.78 = 688.89;
        // se = √(3/2 · 688.89)/600 = 32.146/600 (numpy: np.sqrt(1.5*((30-100*p)**2+(60-300*p)**2+(70-200*p)**2))/600).
        let p: f64 = 160.0 / 600.0;
        let want = (1.5 * ((30.0 - 100.0 * p).powi(2) + (60.0 - 300.0 * p).powi(2) + (70.0 - 200.0 * p).powi(2)))
            .sqrt()
            / 600.0;
        assert!((run.p_one_se(21) - want).abs() < 1e-15 && (want - 0.053_576).abs() < 1e-5, "{}", run.p_one_se(21));
        run.trials.truncate(1);
        assert!(run.p_one_se(21).is_nan(), "one trial gives no standard error");
    }
}
