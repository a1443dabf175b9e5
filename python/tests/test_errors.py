"""A bad argument raises one clear Python exception; nothing panics across
the boundary."""

import gymnasium as gym
import numpy as np
import pytest

import rlfd


def test_unknown_and_invalid_options():
    with pytest.raises(ValueError) as e:
        gym.make("rlfd/Keepaway-3v2-v0", keeper=4)
    assert str(e.value) == 'unknown keepaway option "keeper": expected one of keepers, takers, region, max_episode_steps'
    with pytest.raises(ValueError, match=r"keepaway option keepers=7 is invalid: expected 3, 4 or 5"):
        gym.make("rlfd/Keepaway-3v2-v0", keepers=7)
    with pytest.raises(ValueError, match="keepaway option region=5 is invalid"):
        gym.make("rlfd/Keepaway-3v2-v0", region=5)
    with pytest.raises(ValueError, match='maze option layout="spiral" is invalid'):
        gym.make("rlfd/Maze-v0", layout="spiral")
    with pytest.raises(ValueError, match="maze option max_episode_steps=True is invalid: expected a positive integer"):
        rlfd.envs.MazeEnv(max_episode_steps=True)
    with pytest.raises(ValueError, match=r"keepaway option keepers=\[4\] is invalid"):
        rlfd.envs.KeepawayEnv(keepers=[4])
    with pytest.raises(ValueError, match="render_mode must be None or 'rgb_array'"):
        rlfd.envs.MazeEnv(render_mode="human")


def test_bad_steps_and_seeds():
    env = gym.make("rlfd/Mario-v0").unwrapped
    with pytest.raises(ValueError, match=r"call reset\(\) before step\(\)"):
        env.step(0)
    env.reset(seed=1)
    with pytest.raises(ValueError, match="action 12 is out of range: expected 0 to 11"):
        env.step(12)
    with pytest.raises(ValueError, match="action -1 is out of range"):
        env.step(-1)
    with pytest.raises(TypeError):
        env.step(1.5)
    with pytest.raises(ValueError, match=r"seed must be in 0 … 2\*\*64 - 1, got -3"):
        env.reset(seed=-3)
    with pytest.raises(TypeError, match="seed must be an integer, got str"):
        env.reset(seed="7")
    with pytest.raises(ValueError, match="reset\\(\\) takes no options"):
        env.reset(seed=1, options={"level": 3})
    env.reset(seed=2**64 - 1)  # the largest seed is fine


def test_wrong_shaped_arrays():
    X = np.zeros((10, 2))
    y = np.array([0, 1] * 5)
    with pytest.raises(ValueError, match=r"X must be a 2-D array \(instances × attributes\), got shape \(20,\)"):
        rlfd.ripper.fit(X.ravel(), y)
    with pytest.raises(ValueError, match="y must be a 1-D array of 10 class labels"):
        rlfd.ripper.fit(X, y[:9])
    with pytest.raises(TypeError, match="y must hold integer class indices"):
        rlfd.ripper.fit(X, y.astype(float))
    with pytest.raises(ValueError, match="expected 2 feature names"):
        rlfd.ripper.fit(X, y, feature_names=["x"])
    rules = rlfd.ripper.fit(np.arange(30.0).reshape(15, 2), np.array([0, 1, 1] * 5))
    with pytest.raises(ValueError, match="expected rows of 2 attribute values, got 3"):
        rules.predict(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="row 0: class label 3 is out of range"):
        rlfd.ripper.fit(X, np.array([3] + [0] * 9), class_names=["a", "b"])
    with pytest.raises(ValueError, match="unknown random stream"):
        rlfd.ripper.Ripper(random="mersenne").fit(X, y)
    with pytest.raises(ValueError, match="folds"):
        rlfd.ripper.Ripper(folds=1).fit(X, y)


def test_irl_refuses_unequal_lengths_and_bad_shapes():
    expert = [np.zeros((5, 2)), np.zeros((4, 2))]
    with pytest.raises(ValueError, match="RE-IRL needs trajectories of equal length: expert trajectory 1 has 4"):
        rlfd.irl.relative_entropy(expert, np.zeros((3, 5, 2)))
    with pytest.raises(ValueError, match=r"baseline must be a 3-D array .* got shape \(5, 2\)"):
        rlfd.irl.relative_entropy(np.zeros((2, 5, 2)), np.zeros((5, 2)))
    with pytest.raises(ValueError, match="baseline trajectories have 6 observations, but the expert's have 5"):
        rlfd.irl.relative_entropy(np.zeros((2, 5, 2)), np.zeros((3, 6, 2)))
    with pytest.raises(ValueError, match="expected 2 feature ranges"):
        rlfd.irl.relative_entropy(np.zeros((2, 5, 2)), np.zeros((3, 5, 2)), feature_ranges=[1.0])
    with pytest.raises(ValueError, match="Hoeffding needs 0 < delta < 1"):
        rlfd.irl.relative_entropy(np.zeros((2, 5, 2)), np.zeros((3, 5, 2)), delta=2.0)


def test_malformed_demonstration_files(tmp_path):
    bad = tmp_path / "demos.csv"
    bad.write_text("trajectory,step,x,y,action\n0,0,0.08,0.6,1\n0,1,abc,0.6,\n")
    with pytest.raises(ValueError) as e:
        rlfd.demonstrations.read(bad)
    assert str(e.value) == f'{bad}:3: field "x": "abc" is not a number'
    with pytest.raises(ValueError, match=r"demos.jsonl:2: .*states"):
        rlfd.demonstrations.parse('{"state_names":["x"]}\n{"states":"no"}\n', "jsonl", name="demos.jsonl")
    with pytest.raises(ValueError, match="unknown file format"):
        rlfd.demonstrations.read(tmp_path / "demos.txt")
    with pytest.raises(ValueError, match='<string>:2: field "action": 7 is out of range 0..4'):
        rlfd.demonstrations.parse("trajectory,step,x,action\n0,0,1.0,7\n", "csv", num_actions=4)
    with pytest.raises(ValueError, match="cannot read"):
        rlfd.demonstrations.read(tmp_path / "missing.csv")


def test_state_arguments_of_the_callables():
    coder = rlfd.features.TileCoder(2, [0.5], [0.0], [1.0])
    assert coder([0.25]).tolist() == coder(np.array([0.25], dtype=np.float32)).tolist()
    with pytest.raises(ValueError, match=r"a state: value 0 is NaN \(values must be finite\)"):
        coder(np.array([np.nan]))
    with pytest.raises(ValueError, match=r"expected a state as a 1-D array of 1 values, got shape \[2, 1\]"):
        coder(np.zeros((2, 1)))
    with pytest.raises(TypeError, match="expected a state as numbers, got str"):
        coder("abc")
    with pytest.raises(ValueError, match=r"expected an observation of 3 vs 2 as a 1-D array of 13 values, got shape \[2, 13\]"):
        rlfd.keepaway.HandCoded()(np.zeros((2, 13)))
    with pytest.raises(ValueError, match="expected an observation of 3 vs 2 of 13 values, got 19"):
        rlfd.keepaway.HandCoded()(np.zeros(19))
    sbs = rlfd.shaping.SimilarityPotential(np.zeros((2, 2)), np.array([0, 1]), 2, [0.1, 0.1])
    with pytest.raises(ValueError, match="value 1 is inf"):
        sbs([0.0, np.inf])
    assert rlfd.irl.LinearReward([1.0, 2.0])([1, 1]) == 3.0
