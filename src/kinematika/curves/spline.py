"""A smooth curve through given points: a cubic spline in a chord-length parameter."""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from scipy.interpolate import CubicSpline

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

from .base import Curve, Param
from ..errors import Said


class Spline(Curve):
    """r(u) through points P₀…P_{n−1}: x(u) and y(u) are cubic splines (scipy's
    `CubicSpline`) with knots at the chord-length parameter u₀ = 0, u_{i+1} = u_i + |P_{i+1} − P_i|
    (close to arc length, so the curve does not bunch where points are dense). Open: 'not-a-knot'
    ends. Closed: the first point is repeated at the end and the spline is periodic (C² all
    round), u ∈ [0, L_chords). r' and r'' are the splines' derivatives (r'' is piecewise linear,
    so the curvature is continuous)."""

    def __init__(self, points: ArrayLike, closed: bool = False) -> None:
        pts = np.asarray(points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2:
            raise ValueError(Said("spline-points"))
        if closed and len(pts) > 1 and np.allclose(pts[0], pts[-1]):
            pts = pts[:-1]                   # the closing point is implied
        need = 3 if closed else 2
        if len(pts) < need:
            raise ValueError(Said("spline-too-few", closed=str(closed).lower(), need=need))
        if closed:
            pts = np.vstack([pts, pts[:1]])
        chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
        if np.any(chords <= 1e-12 * max(1.0, float(np.max(np.abs(pts))))):
            raise ValueError(Said("spline-points-differ"))
        self.closed = closed
        self.knots = np.concatenate([[0.0], np.cumsum(chords)])
        self.data = pts
        self._spline = CubicSpline(self.knots, pts, bc_type="periodic" if closed else "not-a-knot")

    @property
    def domain(self) -> tuple[float, float]:
        """[0, total chord length]."""
        return (0.0, float(self.knots[-1]))

    def point(self, u: Param) -> np.ndarray:
        """The splines' values at u (wrapped for a closed spline)."""
        return self._spline(self._at(u))

    def d1(self, u: Param) -> np.ndarray:
        """The splines' first derivatives."""
        return self._spline(self._at(u), 1)

    def d2(self, u: Param) -> np.ndarray:
        """The splines' second derivatives."""
        return self._spline(self._at(u), 2)

    def _at(self, u: Param) -> np.ndarray:
        u = np.asarray(u, dtype=float)
        return self.wrap(u) if self.closed else u
