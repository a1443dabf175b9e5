//! The reference numbers Python must reproduce bit for bit, computed here
//! from the workspace's crates directly (not through this crate's adapters),
//! and the demonstrations the package ships.
//!
//! Each fixture is a JSON file in `tests/fixtures/` (floats in Rust's
//! shortest round-trip form, which Python's `json` reads back to the same
//! bits); `tests/test_same_numbers.py` replays it through `rlfd`:
//!
//! - one seeded episode per environment: the seed, the actions, every
//!   observation, reward and end flag (Maze, Mario, Keepaway 3 vs 2 with
//!   random actions, with the Hand-coded and the benchmark's Random policy,
//!   and 4 vs 3 on 25 m);
//! - RIPPER (Weka 3.6's JRip) on the 400 noisy instances of
//!   `rlfd-lfd/tests/ripper_weka.rs`, whose listing is Weka's own;
//! - RE-IRL on the shipped Maze demonstrations, padded, against uniform
//!   rollouts at the demonstrator's resolution, with the chapter's settings.
//!
//! `cargo test --test fixtures` checks that the files are what the crates
//! compute now; `RLFD_BLESS=1 cargo test --test fixtures` rewrites them
//! (after a change that moves a simulator's numbers: the golden test of the
//! root workspace names it too).

use std::path::{Path, PathBuf};

use rlfd_env::Environment;
use rlfd_env::random::{SimRng, below, seeded};
use rlfd_keepaway::{BenchmarkPolicy, Keepaway, KeepawayParams, KeeperAction, Status};
use rlfd_lfd::irl::{
    IrlFeatureScale, Normalisation, RelativeEntropyIrl, RelativeEntropyIrlParams, StateVariables, Stopping, Tolerance,
    rollout_uniform,
};
use rlfd_lfd::ripper::{Attribute, Dataset, Ripper, RipperParams};
use rlfd_mario::{ACTIONS, LevelParams, MarioEnv};
use rlfd_maze::demonstrator::{MazeDemonstrator, thesis, to_demonstration_set};
use rlfd_maze::{Maze, MazeLayout, MazeRewards};
use serde_json::{Value, json};

/// The actions of the fixtures come from their own stream, seeded with this.
const ACTION_STREAM: u64 = 0x6163_7469_6f6e_7321; // "actions!"

/// The seed of the shipped Maze demonstrations.
const DEMONSTRATION_SEED: u64 = 2011;

/// The seed of RE-IRL's uniform baseline rollouts in the fixture.
const BASELINE_SEED: u64 = 99;

/// Baseline rollouts in the fixture (the chapter uses 1,000).
const BASELINE_ROLLOUTS: usize = 200;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// Compares `text` with the committed file, or writes it under `RLFD_BLESS=1`.
fn check_or_bless(path: &Path, text: &str) {
    if std::env::var_os("RLFD_BLESS").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        committed == text,
        "{} is not what the crates compute now: rerun with RLFD_BLESS=1 and commit it",
        path.display()
    );
}

fn fixture(name: &str, value: &Value) {
    let mut text = serde_json::to_string(value).unwrap();
    text.push('\n');
    check_or_bless(&root().join("tests/fixtures").join(name), &text);
}

/// An episode as the fixture records it.
#[derive(Default)]
struct Episode {
    actions: Vec<usize>,
    observations: Vec<Vec<f64>>,
    rewards: Vec<f64>,
    terminated: Vec<bool>,
}

impl Episode {
    fn json(self, env: &str, options: Value, seed: u64, policy: &str) -> Value {
        json!({
            "env": env, "options": options, "seed": seed, "policy": policy,
            "actions": self.actions, "observations": self.observations,
            "rewards": self.rewards, "terminated": self.terminated,
        })
    }
}

/// An `Environment` from `reset` with `seeded(seed)`, actions drawn from the action stream.
fn environment_episode<E: Environment>(env: &mut E, seed: u64, max_steps: usize) -> Episode {
    let mut rng = seeded(seed);
    let mut choices = seeded(ACTION_STREAM);
    env.reset(&mut rng);
    let mut e = Episode { observations: vec![env.state().to_vec()], ..Episode::default() };
    for _ in 0..max_steps {
        let a = below(&mut choices, env.num_actions());
        let s = env.step(a, &mut rng);
        e.actions.push(a);
        e.observations.push(env.state().to_vec());
        e.rewards.push(s.reward);
        e.terminated.push(s.terminal);
        if s.terminal {
            break;
        }
    }
    e
}

#[test]
fn maze_episode() {
    let mut maze = Maze::new(MazeLayout::thesis(), 2, MazeRewards::THESIS);
    let e = environment_episode(&mut maze, 7, 400);
    fixture("maze_seed7.json", &e.json("rlfd/Maze-v0", json!({}), 7, "uniform"));
}

#[test]
fn mario_episode() {
    let mut mario = MarioEnv::new(LevelParams::EXPERIMENT);
    let e = environment_episode(&mut mario, 7, 600);
    assert_eq!(mario.num_actions(), ACTIONS);
    fixture("mario_seed7.json", &e.json("rlfd/Mario-v0", json!({}), 7, "uniform"));
}

/// Keepaway's SMDP: `reset` (again while an episode ends before any
/// decision), then decisions until the end; reward = cycles per step.
fn keepaway_episode(params: KeepawayParams, seed: u64, policy: &str) -> Episode {
    let (keepers, takers) = (params.keepers, params.takers);
    let mut game = Keepaway::new(params).unwrap();
    let mut rng = seeded(seed);
    let mut choices: SimRng = seeded(ACTION_STREAM);
    let mut state = vec![0.0; game.params().state_len()];
    let mut status = loop {
        game.reset(&mut rng);
        match game.run(&mut rng) {
            s @ Status::Decision(_) => break s,
            Status::Ended(_) => continue,
        }
    };
    game.state_vars_into(&mut state);
    let mut e = Episode { observations: vec![state.clone()], ..Episode::default() };
    let mut previous = 0;
    while let Status::Decision(_) = status {
        let a = match policy {
            "uniform" => below(&mut choices, keepers),
            "hand-coded" => BenchmarkPolicy::HandCoded.choose_in(&state, keepers, takers, &mut rng).index(),
            "random" => BenchmarkPolicy::Random.choose_in(&state, keepers, takers, &mut rng).index(),
            other => panic!("no policy {other}"),
        };
        status = game.act(KeeperAction(a as u8), &mut rng);
        let cycle = game.cycle();
        e.actions.push(a);
        e.rewards.push(f64::from(cycle - previous));
        previous = cycle;
        if let Status::Decision(_) = status {
            game.state_vars_into(&mut state);
        }
        e.observations.push(state.clone());
        e.terminated.push(matches!(status, Status::Ended(_)));
    }
    e
}

#[test]
fn keepaway_episodes() {
    for (policy, seed) in [("uniform", 7), ("hand-coded", 8), ("random", 9)] {
        let e = keepaway_episode(KeepawayParams::benchmark(), seed, policy);
        assert!(e.actions.len() > 1, "{policy}: a one-decision episode makes a weak fixture");
        fixture(
            &format!("keepaway_3v2_{policy}_seed{seed}.json"),
            &e.json("rlfd/Keepaway-3v2-v0", json!({}), seed, policy),
        );
    }
    let e = keepaway_episode(KeepawayParams::configuration(4, 3, 25.0), 11, "hand-coded");
    fixture(
        "keepaway_4v3_region25_hand-coded_seed11.json",
        &e.json("rlfd/Keepaway-3v2-v0", json!({"keepers": 4, "takers": 3, "region": 25.0}), 11, "hand-coded"),
    );
}

/// `rlfd-lfd/tests/ripper_weka.rs`'s draw: SplitMix64's output of
/// `i·16 + k + golden`, modulo `m`.
fn draw(i: u64, k: u64, m: u64) -> u64 {
    let mut z = (i * 16 + k).wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) % m
}

#[test]
fn ripper_on_weka_s_data() {
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for i in 0..400 {
        let a0 = draw(i, 0, 20_001) as i64 - 10_000;
        let a1 = draw(i, 1, 1001) as i64;
        let a2 = draw(i, 2, 2001) as i64 - 1000;
        let a3 = draw(i, 3, 10_001) as i64;
        let base = if a0 < -4000 {
            0
        } else if a1 > 650 && a2 < 200 {
            1
        } else if a3 > 7500 || a2 > 800 {
            2
        } else {
            3
        };
        let label = if draw(i, 4, 100) < 12 { (base + 1 + draw(i, 5, 3)) % 4 } else { base };
        rows.push(vec![a0 as f64 / 1000.0, a1 as f64 / 100.0, a2 as f64 / 100.0, a3 as f64 / 1000.0]);
        labels.push(label as usize);
    }
    let attributes = ["a0", "a1", "a2", "a3"].map(Attribute::numeric).to_vec();
    let classes: Vec<String> = ["low", "mid", "high", "rest"].iter().map(|s| s.to_string()).collect();
    let data = Dataset::new(attributes, rows.clone(), "class", classes.clone(), labels.clone()).unwrap();
    let weka = Ripper::fit(&RipperParams::weka_3_6(), &data).unwrap();
    let chacha = Ripper::fit(&RipperParams::weka_defaults(), &data).unwrap();
    let predictions: Vec<usize> = rows.iter().map(|r| weka.predict(r)).collect();
    let by_distribution: Vec<usize> = rows.iter().map(|r| weka.predict_by_distribution(r)).collect();
    fixture(
        "ripper_numeric4.json",
        &json!({
            "x": rows, "y": labels, "attributes": ["a0", "a1", "a2", "a3"], "class_attribute": "class",
            "class_names": classes, "weka_listing": weka.to_weka_string(), "thesis_listing": weka.to_string(),
            "chacha8_listing": chacha.to_weka_string(), "predictions": predictions,
            "predictions_by_distribution": by_distribution,
        }),
    );
}

#[test]
fn shipped_maze_demonstrations_and_re_irl() {
    let demos = MazeDemonstrator::thesis().record(&mut seeded(DEMONSTRATION_SEED), thesis::COUNT, thesis::LENGTH_RANGE);
    let set = to_demonstration_set(&demos);
    let mut text = Vec::new();
    set.write_jsonl(&mut text).unwrap();
    check_or_bless(&root().join("rlfd/data/maze-demonstrations.jsonl"), std::str::from_utf8(&text).unwrap());

    // The chapter's RE-IRL (ch6 `shaping::inputs`): padded demonstrations,
    // Hoeffding's tolerance with δ = 0.05 and the ranges (1, 1), features
    // scaled to them, ‖θ‖ ≤ 1, unit length at the end; the baseline walks
    // at the demonstrator's step of 0.01.
    let padded = set.pad_to_equal_length();
    let horizon = padded.require_equal_lengths().unwrap();
    let ranges = vec![1.0, 1.0];
    let params = RelativeEntropyIrlParams {
        discount: 1.0,
        tolerance: Tolerance::Hoeffding { delta: 0.05, feature_ranges: ranges.clone() },
        feature_scale: IrlFeatureScale::Ranges(ranges),
        norm_bound: Some(1.0),
        stopping: Stopping::DEFAULT,
        normalisation: Normalisation::UnitL2,
    };
    let irl = RelativeEntropyIrl::new(params).unwrap();
    let features = StateVariables { dim: 2 };
    let expert = irl.feature_counts_of(&padded, &features).unwrap();
    let mut walker = Maze::new(MazeLayout::thesis(), 1, MazeRewards::THESIS);
    let baseline = rollout_uniform(&mut walker, &mut seeded(BASELINE_SEED), BASELINE_ROLLOUTS, horizon, &features, 1.0);
    let fit = irl.fit(&expert, &baseline, horizon).unwrap();
    fixture(
        "irl_maze.json",
        &json!({
            "baseline_seed": BASELINE_SEED, "baseline_rollouts": BASELINE_ROLLOUTS, "horizon": horizon,
            "weights": fit.weights, "scaled_weights": fit.scaled_weights, "fitted_norm": fit.fitted_norm,
            "expert_feature_counts": fit.expert_feature_counts, "tolerance": fit.tolerance,
            "objective_last": fit.objective.last(), "objective_len": fit.objective.len(),
            "converged": fit.converged, "on_bound": fit.on_bound, "residual": fit.residual,
            "stability": fit.stability, "iterations": fit.iterations,
        }),
    );
}
