"""Relative Entropy IRL (Boularias, Kober & Peters 2011) as the thesis's
section 6.2 uses it (``rlfd_lfd::irl``): the state variables as reward
features, feature counts summed over trajectories of one length, and θ
maximising the dual by accelerated proximal gradient ascent.

The chapter's Maze inputs, in Python::

    demos = rlfd.demonstrations.shipped("maze").pad_to_equal_length()
    horizon = demos.lengths()[0]
    baseline = rlfd.irl.uniform_rollouts("maze", 1000, horizon, seed=0, step=1)
    fit = rlfd.irl.relative_entropy(demos, baseline)
    fit.weights          # R(s) = w · s, unit length in the scaled features

Defaults are the chapter's: undiscounted counts, Hoeffding's tolerance with
δ = 0.05 over each variable's range, features scaled to their ranges,
‖θ‖ ≤ 1, θ set to unit length at the end, a residual of 1e-9 or 100,000
iterations.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence, Union

import numpy as np

from . import _rlfd
from ._rlfd import DemonstrationSet, LinearStateReward as LinearReward
from .envs import domain_of

__all__ = ["IrlFit", "relative_entropy", "uniform_rollouts", "LinearReward"]


@dataclass(frozen=True)
class IrlFit:
    """A fit: the reward ``R(s) = weights · s`` and the ascent's diagnostics."""

    weights: np.ndarray
    """The reward's weights over the raw state variables."""
    scaled_weights: np.ndarray
    """θ over the scaled features (after the normalisation)."""
    fitted_norm: float
    """‖θ‖₂ of the dual's maximiser, before the normalisation."""
    expert_feature_counts: np.ndarray
    """The expert's mean feature counts f̂."""
    tolerance: np.ndarray
    """ε per scaled feature."""
    objective: np.ndarray
    """The dual objective at θ₀ = 0 and after every iteration."""
    converged: bool
    on_bound: bool
    """The maximiser lies on the norm bound (the unbounded dual's case)."""
    residual: float
    stability: float
    iterations: int
    horizon: int

    def reward(self) -> LinearReward:
        """The recovered reward as a callable, evaluated as the Rust agents evaluate it."""
        return LinearReward(list(map(float, self.weights)))


Trajectories = Union[DemonstrationSet, np.ndarray, Sequence[np.ndarray]]


def _trajectories(data: Trajectories, which: str) -> list:
    if isinstance(data, DemonstrationSet):
        return [np.ascontiguousarray(s) for s, _ in data.trajectories()]
    if isinstance(data, np.ndarray):
        if data.ndim != 3:
            raise ValueError(f"{which} must be a 3-D array (trajectories × steps × variables), got shape {data.shape}")
        return [np.ascontiguousarray(t, dtype=np.float64) for t in data]
    out = []
    for i, t in enumerate(data):
        t = np.ascontiguousarray(t, dtype=np.float64)
        if t.ndim != 2:
            raise ValueError(f"{which} trajectory {i} must be a 2-D array (steps × variables), got shape {t.shape}")
        out.append(t)
    return out


def relative_entropy(
    expert: Trajectories,
    baseline: Trajectories,
    *,
    discount: float = 1.0,
    delta: Optional[float] = 0.05,
    epsilon: Optional[Sequence[float]] = None,
    feature_ranges: Optional[Sequence[float]] = None,
    scale_features: bool = True,
    norm_bound: Optional[float] = 1.0,
    normalise: bool = True,
    tolerance: float = 1e-9,
    max_iterations: int = 100_000,
) -> IrlFit:
    """Fits RE-IRL's θ.

    ``expert`` and ``baseline``: a :class:`DemonstrationSet`, a 3-D array
    (trajectories × steps × variables) or a list of 2-D arrays, all of one
    length (pad or prune demonstrations first). ``delta``: Hoeffding's
    tolerance (with ``feature_ranges``, default 1 per variable); ``epsilon``
    (one per variable), if given, replaces it; ``delta=None`` without
    ``epsilon`` is exact matching.
    ``norm_bound=None`` drops the bound; ``normalise=False`` keeps θ's size.
    """
    e = _trajectories(expert, "expert")
    b = _trajectories(baseline, "baseline")
    dim = e[0].shape[1] if e else 0
    ranges = [1.0] * dim if feature_ranges is None else [float(r) for r in feature_ranges]
    eps = None if epsilon is None else [float(x) for x in epsilon]
    out = _rlfd.relative_entropy(
        e, b, discount, delta if eps is None else None, eps, ranges, scale_features, norm_bound, normalise,
        tolerance, max_iterations,
    )
    return IrlFit(**out)


def uniform_rollouts(env: str, n: int, horizon: int, seed: int, **options: Any) -> np.ndarray:
    """``n`` rollouts of the uniformly random policy from the start, each of
    ``horizon`` observations (an episode that ends early repeats its last
    one), drawn from ``seeded(seed)`` as ``rlfd_lfd::irl::rollout_uniform``
    draws: RE-IRL's baseline, (n × horizon × variables). ``env`` is a
    registered id or a domain name; ``options`` as the environment's (the
    chapter's Maze baseline walks at the demonstrations' resolution: ``step=1``)."""
    domain, defaults = domain_of(env)
    defaults.update(options)
    return _rlfd.uniform_rollouts(domain, n, horizon, seed, defaults)
