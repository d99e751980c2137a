"""How model coordinates become drawing coordinates: the identity in the plane, an
orthographic projection in space.

A 3D model is drawn in isometric projection by default (looking from (1, 1, 1) towards
the origin, z up, the three axes at 120° on the page), or in one of the three principal
views (`top`: x right, y up; `front`: x right, z up; `side`: y right, z up). Being
orthographic, the projection is linear: a vector is projected like a point.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

VIEWS = {                     # name: (direction towards the viewer, world "up")
    "iso": ((1.0, 1.0, 1.0), (0.0, 0.0, 1.0)),
    "top": ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
    "front": ((0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
    "side": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
}


@dataclass(frozen=True)
class Projection:
    """A linear map from model coordinates (2 or 3) to the page (2)."""

    matrix: np.ndarray          # (2, dim)
    view: str = "plane"

    def __call__(self, v) -> np.ndarray:
        return self.matrix @ np.asarray(v, dtype=float)

    @property
    def dim(self) -> int:
        return self.matrix.shape[1]

    def axes(self) -> dict[str, np.ndarray]:
        """The page image of each model axis (for the 3D axis triad)."""
        return {name: self.matrix[:, i] for i, name in enumerate("xyz"[: self.dim])}


def projection(dim: int, view: str = "iso") -> Projection:
    """The identity for a planar model; the orthographic `view` of a spatial one."""
    if dim == 2:
        return Projection(np.eye(2), "plane")
    if view not in VIEWS:
        raise ValueError(f"unknown view {view!r} (views: {', '.join(VIEWS)})")
    towards, up = (np.asarray(v) for v in VIEWS[view])
    towards = towards / np.linalg.norm(towards)
    right = np.cross(up, towards)
    right /= np.linalg.norm(right)
    screen_up = np.cross(towards, right)
    return Projection(np.vstack([right, screen_up]), view)
