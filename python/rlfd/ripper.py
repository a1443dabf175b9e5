"""RIPPER (Cohen 1995) as Weka's JRip implements it, on NumPy arrays: the rule
learner the thesis summarises demonstrations with (``rlfd_lfd::ripper``).

With the defaults (``random="weka"``: Weka 3.6's own ``java.util.Random``
stream, seeded as JRip seeds itself with ``-S 1``; ``-F 3 -N 2.0 -O 2``) the
rules are those Weka 3.6's ``weka.classifiers.rules.JRip`` prints for the same
data; ``random="chacha8"`` runs the same algorithm on the project's ChaCha8
stream (the chapters' stored rules). Multiclass data give one ordered decision
list::

    rules = rlfd.ripper.Ripper().fit(X, y, feature_names=["x", "y"],
                                     class_names=["left", "right", "up", "down"])
    rules.predict(X)          # first covering rule's class, else the default
    print(rules)              # if (x <= 0.22 and y >= 0.7) -> Action = up …
    print(rules.weka_string())  # Weka's JRIP rules: listing with (covered/errors)

``X`` holds one row per instance (numeric values; a nominal attribute's value
index; NaN for missing), ``y`` the class indices ``0 … k − 1``.
"""

from __future__ import annotations

from typing import Mapping, Optional, Sequence

import numpy as np

from . import _rlfd
from ._rlfd import DecisionList

__all__ = ["Ripper", "DecisionList", "fit"]


def _data(X, y, feature_names, class_names, nominal, sample_weight):
    X = np.ascontiguousarray(X, dtype=np.float64)
    if X.ndim != 2:
        raise ValueError(f"X must be a 2-D array (instances × attributes), got shape {X.shape}")
    y = np.asarray(y)
    if y.ndim != 1 or y.shape[0] != X.shape[0]:
        raise ValueError(f"y must be a 1-D array of {X.shape[0]} class labels (one per row of X), got shape {y.shape}")
    if y.size and not np.issubdtype(y.dtype, np.integer):
        raise TypeError(f"y must hold integer class indices, got {y.dtype}")
    y = y.astype(np.int64)
    if feature_names is None:
        feature_names = [f"state_{i}" for i in range(X.shape[1])]
    feature_names = list(feature_names)
    if len(feature_names) != X.shape[1]:
        raise ValueError(f"expected {X.shape[1]} feature names (one per column of X), got {len(feature_names)}")
    if class_names is None:
        k = int(y.max()) + 1 if y.size else 1
        class_names = [str(c) for c in range(k)]
    nominal = dict(nominal or {})
    unknown = set(nominal) - set(feature_names)
    if unknown:
        raise ValueError(f"nominal names no feature: {sorted(unknown)}")
    nominal_list = [list(nominal[name]) if name in nominal else None for name in feature_names]
    weights = None if sample_weight is None else np.ascontiguousarray(sample_weight, dtype=np.float64)
    return X, y, feature_names, list(class_names), nominal_list, weights


class Ripper:
    """JRip's options (``-F folds -N min_no -O optimizations -S seed``, ``-E``
    as ``check_error_rate=False``, ``-P`` as ``prune=False``) and the random
    stream ("weka" or "chacha8")."""

    def __init__(
        self,
        *,
        folds: int = 3,
        min_no: float = 2.0,
        optimizations: int = 2,
        seed: int = 1,
        check_error_rate: bool = True,
        prune: bool = True,
        random: str = "weka",
    ) -> None:
        self.params = dict(
            folds=folds,
            min_no=min_no,
            optimizations=optimizations,
            seed=seed,
            check_error_rate=check_error_rate,
            prune=prune,
            random=random,
        )
        self.rules_: Optional[DecisionList] = None

    def fit(
        self,
        X,
        y,
        *,
        feature_names: Optional[Sequence[str]] = None,
        class_names: Optional[Sequence[str]] = None,
        class_attribute: str = "Action",
        nominal: Optional[Mapping[str, Sequence[str]]] = None,
        sample_weight=None,
    ) -> DecisionList:
        """Learns a decision list; also kept as ``self.rules_``."""
        X, y, names, classes, nominal_list, w = _data(X, y, feature_names, class_names, nominal, sample_weight)
        p = self.params
        self.rules_ = _rlfd.ripper_fit(
            X, y, names, nominal_list, class_attribute, classes, w,
            p["folds"], p["min_no"], p["optimizations"], p["seed"], p["check_error_rate"], p["prune"], p["random"],
        )
        return self.rules_

    def predict(self, X) -> np.ndarray:
        """The fitted list's predictions (see :meth:`DecisionList.predict`)."""
        if self.rules_ is None:
            raise ValueError("call fit() before predict()")
        return self.rules_.predict(np.ascontiguousarray(X, dtype=np.float64))

    def cross_validate(
        self,
        X,
        y,
        *,
        cv_folds: int = 10,
        cv_seed: int = 1,
        feature_names: Optional[Sequence[str]] = None,
        class_names: Optional[Sequence[str]] = None,
        class_attribute: str = "Action",
        nominal: Optional[Mapping[str, Sequence[str]]] = None,
        sample_weight=None,
    ) -> dict:
        """Weka's stratified cross-validation (``-x cv_folds -s cv_seed``):
        ``accuracy``, ``correct``, ``total`` and ``per_fold``."""
        X, y, names, classes, nominal_list, w = _data(X, y, feature_names, class_names, nominal, sample_weight)
        p = self.params
        return _rlfd.ripper_cross_validate(
            X, y, names, nominal_list, class_attribute, classes, w,
            p["folds"], p["min_no"], p["optimizations"], p["seed"], p["check_error_rate"], p["prune"], p["random"],
            cv_folds, cv_seed,
        )


def fit(X, y, **kwargs) -> DecisionList:
    """``Ripper().fit(X, y, **kwargs)`` with JRip's defaults on Weka's stream."""
    return Ripper().fit(X, y, **kwargs)
