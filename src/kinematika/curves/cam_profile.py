"""A curve given by a formula of its parameter, with exact derivatives: a cam's profile.

A cam's pitch curve and profile are formulas of the cam angle θ (the follower's trace point
turned back by the cam's rotation; that curve offset by the roller's radius; the envelope
of a flat face). `CamProfile` takes the formula as a function of a `Jet` (the parameter with
its derivatives) returning the jets of x and y, so point, r' and r'' are exact (no finite
differences): the formula is written once and differentiated as it is evaluated.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from .base import Curve, Param
from .jet import Jet

Trace = Callable[[Jet], "tuple[Jet, Jet]"]


class CamProfile(Curve):
    """r(u) = (x(u), y(u)) from `trace(u as a jet)`; closed with period 2π by default (u is
    the cam angle θ in radians), or open over `domain` (a translating cam: u is the cam's
    travel). The trace must return jets of at least second order."""

    samples = 1440

    def __init__(self, trace: Trace, domain: tuple[float, float] = (0.0, 2 * math.pi),
                 closed: bool = True, name: str = "") -> None:
        self.trace = trace
        self._domain = (float(domain[0]), float(domain[1]))
        self.closed = closed
        self.name = name

    @property
    def domain(self) -> tuple[float, float]:
        """The parameter's range (one turn of the cam, or its travel)."""
        return self._domain

    def jets(self, u: Param) -> tuple[Jet, Jet]:
        """x and y as jets at u (a closed profile's u is wrapped into its period)."""
        u = np.asarray(u, dtype=float)
        return self.trace(Jet.variable(self.wrap(u) if self.closed else u))

    def _stack(self, u: Param, k: int) -> np.ndarray:
        x, y = self.jets(u)
        return np.stack([x.d(k), y.d(k)], axis=-1)

    def derivatives(self, u: Param) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """r, r' and r'' from one evaluation of the trace."""
        x, y = self.jets(u)
        return tuple(np.stack([x.d(k), y.d(k)], axis=-1) for k in range(3))  # type: ignore[return-value]  # three, by range(3): a tuple() of a generator is typed tuple[ndarray, ...]

    def point(self, u: Param) -> np.ndarray:
        """r(u)."""
        return self._stack(u, 0)

    def d1(self, u: Param) -> np.ndarray:
        """r'(u), exact."""
        return self._stack(u, 1)

    def d2(self, u: Param) -> np.ndarray:
        """r''(u), exact."""
        return self._stack(u, 2)
