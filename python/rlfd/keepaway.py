"""Keepaway's three benchmark keeper policies as callables (``HandCodedAgent.cc``
of the UT-Austin keepaway players, the simulator's validation policies):

- :func:`AlwaysHold`: Hold at every decision;
- :func:`Random`: uniform over the ``keepers`` actions, from its own ChaCha8
  generator seeded with ``seed``;
- :func:`HandCoded` (Stone, Sutton & Kuhlmann 2005): hold when the nearest
  taker is more than 5 m away, else score Hold 90 and a pass to teammate i
  ``4 · (its distance to its nearest taker) + (its smallest angle to a taker
  at the holder, degrees)`` and take the best.

Each is ``policy(observation) -> action`` on the observation of
``rlfd/Keepaway-*``::

    env = gym.make("rlfd/Keepaway-3v2-v0")
    policy = rlfd.keepaway.HandCoded()
    obs, info = env.reset(seed=1)
    done = False
    while not done:
        obs, reward, done, _, info = env.step(policy(obs))

To draw Random's choices from the environment's own stream, exactly as the
Rust benchmark runs do, use ``env.unwrapped.benchmark_action("random")``.
"""

from __future__ import annotations

from . import _rlfd

__all__ = ["AlwaysHold", "Random", "HandCoded", "policy", "POLICIES"]

POLICIES = ("always-hold", "random", "hand-coded")


def policy(name: str, keepers: int = 3, takers: int = 2, seed: int = 0) -> _rlfd.KeepawayPolicy:
    """The benchmark policy ``name`` (one of :data:`POLICIES`) for ``keepers`` vs ``takers``."""
    return _rlfd.KeepawayPolicy(name, keepers, takers, seed)


def AlwaysHold(keepers: int = 3, takers: int = 2) -> _rlfd.KeepawayPolicy:
    """Always Hold."""
    return policy("always-hold", keepers, takers)


def Random(keepers: int = 3, takers: int = 2, seed: int = 0) -> _rlfd.KeepawayPolicy:
    """Uniformly random over the actions, from a generator seeded with ``seed``."""
    return policy("random", keepers, takers, seed)


def HandCoded(keepers: int = 3, takers: int = 2) -> _rlfd.KeepawayPolicy:
    """The hand-coded policy of Stone, Sutton & Kuhlmann (2005)."""
    return policy("hand-coded", keepers, takers)
