"""N environments stepped in Rust per call.

``VectorEnv("rlfd/Keepaway-3v2-v0", num_envs=64)`` (or ``rlfd.make_vec``, or
``gymnasium.make_vec("rlfd/Keepaway-3v2-v0", num_envs=64)``, which uses it)
is a ``gymnasium.vector.VectorEnv`` whose ``step(actions)`` moves every
instance one step inside one Rust call: Python's per-step overhead is paid
once per batch, not once per environment.

- ``reset(seed=s)`` seeds instance ``i`` with ``s + i`` (Gymnasium's
  convention), so instance ``i`` follows exactly the trajectory of a single
  environment reset with ``seed=s + i``.
- Episodes reset in the same step (``AutoresetMode.SAME_STEP``): an instance
  whose episode ended returns its reward and end flag, its row of the
  observations is already the next episode's first, and
  ``infos["final_obs"]`` (a float array, num_envs × dim) holds the ended
  episode's last observation where ``infos["_final_obs"]`` is True.
- Keepaway adds ``infos["keeper"]``: each instance's deciding keeper.
- ``actions`` must be integers, one per instance, each in range; anything
  else raises ``ValueError`` (``TypeError`` for a non-integer array) before
  any instance moves.
"""

from __future__ import annotations

from typing import Any, Optional

import gymnasium as gym
import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode
from gymnasium.vector.utils import batch_space

from . import _rlfd
from .envs import check_seed, domain_of

__all__ = ["VectorEnv", "MazeVectorEnv", "MarioVectorEnv", "KeepawayVectorEnv", "make_vec"]


class VectorEnv(gym.vector.VectorEnv):
    """``num_envs`` instances of one environment, stepped in Rust (see the module docs)."""

    metadata = {"autoreset_mode": AutoresetMode.SAME_STEP, "render_modes": []}

    def __init__(self, env_id: str, num_envs: int = 1, render_mode: Optional[str] = None, **options: Any) -> None:
        if render_mode is not None:
            raise ValueError("the vector environments do not render: make single environments for pictures")
        if isinstance(num_envs, bool) or not isinstance(num_envs, (int, np.integer)) or num_envs < 1:
            raise ValueError(f"num_envs must be a positive integer, got {num_envs!r}")
        domain, defaults = domain_of(env_id)
        defaults.update(options)
        self.domain = domain
        self._core = _rlfd.VectorEnv(domain, int(num_envs), defaults)
        probe = _rlfd.Env(domain, defaults)
        low, high = probe.bounds()
        self.num_envs = int(num_envs)
        self.single_observation_space = spaces.Box(low, high, dtype=np.float64)
        self.single_action_space = spaces.Discrete(probe.num_actions)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.render_mode = None
        self._keepaway = domain == "keepaway"
        self._seeded = False

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        if isinstance(seed, (list, tuple)):
            raise TypeError("seed must be one integer (instance i gets seed + i) or None")
        seed = check_seed(seed)
        super().reset(seed=seed)
        if options:
            raise ValueError(f"reset() takes no options, got {sorted(options)}")
        if seed is None and not self._seeded:
            seed = int(self.np_random.integers(0, 2**63))
        if seed is not None:
            self._seeded = True
        obs = self._core.reset(seed)
        infos = {"keeper": self._core.keepers()} if self._keepaway else {}
        return obs, infos

    def step(self, actions):
        actions = np.asarray(actions)
        if actions.shape != (self.num_envs,):
            raise ValueError(f"expected actions of shape ({self.num_envs},), one per environment, got {actions.shape}")
        if not np.issubdtype(actions.dtype, np.integer):
            raise TypeError(f"actions must be integers, got an array of {actions.dtype}")
        obs, rewards, terminated, truncated, finals = self._core.step(actions.astype(np.int64, copy=False))
        infos: dict = {}
        if finals is not None:
            infos["final_obs"], infos["_final_obs"] = finals
        if self._keepaway:
            infos["keeper"] = self._core.keepers()
        return obs, rewards, terminated, truncated, infos


class MazeVectorEnv(VectorEnv):
    """``rlfd/Maze-v0`` vectorised (Gymnasium's ``vector_entry_point``)."""

    def __init__(self, num_envs: int = 1, **options: Any) -> None:
        super().__init__("maze", num_envs, **options)


class MarioVectorEnv(VectorEnv):
    """``rlfd/Mario-v0`` vectorised."""

    def __init__(self, num_envs: int = 1, **options: Any) -> None:
        super().__init__("mario", num_envs, **options)


class KeepawayVectorEnv(VectorEnv):
    """``rlfd/Keepaway-*`` vectorised."""

    def __init__(self, num_envs: int = 1, **options: Any) -> None:
        super().__init__("keepaway", num_envs, **options)


def make_vec(env_id: str, num_envs: int = 1, **options: Any) -> VectorEnv:
    """``num_envs`` instances of a registered id (e.g. ``"rlfd/Mario-v0"``), stepped in Rust."""
    return VectorEnv(env_id, num_envs, **options)
