"""A cam's pitch curve and profile from its motion program and follower (as `CamProfile`s).

Kinematic inversion (Norton §8.6, Shigley/Uicker §6.6): hold the cam still and turn the
follower's layout the other way. A disc cam turning by σθ (σ = +1 counter-clockwise, −1
clockwise) sees a ground point X at R(−σθ)·X in its own frame, so

- pitch curve (the trace point's path on the cam):  P(θ) = R(−σθ)·B(s(θ)),  B the trace
  point of `follower` (knife edge: the profile itself);
- roller: the profile is the envelope of the roller's circles, the pitch curve moved
  inwards along its normal by R_f:  C(θ) = P(θ) − R_f·n_out(θ),  n_out the outward normal
  (n_out = τ·(P' turned +90°)/|P'|, τ = σ since the pitch curve runs clockwise for σ = +1);
- flat face: the envelope of the face's lines n(α)·X = c in the cam's frame, α = α_g − σθ:
  X = c·n + (dc/dα)·t with t = dn/dα. For a translating follower with its face
  perpendicular to the motion this is Shigley's closed form (eq. 6-20):
  x = (R_b + s) cos(σθ) … written as R(−σθ)·(σ·ds/dθ, R_b + s), the contact at ds/dθ from the
  axis, and the profile's radius of curvature is ρ = R_b + s + d²s/dθ² (eq. 6-23).

A translating (wedge, plate) cam moves along +x by u: X ↦ X − (u, 0); its pitch curve is
(−u, R_p + s(u)), its roller profile offset likewise (τ = −1: the curve runs towards −x).

Derivatives come exact from jets (`curves.jet`): the program gives s, s', s'', s'''.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..curves import CamProfile, Spline, jet
from ..curves.jet import Jet
from .follower import Follower
from .program import Program
from ..errors import Said


def _offset_inwards(pitch: CamProfile, radius: float, tau: int, name: str) -> CamProfile:
    """The curve P − radius·n_out, n_out = τ·(P' turned +90°)/|P'| (to second order)."""

    def trace(u: Jet) -> tuple[Jet, Jet]:
        x, y = pitch.trace(u)
        dx, dy = x.derivative(), y.derivative()
        size = jet.hypot(dx, dy)
        nx, ny = -dy / size * tau, dx / size * tau
        return x - nx * radius, y - ny * radius

    return CamProfile(trace, pitch.domain, pitch.closed, name)


@dataclass(frozen=True)
class DiscCam:
    """A disc (plate, radial) cam: `program` over one turn, `follower`, base circle radius
    `base` (R_b), turning counter-clockwise (`sense` = +1) or clockwise (−1)."""

    program: Program
    follower: Follower
    base: float
    sense: int = 1

    @property
    def outward(self) -> int:
        """τ: the sign that turns (P' turned +90°) into the outward normal."""
        return self.sense

    @property
    def prime(self) -> float:
        """The prime circle's radius R_p = R_b + R_f."""
        return self.follower.prime(self.base)

    def to_cam(self, x: Jet, y: Jet, u: Jet) -> tuple[Jet, Jet]:
        """A ground point seen from the cam turned by σu: R(−σu)·(x, y)."""
        return jet.rotate(x, y, -self.sense * u)

    def to_ground(self, points: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Cam-frame points (…, 2) at cam angles u, in the ground frame: R(σu)·p."""
        a = self.sense * np.asarray(u, dtype=float)
        c, s = np.cos(a), np.sin(a)
        return np.stack([c * points[..., 0] - s * points[..., 1], s * points[..., 0] + c * points[..., 1]], axis=-1)

    def vector_to_ground(self, vectors: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Directions turn as points do about O."""
        return self.to_ground(vectors, u)

    @cached_property
    def pitch(self) -> CamProfile:
        """The trace point's path on the cam, P(θ) = R(−σθ)·B(s(θ))."""

        def trace(u: Jet) -> tuple[Jet, Jet]:
            x, y = self.follower.trace(self.program.jet(u), self.base)
            return self.to_cam(x, y, u)

        return CamProfile(trace, (0.0, self.program.period), self.program.periodic, "pitch")

    @cached_property
    def profile(self) -> CamProfile:
        """The cam's surface: the pitch curve (knife), its inward offset by R_f (roller), or the
        envelope of the face's lines (flat)."""
        contact = self.follower.contact
        if contact.touches_with_face:
            return self._envelope()
        if contact.radius > 0:
            return _offset_inwards(self.pitch, contact.radius, self.outward, "profile")
        return CamProfile(self.pitch.trace, self.pitch.domain, self.pitch.closed, "profile")

    def face_line(self, u: Jet) -> tuple[Jet, Jet]:
        """The flat face in the cam's frame: (angle α of its outward normal, distance c)."""
        alpha, c = self.follower.face(self.program.jet(u), self.base)
        return alpha - self.sense * u, c

    def _envelope(self) -> CamProfile:
        def trace(u: Jet) -> tuple[Jet, Jet]:
            alpha, c = self.face_line(u)
            rate = c.derivative() / alpha.derivative()          # dc/dα
            n = (jet.cos(alpha), jet.sin(alpha))
            return c * n[0] - rate * n[1], c * n[1] + rate * n[0]

        return CamProfile(trace, (0.0, self.program.period), True, "profile")

    def face_radius(self, u: np.ndarray) -> np.ndarray:
        """The flat-faced profile's radius of curvature ρ = c + d²c/dα² (ρ = R_b + s + s''
        for a translating follower, Shigley eq. 6-23): the envelope X(α) has dX/dα = (c + c_αα)·t."""
        alpha, c = self.face_line(Jet.variable(np.asarray(u, dtype=float)))
        a1 = alpha.derivative()
        c_a = c.derivative() / a1
        c_aa = c_a.derivative() / a1
        return c.value + c_aa.value


@dataclass(frozen=True)
class PlateCam(DiscCam):
    """A translating (wedge, plate) cam moving along +x by u; `program` over its travel
    (lengths), `base` the profile's height above the cam's base line at s = 0 (the follower
    slides along x = 0; no offset, no flat face)."""

    @property
    def outward(self) -> int:
        """The pitch curve runs towards −x: the outward normal is −(P' turned +90°)."""
        return -1

    def to_cam(self, x: Jet, y: Jet, u: Jet) -> tuple[Jet, Jet]:
        """X − (u, 0)."""
        return x - u, y

    def to_ground(self, points: np.ndarray, u: np.ndarray) -> np.ndarray:
        """p + (u, 0)."""
        out = np.array(points, dtype=float, copy=True)
        out[..., 0] += np.asarray(u, dtype=float)
        return out

    def vector_to_ground(self, vectors: np.ndarray, u: np.ndarray) -> np.ndarray:
        """A translation leaves directions as they are."""
        return np.asarray(vectors, dtype=float)

    def _envelope(self) -> CamProfile:
        raise ValueError(Said("cam-flat-translating"))


def measured(points: np.ndarray) -> Spline:
    """A disc cam given by measured points of its profile (in the cam's frame, in order round
    it): the closed periodic spline through them."""
    return Spline(np.asarray(points, dtype=float), closed=True)


FULL_TURN = 2 * math.pi
