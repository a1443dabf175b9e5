"""rlfd: the rlfd reproduction's validated domains as Gymnasium environments,
and its learning-from-demonstration algorithms on NumPy arrays.

Importing the package registers the environments with Gymnasium::

    import gymnasium as gym
    import rlfd

    env = gym.make("rlfd/Maze-v0", render_mode="rgb_array")
    env = gym.make("rlfd/Mario-v0")
    env = gym.make("rlfd/Keepaway-3v2-v0")                    # the thesis's 3 vs 2 on 20 m
    env = gym.make("rlfd/Keepaway-3v2-v0", keepers=4, takers=3, region=25.0)
    envs = rlfd.make_vec("rlfd/Keepaway-3v2-v0", num_envs=64)  # stepped in Rust

Submodules:

- :mod:`rlfd.envs`: the Gymnasium environments (:class:`~rlfd.envs.MazeEnv`,
  :class:`~rlfd.envs.MarioEnv`, :class:`~rlfd.envs.KeepawayEnv`);
- :mod:`rlfd.vector`: N environments stepped per call in Rust;
- :mod:`rlfd.keepaway`: the benchmark keeper policies (Always Hold, Random,
  Hand-coded) as callables;
- :mod:`rlfd.ripper`: RIPPER as Weka 3.6's JRip (fit, predict, rule listings);
- :mod:`rlfd.irl`: Relative Entropy IRL, uniform baseline rollouts, linear rewards;
- :mod:`rlfd.shaping`: potential-based shaping wrappers (SIS from IRL
  weights; SBS and HAT as look-ahead advice);
- :mod:`rlfd.demonstrations`: demonstration files (CSV, JSON Lines) and the
  shipped Maze demonstrations;
- :mod:`rlfd.features`: the tile coder of the Rust agents.

Every number comes from the workspace's Rust crates: a seeded episode
through Python is the Rust simulator's trajectory bit for bit.
"""

from . import _rlfd
from . import demonstrations, envs, features, irl, keepaway, ripper, shaping, vector
from .envs import register_envs
from .vector import make_vec

__all__ = [
    "demonstrations",
    "envs",
    "features",
    "irl",
    "keepaway",
    "make_vec",
    "register_envs",
    "ripper",
    "shaping",
    "vector",
]

__version__ = "0.1.0"

register_envs()
