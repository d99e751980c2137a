"""The one parsed representation of a mechanism, shared by every command and view.

A `Model` holds names resolved and expressions parsed but not evaluated: the engine
evaluates it on numbers or on symbols (see `engine.instant`). Files and the Python API
both end here, through `model.build`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Optional, Union

from ..errors import KinematikaError, Names
from ..joints import JointKind
from ..joints import kind as joint_kind
from ..expressions import Direction, Expr, ExprVector
from .point_ref import PointRef as PointRef           # re-exported: written `model.PointRef` across the package

if TYPE_CHECKING:
    from .body_shapes import Shape
    from .constructions import Construction
    from .exercise_section import ExerciseSection
    from .motion_sections import Simulate, Sweep, Turn
    from .parameter import Parameter
    from .question import Question
    from .wording import Wording


def _wording() -> "Wording":
    from .wording import Wording

    return Wording()


@dataclass
class Body:
    """A rigid body: its name, the names of the points it carries (a point may belong to several
    bodies) and its shapes (circles, lines, curves, a cam …) for rolling and contact."""

    name: str
    points: list[str]
    shapes: list[Shape] = field(default_factory=list)


_KINDS_BY_NAME: dict[str, JointKind] = {}     # the kinds joints have been made of: the registry asked once each


@dataclass(slots=True)
class Joint:
    """A joint between body `a` (the one `along` directions are fixed in) and body `b`, of kind
    `type` (ask `kind`, never compare the name), with the keys its kind declares: point `at`,
    directions `along` and `axis`, `internal` for circles inside circles. `index` is its place
    in the file.

    Slotted: a model may have thousands (a chain of a thousand pins), each made once and read
    by every solve."""

    id: str
    type: str
    a: str                         # first body: the one `along` directions are fixed in
    b: str
    index: int
    at: Optional[str] = None
    along: Optional[Direction] = None
    axis: Optional[Direction] = None
    internal: Optional[bool] = None
    # what this kind of joint means (`kinematika.joints`): ask it, never its name; set once
    # from `type` when the joint is made (read for every joint of every solve)
    kind: JointKind = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        kind = _KINDS_BY_NAME.get(self.type)
        if kind is None:
            kind = _KINDS_BY_NAME[self.type] = joint_kind(self.type)
        self.kind = kind

    @property
    def where(self) -> str:
        """Where the joint is written, for errors: ``joints[2] (j3)``."""
        return f"joints[{self.index}] ({self.id})"

    def point_at(self) -> str:
        """The joint's point `at`, for a kind that has one (a pin, a slot, a contact): the
        builder sets it for every such kind, so its absence is a bug, not the user's."""
        assert self.at is not None, f"{self.where}: no point"
        return self.at


@dataclass
class Driver:
    """A known motion: a body's ω (`kind` "omega", `body`), a joint's rate ("joint", `joint`) or
    a material point's velocity ("velocity", `point`, optionally only `along` a direction), with
    its value and acceleration, relative to the frame or to body `relative_to`."""

    kind: str                      # "omega", "joint" or "velocity"
    index: int
    body: Optional[str] = None     # omega driver
    joint: Optional[str] = None    # joint-rate driver
    point: Optional[PointRef] = None   # velocity driver
    value: Union[Expr, ExprVector, None] = None
    accel: Union[Expr, ExprVector, None] = None
    relative_to: Optional[str] = None
    along: Optional[Direction] = None

    @property
    def where(self) -> str:
        """Where the driver is written, for errors: ``drivers[0]``."""
        return f"drivers[{self.index}]"

    # The fields a driver has depend on its kind; these narrow them (the builder sets each
    # kind's, so a missing one is a bug, not the user's).
    def driven_body(self) -> str:
        """The body whose ω an "omega" driver gives."""
        assert self.body is not None, f"{self.where}: not an omega driver"
        return self.body

    def driven_joint(self) -> str:
        """The id of the joint whose rate a "joint" driver gives."""
        assert self.joint is not None, f"{self.where}: not a joint-rate driver"
        return self.joint

    def driven_point(self) -> PointRef:
        """The material point whose velocity a "velocity" driver gives."""
        assert self.point is not None, f"{self.where}: not a velocity driver"
        return self.point

    def given(self, accel: bool = False) -> Union[Expr, ExprVector]:
        """The driver's value, or with `accel` its acceleration (set by the builder for every
        driver: a number for a joint's rate, a planar ω or a velocity `along`, else a vector)."""
        given = self.accel if accel else self.value
        assert given is not None, f"{self.where}: no {'accel' if accel else 'value'}"
        return given

    def rate(self, accel: bool = False) -> Expr:
        """`given` when it is one number (a joint's rate, a planar ω, a velocity `along`)."""
        given = self.given(accel)
        assert not isinstance(given, tuple), f"{self.where}: a vector, not one number"
        return given

    def vector(self, accel: bool = False) -> ExprVector:
        """`given` when it is a vector (a spatial ω, a point's velocity)."""
        given = self.given(accel)
        assert isinstance(given, tuple), f"{self.where}: one number, not a vector"
        return given


@dataclass
class Model:
    """A mechanism parsed: its parameters, points (coordinates or constructions), bodies,
    joints, drivers and questions, with names resolved and expressions unevaluated; the engine
    evaluates it on numbers or on symbols (`engine.instant`). Optional parts: a `sweep`, a
    `move` to another position (`turns`: the bodies carried there), the figures' `draw_at` and
    `up`, and an `exercise` section."""

    name: str
    dimension: int
    frame: str
    parameters: dict[str, Parameter]
    points: dict[str, Union[ExprVector, "Construction"]]   # coordinates, or a construction
    bodies: dict[str, Body]
    joints: list[Joint]
    drivers: list[Driver]
    questions: list[Question]
    sweep: Optional["Sweep"] = None
    simulate: Optional["Simulate"] = None                    # `kinematika simulate`: time, steps
    move: dict[str, Expr] = field(default_factory=dict)    # joint id -> advance (deg or length)
    turns: list["Turn"] = field(default_factory=list)        # bodies carried from the drawing
    default_questions: bool = False   # no `ask` was written: every body and point is asked
    draw_at: dict[str, float] = field(default_factory=dict)   # figures: values of the symbols
    up: Optional[tuple[float, ...]] = None                    # figures: the vertical (3D)
    exercise: Optional["ExerciseSection"] = None              # `kinematika exercise` (its section)
    wording: "Wording" = field(default_factory=_wording)   # words per language, notation

    _index: Optional["_Index"] = field(default=None, init=False, repr=False, compare=False)

    def index(self) -> "_Index":
        """Who carries each point and which joints are at it, found once (a model's bodies
        and joints are not changed after it is built; changed copies are new models)."""
        if self._index is None:
            self._index = _Index(self)
        return self._index

    def carriers(self, point: str) -> list[str]:
        """The bodies that list `point`, in the file's order."""
        return list(self.index().carriers.get(point, ()))

    def material_points(self) -> list[PointRef]:
        """Every material point, body by body, in the file's order."""
        return [PointRef(p, b.name) for b in self.bodies.values() for p in b.points]

    def material_pairs(self) -> list[tuple[str, str]]:
        """`material_points` as (point, body) pairs, for a reader of every point at once (an
        answer's tables) that needs no `PointRef` of each."""
        return [(p, b.name) for b in self.bodies.values() for p in b.points]

    def joint(self, joint_id: str) -> Joint:
        """The joint with id `joint_id` (the id must exist: a model's ids are checked when it is
        built)."""
        return next(j for j in self.joints if j.id == joint_id)

    def resolve_point(self, text: "str | PointRef", where: str = "") -> PointRef:
        """``P@body``, or a bare ``P`` when every body carrying P moves alike there."""
        if isinstance(text, PointRef):
            return text
        if not isinstance(text, str):
            raise KinematikaError("schema", "point-name-not-text", where, got=repr(text))
        point, at, body = text.partition("@")
        if at and not body:
            example = next(iter(self.carriers(point)), "body")
            raise KinematikaError("schema", "point-body-after-at", where, text=text, example=f"{point}@{example}")
        if point not in self.points:
            raise KinematikaError("schema", "unknown-point", where, point=point, points=list(self.points))
        carriers = self.carriers(point)
        if body:
            if body not in self.bodies:
                raise KinematikaError("schema", "unknown-body", where, body=body, bodies=list(self.bodies))
            if body not in carriers:
                raise KinematikaError("schema", "body-not-carrying", where, body=body, point=point,
                                      carriers=carriers)
            return PointRef(point, body)
        if len(carriers) > 1 and not self.share_motion(point, carriers):
            choices = Names([f"{point}@{b}" for b in carriers], joined="or")
            raise KinematikaError("schema", "point-ambiguous", where, point=point, carriers=carriers,
                                  choices=choices)
        return PointRef(point, carriers[0])

    def share_motion(self, point: str, carriers: list[str]) -> bool:
        """Carriers joined at `point` by revolute/spherical joints or welds move alike there."""
        return len(self.motion_classes(point, carriers)) == 1

    def motion_classes(self, point: str, carriers: list[str]) -> list[list[str]]:
        """`carriers` grouped by the motion of their material points at `point`: bodies joined
        there by revolute or spherical joints (or welded), directly or through each other."""
        root = {b: b for b in carriers}

        def find(b: str) -> str:
            while root[b] != b:
                b = root[b]
            return b

        index = self.index()
        for j in (*index.welds, *index.joints_at.get(point, ())):
            linked = j.kind.rigid or j.kind.pins
            if linked and j.a in root and j.b in root:
                root[find(j.a)] = find(j.b)
        classes: dict[str, list[str]] = {}
        for b in carriers:
            classes.setdefault(find(b), []).append(b)
        return list(classes.values())

    def place_owner(self, point: str) -> str:
        """The body whose material point gives a point name's place when its carriers move
        differently there (after a move, in a sweep's rows): the pin of a slot or knife
        edge, else the first moving carrier. The other carriers' points named so are the
        points of those bodies that coincide with it."""
        carriers = self.carriers(point)
        classes = self.motion_classes(point, carriers)
        if len(classes) == 1:
            return classes[0][0]
        for j in self.index().joints_at.get(point, ()):
            if j.kind.guides_point:
                return j.b
        moving = [b for b in carriers if b != self.frame]
        return moving[0] if moving else carriers[0]

    @property
    def moving_bodies(self) -> list[str]:
        """Every body but the frame, in the file's order: the bodies whose twists are the
        unknowns."""
        return [name for name in self.bodies if name != self.frame]


class _Index:
    """A model's lookups by point: its carriers (file order) and the joints at it (joint
    order), and the welds, so that resolving every point takes linear time."""

    def __init__(self, model: Model) -> None:
        self.carriers: dict[str, list[str]] = {}
        for body in model.bodies.values():
            for point in body.points:
                self.carriers.setdefault(point, []).append(body.name)
        self.joints_at: dict[str, list[Joint]] = {}
        for j in model.joints:
            if j.at is not None:
                self.joints_at.setdefault(j.at, []).append(j)
        self.welds = [j for j in model.joints if j.kind.rigid]
