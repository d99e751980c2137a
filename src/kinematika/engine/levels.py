"""The two levels of the instant problem, with one vocabulary for the constraint formulas.

At the velocity level the unknowns are each moving body's (ω, v₀); at the acceleration
level they are (α, a₀), and the known velocities put the centripetal and Coriolis terms in
the constants. A joint writes ``lv.point(body, P)`` and ``lv.omega(body)`` once, adding its
Coriolis terms from the solved velocities (``lv.w``, ``lv.v``) when ``lv.accel``; both
systems then share their matrix by construction.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import Space, add, sub
from .linear import Lin
from .motion import Motion
from .terms import MECHANICS, Terms


class Unknowns:
    """Column layout: per moving body, the rotation components then the translation ones."""

    def __init__(self, bodies: list[str], space: Space) -> None:
        self.bodies = bodies
        self.space = space
        self.width = space.rot + space.dim
        self.offset = {b: k * self.width for k, b in enumerate(bodies)}
        self.n = self.width * len(bodies)

    def rot(self, body: str) -> Any:
        if body not in self.offset:
            return self.space.rot_zero()
        o = self.offset[body]
        parts = tuple(Lin.unknown(o + i) for i in range(self.space.rot))
        return parts[0] if self.space.dim == 2 else parts

    def trans(self, body: str) -> tuple:
        if body not in self.offset:
            return self.space.zero()
        o = self.offset[body] + self.space.rot
        return tuple(Lin.unknown(o + i) for i in range(self.space.dim))

    def body_of(self, column: int) -> str:
        return self.bodies[column // self.width]


class KnownTerms(Unknowns):
    """The unknowns taken as zero: rows then hold only their known terms (their right sides).

    The acceleration system shares the velocity system's matrix, so only its known terms
    (centripetal, Coriolis, drivers' accelerations) need computing.
    """

    def __init__(self, unknowns: Unknowns) -> None:
        self.__dict__.update(unknowns.__dict__)

    def rot(self, body: str) -> Any:
        return self.space.rot_zero()

    def trans(self, body: str) -> tuple:
        return self.space.zero()


class Level:
    """Shared by both levels: the unknowns, the space and the reference point."""

    accel = False

    def __init__(self, unknowns: Unknowns, ref: tuple, motion: Optional[Motion] = None) -> None:
        self.u = unknowns
        self.space = unknowns.space
        self.ref = ref
        self.motion = motion
        # the factors of the velocity-squared terms (`engine.terms`): mechanics unless a view
        # models a student's mistake; the motion of the velocities carries them
        self.terms: Terms = motion.terms if motion is not None else MECHANICS

    def omega(self, body: str) -> Any:
        """ω (velocity level) or α (acceleration level) of `body`, as linear forms."""
        return self.u.rot(body)

    def point(self, body: str, p: tuple) -> tuple:
        raise NotImplementedError

    # the solved velocities, for the terms of the acceleration level
    def w(self, body: str) -> Any:
        return self.motion.states[body].omega if body in self.motion.states else self.space.rot_zero()

    def v(self, body: str, p: tuple) -> tuple:
        if body not in self.motion.states:
            return self.space.zero()
        return self.motion.velocity(self.motion.states[body], p)


class VelocityLevel(Level):
    accel = False

    def point(self, body: str, p: tuple) -> tuple:
        """v = v₀ + ω × (P − ref)."""
        r = sub(p, self.ref)
        return add(self.u.trans(body), self.space.cross(self.u.rot(body), r))


class AccelerationLevel(Level):
    accel = True

    def point(self, body: str, p: tuple) -> tuple:
        """a = a₀ + α × r + ω × (ω × r), with ω known."""
        r = sub(p, self.ref)
        w = self.w(body)
        centripetal = self.terms.normal_part(self.space.cross(w, self.space.cross(w, r)))
        return add(add(self.u.trans(body), self.space.cross(self.u.rot(body), r)), centripetal)
