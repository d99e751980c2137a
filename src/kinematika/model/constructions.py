"""Points by construction: where a planar point is, said as a textbook problem says it.

A construction names the points and lengths it is drawn from, as one would with ruler
and compass: polar (a distance at an angle from a point), in the frame of two points, the
intersection of two circles, of a circle and a line, of two lines. This module holds the
parsed constructions (expressions unevaluated) and reads them from the checked file;
`engine.positions` evaluates them, on numbers or symbols, in dependency order.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional, Protocol, TypeGuard, Union

from ..errors import KinematikaError
from ..expressions import Expr

ExprVector = tuple[Expr, ...]
Location = Union[str, ExprVector]          # a point's name, or coordinates


@dataclass(frozen=True)
class LineDef:
    """A line through `through`, towards `toward` (a second point) or along `direction`."""

    through: Location
    toward: Optional[Location] = None
    direction: Optional[ExprVector] = None


@dataclass(frozen=True)
class Polar:
    """A point at `distance` from `origin` along the direction at `angle` counter-clockwise from
    the x axis, or from the direction reference[0] → reference[1] when given (a crank's pin: O2
    + L·(cos θ, sin θ))."""

    origin: Location
    distance: Expr
    angle: Expr
    reference: Optional[tuple[Location, Location]] = None


@dataclass(frozen=True)
class InFrame:
    """A point fixed in the frame of two points: origin + x·u + y·n, u the unit vector origin →
    toward and n = u turned +90°, (x, y) = `at`."""

    origin: Location
    toward: Location
    at: tuple[Expr, Expr]


@dataclass(frozen=True)
class TwoCircles:
    """A point at radii[0] from centers[0] and radii[1] from centers[1] (a four-bar's coupler
    pin): the intersection on `side` of the directed line centers[0] → centers[1], or the one
    nearest the sketch point `near`."""

    centers: tuple[Location, Location]
    radii: tuple[Expr, Expr]
    side: Optional[str] = None             # "left" or "right" of centers[0] → centers[1]
    near: Optional[tuple[Expr, Expr]] = None


@dataclass(frozen=True)
class CircleLine:
    """A point at `radius` from `center` on `line` (a slider-crank's slider): the intersection
    `side` ("ahead" farther along the line's direction, or "behind"), or the one nearest `near`."""

    center: Location
    radius: Expr
    line: LineDef
    side: Optional[str] = None             # "ahead" or "behind" along the line's direction
    near: Optional[tuple[Expr, Expr]] = None


@dataclass(frozen=True)
class TwoLines:
    """The point where two lines meet (parallel lines are a geometry error when evaluated)."""

    lines: tuple[LineDef, LineDef]


Construction = Union[Polar, InFrame, TwoCircles, CircleLine, TwoLines]
KIND_NAMES = {Polar: "polar", InFrame: "frame", TwoCircles: "two circles", CircleLine: "circle and line",
              TwoLines: "two lines"}


def uses(c: Construction) -> list[str]:
    """The names of the points a construction is drawn from."""
    locs: list[Optional[Location]] = []
    if isinstance(c, Polar):
        locs = [c.origin, *(c.reference or ())]
    elif isinstance(c, InFrame):
        locs = [c.origin, c.toward]
    elif isinstance(c, TwoCircles):
        locs = list(c.centers)
    elif isinstance(c, CircleLine):
        locs = [c.center, c.line.through, c.line.toward]
    elif isinstance(c, TwoLines):
        locs = [loc for line in c.lines for loc in (line.through, line.toward)]
    return [loc for loc in locs if isinstance(loc, str)]


ExprOf = Callable[[object, str], Expr]
VectorOf = Callable[[list, str], ExprVector]


# What the reader takes from each checked construction: one of `schema`'s classes or
# `shape`'s records of the same name (values as written: numbers, expressions' text, point
# names, [x, y] lists), told apart by the class's name.
class PolarSpec(Protocol):
    """`{from, distance, angle, reference}`: a polar construction."""

    from_: object
    distance: object
    angle: object
    reference: Optional[list]


class FrameSpec(Protocol):
    """`{frame: [P, Q], at: [x, y]}`: a point fixed in the frame of two points."""

    frame: list
    at: list


class CirclesSpec(Protocol):
    """`{circles: [[centre, radius], [centre, radius]], side, near}`."""

    circles: list
    side: Optional[str]
    near: Optional[list]


class CircleLineSpec(Protocol):
    """`{circle: [centre, radius], line, side, near}`."""

    circle: list
    line: object
    side: Optional[str]
    near: Optional[list]


class LinesSpec(Protocol):
    """`{lines: [line, line]}`."""

    lines: list


class LineSpec(Protocol):
    """`{through, direction}`: a line written in full."""

    through: object
    direction: list


def _line_spec(raw: object) -> TypeGuard[LineSpec]:
    """Whether `raw` is a line written in full (else [P, Q] through two points)."""
    return type(raw).__name__ == "LineSpec"


class ConstructionReader:
    """Turns a checked construction spec into a `Construction`, naming places in errors.

    `expr` and `vector` parse values (with the model's parameter names); `known` is the set
    of point names of the model, so that a misspelt name is reported here.
    """

    def __init__(self, expr: ExprOf, vector: VectorOf, known: set[str], symbolic: bool) -> None:
        self.expr, self.vector, self.known, self.symbolic = expr, vector, known, symbolic

    def read(self, spec: Any, where: str) -> Construction:
        """The `Construction` a checked spec describes (polar, frame, two circles, circle and
        line, two lines), its points' names checked and its values parsed; `where` names the
        place in errors."""
        # the checked spec is one of `schema`'s classes or `shape`'s records of the same name
        kind = type(spec).__name__
        if kind == "PolarSpec":
            return self._polar(spec, where)
        if kind == "FrameSpec":
            return self._in_frame(spec, where)
        if kind == "CirclesSpec":
            return self._two_circles(spec, where)
        if kind == "CircleLineSpec":
            return self._circle_line(spec, where)
        assert kind == "LinesSpec", kind
        return self._two_lines(spec, where)

    def _polar(self, spec: PolarSpec, where: str) -> Polar:
        ref = None
        if spec.reference is not None:
            ref = (self.loc(spec.reference[0], f"{where}.reference[0]"),
                   self.loc(spec.reference[1], f"{where}.reference[1]"))
            self.distinct(ref, f"{where}.reference")
        return Polar(self.loc(spec.from_, f"{where}.from"), self.expr(spec.distance, f"{where}.distance"),
                     self.expr(spec.angle, f"{where}.angle"), ref)

    def _in_frame(self, spec: FrameSpec, where: str) -> InFrame:
        origin, toward = (self.loc(p, f"{where}.frame[{i}]") for i, p in enumerate(spec.frame))
        self.distinct((origin, toward), f"{where}.frame")
        at = self.vector(spec.at, f"{where}.at")
        return InFrame(origin, toward, (at[0], at[1]))

    def _two_circles(self, spec: CirclesSpec, where: str) -> TwoCircles:
        (c1, r1), (c2, r2) = (self.circle(c, f"{where}.circles[{i}]") for i, c in enumerate(spec.circles))
        self.distinct((c1, c2), f"{where}.circles")
        return TwoCircles((c1, c2), (r1, r2), spec.side, self.near(spec.near, where))

    def _circle_line(self, spec: CircleLineSpec, where: str) -> CircleLine:
        center, radius = self.circle(spec.circle, f"{where}.circle")
        return CircleLine(center, radius, self.line(spec.line, f"{where}.line"), spec.side,
                          self.near(spec.near, where))

    def _two_lines(self, spec: LinesSpec, where: str) -> TwoLines:
        first, second = (self.line(line, f"{where}.lines[{i}]") for i, line in enumerate(spec.lines))
        return TwoLines((first, second))

    def loc(self, raw: object, where: str) -> Location:
        """A location: a known point's name, or planar coordinates [x, y] parsed; an unknown
        name or another shape is a schema error at `where`."""
        if isinstance(raw, str):
            if raw not in self.known:
                raise KinematikaError("schema", "unknown-point", where, point=raw, points=sorted(self.known))
            return raw
        if not isinstance(raw, list):
            raise KinematikaError("schema", "construction-point-expected", where, got=_short(raw))
        vec = self.vector(raw, where)
        if len(vec) != 2:
            raise KinematikaError("schema", "construction-coordinates", where, got=len(vec))
        return vec

    def circle(self, raw: list, where: str) -> tuple[Location, Expr]:
        """A circle written [centre, radius]: the centre's location and the radius parsed (one
        number, not a list)."""
        center, radius = raw
        if isinstance(radius, list):
            raise KinematikaError("schema", "construction-circle-radius", f"{where}[1]")
        return self.loc(center, f"{where}[0]"), self.expr(radius, f"{where}[1]")

    def line(self, raw: object, where: str) -> LineDef:
        """A `LineDef`: ``{through, direction}`` (a vector: two point names there mean [P, Q]
        was meant, said in the error) or [P, Q] through two distinct points."""
        if _line_spec(raw):
            direction = raw.direction
            if len(direction) == 2 and all(isinstance(v, str) and v in self.known for v in direction):
                raise KinematikaError("schema", "construction-line-direction", f"{where}.direction")
            vec = self.vector(direction, f"{where}.direction")
            if len(vec) != 2:
                raise KinematikaError("schema", "construction-direction-planar", f"{where}.direction")
            return LineDef(self.loc(raw.through, f"{where}.through"), direction=vec)
        assert isinstance(raw, list)
        through, toward = (self.loc(p, f"{where}[{i}]") for i, p in enumerate(raw))
        self.distinct((through, toward), where)
        return LineDef(through, toward=toward)

    def near(self, raw: Optional[list], where: str) -> Optional[tuple[Expr, Expr]]:
        """The sketch point [x, y] that chooses an intersection, or None; a model with symbolic
        parameters must use `side` instead, which holds for every value of the symbols."""
        if raw is None:
            return None
        if self.symbolic:
            raise KinematikaError("schema", "near-symbolic", f"{where}.near")
        vec = self.vector(raw, f"{where}.near")
        if len(vec) != 2:
            raise KinematikaError("schema", "near-point", f"{where}.near")
        return vec[0], vec[1]

    @staticmethod
    def distinct(pair: tuple[Location, Location], where: str) -> None:
        """Two named points must differ (a line or a frame through P and P has no direction)."""
        if isinstance(pair[0], str) and pair[0] == pair[1]:
            raise KinematikaError("schema", "two-points-same", where, point=pair[0])


def _short(raw: object) -> str:
    text = repr(raw)
    return text if len(text) <= 40 else text[:37] + "..."
