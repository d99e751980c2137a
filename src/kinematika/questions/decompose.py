"""Composition of motions: a point's motion = drag + relative (+ Coriolis) for a moving frame.

Drag is the motion of the frame's material point that coincides with P; relative is P's
motion seen from the frame; Coriolis is 2 ω_frame × v_rel. All are measured from the
question's base frame (ground by default), and their sum is checked against the total.
"""
from __future__ import annotations

from typing import Any

from ..algebra.vectors import add, scale, sub
from ..model.model import Question
from ..solution import Solution


def decompose(sol: Solution, q: Question) -> dict[str, Any]:
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


def _check_sum(sol: Solution, parts: tuple, total: tuple, size: float) -> None:
    if not sol.is_zero(sub(parts, total), max(size, 1e-300) * 1e3):
        raise AssertionError("decomposition does not add up to the total: an internal error")
