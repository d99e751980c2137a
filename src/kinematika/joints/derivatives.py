"""The time derivatives joints are written in, shared by the joint modules.

Each takes the level `lv` (velocities or accelerations: `engine.levels`) and returns the
derivative of a geometric quantity of the pair (a, b): at the velocity level linear in the
unknown (ω, v₀), at the acceleration level in (α, a₀) plus the terms quadratic in the known
velocities (the centripetal ones come with `lv.point`; the Coriolis ones are added here).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..algebra.vectors import dot, sub

if TYPE_CHECKING:
    from .seam import Level


def coincident(lv: Level, a: str, b: str, p: tuple) -> tuple:
    """v_P(b) − v_P(a) (or the accelerations): zero when both bodies share P."""
    return sub(lv.point(b, p), lv.point(a, p))


def sliding(lv: Level, a: str, b: str, q: tuple, e: tuple) -> Any:
    """d/dt [(Q_b − Q_a)·e], e fixed in a: the relative motion of Q along e.

    Velocity: v_rel·e. Acceleration: (a_Qb − a_Qa)·e + 2 v_rel·(ω_a × e), the Coriolis term
    (times the level's factor, 1 in mechanics: `engine.terms`).
    """
    row = dot(coincident(lv, a, b, q), e)
    if lv.accel:
        v_rel = sub(lv.v(b, q), lv.v(a, q))
        row = row + lv.terms.coriolis_factor() * dot(v_rel, lv.space.cross(lv.w(a), e))
    return row


def turning(lv: Level, a: str, b: str, e: tuple) -> Any:
    """d/dt [(ω_b − ω_a)·e], e fixed in a (3D): (α_b − α_a)·e + ω_rel·(ω_a × e)."""
    sp = lv.space
    row = sp.rot_dot(sp.rot_sub(lv.omega(b), lv.omega(a)), e)
    if lv.accel:
        w_rel = sp.rot_sub(lv.w(b), lv.w(a))
        row = row + dot(w_rel, sp.cross(lv.w(a), e))
    return row


def same_rotation(lv: Level, a: str, b: str) -> list:
    """ω_b − ω_a (α_b − α_a) component by component."""
    sp = lv.space
    return list(sp.rot_components(sp.rot_sub(lv.omega(b), lv.omega(a))))
