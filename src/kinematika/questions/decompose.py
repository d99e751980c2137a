"""Composition of motions: a point's motion = drag + relative (+ Coriolis) for a moving frame.

Drag is the motion of the frame's material point that coincides with P; relative is P's
motion seen from the frame; Coriolis is 2 ω_frame × v_rel. All are measured from the
question's base frame (ground by default), and their sum is checked against the total.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import add, scale, sub
from .base import Asked, Figure, QuestionKind, Solved, Steps, Words


def decompose(sol: Solved, q: Asked) -> dict[str, Any]:
    """Point `q.target`'s motion seen from `q.relative_to`, composed through the moving body
    `q.moving`: v = v_drag + v_rel and a = a_drag + a_rel + a_Coriolis, a_Coriolis = 2 ω_moving
    × v_rel, each part and the total; the sums are checked against the total."""
    ref, base, moving = q.target, q.relative_to, q.moving
    p = sol.position(ref)
    if moving is None:
        raise TypeError(f"{q.where}: a decomposition needs its moving body")
    frame = sol.state(moving, base)
    motion = sol.motion
    v_drag = motion.velocity(frame, p)
    a_drag = motion.acceleration(frame, p)
    v_rel = sol.velocity(ref, moving)
    a_rel = sol.acceleration(ref, moving)
    coriolis = scale(motion.terms.coriolis_factor(), sol.space.cross(frame.omega, v_rel))
    v_total = sol.velocity(ref, base)
    a_total = sol.acceleration(ref, base)
    _check_sum(sol, add(v_drag, v_rel), v_total, sol.speed_scale())
    if motion.terms.mechanics:       # a student's mistaken world (`engine.terms`) need not add up
        _check_sum(sol, add(add(a_drag, a_rel), coriolis), a_total, sol.accel_scale())
    return {"velocity": {"drag": v_drag, "relative": v_rel, "total": v_total},
            "acceleration": {"drag": a_drag, "relative": a_rel, "coriolis": coriolis, "total": a_total}}


def _check_sum(sol: Solved, parts: tuple, total: tuple, size: float) -> None:
    if not sol.is_zero(sub(parts, total), max(size, 1e-300) * 1e3):
        raise AssertionError("decomposition does not add up to the total: an internal error")


PARTS = {"drag": "sub.drag", "relative": "sub.rel", "coriolis": "sub.cor"}   # their subscripts' words


class Decompose(QuestionKind):
    """A point's motion composed through a moving body."""

    name = "decompose"
    summary = "a material point's velocity and acceleration as drag, relative and Coriolis parts"
    about = "point"
    moving = True
    level = "acceleration"
    unit_kind = "velocity"
    fields = {"velocity": "velocity", "acceleration": "acceleration", "coriolis": "acceleration"}
    page = True
    linear = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """v = v_drag + v_rel, a = a_drag + a_rel + 2 ω_moving × v_rel (`decompose`)."""
        return decompose(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """Its drag (and Coriolis) arrows beside the point's own."""
        figure.composition(q)

    def explain(self, steps: Steps, q: Asked) -> None:
        """Worked out as a composition of motions."""
        steps.composition(q)

    def label(self, words: Words, q: Asked) -> Any:
        """The composition of the motion of the point, with the moving frame."""
        return words.msg("ask.decompose", point=words.name(words.point(q)), frame=words.name(q.moving or "", "body"))

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """v_{arr,P}, a_{rel,P}, a_{Cor,P}, v_P: the part's word as the subscript."""
        level = "v" if key == "velocity" else "a"
        ref = words.ref(q)
        if sub == "relative" and ref.body and q.moving:
            # the relative part as the steps write it, both bodies named (v_{B∈N rel M}): one
            # vector, one symbol in the step, the composition and the answers (round 19a)
            return words.sym(level, f"{ref.point}∈{ref.body}/{q.moving}")
        if sub not in PARTS:
            # the point's own motion as the question and the steps label it (v_{B∈N}, not v_B
            # beside Step 2's v_{B∈N}: one velocity, one symbol, twenty-first round (e))
            return words.sym(level, words.point(q))
        return words.sym(level, ref.point, sub_key=PARTS[sub])


KIND = Decompose()
