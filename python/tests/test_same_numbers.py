"""Python reproduces the Rust crates' numbers bit for bit: seeded episodes of
every environment (single and vectorised), RIPPER's rules and predictions,
and RE-IRL's fit, against fixtures written by tests/fixtures.rs from the
crates directly. A failure here after a simulator change means the fixtures
are stale: `cd python && RLFD_BLESS=1 cargo test --test fixtures`."""

import glob
import os

import gymnasium as gym
import numpy as np
import pytest

import rlfd
from conftest import FIXTURES, load_fixture

EPISODES = sorted(os.path.basename(p) for p in glob.glob(str(FIXTURES / "*_seed*.json")))


def bits(values) -> list:
    """Floats as their 64-bit patterns: equality of these is equality bit for bit."""
    return np.asarray(values, dtype=np.float64).view(np.uint64).tolist()


def test_every_environment_has_a_fixture():
    names = " ".join(EPISODES)
    for part in ("maze", "mario", "keepaway_3v2", "keepaway_4v3"):
        assert part in names


@pytest.mark.parametrize("name", EPISODES)
def test_a_seeded_episode_is_the_rust_trajectory(name):
    f = load_fixture(name)
    env = gym.make(f["env"], **f["options"]).unwrapped
    obs, _ = env.reset(seed=f["seed"])
    observations, rewards, terminated = [bits(obs)], [], []
    policy = f["policy"]
    hand_coded = None
    if policy == "hand-coded":
        keepers, takers, _ = env.configuration
        hand_coded = rlfd.keepaway.HandCoded(keepers, takers)
    for recorded in f["actions"]:
        if policy == "hand-coded":
            action = hand_coded(obs)
        elif policy == "random":
            action = env.benchmark_action("random")
        else:
            action = recorded
        assert action == recorded
        obs, reward, term, trunc, _ = env.step(action)
        assert not trunc
        observations.append(bits(obs))
        rewards.append(reward)
        terminated.append(term)
    assert observations == [bits(o) for o in f["observations"]]
    assert bits(rewards) == bits(f["rewards"])
    assert terminated == f["terminated"]


@pytest.mark.parametrize("name", ["maze_seed7.json", "mario_seed7.json", "keepaway_3v2_uniform_seed7.json"])
def test_a_vector_instance_is_the_rust_trajectory(name):
    f = load_fixture(name)
    # Instance 2 of a batch reset with seed s − 2 is seeded with s.
    envs = rlfd.make_vec(f["env"], 3, **f["options"])
    obs, _ = envs.reset(seed=f["seed"] - 2)
    assert bits(obs[2]) == bits(f["observations"][0])
    for t, action in enumerate(f["actions"]):
        obs, rewards, term, trunc, infos = envs.step(np.array([0, 0, action]))
        assert bits([rewards[2]]) == bits([f["rewards"][t]])
        assert bool(term[2]) == f["terminated"][t]
        seen = infos["final_obs"][2] if term[2] else obs[2]
        assert bits(seen) == bits(f["observations"][t + 1])


WEKA_LISTING = (
    "JRIP rules:\n===========\n\n"
    "(a1 >= 6.54) and (a2 <= 1.97) and (a0 >= -3.839) => class=mid (53.0/1.0)\n"
    "(a2 >= 5.69) and (a2 <= 5.79) and (a3 <= 2.238) => class=mid (5.0/1.0)\n"
    "(a3 >= 7.699) and (a0 >= -3.517) => class=high (57.0/3.0)\n"
    "(a2 >= 7.92) and (a0 >= -3.593) => class=high (17.0/0.0)\n"
    "(a0 <= -3.974) => class=low (125.0/14.0)\n"
    " => class=rest (143.0/14.0)\n\nNumber of Rules : 6\n"
)
"""Weka 3.6.14's `JRip -F 3 -N 2.0 -O 2 -S 1` on numeric4.arff, as printed
(crates/rlfd-lfd/tests/ripper_weka.rs)."""


def splitmix_draw(i: int, k: int, m: int) -> int:
    """ripper_weka.rs's draw: SplitMix64's output of i·16 + k + golden, mod m."""
    mask = (1 << 64) - 1
    z = (i * 16 + k + 0x9E3779B97F4A7C15) & mask
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & mask
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & mask
    return (z ^ (z >> 31)) % m


def numeric4():
    """The 400 noisy instances of ripper_weka.rs, built here in Python."""
    rows, labels = [], []
    for i in range(400):
        a0 = splitmix_draw(i, 0, 20001) - 10000
        a1 = splitmix_draw(i, 1, 1001)
        a2 = splitmix_draw(i, 2, 2001) - 1000
        a3 = splitmix_draw(i, 3, 10001)
        if a0 < -4000:
            base = 0
        elif a1 > 650 and a2 < 200:
            base = 1
        elif a3 > 7500 or a2 > 800:
            base = 2
        else:
            base = 3
        label = (base + 1 + splitmix_draw(i, 5, 3)) % 4 if splitmix_draw(i, 4, 100) < 12 else base
        rows.append([a0 / 1000, a1 / 100, a2 / 100, a3 / 1000])
        labels.append(label)
    return np.array(rows), np.array(labels)


def test_ripper_gives_weka_s_rules_and_the_rust_predictions():
    X, y = numeric4()
    f = load_fixture("ripper_numeric4.json")
    assert bits(X.ravel()) == bits(np.array(f["x"]).ravel())
    assert y.tolist() == f["y"]
    kw = dict(feature_names=["a0", "a1", "a2", "a3"], class_names=["low", "mid", "high", "rest"], class_attribute="class")
    rules = rlfd.ripper.Ripper().fit(X, y, **kw)
    assert rules.weka_string() == WEKA_LISTING == f["weka_listing"]
    assert str(rules) == f["thesis_listing"]
    assert rules.predict(X).tolist() == f["predictions"]
    assert rules.predict_by_distribution(X).tolist() == f["predictions_by_distribution"]
    # Weka: "Correctly Classified Instances 367 91.75 %" on the training data,
    # 355 in its 10-fold stratified cross-validation (-x 10 -s 1).
    assert int((rules.predict_by_distribution(X) == y).sum()) == 367
    cv = rlfd.ripper.Ripper().cross_validate(X, y, cv_folds=10, cv_seed=1, **kw)
    assert (cv["correct"], cv["total"]) == (355.0, 400.0)
    chacha = rlfd.ripper.Ripper(random="chacha8").fit(X, y, **kw)
    assert chacha.weka_string() == f["chacha8_listing"]
    first = rules.rules()[0]
    assert first["conditions"] == [("a1", ">=", 6.54), ("a2", "<=", 1.97), ("a0", ">=", -3.839)]
    assert (first["class"], first["covered"], first["false_positives"]) == (1, 53.0, 1.0)


def test_re_irl_gives_the_rust_fit():
    f = load_fixture("irl_maze.json")
    demos = rlfd.demonstrations.shipped("maze").pad_to_equal_length()
    horizon = demos.lengths()[0]
    assert horizon == f["horizon"]
    baseline = rlfd.irl.uniform_rollouts("maze", f["baseline_rollouts"], horizon, f["baseline_seed"], step=1)
    assert baseline.shape == (f["baseline_rollouts"], horizon, 2)
    fit = rlfd.irl.relative_entropy(demos, baseline)
    for key in ("weights", "scaled_weights", "expert_feature_counts", "tolerance"):
        assert bits(getattr(fit, key)) == bits(f[key]), key
    for key in ("fitted_norm", "residual", "stability"):
        assert bits([getattr(fit, key)]) == bits([f[key]]), key
    assert bits([fit.objective[-1]]) == bits([f["objective_last"]])
    assert (len(fit.objective), fit.iterations, fit.converged, fit.on_bound) == (
        f["objective_len"], f["iterations"], f["converged"], f["on_bound"])
