"""The domains as Gymnasium environments.

=========================  ======================  =========================  ==========================
id                         observation             actions                    episode
=========================  ======================  =========================  ==========================
``rlfd/Maze-v0``           (x, y) in [0, 1)²       4: left, right, up, down   goal, or 6,000 steps (cut)
``rlfd/Mario-v0``          the thesis's 27 vars    12: Liao et al.'s keys     the game's end or timer
``rlfd/Keepaway-3v2-v0``   13 state variables      3: hold, pass1, pass2      the ball lost or out
``rlfd/Keepaway-4v3-v0``   19 state variables      4: hold, pass1..3          the ball lost or out
=========================  ======================  =========================  ==========================

Options (keyword arguments of ``gymnasium.make`` or the classes):

- Maze: ``layout`` ("low-detour", the default; "high-detour"; "floor-route"),
  ``step`` (a move's length in hundredths, 2: the agent's 0.02).
- Keepaway: ``keepers`` (3 to 5), ``takers`` (2 to 4), ``region`` (the side of
  the square region in metres, 20).
- Every class also takes ``max_episode_steps`` (a truncation inside the
  simulator; None: none). Through ``gymnasium.make`` that name is Gymnasium's
  own ``TimeLimit``: ``rlfd/Maze-v0`` is registered with the chapter's 6,000
  steps; Mario's timer and Keepaway's referee end their episodes themselves.

An unknown option or a value outside its domain raises ``ValueError``.

**Keepaway's step** is one SMDP decision of the keeper with the ball, as
chapter 5's learners see it: the observation is ``keeperStateVars`` from that
keeper's view; the reward is the simulated time the step took in cycles
(100 ms), counted from the episode's start for the first step, so an
episode's return is its duration, the thesis's score. ``info`` carries
``keeper`` (who decides), ``smdp_reward`` (the cycles since *that* keeper's
previous action, a pass's follow-through kick included: what its own learner
is rewarded in chapter 5, 0 at its first decision), ``cycle``,
and at the end ``final_smdp_rewards`` (each keeper's last reward, NaN if it
never acted) and ``end_cause`` ("out" or "taken").

**Seeds**: ``reset(seed=s)`` seeds the simulator's ChaCha8 generator with
``s`` (an integer in 0 … 2⁶⁴ − 1) exactly as a Rust trial seeded with ``s``;
``reset()`` continues the stream; an environment never seeded draws its seed
from Gymnasium's ``np_random``.
"""

from __future__ import annotations

from typing import Any, Optional

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from . import _rlfd

__all__ = ["RlfdEnv", "MazeEnv", "MarioEnv", "KeepawayEnv", "register_envs", "ENV_IDS", "domain_of"]

ENV_IDS = {
    "rlfd/Maze-v0": ("maze", {}),
    "rlfd/Mario-v0": ("mario", {}),
    "rlfd/Keepaway-3v2-v0": ("keepaway", {}),
    "rlfd/Keepaway-4v3-v0": ("keepaway", {"keepers": 4, "takers": 3}),
}
"""Each id's domain and default options."""

STEP_CAPS = {"rlfd/Maze-v0": 6000}
"""Each id's ``max_episode_steps`` (Gymnasium's ``TimeLimit``): the chapter's Maze cap."""


def domain_of(env_id: str) -> tuple[str, dict]:
    """The domain name and default options of a registered id (or of a bare
    domain name), the id's step cap included."""
    if env_id in ENV_IDS:
        domain, options = ENV_IDS[env_id]
        options = dict(options)
        if env_id in STEP_CAPS:
            options["max_episode_steps"] = STEP_CAPS[env_id]
        return domain, options
    if env_id in _rlfd.DOMAINS:
        return env_id, {}
    raise ValueError(f"unknown environment {env_id!r}: expected one of {', '.join(ENV_IDS)}")


def check_seed(seed: Any) -> Optional[int]:
    """A seed as the simulators take it: None, or an integer in 0 … 2**64 − 1."""
    if seed is None:
        return None
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed must be an integer, got {type(seed).__name__}")
    if not 0 <= int(seed) < 2**64:
        raise ValueError(f"seed must be in 0 … 2**64 - 1, got {seed}")
    return int(seed)


class RlfdEnv(gym.Env):
    """A domain of the reproduction as a Gymnasium environment (see the module docs)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}
    domain: str = ""

    def __init__(self, render_mode: Optional[str] = None, **options: Any) -> None:
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        self._core = _rlfd.Env(self.domain, options)
        low, high = self._core.bounds()
        self.observation_space = spaces.Box(low, high, dtype=np.float64)
        self.action_space = spaces.Discrete(self._core.num_actions)
        self.render_mode = render_mode
        self.options = dict(options)
        self._seeded = False

    @property
    def state_names(self) -> list[str]:
        """The names of the observation's variables, in order."""
        return self._core.state_names

    @property
    def action_names(self) -> list[str]:
        """The names of the actions, in order."""
        return self._core.action_names

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        seed = check_seed(seed)
        super().reset(seed=seed)
        if options:
            raise ValueError(f"reset() takes no options, got {sorted(options)}")
        if seed is None and not self._seeded:
            seed = int(self.np_random.integers(0, 2**63))
        if seed is not None:
            self._seeded = True
        return self._core.reset(seed)

    def step(self, action):
        return self._core.step(action)

    def render(self):
        if self.render_mode is None:
            gym.logger.warn("render() without a render_mode: make the environment with render_mode='rgb_array'")
            return None
        return self._core.render()


class MazeEnv(RlfdEnv):
    """The Maze of the thesis's section 6.3.1 (a modified Dyna Maze, continuous, 4 moves)."""

    domain = "maze"


class MarioEnv(RlfdEnv):
    """Mario after the Mario AI Benchmark (section 6.3.2): 27 state variables, 12 actions."""

    domain = "mario"


class KeepawayEnv(RlfdEnv):
    """Keepaway (chapter 5): the keepers' SMDP decisions against the hand-coded takers."""

    domain = "keepaway"

    def benchmark_action(self, policy: str) -> int:
        """The benchmark policy's action now ("always-hold", "random",
        "hand-coded"); Random draws from this environment's generator, exactly
        as the benchmark runs of the Rust simulator draw."""
        return self._core.benchmark_action(policy)

    @property
    def configuration(self) -> tuple[int, int, float]:
        """(keepers, takers, region side in metres)."""
        return self._core.keepaway_configuration


_CLASSES = {"maze": "MazeEnv", "mario": "MarioEnv", "keepaway": "KeepawayEnv"}


def register_envs() -> None:
    """Registers the ids of :data:`ENV_IDS` with Gymnasium (done on import)."""
    for env_id, (domain, defaults) in ENV_IDS.items():
        if env_id in gym.registry:
            continue
        gym.register(
            id=env_id,
            entry_point=f"rlfd.envs:{_CLASSES[domain]}",
            vector_entry_point=f"rlfd.vector:{_CLASSES[domain].replace('Env', 'VectorEnv')}",
            kwargs=dict(defaults),
            max_episode_steps=STEP_CAPS.get(env_id),
            disable_env_checker=False,
        )
