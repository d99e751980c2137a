"""The position analysis of points given by construction, told as the notes tell it.

A model may place a point as a textbook statement does ("B is 4 from A and 3 from O4",
`{circles: [[A, b], [O4, c]], side: left}`); the engine evaluates the construction
(`engine.positions`). This step says, point by point in the order they are drawn, which
construction gives it, with the lengths and angles of the statement, which of two
intersections was taken (and, for a four-bar loop, whether that is the open or the
crossed assembly), and where the point is. Every number is the instant's.
"""
from __future__ import annotations

import math
from typing import Any, Optional

from ..engine.turns import turn_for, turned_polar
from ..model.constructions import CircleLine, InFrame, LineDef, Polar, TwoCircles, TwoLines
from ..model.point_order import construction_order
from .context import Ctx, segment
from .document import Inline, Msg, Name, Section, Value, msg, point


def position_section(ctx: Ctx) -> Optional[Section]:
    """The constructed points of a planar model, one sentence each; None when every point
    is given by its coordinates."""
    model = ctx.model
    built = [n for n in construction_order(model.points) if not isinstance(model.points[n], tuple)]
    turned = {n: turn_for(model, n) for n in model.points if isinstance(model.points[n], tuple)}
    carried = {n: t for n, t in turned.items() if t}        # each point a turn places, with its turn
    if not ctx.planar or not (built or carried):
        return None
    sec = Section(msg("sec.position"))
    sec.add(msg("pos.intro"))
    if model.turns:
        sec.add(msg("pos.moved"))
    for turn in model.turns:
        sec.add(_turn(ctx, turn))
    for name in construction_order(model.points):
        if name in built:
            sec.add(_sentence(ctx, name, turned_polar(model, name, model.points[name]) or model.points[name]))
        elif name in carried:
            sec.add(msg("pos.carried", point=point(name), body=Name(carried[name].body, "body"),
                        at=Value(ctx.clean(ctx.pos(name), "len"), "len")))
        else:
            continue
        for coordinate in _named(ctx, name):
            sec.add(msg("pos.named", name=Value(coordinate, "len"),
                        formula=Value(ctx.inst.names[coordinate], "len")))
    return sec


def _turn(ctx: Ctx, turn: Any) -> Msg:
    """How a moved model's body was carried from the drawing (`Model.turns`)."""
    body = Name(turn.body, "body")
    if turn.pivot is None:
        return msg("pos.turn_shift", body=body, shift=_quantity(ctx, turn.shift, "len"))
    if turn.toward is not None:
        return msg("pos.turn_toward", body=body, line=_pair(ctx, turn.pivot, turn.toward))
    import sympy

    angle = sympy.sympify(ctx.inst.value(turn.angle, "explain"))
    degrees = sympy.nsimplify(angle * 180 / sympy.pi)
    shown = Value(float(degrees), "deg") if degrees.is_Rational else Value(ctx.clean(degrees, ""), "deg")
    return msg("pos.turn_angle", body=body, angle=shown, pivot=point(turn.pivot))


def _named(ctx: Ctx, name: str) -> list:
    """The point's coordinates that the engine named (x_E, y_E: written out they would be
    past reading), whose formulas the explanation must give as the answer's `where` does."""
    if not ctx.symbolic:
        return []
    return [c for c in ctx.pos(name) if getattr(c, "is_Symbol", False) and c in ctx.inst.names]


def _sentence(ctx: Ctx, name: str, c: Any) -> Msg:
    at = Value(ctx.clean(ctx.pos(name), "len"), "len")
    p = point(name)
    if isinstance(c, Polar):
        args = dict(point=p, origin=_loc(ctx, c.origin), distance=_quantity(ctx, c.distance, "len"),
                    angle=_angle(ctx, name, c), at=at)
        if c.reference is None:
            return msg("pos.polar", **args)
        return msg("pos.polar_ref", ref=_pair(ctx, *c.reference), **args)
    if isinstance(c, InFrame):
        across = ctx.clean(ctx.inst.value(c.at[1], "explain"), "len")
        key = "pos.frame_on" if not ctx.symbolic and across == 0 else "pos.frame"
        y = _quantity(ctx, c.at[1], "len")
        if key == "pos.frame" and _negative(across):
            # an offset written negative is that length to the other side: −a/2 to its left
            # reads a/2 to its right
            key, y = "pos.frame_right", Value(ctx.clean(-across, "len"), "len")
        # the side is said as one looks along the line, never "to its left" alone; a
        # vehicle's wheel is said looking the way the vehicle moves (C5-2.2's S2 travels from
        # P towards O: its left wheel C3 is on the left looking from P towards O, round 17a)
        view = (c.toward, c.origin) if _backwards(ctx, name, c.origin, c.toward) else (c.origin, c.toward)
        if view[0] != c.origin:
            key = {"pos.frame": "pos.frame_right", "pos.frame_right": "pos.frame"}.get(key, key)
        return msg(key, point=p, origin=_loc(ctx, c.origin), line=_pair(ctx, c.origin, c.toward),
                   toward=_loc(ctx, c.toward), x=_quantity(ctx, c.at[0], "len"), y=y, at=at,
                   **{"from": _loc(ctx, view[0]), "to": _loc(ctx, view[1])})
    if isinstance(c, TwoCircles):
        (c1, c2), (r1, r2) = c.centers, c.radii
        which = _plainly(ctx, name, c1, c2) if c.side is not None else None
        which = which or _which(ctx, c.side, c.near, a=_loc(ctx, c1), b=_loc(ctx, c2))
        assembly = _assembly(ctx, name, c)
        if assembly:
            which = msg("pos.assembly", which=which, assembly=msg(f"pos.{assembly}"))
        return msg("pos.circles", point=p, c1=_loc(ctx, c1), c2=_loc(ctx, c2), r1=_quantity(ctx, r1, "len"),
                   r2=_quantity(ctx, r2, "len"), which=which, at=at)
    if isinstance(c, CircleLine):
        return msg("pos.circle_line", point=p, c=_loc(ctx, c.center), r=_quantity(ctx, c.radius, "len"),
                   line=_line(ctx, c.line), which=_which(ctx, c.side, c.near, line=_line(ctx, c.line)), at=at)
    assert isinstance(c, TwoLines)
    return msg("pos.lines", point=p, l1=_line(ctx, c.lines[0]), l2=_line(ctx, c.lines[1]), at=at)


def _backwards(ctx: Ctx, name: str, origin: Any, toward: Any) -> bool:
    """Whether `name` is a vehicle's wheel centre (a knife-edge joint there) whose vehicle
    moves against the line origin → toward at the instant: the velocity of the wheel's centre
    on its chassis points from `toward` to `origin`. Its sides are then said looking the way
    it moves, as one names a vehicle's left and right wheels."""
    from .kinds import knife_edge

    if not (isinstance(origin, str) and isinstance(toward, str)):
        return False
    for j in ctx.model.joints:
        if j.at != name or not knife_edge(j):
            continue
        body = j.b if j.a == ctx.frame else j.a
        try:
            v = ctx.num(ctx.vel(body, name))
            d = ctx.num(ctx.r(origin, toward))
        except (KeyError, TypeError, ValueError):
            return False
        return float(sum(a * b for a, b in zip(v, d))) < 0
    return False


def _loc(ctx: Ctx, loc: Any) -> Any:
    """A point's name, or given coordinates as a value."""
    if isinstance(loc, str):
        return point(loc)
    return Value(ctx.clean(tuple(ctx.inst.value(e, "explain") for e in loc), "len"), "len")


def _pair(ctx: Ctx, a: Any, b: Any) -> Any:
    """A segment or direction named by two points as every segment of the page is named
    (`context.segment`: AB, OP1, O1-A only where the run-together text is ambiguous; issue 30,
    twenty-seventh round (e): C5-2.2 wrote "along O–P1" and "along OP" on one page), or by its
    ends' coordinates."""
    if isinstance(a, str) and isinstance(b, str):
        return Name(segment(a, b), "segment")
    return Inline([_loc(ctx, a), "–", _loc(ctx, b)])


def _line(ctx: Ctx, line: LineDef) -> Any:
    if line.toward is not None:
        return _pair(ctx, line.through, line.toward)
    assert line.direction is not None, "a line goes toward a point or along a direction"
    d = ctx.clean(tuple(ctx.inst.value(e, "explain") for e in line.direction), "")
    return msg("pos.line_dir", through=_loc(ctx, line.through), dir=Value(d, ""))


def _negative(x: Any) -> bool:
    """Whether a length is written with a leading minus (a number below zero, or a formula
    such as −a/2): sympy's `could_extract_minus_sign`, a reading of its form, not of values."""
    import sympy

    return bool(sympy.sympify(x).could_extract_minus_sign())


def _quantity(ctx: Ctx, expr: Any, unit: str) -> Any:
    """A length of the statement: `b = 4` when the model names it by a parameter."""
    value = Value(ctx.clean(ctx.inst.value(expr, "explain"), unit), unit)
    text = getattr(expr, "text", "").strip()
    if text in ctx.model.parameters and not ctx.symbolic:
        return Inline([Name(text, "param"), " = ", value])
    return value


def _angle(ctx: Ctx, name: str, c: Polar) -> Any:
    """The angle of a polar point at the instant: in degrees from its coordinates for a
    numeric model (so a moved crank reads its present angle); the formula for a symbolic one."""
    if ctx.symbolic:
        import sympy

        angle = sympy.sympify(ctx.inst.value(c.angle, "explain"))
        deg = sympy.nsimplify(angle * 180 / sympy.pi) if not angle.free_symbols else None
        return Value(float(deg), "deg") if deg is not None and deg.is_Rational else Value(angle, "")
    o = ctx.num(ctx.pos(c.origin)) if isinstance(c.origin, str) else ctx.num(_loc(ctx, c.origin).value)
    p = ctx.num(ctx.pos(name))
    theta = math.atan2(p[1] - o[1], p[0] - o[0])
    if c.reference is not None:
        a, b = (ctx.num(ctx.pos(r)) if isinstance(r, str) else ctx.num(_loc(ctx, r).value) for r in c.reference)
        theta -= math.atan2(b[1] - a[1], b[0] - a[0])
    deg = (math.degrees(theta) + 180.0) % 360.0 - 180.0
    return Value(round(deg, 6) + 0.0, "deg")


def _plainly(ctx: Ctx, name: str, c1: Any, c2: Any) -> Optional[Msg]:
    """Which of two circles' intersections, said as one sees it on the page when the two
    points are one above the other (the centres at one height: "the upper one", issue 30,
    twenty-ninth round (d): C5-E.4's U was "the one on the left looking from A1 to A2") or
    side by side (the centres on one vertical: "the one on the left"); None otherwise, and
    the side is said looking from one centre to the other. The points are mirror images
    in the line of centres, so the one is above the other exactly when that line is level."""
    try:
        a, b, p = (ctx.num(ctx.pos(c)) if isinstance(c, str) else ctx.num(_loc(ctx, c).value)
                   for c in (c1, c2, name))
    except (KeyError, TypeError, ValueError):
        return None
    dx, dy = float(b[0] - a[0]), float(b[1] - a[1])
    size = math.hypot(dx, dy)
    if size == 0:
        return None
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    if abs(dy) <= 1e-9 * size:
        return msg("pos.upper" if float(p[1]) > mid[1] else "pos.lower")
    if abs(dx) <= 1e-9 * size:
        return msg("pos.leftmost" if float(p[0]) < mid[0] else "pos.rightmost")
    return None


def _which(ctx: Ctx, side: Optional[str], near: Optional[tuple], **names: Any) -> Msg:
    """Which of two intersections: by its side (of a→b, or along the line), or nearest a sketch point."""
    if side is not None:
        return msg(f"pos.{side}", **names)
    if near is not None:
        sketch = tuple(float(ctx.inst.num(ctx.inst.value(e, "explain"))) for e in near)
        return msg("pos.near", near=Value(sketch, "len"))
    return msg("pos.touch")


def _assembly(ctx: Ctx, name: str, c: TwoCircles) -> str:
    """`open` or `crossed` when the circles close a four-bar loop O–A–P–Q (A a crank pin
    placed polar from a fixed pivot O, Q a fixed pivot): open when the quadrilateral does
    not cross itself."""
    model = ctx.model
    fixed = set(model.bodies[ctx.frame].points)
    for pin, pivot in (c.centers, c.centers[::-1]):
        if not (isinstance(pin, str) and isinstance(pivot, str)) or pivot not in fixed:
            continue
        spec = model.points.get(pin)
        if isinstance(spec, Polar) and isinstance(spec.origin, str) and spec.origin in fixed \
                and spec.origin != pivot:
            o, a, p, q = (ctx.num(ctx.pos(n)) for n in (spec.origin, pin, name, pivot))
            crossed = _cross(o, a, p, q) or _cross(a, p, q, o)
            return "crossed" if crossed else "open"
    return ""


def _cross(a: tuple, b: tuple, c: tuple, d: tuple) -> bool:
    """Whether the segments ab and cd cross (properly)."""
    def turn(p: tuple, q: tuple, r: tuple) -> float:
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    d1, d2, d3, d4 = turn(c, d, a), turn(c, d, b), turn(a, b, c), turn(a, b, d)
    return d1 * d2 < 0 and d3 * d4 < 0
