"""Building a model in Python: the same tree a model file holds, written with methods.

    m = Mechanism("Slider-crank", parameters={"w": 10})
    m.point("O", 0, 0); m.point("A", 0.1, 0); m.point("B", 0.4, 0)
    m.body("ground", "O"); m.body("crank", "O", "A"); m.body("rod", "A", "B")
    m.body("slider", "B")
    m.revolute("ground", "crank", at="O"); m.revolute("crank", "rod", at="A")
    m.revolute("rod", "slider", at="B"); m.prismatic("ground", "slider", along=(1, 0))
    m.drive_omega("crank", "w")
    sol = m.solve()
    sol.velocity("B")

Points may be constructed as a problem states them (`polar`, `in_frame`, `circles`,
`circle_line`, `lines`), and the mechanism analysed elsewhere than drawn (`move`,
`solve(assembly=N)`):

    m.points(O2=(0, 0), O4=(5.2, 0)).polar("A", "O2", 2.25, "deg(52)")
    m.circles("B", ("A", 6.1), ("O4", 4.35), side="left").move(j1=30)

The tree goes through the same checks as a file (`build_model`), so every error names the
same place a file would.
"""
from __future__ import annotations

from typing import Any, Mapping, Optional, Sequence

from ..errors import KinematikaError
from ..joints import KINDS

from .build import build_model
from .model import Model

Value = Any


class Mechanism:
    """A model under construction; `to_model()` checks it, `solve()` solves it."""

    def __init__(self, name: str = "Mechanism", parameters: Optional[dict[str, Any]] = None,
                 dimension: Optional[int] = None, frame: str = "ground") -> None:
        if parameters is not None and not isinstance(parameters, Mapping):
            raise KinematikaError("schema", "parameters-mapping", "parameters", type=type(parameters).__name__)
        self.tree: dict[str, Any] = {"name": name, "parameters": dict(parameters or {}),
                                     "points": {}, "bodies": {}, "joints": [], "drivers": []}
        if dimension is not None:
            self.tree["dimension"] = dimension
        if frame != "ground":
            self.tree["frame"] = frame

    # geometry ----------------------------------------------------------------------------
    def parameter(self, name: str, value: Value = None, positive: bool = True) -> "Mechanism":
        """A named value (None keeps it a symbol; `positive=False` for any real sign)."""
        self.tree["parameters"][name] = value if positive else {"value": value, "positive": False}
        return self

    def point(self, name: str, *coords: Value) -> "Mechanism":
        """A point at coordinates given as numbers, parameter names or formulas: ``m.point("B",
        "L*cos(theta)", 2)``."""
        self.tree["points"][name] = list(coords)
        return self

    def points(self, **coords: Sequence[Value]) -> "Mechanism":
        """Several points at once, by keyword: ``m.points(O2=(0, 0), O4=(4, 0))``."""
        for name, xy in coords.items():
            self.point(name, *xy)
        return self

    # points by construction (planar) ---------------------------------------------------
    def polar(self, name: str, origin: Any, distance: Value, angle: Value,
              reference: Optional[tuple[Any, Any]] = None) -> "Mechanism":
        """`name` at `distance` from `origin`, `angle` (radians: "deg(30)") counter-clockwise
        from the x axis, or from the direction reference[0] → reference[1]."""
        spec: dict[str, Any] = {"from": _loc(origin), "distance": distance, "angle": angle}
        if reference is not None:
            spec["reference"] = [_loc(p) for p in reference]
        return self._constructed(name, spec)

    def in_frame(self, name: str, frame: tuple[Any, Any], at: Sequence[Value]) -> "Mechanism":
        """`name` at x along frame[0] → frame[1] and y to its left, from frame[0]."""
        return self._constructed(name, {"frame": [_loc(p) for p in frame], "at": list(at)})

    def circles(self, name: str, first: tuple[Any, Value], second: tuple[Any, Value],
                side: Optional[str] = None, near: Optional[Sequence[Value]] = None) -> "Mechanism":
        """`name` at first[1] from first[0] and second[1] from second[0], on the `side`
        ("left" or "right") of first[0] → second[0], or `near` a sketch point."""
        spec: dict[str, Any] = {"circles": [[_loc(c), r] for c, r in (first, second)]}
        return self._constructed(name, _branch(spec, side, near))

    def circle_line(self, name: str, circle: tuple[Any, Value], line: Optional[tuple[Any, Any]] = None,
                    through: Any = None, direction: Optional[Sequence[Value]] = None,
                    side: Optional[str] = None, near: Optional[Sequence[Value]] = None) -> "Mechanism":
        """`name` at circle[1] from circle[0] on the line through two points (`line`) or
        `through` a point along `direction`; `side` "ahead" or "behind" along the line."""
        spec: dict[str, Any] = {"circle": [_loc(circle[0]), circle[1]], "line": _line(line, through, direction)}
        return self._constructed(name, _branch(spec, side, near))

    def lines(self, name: str, first: Any, second: Any) -> "Mechanism":
        """`name` where two lines meet: each two points (P, Q), or {"through": P, "direction": d}."""
        return self._constructed(name, {"lines": [_line_spec(first), _line_spec(second)]})

    def _constructed(self, name: str, spec: dict[str, Any]) -> "Mechanism":
        self.tree["points"][name] = spec
        return self

    def move(self, **amounts: Value) -> "Mechanism":
        """Analyse the mechanism advanced along driven joints: ``m.move(j1=30)`` (degrees or
        length from the drawn configuration), as the sweep reaches it."""
        self.tree.setdefault("move", {}).update(amounts)
        return self

    def body(self, name: str, *points: str, circle: Optional[tuple[Any, Value]] = None,
             line: Optional[tuple[Any, Sequence[Value]]] = None,
             disc: Optional[tuple[Any, Value, Sequence[Value]]] = None,
             plane: Optional[tuple[Any, Sequence[Value]]] = None) -> "Mechanism":
        """A rigid body carrying `points`; shapes as (center, radius), (through, direction),
        (center, radius, axis) or (through, normal)."""
        spec: dict[str, Any] = {"points": list(points)}
        if circle:
            spec["circle"] = {"center": _loc(circle[0]), "radius": circle[1]}
        if line:
            spec["line"] = {"through": _loc(line[0]), "direction": list(line[1])}
        if disc:
            spec["disc"] = {"center": _loc(disc[0]), "radius": disc[1], "axis": list(disc[2])}
        if plane:
            spec["plane"] = {"through": _loc(plane[0]), "normal": list(plane[1])}
        self.tree["bodies"][name] = spec
        return self

    # joints ------------------------------------------------------------------------------
    def joint(self, type: str, a: str, b: str, id: Optional[str] = None, **fields: Any) -> str:
        """Add a joint of any type; returns its id (``j1``, ``j2``… unless given)."""
        spec: dict[str, Any] = {"type": type, "bodies": [a, b]}
        if id is not None:
            spec["id"] = id
        for key, value in fields.items():
            if value is not None:
                spec[key] = list(value) if isinstance(value, tuple) else value
        self.tree["joints"].append(spec)
        return id or f"j{len(self.tree['joints'])}"

    # one method per kind of joint, from its module (`kinematika.joints`): revolute, prismatic,
    # slot, wheel, rolling, gear, weld, spherical, cylindrical, ...

    # drivers and questions ---------------------------------------------------------------
    def drive_omega(self, body: str, value: Any, alpha: Any = 0,
                    relative_to: Optional[str] = None) -> "Mechanism":
        """A driver: `body` turns at ω = `value` with α = `alpha` (a vector in 3D), relative to
        the frame or to body `relative_to`: ``m.drive_omega("crank", 10)``."""
        spec = {"omega": body, "value": _list(value), "alpha": _list(alpha)}
        if relative_to:
            spec["relative_to"] = relative_to
        self.tree["drivers"].append(spec)
        return self

    def drive_joint(self, joint: str, rate: Value, accel: Value = 0) -> "Mechanism":
        """A driver: joint `joint`'s coordinate changes at `rate` with acceleration `accel`
        (rad/s for a pin's angle, length/s for a slider): ``m.drive_joint("j1", 2)``."""
        self.tree["drivers"].append({"joint": joint, "rate": rate, "accel": accel})
        return self

    def drive_velocity(self, point: str, value: Any, acceleration: Any = 0,
                       along: Optional[Sequence[Value]] = None,
                       relative_to: Optional[str] = None) -> "Mechanism":
        """A driver: material point `point` (``"C@slider"``) moves at `value` with
        `acceleration` — a vector, or a speed along `along` — relative to the frame or to body
        `relative_to`: ``m.drive_velocity("C", 1.5, along=(1, 0))``."""
        spec: dict[str, Any] = {"velocity": point, "value": _list(value),
                                "acceleration": _list(acceleration)}
        if along is not None:
            spec["along"] = list(along)
        if relative_to:
            spec["relative_to"] = relative_to
        self.tree["drivers"].append(spec)
        return self

    def ask(self, **question: Any) -> "Mechanism":
        """A question, as in a file: ``m.ask(velocity="B", relative_to="rocker")``."""
        self.tree.setdefault("ask", []).append(question)
        return self

    # results -----------------------------------------------------------------------------
    def to_model(self) -> Model:
        """The checked `Model`: the tree goes through the same checks as a file, so an error
        names the place a file would (``drivers[0].omega``)."""
        return build_model(self.tree)

    # solve(), assemblies() and Jupyter's _repr_svg_ are registered by `kinematika.api`, which
    # `import kinematika` makes available (the layers above the model's)


def _loc(value: Any) -> Any:
    return value if isinstance(value, str) else list(value)


def _branch(spec: dict[str, Any], side: Optional[str], near: Optional[Sequence[Value]]) -> dict[str, Any]:
    if side is not None:
        spec["side"] = side
    if near is not None:
        spec["near"] = list(near)
    return spec


def _line(line: Optional[tuple[Any, Any]], through: Any, direction: Optional[Sequence[Value]]) -> Any:
    if line is not None:
        return [_loc(p) for p in line]
    return {"through": _loc(through), "direction": list(direction or ())}


def _line_spec(line: Any) -> Any:
    if isinstance(line, dict):
        return {"through": _loc(line["through"]), "direction": list(line["direction"])}
    return [_loc(p) for p in line]


def _list(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value


class _KindMethod:
    """`Mechanism.revolute`, `Mechanism.cam`, …: the kind's `add` (its signature and
    docstring), its module imported when the method is first looked up."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __get__(self, obj: Any, owner: Any = None) -> Any:
        method = KINDS[self.name].builder()
        return method if obj is None else method.__get__(obj, owner)


for _name in KINDS:                        # m.revolute(...), m.prismatic(...): each kind's `add`
    setattr(Mechanism, _name, _KindMethod(_name))
