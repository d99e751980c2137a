"""Bodies that repeat another one, turned about a fixed centre: the planets of an epicyclic
train (seed 002, C5-1.4's three planets, C5-E.2's two). The notes work one planet and say
"the same for each"; the explanation does the same: a planet placed as an earlier one,
turned about the common centre of the bodies it meshes with, moves as it does, turned, with
the same angular velocity and acceleration.

A body B is a turned copy of an earlier body A when

- B is joined to the same bodies as A by joints of the same kinds (a pin to the carrier,
  rolling contacts with the sun and the ring, in or outside),
- its shapes are A's (circles of the same radii, about its pin),
- every body it is joined to turns about one fixed centre Z (pinned to the frame there, or
  the frame itself with its circles about Z), so the neighbourhood looks the same from B as
  from A once turned about Z,
- B's pins lie as far from Z as A's,

and, as a check, B turns as A does (the same ω and α). Nothing is solved here: the angular
velocity stated is the solution's.
"""
from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass
from typing import Optional

from .context import Ctx
from .kinds import pin_only

TOL = 1e-9


@dataclass(frozen=True)
class Copy:
    """`body` is `original` turned by `angle` degrees (counter-clockwise) about point `centre`."""

    body: str
    original: str
    centre: str
    angle: float


def _joints(ctx: Ctx, body: str) -> list:
    return [j for j in ctx.model.joints if body in (j.a, j.b)]


def _other(j, body: str) -> str:
    return j.b if j.a == body else j.a


def _signature(ctx: Ctx, body: str) -> Counter:
    """The kinds of the body's joints and the bodies they join it to."""
    return Counter((j.kind.name, _other(j, body), bool(j.internal)) for j in _joints(ctx, body))


def _close(ctx: Ctx, x: float, y: float) -> bool:
    return abs(x - y) <= TOL * max(1.0, ctx.inst.scale)


def _radii(ctx: Ctx, body: str) -> Optional[list[float]]:
    """The radii of the body's shapes (None when it has a shape that is not a circle)."""
    out = []
    for shape in ctx.inst.shapes[body]:
        if not hasattr(shape, "radius"):
            return None
        out.append(float(ctx.num(shape.radius)))
    return sorted(out)


def _pivot(ctx: Ctx, other: str) -> Optional[tuple]:
    """The fixed centre a body turns about: its pin to the frame, or, for the frame, the
    common centre of its circles; None when there is none, or more than one."""
    if other == ctx.frame:
        centres = {tuple(round(c, 9) for c in ctx.num(s.center)) for s in ctx.inst.shapes[other]
                   if hasattr(s, "radius")}
        return next(iter(centres)) if len(centres) == 1 else None
    pins = [j for j in _joints(ctx, other) if _other(j, other) == ctx.frame and pin_only(j) and j.at]
    if len(pins) != 1:
        return None
    return ctx.num(ctx.pos(pins[0].at))


def _centre(ctx: Ctx, body: str) -> Optional[tuple]:
    """The common fixed centre of every body `body` is joined to (None when they differ)."""
    found = None
    for j in _joints(ctx, body):
        z = _pivot(ctx, _other(j, body))
        if z is None or (found is not None and math.dist(z, found) > TOL * max(1.0, ctx.inst.scale)):
            return None
        found = z
    return found


def _pins(ctx: Ctx, body: str) -> list[str]:
    return [j.at for j in _joints(ctx, body) if pin_only(j) and j.at]


def _angle(z: tuple, p: tuple, q: tuple) -> float:
    """The angle in degrees (−180, 180] that turns p into q about z."""
    a = math.atan2(p[1] - z[1], p[0] - z[0])
    b = math.atan2(q[1] - z[1], q[0] - z[0])
    d = math.degrees(b - a)
    while d <= -180:
        d += 360
    while d > 180:
        d -= 360
    return d


def copy_of(ctx: Ctx, body: str, earlier: list[str]) -> Optional[Copy]:
    """The earlier body `body` repeats, turned about the fixed centre of its neighbours, or
    None (see the module's rules)."""
    if not ctx.planar or body == ctx.frame or ctx.fixed(body):
        return None
    z = _centre(ctx, body)
    pins = _pins(ctx, body)
    radii = _radii(ctx, body)
    if z is None or len(pins) != 1 or radii is None or not radii:
        return None
    p = ctx.num(ctx.pos(pins[0]))
    if math.dist(z, p) <= TOL * max(1.0, ctx.inst.scale):
        return None
    mine = _signature(ctx, body)
    for a in earlier:
        if a == body or a == ctx.frame or _signature(ctx, a) != mine or _radii(ctx, a) != radii:
            continue
        theirs = _pins(ctx, a)
        if len(theirs) != 1:
            continue
        centre = _centre(ctx, a)
        if centre is None:
            continue
        q = ctx.num(ctx.pos(theirs[0]))
        if math.dist(centre, z) > TOL * max(1.0, ctx.inst.scale) or \
                not _close(ctx, math.dist(z, q), math.dist(z, p)):
            continue
        if not _same_motion(ctx, body, a):
            continue
        return Copy(body, a, _centre_name(ctx, z), _angle(z, q, p))
    return None


def _same_motion(ctx: Ctx, b: str, a: str) -> bool:
    """The check: b turns as a does (ω, and α where there are accelerations)."""
    return all(ctx.is_zero(x - y, "rate") for x, y in ((ctx.omega(b), ctx.omega(a)), (ctx.alpha(b), ctx.alpha(a))))


def _centre_name(ctx: Ctx, z: tuple) -> str:
    """The name of the point at the fixed centre (the model's point there)."""
    for name in ctx.model.bodies[ctx.frame].points + list(ctx.inst.points):
        if math.dist(ctx.num(ctx.pos(name)), z) <= TOL * max(1.0, ctx.inst.scale):
            return name
    return ctx.name_position("Z", z)


def copies(ctx: Ctx, steps: list) -> list:
    """The order of solution with the steps whose every body repeats a body found before
    gathered into one step of kind `copy`, at the first of them, said once (the notes'
    "the same for each planet")."""
    from .order import Step

    known: list[str] = [ctx.frame]
    out: list = []
    merged: Optional[Step] = None
    known_then: set[str] = set()
    for s in steps:
        found = [copy_of(ctx, b, known) for b in s.bodies] if s.kind == "other" else [None]
        made = [c for c in found if c is not None]
        if found and len(made) == len(found):
            originals = [c.original for c in made]
            if merged is None or not set(originals) <= known_then:
                merged = Step("copy", [], [], [], source=s.source)
                known_then = set(known)
                out.append(merged)
            merged.bodies += s.bodies
            merged.joints += [j.id for b in s.bodies for j in _joints(ctx, b) if j.id not in merged.joints]
            merged.known += [o for o in originals if o not in merged.known]
        else:
            out.append(s)
        known += s.bodies
    return out
