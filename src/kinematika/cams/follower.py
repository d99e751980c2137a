"""Cam followers: how the follower moves (translating or oscillating) and what touches the
cam (a knife edge, a roller, a flat face), in the ground frame of the cam's centre.

Layout (the cam's centre O at the origin; Norton's and Shigley's figures):

- translating: the follower slides along the line x = e (the offset e, 0 for an in-line
  follower), its trace point at (e, d + s) with d = √(R_p² − e²), where R_p = R_b + R_f is
  the prime circle (R_b the base circle, R_f the roller's radius, 0 for a knife edge);
  a flat face is the line y = R_b + s, perpendicular to the motion;
- oscillating: the pivot A = (a, 0) at distance a from O, the arm of length ℓ to the trace
  point B = A + ℓ(−cos ψ, sin ψ), ψ = ψ₀ + s (s in radians, the follower's angle from its
  lowest position), ψ₀ = arccos((a² + ℓ² − R_p²)/(2aℓ)) so that |OB| = R_p at s = 0 and |OB|
  grows with s; a flat face is the line through A along the arm, moved towards the cam by
  f (`face`): n·X = a sin ψ − f with n = (sin ψ, cos ψ), ψ₀ = arcsin((R_b + f)/a).

Each kind of contact (`Knife`, `Roller`, `Flat`) and each kind of motion (`Translating`,
`Oscillating`) is a class; code asks them (`touches_with_face`, `radius`, `trace`, `face`,
`direction`) and never compares names. The flat face's own dimension (`Flat.face`) belongs
to that class only: code that reads it narrows the contact by its class
(`isinstance(contact, Flat)`), which is what a type checker follows.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..curves import jet
from ..curves.jet import Jet


@dataclass(frozen=True)
class Knife:
    """A knife edge: the trace point itself touches the cam (profile = pitch curve)."""

    radius: float = 0.0
    touches_with_face = False

    def undercut(self, pitch: np.ndarray, profile: np.ndarray) -> np.ndarray:
        """A knife edge follows any pitch curve: never undercut."""
        return np.zeros(np.shape(pitch), dtype=bool)


@dataclass(frozen=True)
class Roller:
    """A roller of radius R_f: its centre is the trace point; the profile is the pitch curve
    moved inwards along its normal by R_f (the envelope of the roller's circles)."""

    radius: float
    touches_with_face = False

    def undercut(self, pitch: np.ndarray, profile: np.ndarray) -> np.ndarray:
        """Undercut where the pitch curve is convex (ρ > 0) with ρ_pitch < R_f: the offset
        profile folds back on itself (a cusp) and the roller cannot follow it."""
        pitch = np.asarray(pitch)
        return (pitch > 0) & (pitch < self.radius)


@dataclass(frozen=True)
class Flat:
    """A flat face (for an oscillating follower moved towards the cam by `face` from the
    pivot's line along the arm): the profile is the envelope of the face's lines."""

    face: float = 0.0
    radius: float = 0.0
    touches_with_face = True

    def undercut(self, pitch: np.ndarray, profile: np.ndarray) -> np.ndarray:
        """Undercut where the profile's radius c + d²c/dα² (R_b + s + s'' for a translating
        follower) is negative: the envelope has a cusp; a flat face cannot touch a concave cam."""
        return np.asarray(profile) < 0


Contact = Knife | Roller | Flat


@dataclass(frozen=True)
class Translating:
    """A follower sliding along x = `offset` (positive y outwards) — see the module."""

    contact: Contact
    offset: float = 0.0
    angular = False           # its displacement is a length

    def prime(self, base: float) -> float:
        """R_p = R_b + R_f."""
        return base + self.contact.radius

    def lowest(self, base: float) -> float:
        """d = √(R_p² − e²): the trace point's height at s = 0."""
        return math.sqrt(self.prime(base) ** 2 - self.offset**2)

    def trace(self, s: Jet, base: float) -> tuple[Jet, Jet]:
        """The trace point (e, d + s) in the ground frame."""
        return Jet.constant(self.offset, s.order) + 0 * s, s + self.lowest(base)

    def face(self, s: Jet, base: float) -> tuple[Jet, Jet]:
        """The flat face as (angle of its outward normal, distance from O): (π/2, R_b + s)."""
        return Jet.constant(math.pi / 2, s.order) + 0 * s, s + base

    def direction(self, point: np.ndarray, s: np.ndarray) -> np.ndarray:
        """The unit velocity, for growing s, of the follower's point at `point`: (0, 1)."""
        return np.broadcast_to(np.array([0.0, 1.0]), np.shape(point)).copy()

    def along_face(self, point: np.ndarray, s: np.ndarray, base: float) -> np.ndarray:
        """Where a contact point lies along the flat face, from the follower's axis: x − e."""
        return point[..., 0] - self.offset


@dataclass(frozen=True)
class Oscillating:
    """A follower turning about the pivot (a, 0) with an arm of length ℓ — see the module."""

    contact: Contact
    pivot: float
    arm: float
    angular = True            # its displacement is an angle (radians)

    def prime(self, base: float) -> float:
        """R_p = R_b + R_f."""
        return base + self.contact.radius

    def start(self, base: float) -> float:
        """ψ₀: the arm's angle at s = 0 (roller or knife: |OB| = R_p; flat: the face tangent
        to the base circle)."""
        if isinstance(self.contact, Flat):
            return math.asin((base + self.contact.face) / self.pivot)
        a, l, rp = self.pivot, self.arm, self.prime(base)
        return math.acos((a * a + l * l - rp * rp) / (2 * a * l))

    def trace(self, s: Jet, base: float) -> tuple[Jet, Jet]:
        """B = (a − ℓ cos ψ, ℓ sin ψ), ψ = ψ₀ + s."""
        psi = s + self.start(base)
        return self.pivot - self.arm * jet.cos(psi), self.arm * jet.sin(psi)

    def face(self, s: Jet, base: float) -> tuple[Jet, Jet]:
        """The face: normal n = (sin ψ, cos ψ), at angle π/2 − ψ; distance a sin ψ − f."""
        psi = s + self.start(base)
        return math.pi / 2 - psi, self.pivot * jet.sin(psi) - _setback(self.contact)

    def direction(self, point: np.ndarray, s: np.ndarray) -> np.ndarray:
        """The unit velocity of the arm's point at `point` as ψ grows: −J(X − A)/|X − A|
        (ψ grows clockwise about A in this layout)."""
        r = np.asarray(point, dtype=float) - np.array([self.pivot, 0.0])
        v = np.stack([r[..., 1], -r[..., 0]], axis=-1)
        return v / np.linalg.norm(v, axis=-1, keepdims=True)

    def along_face(self, point: np.ndarray, s: np.ndarray, base: float) -> np.ndarray:
        """Where a contact point lies along the face, from the pivot: (X − A)·u, u the arm's
        direction (−cos ψ, sin ψ)."""
        psi = np.asarray(s) + self.start(base)
        r = np.asarray(point, dtype=float) - np.array([self.pivot, 0.0])
        return -r[..., 0] * np.cos(psi) + r[..., 1] * np.sin(psi)


def _setback(contact: Contact) -> float:
    """How far a flat face is moved towards the cam from the pivot's line (`Flat.face`); a
    knife edge or a roller has no face: 0."""
    return contact.face if isinstance(contact, Flat) else 0.0


Follower = Translating | Oscillating
