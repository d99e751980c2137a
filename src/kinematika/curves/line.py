"""A straight line fixed in a body: through a point, along a direction."""
from __future__ import annotations

import numpy as np

from .base import Curve, Param
from ..errors import Said


class Line(Curve):
    """r(u) = p + u·d̂ (d̂ the unit direction, so u is the distance from p along it);
    r' = d̂, r'' = 0, κ = 0. Unbounded unless `domain` is given."""

    def __init__(self, through: np.ndarray, direction: np.ndarray,
                 domain: tuple[float, float] = (-np.inf, np.inf)) -> None:
        d = np.asarray(direction, dtype=float)
        size = float(np.hypot(*d))
        if not size > 0:
            raise ValueError(Said("curve-line-direction"))
        self.through = np.asarray(through, dtype=float)
        self.direction = d / size
        self._domain = (float(domain[0]), float(domain[1]))

    @property
    def domain(self) -> tuple[float, float]:
        """The range of u (by default the whole line)."""
        return self._domain

    def point(self, u: Param) -> np.ndarray:
        """p + u·d̂."""
        u = np.asarray(u, dtype=float)
        return self.through + u[..., None] * self.direction

    def d1(self, u: Param) -> np.ndarray:
        """d̂ everywhere."""
        return np.broadcast_to(self.direction, np.shape(u) + (2,)).copy()

    def d2(self, u: Param) -> np.ndarray:
        """Zero everywhere."""
        return np.zeros(np.shape(u) + (2,))

    def nearest(self, p: np.ndarray) -> Param:
        """The foot of the perpendicular: u = (p − p₀)·d̂ (clipped to the domain)."""
        p = np.asarray(p, dtype=float)
        u = self.wrap((p - self.through) @ self.direction)
        return float(u) if p.ndim == 1 else u
