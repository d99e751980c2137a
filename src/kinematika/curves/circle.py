"""A circle, and an arc of one, fixed in a body."""
from __future__ import annotations

import math

import numpy as np

from .base import Curve, Param
from ..errors import Said


class Circle(Curve):
    """r(u) = c + R(cos u, sin u), u ∈ [0, 2π) counter-clockwise: r' = R(−sin u, cos u),
    r'' = −R(cos u, sin u), κ = +1/R, length 2πR."""

    closed = True

    def __init__(self, center: np.ndarray, radius: float) -> None:
        if not radius > 0:
            raise ValueError(Said("circle-radius-positive"))
        self.center = np.asarray(center, dtype=float)
        self.radius = float(radius)

    @property
    def domain(self) -> tuple[float, float]:
        """One turn, [0, 2π)."""
        return (0.0, 2 * math.pi)

    def _unit(self, u: Param) -> np.ndarray:
        u = np.asarray(u, dtype=float)
        return np.stack([np.cos(u), np.sin(u)], axis=-1)

    def point(self, u: Param) -> np.ndarray:
        """c + R(cos u, sin u)."""
        return self.center + self.radius * self._unit(u)

    def d1(self, u: Param) -> np.ndarray:
        """R(−sin u, cos u)."""
        e = self._unit(u)
        return self.radius * np.stack([-e[..., 1], e[..., 0]], axis=-1)

    def d2(self, u: Param) -> np.ndarray:
        """−R(cos u, sin u)."""
        return -self.radius * self._unit(u)

    @property
    def length(self) -> float:
        """2πR."""
        return 2 * math.pi * self.radius

    def nearest(self, p: np.ndarray) -> Param:
        """The polar angle of p about the centre (any u for the centre itself: 0)."""
        p = np.asarray(p, dtype=float)
        d = p - self.center
        u = self.wrap(np.arctan2(d[..., 1], d[..., 0]))
        return float(u) if p.ndim == 1 else u


class Arc(Circle):
    """The part of a circle from angle a0 to a1 (radians, counter-clockwise, a0 < a1 ≤ a0 + 2π):
    the circle's formulas on the domain [a0, a1], open."""

    closed = False

    def __init__(self, center: np.ndarray, radius: float, a0: float, a1: float) -> None:
        super().__init__(center, radius)
        if not (a0 < a1 <= a0 + 2 * math.pi):
            raise ValueError(Said("arc-angles"))
        self.a0, self.a1 = float(a0), float(a1)

    @property
    def domain(self) -> tuple[float, float]:
        """[a0, a1]."""
        return (self.a0, self.a1)

    @property
    def length(self) -> float:
        """R·(a1 − a0)."""
        return self.radius * (self.a1 - self.a0)

    def nearest(self, p: np.ndarray) -> Param:
        """The polar angle of p if it lies within the arc, else the nearer end."""
        p = np.asarray(p, dtype=float)
        d = p.reshape(-1, 2) - self.center
        angle = self.a0 + np.mod(np.arctan2(d[:, 1], d[:, 0]) - self.a0, 2 * math.pi)
        inside = angle <= self.a1
        ends = np.stack([self.point(self.a0), self.point(self.a1)])
        to_end = np.linalg.norm(p.reshape(-1, 1, 2) - ends[None], axis=-1)
        u = np.where(inside, angle, np.where(to_end[:, 0] <= to_end[:, 1], self.a0, self.a1))
        return float(u[0]) if p.ndim == 1 else u
