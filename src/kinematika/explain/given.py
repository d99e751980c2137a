"""What a driver gives, as the notes state a datum: a point's velocity (acceleration) is a
vector, written with its direction in words (C5-E.4: "the chassis moves to the left at v",
v_U = (←v); C5-E.6: v_H = (→v)), not "the component of v_U along (1, 0)".

A model states such a datum as a component along a direction (`velocity: U, along: [1, 0]`)
when the mechanism itself fixes the rest: a wheel's centre on flat ground moves along it.
The component is then the whole vector — the point's motion across the direction is zero
whatever the driver's value — and the explanation writes it whole, in the Data section
and in the equations (the point is known, M and D). It stays a component where the datum
truly is one: where the point also moves across the direction (C5-1.1's pulley, pushed
sideways while it climbs; the tricycle's front wheel's acceleration, which has a normal
part as the chassis turns).
"""
from __future__ import annotations

from typing import Any, Optional

from .context import Ctx
from .document import Msg, msg


def whole_along(ctx: Ctx, d: Any, level: str) -> bool:
    """Whether a driver's component along a direction is the point's whole velocity (level
    "v") or acceleration ("a"): the point's motion across the direction is zero."""
    if d.kind != "velocity" or d.along is None:
        return False
    if level == "a" and d.accel is None:
        return False
    motion = ctx.vel(d.point.body, d.point.point) if level == "v" else ctx.acc(d.point.body, d.point.point)
    e, x = ctx.inst.direction(d.along, d.where), motion
    across = ((x[0] * e[1] - x[1] * e[0],) if len(x) == 2 else        # x × e: the part off the direction
              (x[1] * e[2] - x[2] * e[1], x[2] * e[0] - x[0] * e[2], x[0] * e[1] - x[1] * e[0]))
    return ctx.is_zero(across, "speed" if level == "v" else "accel")


def heading(ctx: Ctx, vector: tuple, along: Any = None) -> Optional[Msg]:
    """The direction of a given vector in words, as the notes draw it with an arrow: to the
    right (→), to the left (←), upwards (↑), downwards (↓) for a vector along an axis; else
    along the driver's direction `along` (as the model writes it, turned when the datum is
    negative), or None. A symbol stands for a positive size, as in the notes (v_U = (←v) for
    a component −v); a zero vector has none."""
    signs = [sign_of(ctx, c) for c in vector]
    if not any(signs):
        return None
    if len(vector) == 2 and signs[1] == 0:
        return msg("heading.right" if signs[0] > 0 else "heading.left")
    if len(vector) == 2 and signs[0] == 0:
        return msg("heading.up" if signs[1] > 0 else "heading.down")
    return None if along is None else msg("heading.along", along=along)


def sign_of(ctx: Ctx, x: Any) -> int:
    """0, 1 or −1: a number's sign; a formula's as written (−v is negative, v positive)."""
    if ctx.is_zero(x, ""):
        return 0
    if ctx.symbolic and hasattr(x, "could_extract_minus_sign"):
        return -1 if x.could_extract_minus_sign() else 1
    return -1 if float(ctx.num(x)) < 0 else 1


def speeding(ctx: Ctx, rate: Any, accel: Any) -> Optional[bool]:
    """Whether a body given a rate ω and an angular acceleration α (planar, signed) is
    speeding up (True) or slowing down (False); None when either is zero or a vector.

    |ω| grows when d(ω²)/dt = 2·ω·α > 0: the body speeds up when α has the sense of ω and
    slows down when it is against it, whatever the sense of the turning (seed 001's crank
    O2E, ω = −5 rad/s and α = +2 rad/s², is slowing down). Numbers only: a symbol's sign is
    not known. The words are the driver's
    values', never a model's own text: a word for the wrong sign is a wrong answer."""
    if isinstance(rate, tuple) or isinstance(accel, tuple):
        return None
    if any(getattr(x, "free_symbols", None) for x in (rate, accel)):
        return None             # a symbol may have either sign (C5-E.1's θ̇, θ̈: "any value")
    product = sign_of(ctx, rate) * sign_of(ctx, accel)
    return None if product == 0 else product > 0


def driven(ctx: Ctx, d: Any) -> list[str]:
    """The bodies whose motion a driver states (every carrier of a shared point)."""
    if d.kind == "omega":
        return [d.body]
    if d.kind == "joint":
        j = ctx.model.joint(d.joint)
        return [b for b in (j.a, j.b) if b != ctx.frame]
    point = d.point.point
    return ctx.model.carriers(point) if ctx.shared(point) else [d.point.body]
