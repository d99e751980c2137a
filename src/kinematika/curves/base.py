"""A planar curve fixed in a body: the interface every kind of curve gives.

A curve is r(u) = (x(u), y(u)) in its body's own coordinates, u in `domain` = [a, b]
(a closed curve repeats with period b − a). A kind of curve gives `point`, `d1` (r'(u)) and
`d2` (r''(u)); everything else follows here, once, from the differential geometry of plane
curves:

- unit tangent  t = r'/|r'|,   unit normal  n = t turned +90° = (−t_y, t_x);
- signed curvature  κ = (x'y'' − y'x'')/|r'|³  (positive when the curve turns to the left,
  i.e. towards n: a circle run counter-clockwise has κ = +1/R);
- length  L = ∫ₐᵇ |r'(u)| du  (Gauss–Legendre on many short pieces);
- nearest(p): the u minimising |r(u) − p| — global sampling (so the right valley is found),
  then safeguarded Newton on g(u) = (r − p)·r' = 0 with g' = |r'|² + (r − p)·r'', kept
  inside the sampled bracket; closed curves wrap u into the domain.

Every method takes a number or an array of parameters (vectorised); points are arrays whose
last axis is (x, y).
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Union

import numpy as np
from ..errors import Said

Param = Union[float, np.ndarray]


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The planar cross product a_x b_y − a_y b_x (over the last axis)."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def turned(v: np.ndarray) -> np.ndarray:
    """v turned +90°: (−v_y, v_x)."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


class Curve(ABC):
    """A planar parametric curve r(u) in its body's coordinates (see the module's formulas)."""

    closed: bool = False
    samples: int = 512          # points of the global search in `nearest`

    @property
    @abstractmethod
    def domain(self) -> tuple[float, float]:
        """The parameter's range [a, b] (a closed curve: one period)."""

    @abstractmethod
    def point(self, u: Param) -> np.ndarray:
        """r(u)."""

    @abstractmethod
    def d1(self, u: Param) -> np.ndarray:
        """r'(u) = dr/du."""

    @abstractmethod
    def d2(self, u: Param) -> np.ndarray:
        """r''(u) = d²r/du²."""

    def derivatives(self, u: Param) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """r, r' and r'' at once (a kind that computes them together overrides this)."""
        return self.point(u), self.d1(u), self.d2(u)

    # derived geometry ------------------------------------------------------------------
    def wrap(self, u: Param) -> np.ndarray:
        """u brought into the domain: wrapped by the period for a closed curve, clipped for
        an open one."""
        a, b = self.domain
        u = np.asarray(u, dtype=float)
        if self.closed:
            return a + np.mod(u - a, b - a)
        return np.clip(u, a, b)

    def tangent(self, u: Param) -> np.ndarray:
        """The unit tangent t = r'/|r'|."""
        d = self.d1(u)
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def normal(self, u: Param) -> np.ndarray:
        """The unit normal n: t turned +90° (to the left of the direction of travel)."""
        return turned(self.tangent(u))

    def curvature(self, u: Param) -> np.ndarray:
        """Signed curvature κ = (x'y'' − y'x'')/|r'|³ (1/κ is the signed radius)."""
        d, dd = self.d1(u), self.d2(u)
        return cross(d, dd) / np.linalg.norm(d, axis=-1) ** 3

    @property
    def length(self) -> float:
        """L = ∫|r'(u)|du over the domain (Gauss–Legendre, 8 nodes on each of 256 pieces)."""
        a, b = self.domain
        if not (np.isfinite(a) and np.isfinite(b)):
            return float("inf")
        nodes, weights = np.polynomial.legendre.leggauss(8)
        edges = np.linspace(a, b, 257)
        half = np.diff(edges)[:, None] / 2
        u = (edges[:-1, None] + edges[1:, None]) / 2 + half * nodes[None, :]
        speed = np.linalg.norm(self.d1(u.ravel()), axis=-1).reshape(u.shape)
        return float(np.sum(speed * weights[None, :] * half))

    def points(self, n: int = 200) -> np.ndarray:
        """n points from one end of the domain to the other, for drawing (a closed curve's
        last point is its first)."""
        a, b = self.domain
        if not (np.isfinite(a) and np.isfinite(b)):
            raise ValueError(Said("curve-unbounded"))
        return self.point(np.linspace(a, b, n))

    def nearest(self, p: np.ndarray) -> Param:
        """The parameter of the curve's point nearest to p (one point (2,) → a float; an
        array (m, 2) → m parameters). See the module's docstring for the method."""
        p = np.asarray(p, dtype=float)
        single = p.ndim == 1
        q = p.reshape(-1, 2)
        u = np.array([self._nearest_one(x) for x in q])
        return float(u[0]) if single else u

    def _nearest_one(self, p: np.ndarray) -> float:
        a, b = self.domain
        n = self.samples
        grid = np.linspace(a, b, n, endpoint=not self.closed)
        dist = np.sum((self.point(grid) - p) ** 2, axis=-1)
        step = grid[1] - grid[0]
        best, best_d = float(grid[np.argmin(dist)]), float(np.min(dist))
        # refine the few deepest valleys of the sampled distance (ties between branches)
        lower = np.roll(dist, 1) if self.closed else np.concatenate([[np.inf], dist[:-1]])
        upper = np.roll(dist, -1) if self.closed else np.concatenate([dist[1:], [np.inf]])
        valleys = np.flatnonzero((dist <= lower) & (dist <= upper))
        for i in valleys[np.argsort(dist[valleys])][:4]:
            u = self._newton(p, float(grid[i]), float(grid[i]) - step, float(grid[i]) + step)
            d = float(np.sum((self.point(u) - p) ** 2))
            if d < best_d:
                best, best_d = u, d
        return float(self.wrap(best))

    def near(self, p: np.ndarray, u: float, span: float = 1 / 32) -> float:
        """The parameter of the point nearest to p, close to `u` (within `span` of the domain's
        length on each side): the nearest point followed along a motion, without jumping to
        another branch of the distance (Newton as in `nearest`)."""
        a, b = self.domain
        width = (b - a) * span if np.isfinite(b - a) else max(1.0, abs(u)) * span * 32
        p = np.asarray(p, dtype=float)
        x = float(u)
        for _ in range(8):                 # plain Newton from a close hint: two or three steps
            r, d, dd = self.derivatives(x)
            slope = float(np.dot(d, d) + np.dot(r - p, dd))
            if slope <= 0:
                break
            step = float(np.dot(r - p, d)) / slope
            x -= step
            if abs(x - u) > width:
                break
            if abs(step) <= 1e-13 * max(1.0, abs(x)):
                return float(self.wrap(x))
        return float(self.wrap(self._newton(p, float(u), u - width, u + width)))

    def _newton(self, p: np.ndarray, u: float, lo: float, hi: float) -> float:
        """Safeguarded Newton on g(u) = (r − p)·r' inside [lo, hi] (bisection when a step
        leaves the bracket or g' ≤ 0); open curves keep to their domain."""
        a, b = self.domain
        if not self.closed:
            lo, hi = max(lo, a), min(hi, b)

        def g(x: float) -> float:
            r, d, _ = self.derivatives(x)
            return float(np.dot(r - p, d))

        g_lo, g_hi = g(lo), g(hi)
        if g_lo > 0 and g_hi > 0:                 # distance rises across the bracket
            return lo
        if g_lo < 0 and g_hi < 0:
            return hi
        for _ in range(60):
            r, d, dd = self.derivatives(u)
            r = r - p
            gu = float(np.dot(r, d))
            slope = float(np.dot(d, d) + np.dot(r, dd))
            if gu < 0:
                lo = u
            else:
                hi = u
            step = u - gu / slope if slope > 0 else None
            nxt = step if step is not None and lo < step < hi else (lo + hi) / 2
            if abs(nxt - u) <= 1e-15 * max(1.0, abs(u)) or hi - lo <= 1e-15 * max(1.0, abs(u)):
                return nxt
            u = nxt
        return u
