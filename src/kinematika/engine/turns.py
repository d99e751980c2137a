"""Bodies carried by a move of a model with symbolic parameters (`Model.turns`).

A turn places a body's points from their drawn places, p ↦ P + R (p − P₀), P₀ and P the
drawn and present places of its pivot and R a rotation: by an angle, or the one that takes
the drawn direction P₀→T₀ to the present P→T,

    cos = d₀·d / |d₀|²,  sin = d₀ × d / |d₀|²   (d₀ = T₀ − P₀, d = T − P, |d| = |d₀|),

or, for a pin T sliding in a slot of the body through P, the same over |d₀||d|. A shift
moves every point by s u. Each point name is placed by at most one turn (`turn_for`): that
of a body its place moves with, never one taken from the point itself.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any, Optional, Protocol

from ..algebra.vectors import dot, sub
from ..expressions import Expr, parse
from ..model.model import Direction, Model
from ..model.motion_sections import Turn


class Placed(Protocol):
    """What turning a body's points reads of an instant (`instant.Instant`): the model, the
    backend, the turns' pivots where drawn (`drawn`) and the points where they are now
    (`points`), and its parameters' values and directions."""

    model: Model
    backend: Any
    drawn: dict
    points: dict[str, tuple]

    def value(self, expr: Expr, where: str) -> Any:
        """`expr` evaluated on the instant's parameters."""

    def direction(self, d: Direction, where: str) -> tuple:
        """A unit direction of the model."""


def turn_for(model: Model, name: str) -> Optional[Turn]:
    """The turn that places point `name`: of the body that owns its place or of one moving
    with it there (the owner first), not anchored at `name` itself; None when the frame
    holds the place or no such body is turned."""
    if not model.turns or not model.carriers(name):
        return None
    by_body = {t.body: t for t in model.turns}
    owner = model.place_owner(name)
    for members in model.motion_classes(name, model.carriers(name)):
        if owner not in members:
            continue
        if model.frame in members:
            return None
        for body in [owner, *(b for b in members if b != owner)]:
            turn = by_body.get(body)
            if turn is not None and name not in turn.anchors:
                return turn
    return None


def moves_with(model: Model, point: str, body: str) -> bool:
    """Whether `body`'s material point at `point` is the point's place (the body owns it, or
    is pinned or welded to its owner there)."""
    if body not in model.carriers(point):
        return False
    owner = model.place_owner(point)
    return any(body in c and owner in c for c in model.motion_classes(point, model.carriers(point)))


def turned_polar(model: Model, name: str, spec: Any) -> Any:
    """A polar point from a point of the body whose turn places it (`turn_for`), that turn an
    angle: the same polar point with its angle advanced by the turn's (a crank pin at θ,
    the crank turned 30°, is at θ + 30°); None for any other point."""
    from ..model.constructions import Polar

    turn = turn_for(model, name)
    if (turn is None or turn.angle is None or not isinstance(spec, Polar) or spec.reference is not None
            or not isinstance(spec.origin, str) or not moves_with(model, spec.origin, turn.body)):
        return None
    return replace(spec, angle=parse(f"({spec.angle.text}) + ({turn.angle.text})"))


def rotation(inst: Placed, turn: Turn, now: dict[str, tuple]) -> tuple[Any, Any]:
    """(cos, sin) of the turn's rotation (1, 0 for a shift)."""
    bk = inst.backend
    if turn.angle is not None:
        t = inst.value(turn.angle, "move")
        return bk.function("cos")(t), bk.function("sin")(t)
    if turn.toward is None or turn.pivot is None:
        return 1, 0
    d0 = sub(inst.drawn[turn.toward], inst.drawn[turn.pivot])
    d = sub(now[turn.toward], now[turn.pivot])
    along, across = dot(d0, d), d0[0] * d[1] - d0[1] * d[0]
    norm = bk.sqrt(dot(d0, d0)) * bk.sqrt(dot(d, d)) if turn.slides else dot(d0, d0)
    return bk.simplify(along / norm), bk.simplify(across / norm)


def carry(inst: Placed, turn: Turn, p: tuple, now: dict[str, tuple]) -> tuple:
    """The drawn place `p` of a point of the turned body, now (`now`: the present places)."""
    bk = inst.backend
    if turn.pivot is None:
        assert turn.along is not None and turn.shift is not None
        u = inst.direction(turn.along, "move")
        d = inst.value(turn.shift, "move")
        return tuple(bk.simplify(v) for v in (p[0] + d * u[0], p[1] + d * u[1]))
    c, s = rotation(inst, turn, now)
    o, o0 = now[turn.pivot], inst.drawn[turn.pivot]
    dx, dy = p[0] - o0[0], p[1] - o0[1]
    return tuple(bk.simplify(v) for v in (o[0] + c * dx - s * dy, o[1] + s * dx + c * dy))


def turn_offset(inst: Placed, turn: Turn, origin: tuple, p: tuple, now: dict[str, tuple]) -> tuple:
    """`p` turned about `origin` by the turn's rotation (an offset drawn in the body)."""
    bk = inst.backend
    c, s = rotation(inst, turn, now)
    dx, dy = p[0] - origin[0], p[1] - origin[1]
    return tuple(bk.simplify(v) for v in (origin[0] + c * dx - s * dy, origin[1] + s * dx + c * dy))


def turned(inst: Placed, body: str, u: tuple) -> tuple:
    """A direction fixed in `body`, turned with it by its turn (unit stays unit)."""
    turn = next((t for t in inst.model.turns if t.body == body), None)
    if turn is None or turn.pivot is None:
        return u
    bk = inst.backend
    c, s = rotation(inst, turn, inst.points)
    return (bk.simplify(c * u[0] - s * u[1]), bk.simplify(s * u[0] + c * u[1]))
