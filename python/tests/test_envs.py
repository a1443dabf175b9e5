"""The environments keep Gymnasium's contract: check_env passes, seeded
resets are deterministic, spaces and pictures are what the docs say, and
Keepaway's step is the keepers' SMDP decision with the episode's duration as
its return."""

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import rlfd

IDS = ["rlfd/Maze-v0", "rlfd/Mario-v0", "rlfd/Keepaway-3v2-v0", "rlfd/Keepaway-4v3-v0"]


@pytest.mark.parametrize("env_id", IDS)
def test_check_env_passes(env_id):
    env = gym.make(env_id, render_mode="rgb_array")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    messages = [str(w.message) for w in caught]
    # Keepaway's distances are unbounded above (players may stray past the
    # region's lines): the one warning check_env gives, and the only one allowed.
    assert all("maximum value is infinity" in m for m in messages), messages
    assert bool(messages) == env_id.startswith("rlfd/Keepaway")


@pytest.mark.parametrize(
    "env_id, dim, actions, picture",
    [
        ("rlfd/Maze-v0", 2, 4, (400, 400, 3)),
        ("rlfd/Mario-v0", 27, 12, (120, 256, 3)),
        ("rlfd/Keepaway-3v2-v0", 13, 3, (240, 240, 3)),
        ("rlfd/Keepaway-4v3-v0", 19, 4, (240, 240, 3)),
    ],
)
def test_spaces_and_pictures(env_id, dim, actions, picture):
    env = gym.make(env_id, render_mode="rgb_array")
    assert env.observation_space.shape == (dim,)
    assert env.observation_space.dtype == np.float64
    assert env.action_space.n == actions
    obs, _ = env.reset(seed=4)
    assert obs.shape == (dim,) and env.observation_space.contains(obs)
    frame = env.render()
    assert frame.shape == picture and frame.dtype == np.uint8
    assert len(env.unwrapped.state_names) == dim and len(env.unwrapped.action_names) == actions


def test_the_maze_starts_at_the_thesis_s_start_and_pays_its_rewards():
    env = gym.make("rlfd/Maze-v0")
    obs, _ = env.reset(seed=0)
    assert obs.tolist() == [0.08, 0.6]
    obs, reward, term, trunc, _ = env.step(2)  # up
    assert (obs.tolist(), reward, term, trunc) == ([0.08, 0.62], -1.0, False, False)
    for _ in range(4):
        env.step(0)  # left, to the border
    obs, reward, *_ = env.step(0)
    assert (obs.tolist(), reward) == ([0.0, 0.62], -11.0)
    assert env.unwrapped.action_names == ["left", "right", "up", "down"]


def test_the_maze_cap_truncates():
    assert gym.make("rlfd/Maze-v0").spec.max_episode_steps == 6000
    env = gym.make("rlfd/Maze-v0", max_episode_steps=3)  # Gymnasium's TimeLimit
    env.reset(seed=0)
    assert [env.step(1)[3] for _ in range(3)] == [False, False, True]
    env = rlfd.envs.MazeEnv(max_episode_steps=3)  # the simulator's own cap
    env.reset(seed=0)
    assert [env.step(1)[3] for _ in range(3)] == [False, False, True]
    with pytest.raises(ValueError, match="the episode has ended: call reset"):
        env.step(1)


def test_seeded_resets_repeat_and_unseeded_ones_continue():
    env = gym.make("rlfd/Mario-v0")
    a = env.reset(seed=12)[0]
    first = [env.step(11)[0] for _ in range(30)]
    b = env.reset()[0]  # continues the stream: another level
    assert env.reset(seed=12)[0].tolist() == a.tolist()
    again = [env.step(11)[0] for _ in range(30)]
    assert [x.tolist() for x in again] == [x.tolist() for x in first]
    assert b.shape == a.shape


def test_a_keepaway_episode_returns_its_duration_and_the_keepers_smdp_rewards():
    env = gym.make("rlfd/Keepaway-3v2-v0")
    policy = rlfd.keepaway.HandCoded()
    obs, info = env.reset(seed=21)
    assert set(info) >= {"keeper", "smdp_reward", "cycle"} and info["smdp_reward"] == 0.0
    total, steps, last_action = 0.0, 0, {}
    done = False
    while not done:
        keeper, cycle = info["keeper"], info["cycle"]
        if keeper in last_action:
            # Chapter 5's keeper is rewarded the cycles since its own last
            # action: its last decision, or a later follow-through kick of a pass.
            assert 1 <= info["smdp_reward"] <= cycle - last_action[keeper]
        else:
            assert info["smdp_reward"] == 0.0
        last_action[keeper] = cycle
        obs, reward, done, trunc, info = env.step(policy(obs))
        assert reward >= 1.0 and not trunc
        total += reward
        steps += 1
    assert total == info["cycle"] and steps > 1
    assert info["end_cause"] in ("out", "taken")
    finals = info["final_smdp_rewards"]
    for k in range(3):
        if k in last_action:
            assert 0 <= finals[k] <= info["cycle"] - last_action[k]
        else:
            assert np.isnan(finals[k])


def test_the_benchmark_policies_rank_as_published():
    # Always Hold < Random < Hand-coded in mean episode duration (the keepaway
    # benchmark's order: about 2.9 s, 4.7 s and 13 s on the real server).
    def mean_duration(name, episodes=60):
        env = gym.make("rlfd/Keepaway-3v2-v0")
        policy = rlfd.keepaway.policy(name, seed=5)
        total = 0.0
        for e in range(episodes):
            obs, _ = env.reset(seed=1000 + e)
            done = False
            while not done:
                obs, r, done, _, _ = env.step(policy(obs))
                total += r
        return total / episodes

    hold, random, hand = (mean_duration(n) for n in ("always-hold", "random", "hand-coded"))
    assert hold < random < hand, (hold, random, hand)


def test_policies_are_callables_of_the_configuration():
    p = rlfd.keepaway.HandCoded(4, 3)
    obs = np.zeros(19)
    obs[3] = 6.0  # nearest taker 6 m away: hold
    assert p(obs) == 0
    with pytest.raises(ValueError, match="expected an observation of 4 vs 3 of 19 values, got 13"):
        p(np.zeros(13))
    random = rlfd.keepaway.Random(seed=1)
    assert {random(np.zeros(13)) for _ in range(50)} == {0, 1, 2}
