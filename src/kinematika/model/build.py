"""From a model tree (a file's content or the Python API's) to the checked `Model`.

Checks happen here, once, with the place named: the file's shape (pydantic), names of
points, bodies and joints, expressions, which body carries a bare point name.
"""
from __future__ import annotations

import functools
import operator
import types
import typing
from typing import TYPE_CHECKING, Any, Iterable, Optional, TypeGuard

from ..errors import KinematikaError, Names, Said, pydantic_choices, pydantic_problem
from ..joints import kind as joint_kind
from ..questions import QUESTIONS
from ..text import brief
from . import shape
from .plain import Record
from .point_order import construction_order
from ..expressions import Expr, ExpressionError, parse
from .model import Body, Direction, Driver, ExprVector, Joint, Model, PointRef

if TYPE_CHECKING:
    from pydantic import ValidationError
    from pydantic_core import ErrorDetails

    from . import schema
    from .motion_sections import Simulate, Sweep
    from .body_shapes import CamShape, Shape
    from .constructions import Construction
    from .parameter import Parameter
    from .question import Question



def build_model(tree: Any) -> Model:
    """Check a model tree and resolve it into a `Model`; raises `KinematikaError`."""
    if not isinstance(tree, dict):
        raise KinematikaError("schema", "model-mapping")
    spec: schema.ModelSpec | Record | None = shape.spec_of(tree)   # plain checks first: pydantic
    if spec is None:                                              # only for files that may be wrong
        from pydantic import ValidationError

        from . import schema

        try:
            spec = schema.ModelSpec.model_validate(tree)
        except ValidationError as err:
            raise _schema_error(err, tree) from None
    return _Builder(spec).model()


def _joint_place(i: int, jid: str) -> str:
    """Where joint `i` (`jid`) is written, for errors: ``joints[2] (j3)`` (as `Joint.where`)."""
    return f"joints[{i}] ({jid})"


_joint_values = operator.attrgetter(*shape.JOINT_KEYS)     # a joint's optional keys, in order
_NONES = (None,) * len(shape.JOINT_KEYS)

MAX_QUESTIONS = 10_000      # a model is read by people; more is a mistake or an attack


class _Builder:
    def __init__(self, spec: schema.ModelSpec | Record) -> None:
        # `schema`'s classes, or `shape`'s records of the same names and fields (a file the
        # plain checks accept): read alike
        self.spec = spec
        self._fields_checked: set[tuple] = set()     # (kind, keys given) whose keys passed `check_fields`
        self._numbers: dict[str, Expr] = {}         # the numbers' expressions by their text (`repr`)

    def model(self) -> Model:
        spec = self.spec
        params = self.parameters()
        points = self.points(params)
        dimension = self.dimension(points)
        self.dim = dimension
        for name, vec in points.items():
            if isinstance(vec, tuple):
                self.check_size(vec, f"points.{name}", "coordinates")
        self.point_coords = points
        bodies = self.bodies()
        if spec.frame not in bodies:
            raise KinematikaError("schema", "frame-missing", "bodies", frame=spec.frame, bodies=_names(bodies))
        self.body_map = bodies
        self.body_points = {name: set(b.points) for name, b in bodies.items()}
        joints = self.joints()
        self.joint_list = joints
        model = Model(name=spec.name or "Mechanism", dimension=dimension, frame=spec.frame,
                      parameters=params, points=points, bodies=bodies, joints=joints,
                      drivers=[], questions=[], sweep=self.sweep(),
                      simulate=self.simulate())
        self.model_ = model
        model.drivers = [self.driver(i, d) for i, d in enumerate(spec.drivers)]
        model.questions = self.questions()
        model.default_questions = self.spec.ask is None
        model.draw_at, model.up = self.figure_hints(params, dimension)
        model.wording = self.wording(params, model.name)
        model.move = self.move()
        if spec.exercise is not None:
            from .exercise_section import exercise_section

            model.exercise = exercise_section(spec.exercise, params, len(model.questions), points)
        return model

    def figure_hints(self, params: dict[str, Parameter], dimension: int) -> tuple[dict, Any]:
        """`draw_at` (numbers for symbolic parameters, to draw at) and `up` (a 3D vertical)."""
        from .figure_hints import draw_values, up_vector

        return draw_values(self.spec.draw_at, params), up_vector(self.spec.up, dimension)

    def wording(self, params: dict[str, Parameter], title: str) -> Any:
        """`names` (titles, bodies, points, notes per language) and `notation`."""
        from .wording import read_wording

        joints = {j.id: j for j in self.joint_list}
        return read_wording(self.spec.names, self.spec.notation, self.body_map, self.point_coords, params, title,
                            joints, self.spec.frame)

    # parameters and points -------------------------------------------------------------
    def parameters(self) -> dict[str, Parameter]:
        out: dict[str, Parameter] = {}
        if not self.spec.parameters:       # (`Parameter` is defined only for a model that has one)
            return out
        from .parameter import Parameter

        for name, raw in self.spec.parameters.items():
            where = f"parameters.{name}"
            if not name.isidentifier():
                raise KinematikaError("schema", "parameter-name-invalid", where, name=name)
            positive = True
            if _parameter_spec(raw):             # a ParameterSpec (schema's or shape's)
                positive = raw.positive
                raw = None if raw.symbolic else raw.value
            out[name] = Parameter(name, None if raw is None else self.expr(raw, where), positive)
        known = set(out) | {"pi"}     # a parameter may use pi like any expression
        for p in out.values():
            if p.value is not None:
                unknown = p.value.names() - known
                if unknown:
                    raise KinematikaError("schema", "unknown-name-in", f"parameters.{p.name}", name=sorted(unknown)[0],
                                          text=p.value.text)
        return out

    def expr(self, raw: Any, where: str, index: Optional[int] = None) -> Expr:
        """`raw` as an expression in the parameters (and pi); `where` (component `index` of it,
        when given: its place written only for an error) names it in errors."""
        number = type(raw) is float or type(raw) is int
        if number:          # a number names nothing: one `Expr` per number written (the same text)
            found = self._numbers.get(repr(raw))
            if found is not None:
                return found
        try:
            expr = parse(raw)
        except ExpressionError as err:
            raise KinematikaError("schema", err.said, where if index is None else f"{where}[{index}]") from None
        if number:
            self._numbers[expr.text] = expr
            return expr
        if index is not None:
            where = f"{where}[{index}]"
        unknown = expr.names() - set(getattr(self, "_param_names", ())) - {"pi"}
        if hasattr(self, "_param_names") and unknown:
            raise KinematikaError("schema", "unknown-name-in-parameters", where, name=sorted(unknown)[0],
                                  text=expr.text, parameters=self._param_names)
        return expr

    def vector(self, raw: list, where: str, dims: Iterable[int] = (2, 3)) -> ExprVector:
        if len(raw) not in tuple(dims):
            raise KinematikaError("schema", "components-count", where, dims=Names(map(str, dims), joined="or"),
                                  got=len(raw))
        expr = self.expr
        return tuple([expr(v, where, i) for i, v in enumerate(raw)])

    def points(self, params: dict[str, Parameter]) -> dict[str, ExprVector | Construction]:
        self._param_names = list(params)
        if not self.spec.points:
            raise KinematikaError("schema", "model-no-points", "points")
        for name in [*self.spec.points, *self.spec.bodies]:
            if not name.strip() or "@" in name:
                kind = "points" if name in self.spec.points else "bodies"
                raise KinematikaError("schema", "name-invalid", f"{kind}.{name}", name=name)
        symbolic = any(p.value is None for p in params.values())
        out: dict[str, ExprVector | Construction] = {}
        reader = None
        for name, raw in self.spec.points.items():
            where = f"points.{name}"
            if isinstance(raw, list):
                out[name] = self.vector(raw, where)
                continue
            if reader is None:           # the first constructed point (start-up: docs/architecture.md)
                from .constructions import ConstructionReader

                reader = ConstructionReader(self.expr, self.vector, set(self.spec.points), symbolic)
            out[name] = reader.read(raw, where)
        construction_order(out)             # a cycle is an error here, with its place
        return out

    def dimension(self, points: dict[str, ExprVector | Construction]) -> int:
        sizes = {len(v) if isinstance(v, tuple) else 2 for v in points.values()}
        constructed = next((n for n, v in points.items() if not isinstance(v, tuple)), None)
        if constructed is not None and (3 in sizes or self.spec.dimension == 3):
            raise KinematikaError("schema", "construction-planar", f"points.{constructed}")
        if self.spec.dimension is not None:
            if self.spec.dimension == 2 and 3 in sizes:
                name = next(n for n, v in points.items() if isinstance(v, tuple) and len(v) == 3)
                raise KinematikaError("schema", "planar-two-coordinates", f"points.{name}")
            return self.spec.dimension
        return 3 if 3 in sizes else 2

    # bodies -----------------------------------------------------------------------------
    def bodies(self) -> dict[str, Body]:
        out: dict[str, Body] = {}
        known = self.point_coords.keys()
        for name, written in self.spec.bodies.items():
            record: Optional[schema.BodySpec | Record] = None     # a bare list: its points, no shapes
            points: list[str]
            if isinstance(written, list):
                points = written
            else:
                record, points = written, written.points
            distinct = set(points)
            if not known >= distinct:        # the first unknown one named
                for p in points:
                    self.known_point(p, f"bodies.{name}")
            if len(distinct) != len(points):
                seen: set[str] = set()
                twice: set[str] = set()
                for p in points:
                    if p in seen:
                        twice.add(p)
                    seen.add(p)
                raise KinematikaError("schema", "point-listed-twice", f"bodies.{name}", point=sorted(twice)[0])
            out[name] = Body(name, list(points), [] if record is None else self.shapes(record, f"bodies.{name}"))
        listed = {p for b in out.values() for p in b.points}
        if not listed >= known:             # the first not carried named
            for name in self.point_coords:
                if name not in listed:
                    raise KinematikaError("schema", "point-not-carried", f"points.{name}", point=name)
        return out

    def known_point(self, name: str, where: str) -> None:
        if name not in self.point_coords:
            raise KinematikaError("schema", "unknown-point", where, point=name, points=list(self.point_coords))

    def location(self, raw: Any, where: str) -> tuple[ExprVector, Optional[str]]:
        """Coordinates, or a point's name (its coordinates are then read at the instant)."""
        if isinstance(raw, str):
            self.known_point(raw, where)
            return (), raw
        return self.check_size(self.vector(raw, where), where), None

    @staticmethod
    def arc(raw: Optional[list], where: str) -> Optional[tuple[float, float]]:
        """A circle's `arc` [from, to] in degrees (counter-clockwise from `from`): a part of the
        disc that is neither nothing nor all of it (0 < to − from < 360), else a `schema` error."""
        if raw is None:
            return None
        start, end = (float(a) for a in raw)
        if not 0.0 < end - start < 360.0:
            raise KinematikaError("schema", "circle-arc", where, start=raw[0], end=raw[1])
        return start, end

    def check_size(self, vec: ExprVector, where: str, what: str = "components") -> ExprVector:
        """A vector of the model's dimension: never padded or cut, so that a slip such as a 2D
        axis in a 3D model is an error rather than a different mechanism."""
        if len(vec) != self.dim:
            raise KinematikaError("schema", "vector-size", where, dim=self.dim, what=what, got=len(vec))
        return vec

    def shapes(self, raw: schema.BodySpec | Record, where: str) -> list[Shape]:
        shapes: list[Shape] = []
        if not (raw.circle or raw.line or raw.disc or raw.plane or raw.curve or raw.cam):
            return shapes
        from .body_shapes import CamShape, Circle, CurveShape, Disc, Line, Plane    # (start-up)

        circles = raw.circle if isinstance(raw.circle, list) else [raw.circle] if raw.circle else []
        for i, circle in enumerate(circles):        # several: solidary wheels (C5-E.1's R and 2R)
            at = f"{where}.circle[{i}]" if isinstance(raw.circle, list) else f"{where}.circle"
            center, cp = self.location(circle.center, f"{at}.center")
            shapes.append(Circle(center, self.expr(circle.radius, f"{at}.radius"), cp,
                                 self.arc(circle.arc, f"{at}.arc")))
        if raw.line:
            through, tp = self.location(raw.line.through, f"{where}.line.through")
            shapes.append(Line(through, self.direction(raw.line.direction,
                                                              f"{where}.line.direction"), tp))
        if raw.disc:
            center, cp = self.location(raw.disc.center, f"{where}.disc.center")
            shapes.append(Disc(center, self.expr(raw.disc.radius, f"{where}.disc.radius"),
                               self.direction(raw.disc.axis, f"{where}.disc.axis"), cp))
        if raw.plane:
            through, tp = self.location(raw.plane.through, f"{where}.plane.through")
            shapes.append(Plane(through, self.direction(raw.plane.normal,
                                                               f"{where}.plane.normal"), tp))
        if raw.curve:
            places = tuple(self.location(p, f"{where}.curve.through[{i}]")
                           for i, p in enumerate(raw.curve.through))
            shapes.append(CurveShape(tuple(name or coords for coords, name in places), raw.curve.closed))
        if raw.cam:
            shapes.append(self.cam(raw.cam, f"{where}.cam"))
        if self.dim == 2 and shapes and any(isinstance(s, (Disc, Plane)) for s in shapes):
            raise KinematikaError("schema", "shapes-3d-only", where)
        if self.dim == 3 and any(isinstance(s, (CurveShape, CamShape)) for s in shapes):
            raise KinematikaError("schema", "shapes-planar-only", where)
        return shapes

    def cam(self, raw: Any, where: str) -> CamShape:
        """A cam's profile: its design checked as a cam-design file's (`cams.spec.design`,
        errors named in the body), placed at its centre."""
        from ..cams.spec import CamFileSpec, CamSpec, SpeedSpec, design
        from .body_shapes import CamShape

        center, cp = self.location(raw.center, f"{where}.center")
        spec = CamFileSpec(cam=CamSpec(kind=raw.kind, base=raw.base, rotation=raw.rotation),
                           follower=raw.follower, program=raw.program, profile=raw.profile,
                           speed=SpeedSpec(velocity=1.0) if raw.kind == "translating" else SpeedSpec(omega=1.0))
        try:
            made = design(spec)
        except KinematikaError as err:
            raise KinematikaError(err.kind, err.said, f"{where}.{err.where}" if err.where else where) from None
        return CamShape(center, self.expr(raw.angle, f"{where}.angle"), self.expr(raw.layout, f"{where}.layout"),
                        made, cp)

    def known_body(self, name: Optional[str], where: str) -> str:
        if name not in self.body_map:
            raise KinematikaError("schema", "unknown-body", where, body=name, bodies=_names(self.body_map))
        return name

    # joints -----------------------------------------------------------------------------
    def joints(self) -> list[Joint]:
        out: list[Joint] = []
        ids: set[str] = set()
        for i, raw in enumerate(self.spec.joints):
            jid = raw.id if raw.id is not None else f"j{i + 1}"
            if not jid.strip():
                raise KinematikaError("schema", "joint-id-empty", f"joints[{i}].id")
            if jid in ids:
                raise KinematikaError("schema", "joint-id-twice", _joint_place(i, jid), id=jid)
            ids.add(jid)
            out.append(self.joint(i, jid, raw))
        return out

    def joint(self, i: int, jid: str, raw: schema.JointSpec | Record) -> Joint:
        """Joint `i` (`jid`) of the file; its place (`_joint_place`) is written only for an
        error or a direction (a chain of a thousand pins writes none)."""
        a, b = raw.bodies
        if a not in self.body_map or b not in self.body_map:
            where = _joint_place(i, jid)
            a, b = (self.known_body(name, f"{where}.bodies") for name in raw.bodies)
        if a == b:
            raise KinematikaError("schema", "joint-same-body", _joint_place(i, jid), body=a)
        kind = joint_kind(raw.type)
        values = _joint_values(raw)
        # the keys' check depends only on the kind and which keys are given: once per such
        # case (a chain of a thousand pins is checked once)
        case = (kind, tuple(map(operator.is_not, values, _NONES)))
        if case not in self._fields_checked:
            kind.check_fields(dict(zip(shape.JOINT_KEYS, values)), self.dim, _joint_place(i, jid))
            self._fields_checked.add(case)
        at = raw.at
        if at is not None:
            if at not in self.point_coords:
                self.known_point(at, f"{_joint_place(i, jid)}.at")
            if at not in self.body_points[a] or at not in self.body_points[b]:     # (else on any it must be)
                carriers = [name for name in (a, b) if at in self.body_points[name]]
                must = kind.point_on.bodies(a, b)
                missing = [name for name in must if name not in carriers]
                if missing:
                    raise KinematikaError("geometry", "joint-point-not-on-body", _joint_place(i, jid), kind=kind.name,
                                          point=at, body=missing[0])
        along = self.direction(raw.along, f"{_joint_place(i, jid)}.along") if raw.along is not None else None
        axis = self.direction(raw.axis, f"{_joint_place(i, jid)}.axis") if raw.axis is not None else None
        # (in the fields' order, by place: keywords cost a third of a joint's making)
        return Joint(jid, kind.name, a, b, i, at, along, axis, raw.internal)

    def direction(self, raw: list, where: str) -> Direction:
        """A direction as a vector, or as two points [P, Q] (from P to Q, at this instant)."""
        if len(raw) == 2 and all(isinstance(v, str) and v in self.point_coords for v in raw):
            if raw[0] == raw[1]:
                raise KinematikaError("schema", "direction-same-points", where)
            from ..point_pair import PointPair     # (defined only for a model that has one: see its module)

            return PointPair(raw[0], raw[1])
        return self.check_size(self.vector(raw, where), where)

    # drivers ----------------------------------------------------------------------------
    def driver(self, i: int, raw: Any) -> Driver:
        where = f"drivers[{i}]"
        if hasattr(raw, "omega"):                # an OmegaDriver (schema's or shape's)
            body = self.known_body(raw.omega, f"{where}.omega")
            rel = (None if raw.relative_to is None else
                   self.known_body(raw.relative_to, f"{where}.relative_to"))
            return Driver("omega", i, body=body, relative_to=rel,
                          value=self.angular(raw.value, f"{where}.value"),
                          accel=self.angular(raw.alpha, f"{where}.alpha"))
        if hasattr(raw, "joint"):
            ids = [j.id for j in self.joint_list]
            if raw.joint not in ids:
                raise KinematikaError("schema", "unknown-joint", f"{where}.joint", joint=raw.joint, joints=ids)
            joint = next(j for j in self.joint_list if j.id == raw.joint)
            if joint.kind.coordinate is None:
                raise joint.kind.no_rate(where)
            return Driver("joint", i, joint=raw.joint, value=self.expr(raw.rate, f"{where}.rate"),
                          accel=self.expr(raw.accel, f"{where}.accel"))
        point = self.point_ref(raw.velocity, f"{where}.velocity")
        rel = None if raw.relative_to is None else self.known_body(raw.relative_to, f"{where}.relative_to")
        if raw.along is not None:
            along = self.direction(raw.along, f"{where}.along")
            return Driver("velocity", i, point=point, relative_to=rel, along=along,
                          value=self.scalar(raw.value, f"{where}.value"),
                          accel=self.scalar(raw.acceleration, f"{where}.acceleration"))
        return Driver("velocity", i, point=point, relative_to=rel,
                      value=self.full_vector(raw.value, f"{where}.value"),
                      accel=self.full_vector(raw.acceleration, f"{where}.acceleration", zero_ok=True))

    def scalar(self, raw: Any, where: str) -> Expr:
        if isinstance(raw, list):
            raise KinematikaError("schema", "expected-one-number", where)
        return self.expr(raw, where)

    def full_vector(self, raw: Any, where: str, zero_ok: bool = False) -> ExprVector:
        if not isinstance(raw, list):
            if zero_ok and raw in (0, 0.0):
                return tuple(self.expr(0, where) for _ in range(self.dim))
            raise KinematikaError("schema", "expected-vector", where, dim=self.dim)
        return self.vector(raw, where, (self.dim,))

    def angular(self, raw: Any, where: str) -> Expr | ExprVector:
        if self.dim == 2:
            return self.scalar(raw, where)
        return self.full_vector(raw, where, zero_ok=True)

    def point_ref(self, text: str, where: str) -> PointRef:
        return self.model_.resolve_point(text, where)

    # questions --------------------------------------------------------------------------
    def questions(self) -> list[Question]:
        if self.spec.ask is None:
            return self.default_questions()
        if len(self.spec.ask) > MAX_QUESTIONS:
            raise KinematikaError("schema", "questions-too-many", "ask", count=len(self.spec.ask), limit=MAX_QUESTIONS)
        return [self.question(i, q) for i, q in enumerate(self.spec.ask)]

    def default_questions(self) -> list[Question]:
        """The contract's default: every body (ω, α) and every material point (v, a), the
        fixed frame and its points included, in the file's order: the kinds whose answers
        are the columns of the answer's tables (`QuestionKind.column`)."""
        from .question import Question      # (defined only for a model that asks: see its module)

        columns = [k for k in QUESTIONS.values() if k.column]
        out: list[Question] = []
        for body in self.body_map:
            for kind in (k.name for k in columns if k.about == "body"):
                out.append(Question(kind, len(out), body, {kind: body}))
        for ref in self.model_.material_points():
            for kind in (k.name for k in columns if k.about == "point"):
                out.append(Question(kind, len(out), ref, {kind: str(ref)}))
        return out

    def question(self, i: int, raw: schema.QuestionSpec | Record) -> Question:
        """A question of `ask`, checked as its kind says (`questions.QUESTIONS`): its target
        a material point, a body or a joint, a `moving` body when it takes one, its models."""
        from .question import Question

        where = f"ask[{i}]"
        names = [k for k in QUESTIONS if getattr(raw, k) is not None]
        if len(names) != 1:
            raise KinematikaError("schema", "question-one-key", where, keys=list(QUESTIONS))
        name = names[0]
        kind = QUESTIONS[name]
        text = getattr(raw, name)
        rel = None if raw.relative_to is None else self.known_body(raw.relative_to, f"{where}.relative_to")
        echo = raw.model_dump(exclude_none=True)
        target: Any
        if kind.about == "point":
            target = self.point_ref(text, f"{where}.{name}")
        elif kind.about == "joint":
            target = kind.target_joint(text, self.joint_list, f"{where}.{name}")
        else:
            target = self.known_body(text, f"{where}.{name}")
        moving = None
        if kind.moving:
            if raw.moving is None:
                raise KinematikaError("schema", "decompose-needs-moving", where)
            moving = self.known_body(raw.moving, f"{where}.moving")
        elif raw.moving is not None:
            raise KinematikaError("schema", "moving-only-decompose", where)
        if self.dim not in kind.dimensions:
            if self.dim == 3:
                raise KinematikaError("schema", "question-planar-only", where, kind=name)
            raise KinematikaError("schema", "question-3d-only", where)
        return Question(name, i, target, echo, relative_to=rel, moving=moving)

    def move(self) -> dict[str, Expr]:
        """`move: {joint: amount}`: joints checked here, amounts evaluated when moving."""
        out: dict[str, Expr] = {}
        ids = {j.id for j in self.joint_list}
        for jid, raw in (self.spec.move or {}).items():
            if jid not in ids:
                raise KinematikaError("schema", "unknown-joint", f"move.{jid}", joint=jid,
                                      joints=[j.id for j in self.joint_list])
            out[jid] = self.expr(raw, f"move.{jid}")
        return out

    def sweep(self) -> Optional[Sweep]:
        raw = self.spec.sweep
        if raw is None:
            return None
        from .motion_sections import Sweep      # most models have no `sweep:` section

        if raw.joint is not None and raw.joint not in {j.id for j in self.joint_list}:
            raise KinematikaError("schema", "unknown-joint-bare", "sweep.joint", joint=raw.joint)
        if raw.steps < 1:
            raise KinematikaError("schema", "steps-at-least-one", "sweep.steps")
        return Sweep(raw.joint, self.expr(raw.by, "sweep.by"), raw.steps)

    def simulate(self) -> Optional[Simulate]:
        raw = self.spec.simulate
        if raw is None:
            return None
        from .motion_sections import Simulate      # most models have no `simulate:` section

        if raw.steps < 1:
            raise KinematikaError("schema", "steps-at-least-one", "simulate.steps")
        return Simulate(self.expr(raw.time, "simulate.time"), raw.steps)


def _names(items: Iterable[str]) -> Names:
    return Names(items)


# pydantic errors as one line -------------------------------------------------------------
_SCALAR_BRANCHES = {"int", "float", "str", "none"}   # pydantic's names of a union's plain members


@functools.cache
def _branch_names() -> frozenset[str]:
    """The names pydantic puts in an error's place for the member of a union the value was
    tried as: the plain types', and those of `schema`'s classes that are a union's members
    (`BodySpec` in `bodies: {NAME: [points] or BodySpec}`), read from `schema`; lower case."""
    from pydantic import BaseModel, Discriminator

    from . import schema

    found: set[str] = set()
    seen: set[type] = set()

    def walk(tp: Any, member: bool) -> None:
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            if member:
                found.add(tp.__name__.lower())
            if tp not in seen:
                seen.add(tp)
                for field in tp.model_fields.values():
                    walk(field.annotation, False)
            return
        args = typing.get_args(tp)
        if typing.get_origin(tp) is typing.Annotated:
            if any(isinstance(m, Discriminator) for m in args[1:]):   # members named by their tags
                for choice in typing.get_args(args[0]):
                    walk(choice, False)
            else:
                walk(args[0], member)
            return
        is_union = typing.get_origin(tp) in (typing.Union, types.UnionType)
        choices = [a for a in args if a is not type(None)]
        for a in choices:
            walk(a, is_union and len(choices) > 1)

    walk(schema.ModelSpec, False)
    return frozenset(found | _SCALAR_BRANCHES)


def _driver_tags() -> set[str]:
    """The tag of a driver's union (right after its index in an error's place): `schema`'s."""
    from . import schema

    return set(schema._driver_kind.tags.values())


def _point_tags() -> set[str]:
    """The tags of a point's unions (coordinates or a construction, and which): `schema`'s."""
    from . import schema

    return {*schema._point_kind.tags.values(), *schema._construction_kind.tags.values()}


def _parameter_spec(raw: object) -> TypeGuard[schema.ParameterSpec | Record]:
    """Whether a parameter is written in full (`{value, positive, symbolic}`), not as a value."""
    return hasattr(raw, "symbolic")


def _schema_error(err: ValidationError, tree: Any) -> KinematikaError:
    errors = err.errors()
    first = min(errors, key=_rank)
    loc = _clean(first["loc"])
    where = _place(loc, tree)
    others = len({tuple(_clean(e["loc"])) for e in errors}) - 1
    return KinematikaError("schema", "schema-problems", where, problem=_message(first, loc), others=max(others, 0))


def _clean(loc: tuple) -> list:
    """The error's place in the user's tree: pydantic's union branches left out."""
    out = []
    for i, part in enumerate(loc):
        tag = i == 2 and loc[0] == "drivers" and part in _driver_tags()
        tag = tag or (loc[0] == "points" and part in _point_tags())
        if not tag and not _is_branch(part):
            out.append(part)
    return out


def _is_branch(part: Any) -> bool:
    return isinstance(part, str) and (part.lower() in _branch_names()
                                      or "[" in part or part.startswith(("function-", "constrained")))


def _rank(error: ErrorDetails) -> tuple:
    # prefer unknown or missing keys and literal errors over union-member type mismatches
    order = {"extra_forbidden": 0, "missing": 1, "literal_error": 2, "driver_kind": 2,
             "construction_kind": 2}
    return (order.get(error["type"], 5), len(error["loc"]))


def _place(loc: list, tree: Any) -> str:
    out = ""
    node = tree
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
            node = node[part] if isinstance(node, list) and part < len(node) else None
            if len(out) and out.startswith("joints") and out.count("[") == 1 and isinstance(node, dict):
                out += f" ({node.get('id') or 'j' + str(part + 1)})"
        else:
            out += ("." if out else "") + str(part)
            node = node.get(part) if isinstance(node, dict) else None
    return out


def _message(error: ErrorDetails, loc: list) -> Said:
    kind = error["type"]
    last = loc[-1] if loc else ""
    if kind == "extra_forbidden" and loc[:1] == ["drivers"] and last in _driver_tags():
        return Said("driver-second-kind", kinds=sorted(_driver_tags()), key=last)
    if kind == "extra_forbidden":
        return Said("unknown-key", key=last)
    if kind == "missing":
        return Said("missing-key", key=last)
    if kind == "literal_error":
        return Said("not-one-of", value=brief(error['input']), expected=pydantic_choices(error['ctx']['expected']))
    if kind in {"int_type", "float_type", "string_type", "union_tag_invalid"} or kind.endswith("_type"):
        return Said("unexpected-value", value=brief(error.get('input')), problem=pydantic_problem(error, lower=True))
    return pydantic_problem(error)
