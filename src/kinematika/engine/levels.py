"""The two levels of the instant problem, with one vocabulary for the constraint formulas.

At the velocity level the unknowns are each moving body's (ω, v₀); at the acceleration
level they are (α, a₀), and the known velocities put the centripetal and Coriolis terms in
the constants. A joint writes ``lv.point(body, P)`` and ``lv.omega(body)`` once, adding its
Coriolis terms from the solved velocities (``lv.w``, ``lv.v``) when ``lv.accel``; both
systems then share their matrix by construction.
"""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

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
        """The rotation unknowns of `body` as linear forms: ω (or α) — one component in the
        plane, three in space; zero for the frame."""
        if body not in self.offset:
            return self.space.rot_zero()
        o = self.offset[body]
        parts = tuple(Lin.unknown(o + i) for i in range(self.space.rot))
        return parts[0] if self.space.dim == 2 else parts

    def trans(self, body: str) -> tuple:
        """The translation unknowns of `body` as linear forms: v₀ (or a₀), the velocity of its
        point at the reference; zero for the frame."""
        if body not in self.offset:
            return self.space.zero()
        o = self.offset[body] + self.space.rot
        return tuple(Lin.unknown(o + i) for i in range(self.space.dim))

    def body_of(self, column: int) -> str:
        """The body whose twist holds unknown number `column`."""
        return self.bodies[column // self.width]

    def layout(self) -> tuple[np.ndarray, list[str]]:
        """Which columns are translations (a bool array) and the body of each column: what
        the analysis of the matrix reads; counted once per layout (a motion in time builds
        the same layout at every instant)."""
        key = (tuple(self.bodies), self.space.dim)
        found = _LAYOUTS.get(key)
        if found is None:
            found = (np.array([(c % self.width) >= self.space.rot for c in range(self.n)], dtype=bool),
                     [self.body_of(c) for c in range(self.n)])
            found[0].flags.writeable = False          # shared: read, never written
            if len(_LAYOUTS) < 64:
                _LAYOUTS[key] = found
        return found


_LAYOUTS: dict[tuple, tuple[np.ndarray, list[str]]] = {}


class KnownTerms(Unknowns):
    """The unknowns taken as zero: rows then hold only their known terms (their right sides).

    The acceleration system shares the velocity system's matrix, so only its known terms
    (centripetal, Coriolis, drivers' accelerations) need computing.
    """

    def __init__(self, unknowns: Unknowns) -> None:
        self.__dict__.update(unknowns.__dict__)

    def rot(self, body: str) -> Any:
        """Zero: the unknown α taken out, so that a row keeps only its known terms."""
        return self.space.rot_zero()

    def trans(self, body: str) -> tuple:
        """Zero: the unknown a₀ taken out, so that a row keeps only its known terms."""
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
        """The motion of `body`'s material point at `p` as linear forms: its velocity at the
        velocity level, its acceleration at the acceleration level (each level says its
        formula)."""
        raise NotImplementedError

    def column(self, body: str) -> Optional[int]:
        """The first column of `body`'s unknowns (its ω, then v₀), None for the frame: where
        a joint's rows filled as arrays (`JointKind.numeric_rows`) put their coefficients."""
        return self.u.offset.get(body)

    # the solved velocities, for the terms of the acceleration level
    def w(self, body: str) -> Any:
        """The solved ω of `body` (zero for the frame), for the acceleration level's centripetal
        and Coriolis terms."""
        motion = self.solved()
        return motion.states[body].omega if body in motion.states else self.space.rot_zero()

    def v(self, body: str, p: tuple) -> tuple:
        """The solved velocity of `body`'s material point at `p`, v = v₀ + ω × (P − ref) (zero
        for the frame), for the Coriolis terms."""
        motion = self.solved()
        if body not in motion.states:
            return self.space.zero()
        return motion.velocity(motion.states[body], p)

    def solved(self) -> Motion:
        """The solved velocities the acceleration level is written with (a velocity level,
        which has none, asks for them only by mistake)."""
        if self.motion is None:
            raise TypeError("the velocity level has no solved velocities")
        return self.motion


class VelocityLevel(Level):
    """The velocity level: unknowns (ω, v₀) of every moving body; a joint's row is linear in
    them, e.g. a pin's v_P(b) − v_P(a) = 0."""

    accel = False

    def point(self, body: str, p: tuple) -> tuple:
        """v = v₀ + ω × (P − ref)."""
        if self.space.dim != 2 or type(self.u) is not Unknowns:
            return add(self.u.trans(body), self.space.cross(self.u.rot(body), sub(p, self.ref)))
        # in the plane: the same values, written out (the terms in the order, and the
        # constants of the type, that the products above give)
        o = self.u.offset.get(body)
        ref = self.ref
        rx, ry = p[0] - ref[0], p[1] - ref[1]
        if o is None:               # the frame: v₀ = (0, 0) and ω = 0 (integers), so 0 + 0 k × r
            return (0 + 0 * ry, 0 + 0 * rx)
        x = Lin({o + 1: 1}) if _is_zero(ry) else Lin({o + 1: 1, o: -1 * ry}, 0 + 0 * ry)
        y = Lin({o + 2: 1}) if _is_zero(rx) else Lin({o + 2: 1, o: 1 * rx}, 0 + 0 * rx)
        return (x, y)


class AccelerationLevel(Level):
    """The acceleration level: unknowns (α, a₀), with the solved velocities' centripetal and
    Coriolis terms in the constants; the coefficients are the velocity level's, so both systems
    share one matrix."""

    accel = True

    def point(self, body: str, p: tuple) -> tuple:
        """a = a₀ + α × r + ω × (ω × r), with ω known."""
        if self.space.dim == 2 and type(self.u) is KnownTerms:
            ref = self.ref
            rx, ry = p[0] - ref[0], p[1] - ref[1]
            w = self.w(body)
            if type(rx) is float and type(ry) is float and type(w) is float:
                # the known terms only, on floats: the sums below written out (a₀ and α × r
                # are zeros, which leave 0.0 + the centripetal term)
                c = self.terms.normal_part((-w * (w * rx), w * (-w * ry)))
                return (0.0 + c[0], 0.0 + c[1])
        r = sub(p, self.ref)
        w = self.w(body)
        centripetal = self.terms.normal_part(self.space.cross(w, self.space.cross(w, r)))
        return add(add(self.u.trans(body), self.space.cross(self.u.rot(body), r)), centripetal)


def _is_zero(k: Any) -> bool:
    """A factor that `Lin.__mul__` turns into the empty form (a plain zero number)."""
    return isinstance(k, (int, float)) and k == 0
