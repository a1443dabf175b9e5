"""The tile coder of the Rust agents (``rlfd_rl::features::TileCoder`` with
dense indexing): ``TileCoder(tilings, widths, lower, upper)(state)`` gives the
indices of the active tiles (one per tiling) in ``0 … num_features − 1``.

The chapter's Maze agents use ``TileCoder(32, [0.1, 0.1], [0, 0], [1, 1])``.
"""

from ._rlfd import TileCoder

__all__ = ["TileCoder"]
