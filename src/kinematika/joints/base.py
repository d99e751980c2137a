"""What a kind of joint is: the base class every joint module fills in.

A joint relates two bodies, `a` (the first, in which its `along` and `axis` are fixed) and
`b`. Its meaning is a geometric condition between them; everything else follows from it
and lives in the kind's module, asked for by the rest of the package through this class
(never by comparing type names):

- what the file says (`fields`) and the checks of the values (`check`);
- its capabilities, which other modules ask: whether the bodies share a point (`pins`), one
  slides on the other (`slides`), a point of `b` runs in a guide of `a` (`guides_point`),
  they roll (`rolls`), are one body (`rigid`); the joint's own coordinate (`coordinate`:
  an angle or a length, or none), which a driver may give the rate of and a sweep advance;
- at an instant: what its rows need (`prepare` → `JointGeometry`) and the rows, the time
  derivative of the condition at the velocity and acceleration levels (`rows`), written
  once in the levels' vocabulary (`lv.point`, `lv.omega`; `lv.w`, `lv.v` for the known
  velocities when `lv.accel`);
- for structure and instant centres: the scalar conditions it imposes in the plane
  (`conditions`), its pairs in a group's name (`chain`: R, P, or PR), and where the relative
  instant centre of its two bodies is (`centre`);
- how it is drawn and built from Python (`symbol`, `builder`).

The capabilities that are words, not yes/no, are typed in `joints.capabilities`
(`Coordinate`, `Centre`, `Chain`, `Side`, `PointOn`, `Need`).

The rows receive the level `lv` and the instant `inst` as arguments and only call their
methods, so a joint module needs nothing of the engine (sympy's `Joint` and pinocchio's
joint models are the pattern: the model is constant, each computation brings its data).
"""
from __future__ import annotations

import functools
import inspect
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Callable, ClassVar, Optional, Protocol

from ..algebra.vectors import dot, sub
from ..errors import KinematikaError, Names, Num, Said
from . import positions
from .capabilities import Centre, CentreLine, Chain, Coordinate, Need, PointOn, Side
from .positions import Residual
from ..expressions import Direction

if TYPE_CHECKING:
    from .holonomic import Holonomic
    from .seam import DrawContext, Instant, JointView, Level, Mechanism, Scalar
    from .symbols import Mark

AXES = "xyz"


class ModelJoint(Protocol):
    """A joint as the model holds it (`model.model.Joint`): its bodies `a` and `b`, its point
    `at` (a point's name), its directions `along` and `axis` as written, `internal` (circles
    inside circles), its kind (`kind`, named `type`) and where it is written (`where`, for errors)."""

    __dataclass_fields__: ClassVar[dict[str, Any]]   # a dataclass: `dataclasses.replace` makes a variant
    id: str
    type: str
    a: str
    b: str
    at: Optional[str]
    along: Optional[Direction]
    axis: Optional[Direction]
    internal: Optional[bool]

    @property
    def where(self) -> str:
        """Where the joint is written, for errors: ``joints[2] (j3)``."""
        ...

    @property
    def kind(self) -> JointKind:
        """What its kind means (the engine asks it for the joint's rows)."""
        ...


@dataclass
class JointGeometry:
    """What a joint's rows need at this instant, evaluated once: the joint's point, its
    unit directions (fixed in body `a`, in `b` for a knife edge) and their unit normals,
    and the contact of a rolling pair. `JointKind.prepare` makes it with its fields by place
    (one is made per joint at every instant: docs/performance.md)."""

    joint: ModelJoint
    at: Optional[tuple] = None              # a tuple of numbers or formulas, or None
    along: Optional[tuple] = None           # unit; fixed in body a (b for a `wheel`)
    axis: Optional[tuple] = None            # unit; fixed in body a
    perps: list[tuple] = field(default_factory=list)   # unit normals to `along` or `axis`
    contact: object = None                  # a touching pair's contact (`touching.Touch`, `rolling_contact.Contact`)
    roller: float = 0.0                     # a cam follower's roller radius (drawn about `at`)

    def point_at(self) -> tuple:
        """`at`, for a kind whose joints carry it (their `fields` require it)."""
        assert self.at is not None, f"{self.joint.where}: no point"
        return self.at

    def unit_along(self) -> tuple:
        """`along`, for a kind whose joints carry it."""
        assert self.along is not None, f"{self.joint.where}: no direction along"
        return self.along

    def unit_axis(self) -> tuple:
        """`axis`, for a kind whose joints carry it (in 3D)."""
        assert self.axis is not None, f"{self.joint.where}: no axis"
        return self.axis


Rows = list[tuple["Scalar", Said]]       # each condition (a linear form) and its message (errors' catalogue)


class NumericRows:
    """The rows of several joints of one kind at once, on floats, as arrays (`JointKind.numeric_rows`):
    `per_joint` rows for each joint, joint after joint; their coefficients by rows (`indptr`,
    `cols`, `vals`: row i's entries are `cols[indptr[i]:indptr[i + 1]]`, in the order its
    linear form holds them; None at the acceleration level, whose matrix is the velocity
    level's), the right sides `b` (minus each row's constant) and the labels the kind's
    `rows` gives them (None at the acceleration level when they are the velocity level's). A plain class, not a dataclass: it is defined at every start
    (docs/performance.md)."""

    __slots__ = ("b", "cols", "indptr", "labels", "per_joint", "vals")

    def __init__(self, per_joint: int, indptr: Any, cols: Any, vals: Any, b: Any,
                 labels: Optional[Sequence[Said]]) -> None:
        self.per_joint, self.indptr, self.cols, self.vals = per_joint, indptr, cols, vals
        self.b, self.labels = b, labels


class JointKind(ABC):
    """A kind of joint: its name in model files and everything it means (see the module's
    docstring). One instance per kind, registered in `kinematika.joints.KINDS`.

    A new kind must fill `conditions`, `rows` and `add` (abstract: a kind without them cannot
    be made) and set its `name`, `summary`, `fields` and capabilities; `prepare`, `residual`,
    `holonomic`, `displacement`, `moved`, `rate`, `numeric_rows` and `symbol` have defaults that a kind
    overrides as it needs (sympy's `Joint` is the pattern: an abstract base whose subclasses
    fill the hooks it calls). What the hooks receive is typed in `joints.seam`."""

    name: ClassVar[str] = ""
    summary: ClassVar[str] = ""             # one line for the docs and messages
    condition: ClassVar[str] = ""           # its condition at the velocity level, one line for the docs
    dimensions: ClassVar[tuple[int, ...]] = (2, 3)   # the models it exists in
    # capabilities --------------------------------------------------------------------------
    coordinate: ClassVar[Optional[Coordinate]] = None   # an angle (degrees, rad/s) or a length:
                                                 # its own coordinate, which drivers may give the rate of
    sweepable: ClassVar[bool] = False       # a sweep (and `move`) may advance that coordinate
    pins: ClassVar[bool] = False            # the bodies share the point `at` (its motion)
    ball: ClassVar[bool] = False            # ... and turn freely about it, every way (3D)
    rigid: ClassVar[bool] = False           # the bodies move as one
    slides: ClassVar[bool] = False          # b translates relative to a along `along` or `axis`
    guides_point: ClassVar[bool] = False    # the point `at` of b runs along a guide
    touches: ClassVar[bool] = False         # the bodies touch at a contact point (`contact` questions)
    rolls: ClassVar[bool] = False           # ... and roll there without slipping
    pitch: ClassVar[bool] = False           # its circles are pitch circles (gears: drawn dash-dot)
    centre_path: ClassVar[bool] = False     # explained through the circle's centre, which keeps its
                                            # distance from the other profile (the notes' route:
                                            # C5-1.7, slides 4.4), not the geometric contact point
    knife_edge: ClassVar[bool] = False      # the point `at` of b moves only along `along`, fixed in b
                                            # (a vehicle's wheel: no slip sideways)
    velocity_only: ClassVar[tuple[int, ...]] = ()   # the dimensions in which its condition is on
                                            # velocities only (non-holonomic: a motion with it
                                            # is followed in time, `simulate`, not swept)
    along_in: ClassVar[Side] = Side.A       # the body `along` is fixed in
    centre: ClassVar[Centre] = Centre.NONE  # where it puts the relative instant centre of its two
                                            # bodies by itself: at `at` (PIN), at the contact
                                            # point (CONTACT), normal to the sliding (INFINITY),
                                            # none as they move as one (REST); only a line: the
                                            # common normal at the contact (NORMAL)
    chain: ClassVar[Chain] = Chain.NONE     # the lower pairs it is in a chain, read from a to b:
                                            # R, P, or PR for a pin in a slot (a slider block
                                            # between); names dyads (RRR, RRP, …)
    centre_line: ClassVar[CentreLine] = ""         # with centre "normal": which line, in the explanation's
                                            # words (its message `centre-line-…`)
    # what the file says: each optional key of a joint and whether this kind needs it
    # ("required", "optional", "required in 3D" — and then absent in a planar model —,
    # "optional in 3D"; a key not listed is refused), and the bodies that must carry `at`
    fields: ClassVar[dict[str, Need]] = {}
    point_on: ClassVar[PointOn] = PointOn.NONE   # the bodies that carry `at`: both, or the second

    def along_body(self, joint: ModelJoint) -> str:
        """The body the joint's `along` is fixed in (`along_in`): its `a`, or its `b` for a
        knife edge."""
        return joint.b if self.along_in is Side.B else joint.a

    @abstractmethod
    def conditions(self, dim: int) -> int:
        """The independent scalar conditions it imposes on the pair's relative motion."""

    # at an instant ------------------------------------------------------------------------
    def prepare(self, inst: Instant, joint: ModelJoint) -> JointGeometry:
        """Evaluate the joint's point and directions, and check its geometry holds (else a
        `geometry` error naming the joint and the gap)."""
        at = inst.points[joint.at] if joint.at is not None else None
        along = axis = None
        perps: list[tuple] = []
        if joint.along is not None:
            along = inst.body_direction(self.along_body(joint), joint.along, f"{joint.where}.along")
            perps = inst.space.perpendiculars(along, inst.backend.sqrt)
        if joint.axis is not None:
            axis = inst.direction(joint.axis, f"{joint.where}.axis")
        return JointGeometry(joint, at, along, axis, perps)

    @abstractmethod
    def rows(self, geo: JointGeometry, lv: Level) -> Rows:
        """The conditions at the level `lv`, each (a linear form that must vanish, a label)."""

    def numeric_rows(self, geos: list[JointGeometry], lv: Level) -> Optional[NumericRows]:
        """`rows` of many joints of this kind at once, on floats (a large numeric system, whose
        joints are mostly of a few kinds): the same coefficients, right sides and labels, row
        for row, filled as arrays. None (the default): the engine asks `rows` joint by joint."""
        return None

    def residual(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Residual:
        """The condition itself, for sweeps (`joints.positions`): a function of a pose and the
        increment whose rows are the integrals of `rows`, row for row."""
        raise KinematikaError("schema", "sweep-velocity-only", geo.joint.where, kind=self.name, dim=inst.space.dim,
                              in_time=str(inst.space.dim in self.velocity_only).lower())

    def holonomic(self, inst: Instant, geo: JointGeometry, ref: tuple) -> Holonomic:
        """The condition's part on positions (`Holonomic`), for a motion integrated in time: the
        whole condition (`residual`, row for row the engine's) unless the kind is constrained
        on velocities only (a knife edge, a disc rolling on a plane), which says what is left."""
        from .holonomic import Holonomic

        return Holonomic(self.residual(inst, geo, ref))

    def displacement(self, geo: JointGeometry, ref: tuple, swept: bool) -> Residual:
        """The position form of a driver of the joint's rate: the coordinate's change from
        the drawing, less the sweep's increment when it is the swept one (a length here:
        the pin's or the reference point's offset along `along`)."""
        a, b = geo.joint.a, geo.joint.b
        p0 = geo.at if geo.at is not None else ref
        return lambda q, dq: [positions.dot(positions.differences(q.point(b, p0), q.point(a, p0)),
                                            q.turn(a, geo.unit_along())) - (dq if swept else 0.0)]

    def moved(self, geo: JointGeometry, inst: Instant, hint: object = None) -> Optional[JointGeometry]:
        """The joint's geometry at a sweep's new pose, when it must be found anew there (a
        contact that moves along its outlines; `geo` is the geometry as its bodies carried
        it, `hint` what the sweep remembers of it); None: carried by its bodies as drawn."""
        return None

    def rate(self, geo: JointGeometry, lv: Level) -> Scalar:
        """The rate of the joint's coordinate (b relative to a), or its derivative at the
        acceleration level; only for a kind with a `coordinate`."""
        raise self.no_rate(geo.joint.where)

    def check_fields(self, given: dict[str, object], dim: int, where: str) -> None:
        """The joint's keys for this kind in a model of `dim` dimensions: its model exists,
        the keys it needs are given and no other (a `schema` error naming the joint)."""
        if dim not in self.dimensions:
            raise KinematikaError("schema", "joint-other-dimension", where, kind=self.name, dim=dim)
        for key, need in self.fields.items():
            if given.get(key) is None and (need == "required" or (need == "required in 3D" and dim == 3)):
                raise KinematikaError("schema", "joint-needs-key", where, kind=self.name, key=key)
        for key, value in given.items():
            wanted = self.fields.get(key)
            allowed = wanted in ("required", "optional") or (wanted is not None and dim == 3)
            if value is not None and not allowed:
                if key == "internal":
                    owners = Names(sorted(k.name for k in kinds() if "internal" in k.fields), joined="and")
                    raise KinematikaError("schema", "internal-owners", where, owners=owners)
                raise KinematikaError("schema", "joint-no-key", where, kind=self.name, key=key,
                                      planar=str(key == "axis" and dim == 2).lower())

    def no_rate(self, where: str) -> KinematikaError:
        """The error for a driver of this kind's rate, which it has not (`coordinate` None)."""
        return KinematikaError("schema", "joint-no-rate", where, kind=self.name)

    # drawn -----------------------------------------------------------------------------------
    def symbol(self, view: JointView, ctx: DrawContext) -> list[Mark]:
        """How a figure draws it (`joints.symbols.Mark`s): `view` its place on the page (its
        point, directions, contact), `ctx` the figure's (see `joints.symbols`)."""
        return []

    # from Python ---------------------------------------------------------------------------
    @abstractmethod
    def add(self, m: Mechanism, a: str, b: str, *args: Any, **fields: Any) -> str:
        """Add a joint of this kind between bodies `a` and `b` to the `Mechanism` `m`; its id.
        Each kind names its own fields (`Revolute.add(m, a, b, at, axis=None, id=None)`), and
        passes them on as `m.joint(self.name, a, b, id, **fields)`."""

    def builder(self) -> Callable[..., str]:
        """The `Mechanism` method named after this kind (`m.revolute(...)`): its `add`."""
        add, kind = type(self).add, self

        @functools.wraps(add)
        def method(m: Mechanism, *args: Any, **kwargs: Any) -> str:
            return add(kind, m, *args, **kwargs)

        signature = inspect.signature(add)
        params = list(signature.parameters.values())[1:]     # the kind itself is bound
        method.__signature__ = signature.replace(  # type: ignore[attr-defined]  # what inspect and help() read of a function
            parameters=[params[0].replace(name="self"), *params[1:]])
        method.__name__ = method.__qualname__ = self.name
        return method

    def __repr__(self) -> str:
        return f"<joint kind {self.name}>"


def kinds() -> list[JointKind]:
    """Every registered kind (`kinematika.joints.KINDS`), for messages that list them."""
    from . import KINDS

    return list(KINDS.values())


def rounding_hint(gap: float, scale: float, point: "str | Said") -> Said:
    """For a gap small next to the model (coordinates rounded by hand, most likely): the
    tolerance, and how to avoid the rounding (`point`: a point's name, or the contact as
    a message); else nothing."""
    if abs(gap) > 1e-3 * scale:
        return Said("nothing")
    return Said("rounding-hint", tolerance=Num(1e-6 * scale, ".2g"), point=point)


def off_line(inst: Instant, joint: ModelJoint, geo: JointGeometry) -> None:
    """A slot's pin must lie on the slot's line PQ when the slot is given by two points:
    else a `geometry` error with the gap."""
    along = joint.along
    if along is None or isinstance(along, tuple) or joint.at is None:     # (not two points)
        return
    start = inst.points[along.start]
    gap = inst.num(dot(sub(geo.point_at(), start), geo.perps[0]))
    if abs(gap) > 1e-6 * inst.scale:
        raise KinematikaError("geometry", "slot-off-line", joint.where, point=joint.at, line=f"{along.start}{along.end}",
                              gap=Num(gap, ".6g"), hint=rounding_hint(gap, inst.scale, joint.at))
