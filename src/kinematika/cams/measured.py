"""A disc cam known by measured points of its profile: its follower's motion by contact.

The profile is the closed periodic spline through the points (`curves.Spline`); the
follower's coordinate over a turn comes from `contact.positions`; its lowest value fixes the
base circle (translating roller or knife: d = min y, R_p = √(d² + e²), R_b = R_p − R_f; flat
face: R_b = min y; oscillating: R_p = |B(ψ_min)|, flat: R_b = a sin ψ_min − f), and
s(θ) = coordinate − its minimum, interpolated by a periodic quintic spline (so s', s'', s'''
exist; they are those of the interpolant, as good as the measured points). The cam is then a
`DiscCam` like any other: the same analysis, plots and files.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.interpolate import make_interp_spline

from .contact import positions
from .follower import Flat, Follower, Translating
from .laws import Law
from .profile import DiscCam, measured
from .program import Program, Segment

TURN = 2 * math.pi


@dataclass(frozen=True)
class Sampled(Law):
    """A law given by a periodic spline of s over one turn: S(x) = s(βx), S⁽ᵏ⁾ = βᵏ s⁽ᵏ⁾."""

    spline: Any
    span: float = TURN
    name: str = "measured"

    def __call__(self, x: np.ndarray | float) -> tuple:
        theta = np.mod(np.asarray(x, dtype=float) * self.span, TURN)
        return tuple(self.span**k * self.spline(theta, k) for k in range(4))


def base_from(follower: Follower, lowest: float) -> float:
    """The base circle's radius that puts the follower's lowest coordinate at s = 0."""
    contact = follower.contact
    if isinstance(follower, Translating):
        if contact.touches_with_face:
            return lowest
        return math.hypot(lowest, follower.offset) - contact.radius
    if isinstance(contact, Flat):
        return follower.pivot * math.sin(lowest) - contact.face
    b = np.array([follower.pivot - follower.arm * math.cos(lowest), follower.arm * math.sin(lowest)])
    return float(np.hypot(*b)) - contact.radius


def measured_cam(points: np.ndarray, follower: Follower, sense: int = 1, n: int = 720) -> DiscCam:
    """The disc cam through `points` (cam frame, in order), driving `follower`."""
    outline = measured(points)
    thetas = np.linspace(0.0, TURN, n, endpoint=False)
    coordinate = positions(outline, follower, thetas, sense)
    lowest = float(np.min(coordinate))
    s = coordinate - lowest
    spline = make_interp_spline(np.append(thetas, TURN), np.append(s, s[0]), k=5, bc_type="periodic")
    program = Program((Segment(Sampled(spline), 0.0, TURN, 0.0, 0.0, "measured", 1.0),), periodic=True)
    return DiscCam(program, follower, base_from(follower, lowest), sense)
