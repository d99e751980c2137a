"""A motion program: the follower's displacement over the cam's whole travel, by segments.

A disc cam's program is a list of segments over the cam angle θ — dwell, rise, return —
each with a motion law and a span β, the spans summing to 360° (a translating cam's program
runs over the cam's travel instead, in length). Within segment i, starting at θᵢ with the
follower at sᵢ and moving by hᵢ:

    s(θ) = sᵢ + hᵢ·S(x),  x = (θ − θᵢ)/βᵢ,
    ds/dθ = hᵢ S'(x)/βᵢ,  d²s/dθ² = hᵢ S''(x)/βᵢ²,  d³s/dθ³ = hᵢ S'''(x)/βᵢ³

(per radian of cam angle; lengths in the program's unit, or radians for an oscillating
follower). At a constant cam speed ω (rad/s) the follower's velocity, acceleration and jerk
are v = ω·ds/dθ, a = ω²·d²s/dθ², j = ω³·d³s/dθ³ (Norton, *Design of Machinery*, eq. 8.1).

The fundamental law of cam design (Norton §8.3): the displacement, velocity and acceleration
must be continuous over the whole cycle (the jerk finite), including the seam between the
last segment and the first. `jumps` lists each boundary where v or a is not.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ..curves.jet import Jet
from .laws import Law

Motion = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


@dataclass(frozen=True)
class Segment:
    """A stretch of the program: `law` over `span` (rad, or length for a translating cam)
    from `start`, moving the follower from `s0` by `rise` (negative for a return, 0 for a
    dwell). `label` is what the user called it (for messages and plots)."""

    law: Law
    start: float
    span: float
    s0: float
    rise: float
    label: str = ""
    scale: float | None = None      # the law's unit when it is not `rise` (a polynomial with rise 0)

    @property
    def end(self) -> float:
        """Where the segment ends."""
        return self.start + self.span

    def motion(self, u: np.ndarray) -> Motion:
        """s, ds/du, d²s/du², d³s/du³ at u (module docstring's formulas)."""
        x = (np.asarray(u, dtype=float) - self.start) / self.span
        S, S1, S2, S3 = self.law(x)
        h, b = (self.rise if self.scale is None else self.scale), self.span
        return self.s0 + h * S, h * S1 / b, h * S2 / b**2, h * S3 / b**3


@dataclass(frozen=True)
class Jump:
    """A discontinuity of the program at a segment boundary: `quantity` ('velocity' or
    'acceleration', as derivatives per radian: ds/dθ or d²s/dθ²) jumps by `amount` at `at`
    (cam angle in rad, or travel) between segments `before` and `after` (indices)."""

    at: float
    quantity: str
    amount: float
    before: int
    after: int


@dataclass(frozen=True)
class Program:
    """The segments, back to back from 0; `periodic` for a disc cam (the cycle repeats after
    `period` = 2π and the seam is checked like any boundary)."""

    segments: tuple[Segment, ...]
    periodic: bool = True

    @property
    def period(self) -> float:
        """The total span."""
        return self.segments[-1].end

    @property
    def boundaries(self) -> np.ndarray:
        """Where each segment starts, and the end of the last."""
        return np.array([seg.start for seg in self.segments] + [self.period])

    def wrap(self, u: np.ndarray | float) -> np.ndarray:
        """u brought into [0, period) (periodic) or clipped to [0, period]."""
        u = np.asarray(u, dtype=float)
        return np.mod(u, self.period) if self.periodic else np.clip(u, 0.0, self.period)

    def motion(self, u: np.ndarray | float) -> Motion:
        """s, ds/du, d²s/du², d³s/du³ at cam coordinate u (vectorised)."""
        u = self.wrap(u)
        index = np.clip(np.searchsorted(self.boundaries[1:-1], u, side="right"), 0, len(self.segments) - 1)
        out = [np.zeros_like(u) for _ in range(4)]
        for i, seg in enumerate(self.segments):
            mask = index == i
            if np.any(mask):
                for k, value in enumerate(seg.motion(u[mask])):
                    out[k][mask] = value
        return tuple(out)  # type: ignore[return-value]  # as many as `out`'s rows (a tuple() of a list has no length to mypy)

    def jet(self, u: Jet) -> Jet:
        """s as a jet along whatever parameter u is a jet of (chain rule)."""
        return u.compose(*self.motion(u.value))

    def kinematics(self, u: np.ndarray | float, omega: float) -> Motion:
        """Follower s, v = ω·ds/dθ, a = ω²·d²s/dθ², j = ω³·d³s/dθ³ at a constant cam speed ω."""
        s, ds, dds, ddds = self.motion(u)
        return s, omega * ds, omega**2 * dds, omega**3 * ddds

    def jumps(self, tolerance: float = 1e-9) -> list[Jump]:
        """Every boundary where ds/dθ or d²s/dθ² differs on its two sides by more than
        `tolerance` × the program's largest value of that derivative (the seam of a periodic
        program included; the ends of an open one are not boundaries)."""
        segs = self.segments
        pairs = [(i, i + 1) for i in range(len(segs) - 1)]
        if self.periodic:
            pairs.append((len(segs) - 1, 0))
        grid = np.linspace(0.0, self.period, 4001)
        _, ds, dds, _ = self.motion(grid)
        scale = {1: max(float(np.max(np.abs(ds))), 1e-300), 2: max(float(np.max(np.abs(dds))), 1e-300)}
        found = []
        for i, k in pairs:
            left = segs[i].motion(np.array(segs[i].end))
            right = segs[k].motion(np.array(segs[k].start))
            for order, quantity in ((1, "velocity"), (2, "acceleration")):
                amount = float(right[order] - left[order])
                if abs(amount) > tolerance * scale[order]:
                    found.append(Jump(segs[k].start if k else (0.0 if self.periodic else segs[k].start),
                                      quantity, amount, i, k))
        return found


Step = tuple[Law, float, float, str] | tuple[Law, float, float, str, float]
"""One step of a program to `build`: (law, span, rise, label), and a polynomial's scale."""


def build(steps: Sequence[Step], periodic: bool = True) -> Program:
    """A program from (law, span, rise, label[, scale]) in order, starting at s = 0."""
    segments, start, s0 = [], 0.0, 0.0
    for law, span, rise, label, *scale in steps:
        segments.append(Segment(law, start, span, s0, rise, label, scale[0] if scale else None))
        start, s0 = start + span, s0 + rise
    return Program(tuple(segments), periodic)


FULL_TURN = 2 * math.pi
