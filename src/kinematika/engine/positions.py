"""Where the points are at the instant: coordinates as written, or constructed.

Constructed points (`model.constructions`) are evaluated in dependency order with the
instant's algebra, so with symbolic parameters the coordinates are exact formulas (a
four-bar at a general crank angle). The branch of an intersection is chosen by `side`,
which holds for every value of the symbols, or by `near` (numbers only); a numeric
construction that cannot be drawn is a `geometry` error naming the point and by how much.
"""
from __future__ import annotations

import math
import re
import warnings
from typing import TYPE_CHECKING, Any, Optional, Protocol

from .. import limits
from ..errors import KinematikaError, KinematikaWarning, Names, Num, Said
from ..model.point_order import construction_order

from ..expressions import Expr
from ..model.model import Direction, Model

if TYPE_CHECKING:
    from ..model.constructions import CircleLine, Construction, InFrame, LineDef, Location, Polar, TwoCircles, TwoLines


class Evaluated(Protocol):
    """What placing the points reads and records of an instant (`instant.Instant`): the
    model, the backend and whether it is exact, the values of parameters, vectors and
    directions, the turns' pivots where drawn, and the named quantities (`names`) with
    their values at the probe (`probe`), which naming a compound coordinate adds to."""

    model: Model
    backend: Any
    drawn: dict
    points: dict[str, tuple]
    names: dict
    probe: dict

    @property
    def symbolic(self) -> bool:
        """Whether the instant computes on exact formulas."""

    def value(self, expr: Expr, where: str) -> Any:
        """`expr` evaluated on the instant's parameters."""

    def vector(self, exprs: tuple, where: str) -> tuple:
        """Each component of `exprs` evaluated."""

    def direction(self, d: Direction, where: str) -> tuple:
        """A unit direction of the model."""

    def num(self, x: Any) -> float:
        """A scalar as a float (a symbolic one at the probe values)."""

TOLERANCE = 1e-6        # relative: circles this close to touching meet in one point
TURN = 2 * math.pi


def positions(inst: Evaluated, builder: Optional[type] = None) -> dict[str, tuple]:
    """Every point's coordinates at the instant, in the model's order; `builder` evaluates
    the constructions (`_Builder`, or the per-design arrays' in `array_positions`). A moved
    model (`Model.turns`) places its points by `_Moving`."""
    builder = builder or _Builder
    model = inst.model
    if model.turns:
        return _Moving(inst, builder).place()
    out: dict[str, tuple] = {}
    for name in construction_order(model.points):
        out[name] = _place(inst, builder, name, model.points[name], out)
    return {name: out[name] for name in model.points}


def _place(inst: Evaluated, builder: type, name: str, spec: Any, out: dict[str, tuple]) -> tuple:
    """A point as written: its coordinates, or its construction from the points in `out`."""
    where = f"points.{name}"
    if isinstance(spec, tuple):
        return inst.vector(spec, where)
    built = builder(inst, out, where).build(spec)
    if inst.symbolic:
        built = _bounded(inst, builder, spec, built, name, out, where)
    return tuple(inst.backend.simplify(c) for c in built)


class _Moving:
    """The places of a moved model's points (`engine.turns`): each point placed by a turn
    (`turn_for`) is carried from its drawn place, and a construction is built again from
    the present places of its points, except where it is drawn in the turned body:

    - a polar point from a point of that body turns with it (its angle advanced by the
      turn's angle, or its offset turned);
    - a construction from points that have not moved is built as drawn, then carried.

    The drawn places of the turns' pivots are kept in `inst.drawn`."""

    def __init__(self, inst: Evaluated, builder: type) -> None:
        from .turns import turn_for

        self.inst, self.builder, self.model = inst, builder, inst.model
        self.placing = {name: turn_for(self.model, name) for name in self.model.points}
        self.moved: set[str] = set()

    def place(self) -> dict[str, tuple]:
        model = self.model
        anchors = {a for t in model.turns for a in t.anchors}
        self.inst.drawn = self._drawn(anchors)
        extra = {name: t.anchors for name, t in self.placing.items() if t is not None}
        out: dict[str, tuple] = {}
        for name in construction_order(model.points, extra):
            out[name] = self._point(name, model.points[name], out)
        return {name: out[name] for name in model.points}

    def _drawn(self, names: set[str]) -> dict[str, tuple]:
        """The drawn places of `names` (and of the points they are constructed from)."""
        from ..model.constructions import uses

        drawn: dict[str, tuple] = {}
        needed = set(names)
        order = construction_order(self.model.points)
        for name in reversed(order):
            spec = self.model.points[name]
            if name in needed and not isinstance(spec, tuple):
                needed.update(uses(spec))
        for name in order:
            if name in needed:
                drawn[name] = _place(self.inst, self.builder, name, self.model.points[name], drawn)
        return drawn

    def _point(self, name: str, spec: Any, out: dict[str, tuple]) -> tuple:
        from ..model.constructions import Polar, uses
        from .turns import carry, turn_offset, turned_polar

        inst, turn = self.inst, self.placing[name]
        used = [] if isinstance(spec, tuple) else uses(spec)
        if turn is not None or self.moved.intersection(used):
            self.moved.add(name)
        if turn is None:
            return _place(inst, self.builder, name, spec, out)
        advanced = turned_polar(self.model, name, spec)
        if advanced is not None:
            return _place(inst, self.builder, name, advanced, out)
        if isinstance(spec, Polar) and spec.reference is None and isinstance(spec.origin, str) \
                and self._in_body(spec.origin, turn.body):
            built = _place(inst, self.builder, name, spec, out)
            return self._bounded(name, turn_offset(inst, turn, out[spec.origin], built, out))
        if not isinstance(spec, tuple) and self.moved.intersection(used):
            return _place(inst, self.builder, name, spec, out)     # closes a loop: built again
        return self._bounded(name, carry(inst, turn, _place(inst, self.builder, name, spec, out), out))

    def _in_body(self, point: str, body: str) -> bool:
        from .turns import moves_with

        return moves_with(self.model, point, body)

    def _bounded(self, name: str, coords: tuple) -> tuple:
        """A carried point's exact coordinates, named (x_P, y_P) when long (`_bounded`)."""
        inst = self.inst
        if inst.symbolic and (_size(coords) > NAME_OPS or (inst.names and _size(coords) > 0)):
            return name_point(inst, name, coords)
        return coords


NAME_OPS = 400      # a constructed point whose exact coordinates would be longer is named


def angle_warnings(inst: Evaluated) -> list[KinematikaWarning]:
    """A warning for every drawing angle (a polar point's `angle`) that is a number more than
    one turn (2π) from zero: angles are radians, so `angle: 30` is 30 rad (1719°, 4.8 turns),
    most likely 30° written without `deg()`. The model is answered as written; the warning
    names the place and the fix. Angles with symbols are not judged."""
    constructed = {name: spec for name, spec in inst.model.points.items() if not isinstance(spec, tuple)}
    if not constructed:
        return []
    from ..model.constructions import Polar     # only with a constructed point (start-up)

    out = []
    for name, spec in constructed.items():
        if not isinstance(spec, Polar) or _angle_stated(spec.angle, inst.model.parameters, set()):
            continue
        where = f"points.{name}.angle"
        value = inst.value(spec.angle, where)
        if getattr(value, "free_symbols", None):
            continue
        try:
            angle = float(value)
        except (TypeError, ValueError, OverflowError):
            continue
        if math.isfinite(angle) and abs(angle) > TURN * (1 + 1e-9):
            out.append(KinematikaWarning("angle-in-radians", where, angle=angle, degrees=Num(math.degrees(angle), ".0f"),
                                         turns=Num(abs(angle) / TURN, ".1f"), written=f"{angle:g}"))
    for w in out:
        warnings.warn(w, stacklevel=3)
    return out


ANGULAR = {"deg", "rad", "radians", "degrees", "asin", "acos", "atan", "atan2"}


def _angle_stated(expr: Any, parameters: dict, seen: set) -> bool:
    """Whether an angle is written as an angle (`deg(30)`, `pi/6`, `atan2(…)`), itself or in
    the parameters it uses: then its size is the user's meaning, however many turns."""
    if expr.calls() & ANGULAR or "pi" in expr.names():
        return True
    for name in expr.names() - seen:
        seen.add(name)
        p = parameters.get(name)
        if p is not None and p.value is not None and _angle_stated(p.value, parameters, seen):
            return True
    return False


def _bounded(inst: Evaluated, builder: type, spec: Construction, built: tuple, name: str,
             out: dict[str, tuple], where: str) -> tuple:
    """The exact coordinates of a constructed point, bounded: when written out they would
    pass `NAME_OPS` operations (each circle intersection writes the points it is drawn from
    into the next: Jansen's leg in its 15 lengths reaches 160 000 at its foot), the points
    it is drawn from and the point itself are named (x_E, y_E) as a textbook does, and it is
    written in those names: the answers are then formulas in the parameters and the names,
    each name defined by its own short formula (`Instant.names`). Once names are in use,
    every later point that is more than a short formula is named too."""
    if inst.names and _size(built) > 0:
        return name_point(inst, name, tuple(inst.backend.simplify(c) for c in built))
    if _size(built) <= NAME_OPS:
        return built
    from ..model.constructions import uses

    for used in uses(spec):
        out[used] = name_point(inst, used, out[used])
    built = builder(inst, out, where).build(spec)
    _check_size(built, name, where)
    return name_point(inst, name, tuple(inst.backend.simplify(c) for c in built))


STAND_IN_OPS = 12     # coordinates larger than this, or with a root of a formula, stand in


def simple_coordinate(c: Any) -> bool:
    """A coordinate that costs nothing to carry: small, and free of roots of formulas
    (a number like √3 is fine); standing in for it would only hide its simple form."""
    import sympy

    if isinstance(c, (int, float)) or c.is_Number or c.is_Symbol:
        return True
    if any(p.exp.is_Rational and not p.exp.is_Integer and p.base.free_symbols
           for p in c.atoms(sympy.Pow)):
        return False
    from ..algebra.fields import ops

    return ops(c) <= STAND_IN_OPS


def name_point(inst: Evaluated, point: str, coords: tuple) -> tuple:
    """`coords` with each compound coordinate replaced by a named symbol (x_P, y_P), whose
    formula and value at the probe `inst` records."""
    import sympy

    from ..algebra.evaluate import complex_value

    out = []
    for axis, c in zip("xyz", coords):
        if simple_coordinate(c) or c in inst.names:
            out.append(c)
            continue
        symbol = sympy.Symbol(fresh_name(inst, f"{axis}_{point}"), real=True)
        inst.names[symbol] = c
        inst.probe[symbol] = complex_value(c, inst.probe).real
        out.append(symbol)
    return tuple(out)


def fresh_name(inst: Evaluated, wanted: str, taken: set[str] | None = None) -> str:
    """An identifier for a named quantity, free among the parameters, the names and `taken`."""
    base = re.sub(r"\W", "_", wanted)
    taken = (set(inst.model.parameters) | {str(s) for s in inst.names} | {"pi", "E", "I", "oo"}
             | (taken or set()))
    text, k = base, 1
    while text in taken or not text.isidentifier():
        k += 1
        text = f"{base}_{k}"
    return text


def _size(coords: tuple) -> int:
    from ..algebra.fields import _quick_ops

    return max(_quick_ops(c, {}) if hasattr(c, "args") else 0 for c in coords)


def _check_size(coords: tuple, name: str, where: str) -> None:
    """A `limit` error when a constructed point's exact coordinates are past reading even
    in named coordinates (`_bounded`), before any time goes into them."""
    size = _size(coords)
    if size > limits.POINT_OPS:
        raise KinematikaError("limit", "point-too-large", where, point=name, size=Num(size, ","),
                              limit=Num(limits.POINT_OPS, ","))


class _Builder:
    """Evaluates one construction; `points` holds the points already placed."""

    def __init__(self, inst: Evaluated, points: dict[str, tuple], where: str) -> None:
        self.inst, self.points, self.where = inst, points, where
        self.bk = inst.backend

    def build(self, c: Construction) -> tuple:
        from ..model.constructions import CircleLine, InFrame, Polar, TwoCircles, TwoLines

        if isinstance(c, Polar):
            return self.polar(c)
        if isinstance(c, InFrame):
            return self.frame(c)
        if isinstance(c, TwoCircles):
            return self.circles(c)
        if isinstance(c, CircleLine):
            return self.circle_line(c)
        assert isinstance(c, TwoLines)
        return self.lines(c)

    # values --------------------------------------------------------------------------
    def at(self, loc: Location, field: str) -> tuple:
        if isinstance(loc, str):
            return self.points[loc]
        return self.inst.vector(loc, f"{self.where}.{field}")

    def value(self, expr: Any, field: str) -> Any:
        return self.inst.value(expr, f"{self.where}.{field}")

    def num(self, x: Any) -> float:
        return self.inst.num(x)

    def length(self, expr: Any, field: str, what: str) -> Any:
        r = self.value(expr, field)
        if not self.bk.symbolic and r <= 0:
            raise KinematikaError("schema", "length-positive", f"{self.where}.{field}", what=what, value=Num(r, ".6g"))
        return r

    def unit_from(self, p: tuple, q: tuple, field: str) -> tuple:
        d = (q[0] - p[0], q[1] - p[1])
        if _coincide(self, d, p + q):
            raise KinematikaError("geometry", "direction-points-same", f"{self.where}.{field}")
        norm = self.bk.sqrt(d[0] * d[0] + d[1] * d[1]) if self.bk.symbolic else math.hypot(*d)
        return (d[0] / norm, d[1] / norm)

    # constructions -------------------------------------------------------------------
    def polar(self, c: Polar) -> tuple:
        o = self.at(c.origin, "from")
        dist = self.value(c.distance, "distance")
        angle = self.value(c.angle, "angle")
        cos, sin = self.bk.function("cos")(angle), self.bk.function("sin")(angle)
        if isinstance(angle, (int, float)):          # one number (not symbols, not a batch)
            cos, sin = _quarter_turns(float(angle), cos, sin)
        if c.reference is None:
            return (o[0] + dist * cos, o[1] + dist * sin)
        u = self.unit_from(self.at(c.reference[0], "reference[0]"), self.at(c.reference[1], "reference[1]"),
                           "reference")
        return (o[0] + dist * (u[0] * cos - u[1] * sin), o[1] + dist * (u[0] * sin + u[1] * cos))

    def frame(self, c: InFrame) -> tuple:
        p, q = self.at(c.origin, "frame[0]"), self.at(c.toward, "frame[1]")
        u = self.unit_from(p, q, "frame")
        x, y = self.value(c.at[0], "at[0]"), self.value(c.at[1], "at[1]")
        return (p[0] + x * u[0] - y * u[1], p[1] + x * u[1] + y * u[0])

    def circles(self, c: TwoCircles) -> tuple:
        p, q = self.at(c.centers[0], "circles[0][0]"), self.at(c.centers[1], "circles[1][0]")
        r1 = self.length(c.radii[0], "circles[0][1]", "radius")
        r2 = self.length(c.radii[1], "circles[1][1]", "radius")
        dx, dy = q[0] - p[0], q[1] - p[1]
        d2 = dx * dx + dy * dy
        k = r1 * r1 - r2 * r2 + d2
        disc = 4 * r1 * r1 * d2 - k * k                  # (4 d² h²): 16 × the triangle's area²
        tangent = False
        if not self.bk.symbolic:
            disc, tangent = self._circles_meet(c, p, q, r1, r2, d2, disc)
        h = self.bk.sqrt(disc) / (2 * d2)
        base = (p[0] + k * dx / (2 * d2), p[1] + k * dy / (2 * d2))
        left = (base[0] - h * dy, base[1] + h * dx)
        right = (base[0] + h * dy, base[1] - h * dx)
        names = {"left": left, "right": right}
        label = f"{_name(c.centers[0])}→{_name(c.centers[1])}"
        return self.choose(c.side, c.near, names, disc, Said("fit-each-side", line=label), tangent)

    def _circles_meet(self, c: TwoCircles, p: tuple, q: tuple, r1: float, r2: float, d2: float,
                      disc: float) -> tuple[float, bool]:
        """The discriminant (never negative), and whether the circles touch within the
        tolerance; a `geometry` error when they do not meet."""
        d = d2 ** 0.5
        if d <= 1e-12 * max(r1, r2):
            raise KinematikaError("geometry", "circles-same-centre", self.where, a=_name(c.centers[0]),
                                  b=_name(c.centers[1]))
        tol = TOLERANCE * max(d, r1, r2)
        about = dict(a=_name(c.centers[0]), ra=Num(r1, ".6g"), b=_name(c.centers[1]), rb=Num(r2, ".6g"),
                     d=Num(d, ".6g"))
        if d - (r1 + r2) > tol:
            raise KinematikaError("geometry", "circles-apart", self.where, gap=Num(d - (r1 + r2), ".6g"), **about)
        if abs(r1 - r2) - d > tol:
            inner, outer = (_name(c.centers[0]), _name(c.centers[1])) if r1 < r2 else \
                (_name(c.centers[1]), _name(c.centers[0]))
            raise KinematikaError("geometry", "circles-inside", self.where, inner=inner, outer=outer,
                                  gap=Num(abs(r1 - r2) - d, ".6g"), **about)
        tangent = abs(d - (r1 + r2)) <= tol or abs(abs(r1 - r2) - d) <= tol
        return max(disc, 0.0), tangent

    def circle_line(self, c: CircleLine) -> tuple:
        p = self.at(c.center, "circle[0]")
        r = self.length(c.radius, "circle[1]", "radius")
        q, d = self.line(c.line, "line")
        w = (q[0] - p[0], q[1] - p[1])
        dd = d[0] * d[0] + d[1] * d[1]
        dw = d[0] * w[0] + d[1] * w[1]
        disc = dw * dw - dd * (w[0] * w[0] + w[1] * w[1] - r * r)     # dd (r² − distance²)
        tangent = False
        if not self.bk.symbolic:
            disc, tangent = self._line_meets(c, p, r, q, d, dd, disc)
        root = self.bk.sqrt(disc)
        ahead, behind = ((-dw + root) / dd, (-dw - root) / dd)
        names = {"ahead": (q[0] + ahead * d[0], q[1] + ahead * d[1]),
                 "behind": (q[0] + behind * d[0], q[1] + behind * d[1])}
        return self.choose(c.side, c.near, names, disc, Said("fit-on-line", line=_line_name(c.line)), tangent)

    def _line_meets(self, c: CircleLine, p: tuple, r: float, q: tuple, d: tuple, dd: float,
                    disc: float) -> tuple[float, bool]:
        """As `_circles_meet`, for a circle and a line."""
        if dd <= 0:
            raise KinematikaError("schema", "line-direction-zero", f"{self.where}.line")
        dist = abs((p[0] - q[0]) * d[1] - (p[1] - q[1]) * d[0]) / dd ** 0.5
        if dist - r > TOLERANCE * max(r, dist):
            raise KinematikaError("geometry", "circle-misses-line", self.where, centre=_name(c.center),
                                  radius=Num(r, ".6g"), line=_line_name(c.line), distance=Num(dist, ".6g"),
                                  gap=Num(dist - r, ".6g"))
        return max(disc, 0.0), abs(dist - r) <= TOLERANCE * max(r, dist)

    def lines(self, c: TwoLines) -> tuple:
        (q1, d1), (q2, d2) = (self.line(line, f"lines[{i}]") for i, line in enumerate(c.lines))
        cross = d1[0] * d2[1] - d1[1] * d2[0]
        scale = (self.num(d1[0] ** 2 + d1[1] ** 2) * self.num(d2[0] ** 2 + d2[1] ** 2)) ** 0.5
        if abs(self.num(cross)) <= 1e-12 * scale or (self.bk.symbolic and self.bk.simplify(cross) == 0):
            raise KinematikaError("geometry", "lines-parallel", self.where, a=_line_name(c.lines[0]),
                                  b=_line_name(c.lines[1]))
        return line_meet(q1, d1, q2, d2, cross)

    def line(self, line: LineDef, field: str) -> tuple[tuple, tuple]:
        """A point of the line and its direction (not normalised)."""
        q = self.at(line.through, f"{field}.through" if line.direction is not None else f"{field}[0]")
        if line.direction is not None:
            d = self.inst.vector(line.direction, f"{self.where}.{field}.direction")
            if self.num(d[0]) == 0 and self.num(d[1]) == 0:
                raise KinematikaError("schema", "line-direction-zero", f"{self.where}.{field}.direction")
            return q, d
        assert line.toward is not None                  # a line has a direction or a second point
        r = self.at(line.toward, f"{field}[1]")
        d = (r[0] - q[0], r[1] - q[1])
        if _coincide(self, d, q + r):
            raise KinematikaError("geometry", "line-points-coincide", f"{self.where}.{field}", line=_line_name(line))
        return q, d

    # branches ------------------------------------------------------------------------
    def choose(self, side: Optional[str], near: Optional[tuple], options: dict[str, tuple],
               disc: Any, relation: Any, tangent: bool = False) -> tuple:
        """The intersection named by `side`, or nearest `near`; without either, the only one
        (tangent: the two meet within the tolerance, so their midpoint) or a `geometry`
        error listing both."""
        if side is not None:
            return options[side]
        if near is not None:
            sketch = (float(self.value(near[0], "near[0]")), float(self.value(near[1], "near[1]")))
            return min(options.values(), key=lambda p: sum((self.num(a) - b) ** 2 for a, b in zip(p, sketch)))
        first, second = options.values()
        if tangent:
            return tuple((a + b) / 2 for a, b in zip(first, second))
        if self.num(disc) == 0:
            return first
        keys = list(options)
        shown = Names([f"{_coords(self, p)} ({k})" for k, p in zip(keys, (first, second))], joined="and")
        raise KinematikaError("geometry", "two-points-fit", self.where, relation=relation, points=shown,
                              first=keys[0], second=keys[1])


def _quarter_turns(angle: float, cos: float, sin: float) -> tuple[float, float]:
    """cos and sin with a zero that is only the round-off of a multiple of 90° made exact:
    `deg(90)` is π/2 to the float's precision, and cos of it is 6e-17, not 0. A value below
    the float spacing of the angle itself cannot be told from 0."""
    spacing = math.ulp(angle) if angle else 0.0
    return (0.0 if abs(cos) <= spacing else cos), (0.0 if abs(sin) <= spacing else sin)


def _name(loc: Location) -> str:
    if isinstance(loc, str):
        return loc
    return "(" + ", ".join(e.text for e in loc) + ")"


def _line_name(line: LineDef) -> str:
    if line.toward is not None:
        a, b = _name(line.through), _name(line.toward)
        return a + b if isinstance(line.through, str) and isinstance(line.toward, str) else f"{a}–{b}"
    return f"through {_name(line.through)} along (" + ", ".join(e.text for e in line.direction or ()) + ")"


def _coords(builder: _Builder, p: tuple) -> str:
    return "(" + ", ".join(f"{builder.num(c):.6g}" for c in p) + ")"


def _coincide(reader: Any, d: tuple, coords: tuple) -> bool:
    """A difference of points that is round-off of their coordinates (relative, whatever the
    model's unit: no squares to underflow)."""
    return math.hypot(*(reader.num(c) for c in d)) <= 1e-12 * max(abs(reader.num(c)) for c in coords)


def line_meet(q1: tuple, d1: tuple, q2: tuple, d2: tuple, cross: Any) -> tuple:
    """Where the line q1 + t d1 meets the line q2 + s d2, given cross = d1 × d2 (not zero);
    numbers, formulas or arrays alike."""
    t = ((q2[0] - q1[0]) * d2[1] - (q2[1] - q1[1]) * d2[0]) / cross
    return (q1[0] + t * d1[0], q1[1] + t * d1[1])
