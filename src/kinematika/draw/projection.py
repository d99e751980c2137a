"""How model coordinates become drawing coordinates: the identity in the plane, an
orthographic projection in space.

A 3D model is drawn in isometric projection by default (looking from (1, 1, 1) towards
the origin, z up, the three axes at 120° on the page), or in one of the three principal
views (`top`: x right, y up; `front`: x right, z up; `side`: y right, z up). A model's
`up` direction (the fan's vertical shaft along y) replaces z as the vertical: the views
are then taken about it (y up: iso from (1, 1, 1) with y vertical, front with z right).
Being orthographic, the projection is linear: a vector is projected like a point.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

VIEWS = ("iso", "top", "front", "side")


@dataclass(frozen=True)
class Projection:
    """A linear map from model coordinates (2 or 3) to the page (2)."""

    matrix: np.ndarray          # (2, dim)
    view: str = "plane"

    def __call__(self, v) -> np.ndarray:
        return self.matrix @ np.asarray(v, dtype=float)

    @property
    def dim(self) -> int:
        """The model's dimension the projection takes (2 or 3)."""
        return self.matrix.shape[1]

    def axes(self) -> dict[str, np.ndarray]:
        """The page image of each model axis (for the 3D axis triad)."""
        return {name: self.matrix[:, i] for i, name in enumerate("xyz"[: self.dim])}


def projection(dim: int, view: str = "iso", up=None) -> Projection:
    """The identity for a planar model; the orthographic `view` of a spatial one, with the
    model's `up` direction (default z) vertical on the page."""
    if dim == 2:
        return Projection(np.eye(2), "plane")
    if view not in VIEWS:
        raise ValueError(f"unknown view {view!r} (views: {', '.join(VIEWS)})")
    e1, e2, vertical = horizontal_axes(up)
    towards, screen_up = {"iso": (e1 + e2 + vertical, vertical), "top": (vertical, e2),
                          "front": (-e2, vertical), "side": (e1, vertical)}[view]
    towards = towards / np.linalg.norm(towards)
    right = np.cross(screen_up, towards)
    right /= np.linalg.norm(right)
    return Projection(np.vstack([right, np.cross(towards, right)]), view)


def horizontal_axes(up=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(e1, e2, up) right-handed and orthonormal, e1 the model axis that follows the one
    nearest `up` (x, y for z up; z, x for y up; y, z for x up), made horizontal."""
    vertical = np.asarray(up if up is not None else (0.0, 0.0, 1.0), dtype=float)
    vertical = vertical / np.linalg.norm(vertical)
    nearest = int(np.argmax(np.abs(vertical)))
    e1 = np.eye(3)[(nearest + 1) % 3]
    e1 = e1 - (e1 @ vertical) * vertical
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(vertical, e1), vertical
