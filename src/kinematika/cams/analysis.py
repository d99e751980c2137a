"""A cam over its cycle: s–v–a–j, pitch curve and profile, pressure angle, radius of curvature,
undercutting, and the program's jumps.

- Pressure angle φ (Norton §8.7, Shigley/Uicker §6.8): the angle between the common normal at
  the contact and the velocity of the follower's point there (the trace point for a knife
  edge or roller, the contact point on a flat face). With n the outward normal and m that
  velocity's direction, both in the ground frame, φ = atan2(τ·(m × n), m·n) (τ as in
  `profile`), positive on a rise. For a translating roller or knife edge this is Norton's
  eq. 8.31, tan φ = (ds/dθ − σe)/(s + √(R_p² − e²)) (σ = +1 for a counter-clockwise cam,
  e the offset; an offset on the side σe > 0 lowers φ on the rise); a translating flat face
  has φ = 0.
- Radius of curvature, positive where the curve is convex: ρ = 1/(−τκ) with κ the curve's
  signed curvature. For a radial roller this is Norton's eq. 8.33,
  ρ_pitch = [(R_p + s)² + s'²]^{3/2} / [(R_p + s)² + 2s'² − (R_p + s)s''] (s' = ds/dθ); the
  roller's profile has ρ_pitch − R_f, a knife edge's ρ_pitch, a flat face's c + d²c/dα²
  (R_b + s + s'' translating, Shigley eq. 6-23).
- Undercutting: a roller where the pitch curve is convex with ρ_pitch < R_f; a flat face
  where ρ < 0 (the contact kinds' `undercut`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from ..curves.base import cross
from ..errors import KinematikaWarning, Num
from ..curves.jet import Jet
from .profile import DiscCam, PlateCam


@dataclass(frozen=True)
class Range:
    """Where a condition holds: from `start` to `end` (degrees of cam angle, or travel), and
    the worst value there."""

    start: float
    end: float
    worst: float


@dataclass
class CamAnalysis:
    """The cam sampled at n points over its cycle (`u`, rad or length), at cam speed `speed`
    (ω in rad/s for a disc cam, the travel's speed for a translating cam)."""

    cam: DiscCam
    speed: float
    n: int = 720

    @cached_property
    def u(self) -> np.ndarray:
        """The sampled cam coordinate (rad, or length): n points over one cycle."""
        period = self.cam.program.period
        return np.linspace(0.0, period, self.n, endpoint=not self.cam.program.periodic)

    @property
    def angle(self) -> np.ndarray:
        """The abscissa as the user gives it: degrees of cam angle (disc) or travel (plate)."""
        return self.u if isinstance(self.cam, PlateCam) else np.degrees(self.u)

    def angle_of(self, u: np.ndarray) -> np.ndarray:
        """Cam coordinates (rad, or travel) as the abscissa is shown (degrees, or travel)."""
        return np.asarray(u, dtype=float) if isinstance(self.cam, PlateCam) else np.degrees(u)

    @cached_property
    def motion(self) -> tuple[np.ndarray, ...]:
        """s, ds/du, d²s/du², d³s/du³."""
        return self.cam.program.motion(self.u)

    @cached_property
    def svaj(self) -> tuple[np.ndarray, ...]:
        """s, v = ω s', a = ω² s'', j = ω³ s''' (s in the program's unit: length, or radians
        for an oscillating follower)."""
        return self.cam.program.kinematics(self.u, self.speed)

    @cached_property
    def pitch(self) -> np.ndarray:
        """The pitch curve's points (cam frame)."""
        return self.cam.pitch.point(self.u)

    @cached_property
    def profile(self) -> np.ndarray:
        """The profile's points (cam frame)."""
        return self.cam.profile.point(self.u)

    @cached_property
    def pressure_angle(self) -> np.ndarray:
        """φ(θ) in radians (module docstring)."""
        cam, u = self.cam, self.u
        s = self.motion[0]
        tau = cam.outward
        if cam.follower.contact.touches_with_face:
            alpha, _ = cam.follower.face(Jet.variable(s), cam.base)
            n = np.stack([np.cos(alpha.value), np.sin(alpha.value)], axis=-1) * np.ones((len(u), 1))
            at = cam.to_ground(self.profile, u)
        else:
            n = tau * cam.vector_to_ground(cam.pitch.normal(u), u)
            at = cam.to_ground(self.pitch, u)
        m = cam.follower.direction(at, s)
        return np.arctan2(tau * cross(m, n), np.sum(m * n, axis=-1))

    @cached_property
    def pitch_radius(self) -> np.ndarray:
        """ρ of the pitch curve, positive where convex (inf where straight)."""
        kappa = -self.cam.outward * self.cam.pitch.curvature(self.u)
        with np.errstate(divide="ignore"):
            return np.where(kappa == 0, np.inf, 1 / np.where(kappa == 0, 1, kappa))

    @cached_property
    def profile_radius(self) -> np.ndarray:
        """ρ of the profile, positive where convex: ρ_pitch − R_f (roller, knife: R_f = 0) or
        c + d²c/dα² (flat face)."""
        if self.cam.follower.contact.touches_with_face:
            return self.cam.face_radius(self.u)
        return self.pitch_radius - self.cam.follower.contact.radius

    @cached_property
    def undercut(self) -> np.ndarray:
        """Where the follower cannot follow the profile (the contact kind's rule)."""
        return self.cam.follower.contact.undercut(self.pitch_radius, self.profile_radius)

    def ranges(self, mask: np.ndarray, values: np.ndarray) -> list[Range]:
        """The stretches of the cycle where `mask` holds, with the smallest value there."""
        out: list[Range] = []
        x = self.angle
        idx = np.flatnonzero(mask)
        if not len(idx):
            return out
        groups = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        for g in groups:
            out.append(Range(float(x[g[0]]), float(x[g[-1]]), float(np.min(values[g]))))
        return out

    def summary(self) -> dict[str, Any]:
        """What a designer checks first (JSON-ready): the largest pressure angle and where,
        the smallest radii of curvature (convex and concave) and where, undercutting, the
        acceleration jumps, the peaks of s, v, a, j."""
        x, phi = self.angle, self.pressure_angle
        i = int(np.argmax(np.abs(phi)))
        out: dict[str, Any] = {
            "pressure_angle": {"largest": math.degrees(float(phi[i])), "at": float(x[i])},
            "pitch_radius": _radii(self.pitch_radius, x),
            "profile_radius": _radii(self.profile_radius, x),
            "undercut": [vars(r) for r in self.ranges(self.undercut, self.profile_radius)],
            "jumps": [{"at": _abscissa(self.cam, j.at), "quantity": j.quantity,
                       "amount": j.amount * self.speed ** (2 if j.quantity == "acceleration" else 1),
                       "between": [j.before, j.after]} for j in self.cam.program.jumps()],
            "peaks": {name: float(np.max(np.abs(v))) for name, v in zip("svaj", self.svaj)},
            "lift": float(np.max(self.motion[0]) - np.min(self.motion[0])),
        }
        if self.cam.follower.angular:                     # an oscillating follower's angle in degrees
            out["peaks"]["s"] = math.degrees(out["peaks"]["s"])
            out["lift"] = math.degrees(out["lift"])
        if self.cam.follower.contact.touches_with_face:       # no trace point: no pitch curve
            del out["pitch_radius"]
            where = self.cam.follower.along_face(self.cam.to_ground(self.profile, self.u), self.motion[0], self.cam.base)
            out["face"] = {"from": float(np.min(where)), "to": float(np.max(where))}
        return out


    def warnings(self, units: str = "mm") -> list[KinematikaWarning]:
        """One warning per jump of velocity or acceleration (the fundamental law of cam design
        broken: infinite acceleration or jerk there), naming the segments and the size."""
        out = []
        unit = "rad" if self.cam.follower.angular else units
        for j in self.cam.program.jumps():
            order = 1 if j.quantity == "velocity" else 2
            size = j.amount * self.speed**order
            at = _abscissa(self.cam, j.at)
            place = "°" if not isinstance(self.cam, PlateCam) else f" {units}"
            out.append(KinematikaWarning(
                "cam-jump", f"program[{j.before}]→[{j.after}]", quantity=j.quantity, size=Num(size, "+.4g"),
                unit=f"{unit}/s{'²' if order == 2 else ''}", at=Num(at, "g"), place=place))
        return out


def _radii(rho: np.ndarray, x: np.ndarray) -> dict[str, Any]:
    """The smallest convex radius and the smallest concave one (by size), with where."""
    out: dict[str, Any] = {}
    convex, concave = rho > 0, rho < 0
    if np.any(convex):
        i = int(np.flatnonzero(convex)[np.argmin(rho[convex])])
        out["convex"] = {"smallest": float(rho[i]), "at": float(x[i])}
    if np.any(concave):
        i = int(np.flatnonzero(concave)[np.argmax(rho[concave])])
        out["concave"] = {"smallest": float(-rho[i]), "at": float(x[i])}
    return out


def _abscissa(cam: DiscCam, u: float) -> float:
    return u if isinstance(cam, PlateCam) else math.degrees(u)
