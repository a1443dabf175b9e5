"""The vector environment: the same numbers as single environments, same-step
autoreset, Gymnasium's make_vec, and bad actions refused before any instance
moves."""

import gymnasium as gym
import numpy as np
import pytest

import rlfd


@pytest.mark.parametrize("env_id", ["rlfd/Maze-v0", "rlfd/Mario-v0", "rlfd/Keepaway-3v2-v0"])
def test_the_batch_is_the_single_environments(env_id):
    n = 4
    envs = rlfd.make_vec(env_id, n, max_episode_steps=40)
    domain, _ = rlfd.envs.domain_of(env_id)
    cls = {"maze": rlfd.envs.MazeEnv, "mario": rlfd.envs.MarioEnv, "keepaway": rlfd.envs.KeepawayEnv}[domain]
    singles = [cls(max_episode_steps=40) for _ in range(n)]
    obs, _ = envs.reset(seed=100)
    for i, s in enumerate(singles):
        assert s.reset(seed=100 + i)[0].tolist() == obs[i].tolist()
    rng = np.random.default_rng(0)
    ends = 0
    for _ in range(120):
        actions = rng.integers(0, envs.single_action_space.n, n)
        obs, rewards, term, trunc, infos = envs.step(actions)
        for i, s in enumerate(singles):
            o, r, t, tr, _ = s.step(int(actions[i]))
            assert (r, t, tr) == (rewards[i], term[i], trunc[i])
            if t or tr:
                ends += 1
                assert infos["_final_obs"][i] and infos["final_obs"][i].tolist() == o.tolist()
                o, _ = s.reset()
            assert o.tolist() == obs[i].tolist()
    assert ends > 0


def test_gymnasium_make_vec_uses_the_rust_vector_env():
    envs = gym.make_vec("rlfd/Keepaway-3v2-v0", num_envs=3, keepers=4, takers=3)
    assert isinstance(envs, rlfd.vector.KeepawayVectorEnv)
    obs, infos = envs.reset(seed=0)
    assert obs.shape == (3, 19) and infos["keeper"].shape == (3,)
    assert envs.single_action_space.n == 4


def test_bad_actions_are_refused_before_anything_moves():
    envs = rlfd.make_vec("rlfd/Maze-v0", 3)
    obs, _ = envs.reset(seed=0)
    with pytest.raises(ValueError, match=r"expected actions of shape \(3,\)"):
        envs.step(np.zeros((3, 1), dtype=int))
    with pytest.raises(TypeError, match="actions must be integers"):
        envs.step(np.array([0.0, 1.0, 2.0]))
    with pytest.raises(ValueError, match="environment 2: action 4 is out of range: expected 0 to 3"):
        envs.step(np.array([1, 1, 4]))
    obs2, *_ = envs.step(np.array([2, 2, 2]))
    assert obs2[:, 1].tolist() == [0.62, 0.62, 0.62]  # one step up from the start: nothing moved before


def test_bad_vector_arguments():
    with pytest.raises(ValueError, match="num_envs must be a positive integer"):
        rlfd.make_vec("rlfd/Maze-v0", 0)
    with pytest.raises(ValueError, match="unknown environment 'rlfd/Tetris-v0'"):
        rlfd.make_vec("rlfd/Tetris-v0", 2)
    with pytest.raises(ValueError, match='unknown mario option "layout"'):
        rlfd.make_vec("rlfd/Mario-v0", 2, layout="floor-route")
