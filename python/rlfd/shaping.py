"""Potential-based reward shaping from demonstrations, as Gymnasium wrappers
(``rlfd_rl::shaping``, the thesis's chapter 6).

- :class:`StaticShaping` / :func:`SIS`: a state potential Φ(s), the reward
  becomes ``r + scale · (γ Φ(s') − Φ(s))`` (Ng, Harada & Russell 1999; the
  thesis's eq. 6.2). SIS's Φ is RE-IRL's reward ``R(s) = w · s``
  (:func:`rlfd.irl.relative_entropy`), the chapter's scale 100. Φ of a
  terminal state is 0 (``terminal="zero"``) or Φ evaluated there
  (``terminal="literal"``, eq. 6.2 read literally); a truncated episode's
  last state is not terminal.
- :class:`LookAheadAdvice` / :func:`SBS` / :func:`HAT`: a state-action
  potential Φ(s, a) (Wiewiora, Cottrell & Elkan 2003; eq. 6.3). Its shaping
  reward ``γ Φ(s', a') − Φ(s, a)`` needs the *next* action a', which only the
  agent knows, so the wrapper does not change the reward: it puts
  ``scale · Φ(s, ·)`` (one value per action) in ``info["advice"]`` at every
  reset and step, and :func:`look_ahead_reward` computes the shaping term once
  the agent has chosen a'. With Wiewiora's correction (act greedily on
  ``Q + advice``) this is learning from Q initialised to the advice, as the
  thesis describes its SBS and HAT baselines. SBS's Φ is the similarity to
  the demonstrated pairs of the same action (Brys et al. 2015); HAT's is
  ``1[a = rules(s)]`` for a RIPPER decision list.

- :class:`DynamicShaping` / :func:`DIS`: Dynamic IRL Shaping (Harutyunyan,
  Devlin, Vrancx & Nowé 2015; eqs. 6.6–6.8): a secondary SARSA learns
  Φ†(s, a) over the agent's tile features on the reward ``−R†(s)`` (R† from
  RE-IRL's weights) with step size β, and each transition's shaping reward is
  ``scale · (γ Φ†(s', a') − Φ†_old(s, a))``. It learns from the agent's own
  transitions and next actions, so it is not a wrapper: the agent calls
  ``dis.reward(s, a, s2, a2)`` once per transition (``s2 = a2 = None`` at a
  terminal state) and adds it to the environment's reward.

Every wrapper keeps the environment's own reward in ``info["env_reward"]``:
an agent is scored on that, never on the shaped one.
"""

from __future__ import annotations

from typing import Callable, Optional, Sequence

import gymnasium as gym
import numpy as np

from ._rlfd import DecisionList, DemonstrationSet, DynamicShaping, LinearStateReward, SimilarityPotentialPy, TileCoder

__all__ = [
    "StaticShaping",
    "SIS",
    "LookAheadAdvice",
    "SBS",
    "HAT",
    "DynamicShaping",
    "DIS",
    "look_ahead_reward",
    "SimilarityPotential",
]

SimilarityPotential = SimilarityPotentialPy


class StaticShaping(gym.Wrapper):
    """``r + scale · (γ Φ(s') − Φ(s))`` for a state potential ``potential(obs) -> float``."""

    def __init__(
        self,
        env: gym.Env,
        potential: Callable[[np.ndarray], float],
        *,
        scale: float = 1.0,
        gamma: float = 1.0,
        terminal: str = "zero",
    ) -> None:
        super().__init__(env)
        if terminal not in ("zero", "literal"):
            raise ValueError(f"terminal must be 'zero' or 'literal', got {terminal!r}")
        if not (np.isfinite(scale) and np.isfinite(gamma) and 0.0 <= gamma <= 1.0):
            raise ValueError(f"scale must be finite and gamma in [0, 1], got {scale} and {gamma}")
        self.potential = potential
        self.scale = float(scale)
        self.gamma = float(gamma)
        self.terminal = terminal
        self._here: Optional[float] = None

    def reset(self, **kwargs):
        obs, info = self.env.reset(**kwargs)
        self._here = self.scale * float(self.potential(obs))
        return obs, info

    def step(self, action):
        if self._here is None:
            raise ValueError("call reset() before step()")
        obs, reward, terminated, truncated, info = self.env.step(action)
        if terminated and self.terminal == "zero":
            there = 0.0
        else:
            there = self.scale * float(self.potential(obs))
        shaping = self.gamma * there - self._here
        self._here = there
        info = dict(info)
        info["env_reward"] = reward
        info["shaping"] = shaping
        return obs, reward + shaping, terminated, truncated, info


def SIS(
    env: gym.Env,
    weights: Sequence[float],
    *,
    scale: float = 100.0,
    kappa: float = 1.0,
    gamma: float = 1.0,
    terminal: str = "zero",
) -> StaticShaping:
    """Static IRL shaping: Φ(s) = κ · w · s from RE-IRL's weights, scaled by ``scale`` (the chapter's 100)."""
    reward = LinearStateReward([float(w) for w in weights])
    if kappa == 1.0:
        potential = reward
    else:
        def potential(obs, _r=reward, _k=float(kappa)):
            return _k * _r(obs)
    return StaticShaping(env, potential, scale=scale, gamma=gamma, terminal=terminal)


class LookAheadAdvice(gym.Wrapper):
    """Puts ``scale · Φ(s, ·)`` in ``info["advice"]``; the reward is unchanged (see the module docs)."""

    def __init__(self, env: gym.Env, potential: Callable[[np.ndarray], np.ndarray], *, scale: float = 1.0) -> None:
        super().__init__(env)
        if not np.isfinite(scale):
            raise ValueError(f"scale must be finite, got {scale}")
        self.potential = potential
        self.scale = float(scale)

    def _advise(self, obs, info):
        info = dict(info)
        info["advice"] = self.scale * np.asarray(self.potential(obs), dtype=np.float64)
        return info

    def reset(self, **kwargs):
        obs, info = self.env.reset(**kwargs)
        return obs, self._advise(obs, info)

    def step(self, action):
        obs, reward, terminated, truncated, info = self.env.step(action)
        info = self._advise(obs, info)
        info["env_reward"] = reward
        return obs, reward, terminated, truncated, info


def look_ahead_reward(
    advice: np.ndarray,
    action: int,
    next_advice: Optional[np.ndarray],
    next_action: Optional[int],
    gamma: float = 1.0,
) -> float:
    """Wiewiora's shaping term ``γ · advice'[a'] − advice[a]`` (``next_advice=None`` at a terminal state: 0 there)."""
    there = 0.0 if next_advice is None else float(next_advice[next_action])
    return gamma * there - float(advice[action])


def SBS(env: gym.Env, demonstrations: DemonstrationSet, sigma: Sequence[float], *, scale: float = 100.0) -> LookAheadAdvice:
    """Similarity-based shaping from the demonstrated (state, action) pairs, Gaussian widths ``sigma`` per variable."""
    states, actions = demonstrations.state_action_pairs()
    n = env.action_space.n
    potential = SimilarityPotentialPy(states, actions, int(n), [float(s) for s in sigma])
    return LookAheadAdvice(env, potential, scale=scale)


def HAT(env: gym.Env, rules: DecisionList, *, scale: float = 10.0) -> LookAheadAdvice:
    """HAT's rule advice Φ(s, a) = 1[a = rules(s)] (Q-initialisation), scaled by ``scale`` (the chapter's 10)."""
    n = int(env.action_space.n)
    eye = np.eye(n)

    def potential(obs):
        a = int(rules.predict(np.ascontiguousarray(obs, dtype=np.float64))[0])
        return eye[a] if a < n else np.zeros(n)

    return LookAheadAdvice(env, potential, scale=scale)


def DIS(
    coder: TileCoder,
    num_actions: int,
    weights: Sequence[float],
    *,
    beta: float,
    scale: float = 100.0,
    kappa: float = 1.0,
) -> DynamicShaping:
    """Dynamic IRL shaping over ``coder``'s features with R†(s) = κ · weights · s
    (the chapter's Maze: β = 0.05/32 with 32 tilings, scale 100)."""
    return DynamicShaping(coder, int(num_actions), [float(kappa) * float(w) for w in weights], float(beta), float(scale))
