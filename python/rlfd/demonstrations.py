"""Demonstrations in the project's formats: trajectories of state vectors with
the demonstrator's actions, read and written as CSV or JSON Lines exactly as
the Rust crates read and write them (``rlfd_env::demonstration``).

- CSV: header ``trajectory,step,<state names…>[,action]``, one row per state.
- JSON Lines: an optional header ``{"state_names":[…],"num_actions":n}``,
  then one line per trajectory ``{"states":[[…],…],"actions":[…]}``.

``actions[i]`` was taken in ``states[i]``; a trajectory has one action per
state, or one fewer when its last state has none. A malformed file raises
``ValueError`` naming the file, the line and the field, e.g.
``demos.csv:17: field "y": "abc" is not a number``.

:func:`shipped` gives the ten Maze demonstrations the package ships (the
chapter's synthetic demonstrator, seed 2011).
"""

from __future__ import annotations

import os
from importlib import resources
from typing import Optional, Sequence

import numpy as np

from ._rlfd import DemonstrationSet

__all__ = ["DemonstrationSet", "read", "parse", "from_trajectories", "shipped"]


def read(path: "str | os.PathLike[str]", num_actions: Optional[int] = None) -> DemonstrationSet:
    """Reads a ``.csv`` or ``.jsonl`` file; ``num_actions`` checks every action against it."""
    return DemonstrationSet.read(os.fspath(path), num_actions)


def parse(text: str, format: str, name: str = "<string>", num_actions: Optional[int] = None) -> DemonstrationSet:
    """Reads demonstrations from ``text`` in ``format`` ("csv" or "jsonl")."""
    return DemonstrationSet.parse(text, format, name, num_actions)


def from_trajectories(
    states: Sequence[np.ndarray],
    actions: Optional[Sequence[Optional[np.ndarray]]] = None,
    state_names: Optional[Sequence[str]] = None,
    num_actions: Optional[int] = None,
) -> DemonstrationSet:
    """A set from one (steps × variables) array per trajectory and, optionally, their actions."""
    if actions is None:
        actions = [None] * len(states)
    if len(actions) != len(states):
        raise ValueError(f"{len(states)} trajectories but {len(actions)} action sequences")
    pairs = []
    for i, (s, a) in enumerate(zip(states, actions)):
        s = np.ascontiguousarray(s, dtype=np.float64)
        if s.ndim != 2:
            raise ValueError(f"trajectory {i}: states must be a 2-D array (steps × variables), got shape {s.shape}")
        if a is not None:
            a = np.asarray(a)
            if a.ndim != 1 or not np.issubdtype(a.dtype, np.integer):
                raise ValueError(f"trajectory {i}: actions must be a 1-D integer array")
            a = a.astype(np.int64)
        pairs.append((s, a))
    return DemonstrationSet(pairs, None if state_names is None else list(state_names), num_actions)


def shipped(name: str = "maze") -> DemonstrationSet:
    """The demonstrations shipped with the package: ``"maze"`` (ten, of 328 to 353 steps)."""
    files = {"maze": "maze-demonstrations.jsonl"}
    if name not in files:
        raise ValueError(f"no shipped demonstrations {name!r}: expected one of {', '.join(files)}")
    with resources.as_file(resources.files("rlfd") / "data" / files[name]) as path:
        return DemonstrationSet.read(os.fspath(path), 4)
