"""The shape of a model file (the contract's model format), checked by pydantic.

This module only says which keys exist and what type each value has. Names are resolved
and expressions parsed afterwards, in `build`, which turns a checked file into a `Model`.

It is the one place the format is written: `shape`, the plain-Python check the fast path
uses (pydantic is not imported there), is generated from these classes by
`python -m kinematika.model.generate_shape`, and a test regenerates it and compares. A
joint's keys are those its kinds declare (`JointKind.fields`, typed by `JOINT_KEY_TYPES`),
the questions' keys are the registered question kinds (`questions.QUESTIONS`), and a body's `cam:` takes the cam-design
file's own fields (`cams.spec`). See docs/architecture.md, "One source for the model format".
"""
from __future__ import annotations

import copy
from typing import TYPE_CHECKING, Annotated, Any, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Discriminator, Field, StrictBool, StrictFloat, StrictInt, Tag, create_model

from ..cams.spec import CamFileSpec, CamSpec
from ..joints import KINDS
from ..questions import QUESTIONS

Value = Union[StrictInt, StrictFloat, str]
Vector = list[Value]


class Strict(BaseModel):
    """The schema's base: an unknown key is an error (a misspelt key never passes silently), and
    a field may be written by its name or its file key (`from`)."""

    model_config = ConfigDict(extra="forbid", populate_by_name=True)


class ParameterSpec(Strict):
    """A parameter written in full: its value (null keeps it a symbol; TOML, which has no null,
    writes `symbolic = true`), whether it is positive, and a description."""

    value: Optional[Value] = None
    positive: StrictBool = True
    symbolic: StrictBool = False   # TOML has no null: `{symbolic = true}` keeps it a symbol
    description: Optional[str] = None


class CircleSpec(Strict):
    """A body's `circle`: centre (a point's name or coordinates) and radius; `arc` [from, to]
    (degrees, counter-clockwise, in the model's axes at the drawing) when the body is only that
    part of the disc (a semicylinder: `[0, 180]`). The arc is what the figures draw; the
    kinematics read the circle (a contact on it is one on the whole circle)."""

    center: Union[str, Vector]
    radius: Value
    arc: Optional[Annotated[list[Union[StrictInt, StrictFloat]], Field(min_length=2, max_length=2)]] = None


class LineSpec(Strict):
    """A body's `line`: a point it passes through (a name or coordinates) and its direction
    vector."""

    through: Union[str, Vector]
    direction: Vector


class DiscSpec(Strict):
    """A 3D body's `disc`: centre, radius and axis."""

    center: Union[str, Vector]
    radius: Value
    axis: Vector


class PlaneSpec(Strict):
    """A 3D body's `plane`: a point it passes through and its normal."""

    through: Union[str, Vector]
    normal: Vector


# points by construction (planar) -------------------------------------------------------
Location = Union[str, Vector]          # a point's name, or coordinates


class PolarSpec(Strict):
    """`from` + `distance` along `angle` (from the x axis, or from the direction P→Q)."""

    from_: Location = Field(alias="from")
    distance: Value
    angle: Value
    reference: Optional[Annotated[list[Location], Field(min_length=2, max_length=2)]] = None


class FrameSpec(Strict):
    """P + x·u + y·n in the frame of two points (u along P→Q, n to its left)."""

    frame: Annotated[list[Location], Field(min_length=2, max_length=2)]
    at: Annotated[list[Value], Field(min_length=2, max_length=2)]


CircleRef = Annotated[list[Union[str, Vector, StrictInt, StrictFloat]], Field(min_length=2, max_length=2)]
LineRef = Union[Annotated[list[Location], Field(min_length=2, max_length=2)], LineSpec]


class CirclesSpec(Strict):
    """An intersection of two circles `[[P, r1], [Q, r2]]`, on a `side` of P→Q or `near` a point."""

    circles: Annotated[list[CircleRef], Field(min_length=2, max_length=2)]
    side: Optional[Literal["left", "right"]] = None
    near: Optional[Vector] = None


class CircleLineSpec(Strict):
    """An intersection of the circle `[P, r]` and a line, `ahead` or `behind` along it."""

    circle: CircleRef
    line: LineRef
    side: Optional[Literal["ahead", "behind"]] = None
    near: Optional[Vector] = None


class LinesSpec(Strict):
    """Where two lines meet."""

    lines: Annotated[list[LineRef], Field(min_length=2, max_length=2)]


class FirstKey:
    """A union's discriminator: the tag of the first of `tags`' keys a mapping has (None,
    an error, for a mapping with none of them or for anything else). `generate_shape`
    reads `tags` to write the same choice as a plain check; pydantic shows `name`."""

    def __init__(self, name: str, tags: dict[str, str]) -> None:
        self.__name__, self.tags = name, tags

    def __call__(self, data: Any) -> str | None:
        if isinstance(data, dict):
            for key, tag in self.tags.items():
                if key in data:
                    return tag
        return None


class ByType:
    """A union's discriminator: the tag of the value's type (a subclass counts), None for
    any other type."""

    def __init__(self, name: str, tags: dict[type, str]) -> None:
        self.__name__, self.tags = name, tags

    def __call__(self, data: Any) -> str | None:
        return next((tag for kind, tag in self.tags.items() if isinstance(data, kind)), None)


CONSTRUCTION_KEYS = {"from": "polar", "frame": "frame", "circles": "circles", "circle": "circle-line",
                     "lines": "lines"}
_construction_kind = FirstKey("_construction_kind", {key: f"construction:{kind}" for key, kind in CONSTRUCTION_KEYS.items()})

ConstructionSpec = Annotated[
    Union[Annotated[PolarSpec, Tag("construction:polar")], Annotated[FrameSpec, Tag("construction:frame")],
          Annotated[CirclesSpec, Tag("construction:circles")],
          Annotated[CircleLineSpec, Tag("construction:circle-line")],
          Annotated[LinesSpec, Tag("construction:lines")]],
    Discriminator(_construction_kind, custom_error_type="construction_kind",
                  custom_error_message="a point is coordinates [x, y] or a construction with one of "
                                       "the keys from, frame, circles, circle, lines"),
]


_point_kind = ByType("_point_kind", {dict: "construction", list: "coordinates"})

PointSpec = Annotated[
    Union[Annotated[Vector, Tag("coordinates")], Annotated[ConstructionSpec, Tag("construction")]],
    Discriminator(_point_kind, custom_error_type="construction_kind",
                  custom_error_message="a point is coordinates [x, y] or a construction with one of "
                                       "the keys from, frame, circles, circle, lines"),
]


class CurveSpec(Strict):
    """A smooth curve fixed in the body through the given points (a cubic spline, closed or
    open): a curved slot, a cam known by points, a profile that slides on another."""

    through: Annotated[list[Location], Field(min_length=3, max_length=10_000)]
    closed: StrictBool = False


def _fields_of(spec: type[BaseModel], *names: str) -> dict[str, Any]:
    """Fields of another spec as `create_model` takes them: the same types, checks, defaults."""
    fields = spec.model_fields
    return {name: (fields[name].annotation, copy.copy(fields[name])) for name in names or fields}


# Three specs are made by `create_model` from fields known only at run time (another spec's, the
# registered kinds' and questions'). mypy cannot read such a class, so it reads the class each
# stands for, declared under TYPE_CHECKING with the same fields (checked at run time all the
# same: pydantic builds the real one).
if TYPE_CHECKING:
    from ..cams.spec import FollowerSpec, SegmentSpec

    class BodyCamSpec(CamSpec):
        """The cam on a body, as `create_model` makes it below."""

        center: Location
        angle: Value
        layout: Value
        follower: FollowerSpec
        program: Optional[list[SegmentSpec]]
        profile: Optional[list[list[Union[StrictInt, StrictFloat]]]]
else:
    BodyCamSpec = create_model(
        "BodyCamSpec", __base__=Strict, __module__=__name__,
        __doc__="""A cam's profile fixed in the body: its motion program (or measured profile) and
    follower as in a cam-design file (`kinematika.cams.spec`: the keys of its `cam:` and its
    `follower`, `program`, `profile`, with their checks), placed at `center`, turned by
    `angle` (the cam angle at this instant: where the program is) in the design frame, itself
    turned by `layout` in the model's axes (a translating follower rises along the frame's y
    axis).""",
        center=(Location, ...), angle=(Value, 0), layout=(Value, 0),
        **_fields_of(CamSpec), **_fields_of(CamFileSpec, "follower", "program", "profile"))


class BodySpec(Strict):
    """A body written in full: its points and at most the shapes it carries (circle, line, disc,
    plane, curve, cam), and a description; a bare list of points is the short form."""

    points: list[str] = Field(default_factory=list)
    circle: Optional[Union[CircleSpec, list[CircleSpec]]] = None    # a list: a stepped wheel's circles
    line: Optional[LineSpec] = None
    disc: Optional[DiscSpec] = None
    plane: Optional[PlaneSpec] = None
    curve: Optional[CurveSpec] = None
    cam: Optional[BodyCamSpec] = None
    description: Optional[str] = None


JointType = Literal[tuple(KINDS)]          # type: ignore[valid-type]  # a Literal of the registered kinds, made at run time: mypy reads only literal values

# What each key a kind of joint may declare in its `fields` holds. A joint's keys are those
# the registered kinds declare, in this order (the order errors are looked for in).
JOINT_KEY_TYPES: dict[str, Any] = {"at": str, "along": Vector, "axis": Vector, "internal": StrictBool}


def _joint_keys() -> tuple[str, ...]:
    declared = {key for kind in KINDS.values() for key in kind.fields}
    untyped = sorted(declared - set(JOINT_KEY_TYPES))
    if untyped:
        raise TypeError(f"joint keys {untyped} are declared by a kind of joint but have no type in "
                        "kinematika.model.schema.JOINT_KEY_TYPES")
    return tuple(key for key in JOINT_KEY_TYPES if key in declared)


JOINT_KEYS = _joint_keys()
if TYPE_CHECKING:
    class JointSpec(Strict):
        """A joint, as `create_model` makes it below: every key a kind may declare."""

        type: str
        bodies: list[str]
        id: Optional[str]
        at: Optional[str]
        along: Optional[Vector]
        axis: Optional[Vector]
        internal: Optional[bool]
        description: Optional[str]
else:
    JointSpec = create_model(
        "JointSpec", __base__=Strict, __module__=__name__,
        __doc__="A joint: its kind, its two bodies, its id, the keys its kinds declare, a description.",
        type=(JointType, ...), bodies=(Annotated[list[str], Field(min_length=2, max_length=2)], ...),
        id=(Optional[str], None), **{key: (Optional[JOINT_KEY_TYPES[key]], None) for key in JOINT_KEYS},
        description=(Optional[str], None))


class OmegaDriver(Strict):
    """`{omega: BODY, value, alpha}`: the body's angular velocity and acceleration (vectors in
    3D), optionally `relative_to` another body."""

    omega: str
    value: Union[Value, Vector]
    alpha: Union[Value, Vector] = 0
    relative_to: Optional[str] = None


class JointDriver(Strict):
    """`{joint: ID, rate, accel}`: the rate of change of a joint's coordinate (its angle or its
    slide) and its derivative."""

    joint: str
    rate: Value
    accel: Value = 0


class VelocityDriver(Strict):
    """`{velocity: POINT, value, acceleration}`: a material point's velocity and acceleration
    (vectors, or speeds `along` a direction), optionally `relative_to` another body."""

    velocity: str
    value: Union[Value, Vector]
    acceleration: Union[Value, Vector] = 0
    along: Optional[Vector] = None
    relative_to: Optional[str] = None


_driver_kind = FirstKey("_driver_kind", {key: key for key in ("omega", "joint", "velocity")})

DriverSpec = Annotated[
    Union[Annotated[OmegaDriver, Tag("omega")], Annotated[JointDriver, Tag("joint")],
          Annotated[VelocityDriver, Tag("velocity")]],
    Discriminator(_driver_kind, custom_error_type="driver_kind",
                  custom_error_message="a driver needs one of the keys omega, joint or velocity"),
]

if TYPE_CHECKING:
    class QuestionSpec(Strict):
        """One question, as `create_model` makes it below: a key per kind of question."""

        relative_to: Optional[str]
        moving: Optional[str]

        def __getattr__(self, kind: str) -> Optional[str]:
            ...
else:
    QuestionSpec = create_model(
        "QuestionSpec", __base__=Strict, __module__=__name__,
        __doc__="One question; exactly one of the question keys is set (checked in `build`).",
        **dict.fromkeys(QUESTIONS, (Optional[str], None)),
        relative_to=(Optional[str], None), moving=(Optional[str], None))


class SweepSpec(Strict):
    """`sweep`: the joint to advance (default: the first driven joint), by how much in all
    (default 360 degrees) and in how many steps (default 360)."""

    joint: Optional[str] = None
    by: Value = 360
    steps: StrictInt = 360


class SimulateSpec(Strict):
    """`simulate`: how long the motion is followed in time (seconds) and in how many equal
    steps of time (default 200); `kinematika simulate`'s --time and --steps override it."""

    time: Value
    steps: StrictInt = 200


class DimensionSpec(Strict):
    """A dimension drawn on an exercise's figure: the distance between two points, along x,
    along y or aligned with them (the default), labelled with a parameter or a text."""

    between: Annotated[list[str], Field(min_length=2, max_length=2)]
    along: Optional[Literal["x", "y", "aligned"]] = None
    label: Optional[str] = None


class ExerciseSpec(Strict):
    """`exercise`: what `kinematika exercise` states and grades (docs/exercises.md)."""

    title: dict[str, str] = Field(default_factory=dict)
    statement: dict[str, str] = Field(default_factory=dict)
    units: dict[str, str] = Field(default_factory=dict)
    length: str = "m"
    ask: Optional[list[StrictInt]] = None
    tolerance: Union[StrictInt, StrictFloat] = 0.01
    weights: Optional[list[Union[StrictInt, StrictFloat]]] = None
    dimensions: list[DimensionSpec] = Field(default_factory=list)
class LanguageNames(Strict):
    """How a model's things are called in one language (`names.LANG`): explanations and
    figures only (see `model.wording`)."""

    title: Optional[str] = None
    bodies: dict[str, str] = Field(default_factory=dict)
    points: dict[str, str] = Field(default_factory=dict)
    joints: dict[str, str] = Field(default_factory=dict)
    parameters: dict[str, str] = Field(default_factory=dict)
    data: list[str] = Field(default_factory=list)
    notes: list[str] = Field(default_factory=list)


class ModelSpec(Strict):
    """A model file as the contract writes it (docs/model-format.md): name and description,
    dimension (inferred when absent), the frame's name, parameters, points, bodies, joints,
    drivers, questions (`ask`), and the optional `sweep`, `simulate`, `move`, `draw_at`, `up` and `exercise`
    sections."""

    name: Optional[str] = None
    description: Optional[str] = None
    dimension: Optional[Literal[2, 3]] = None
    frame: str = "ground"
    parameters: dict[str, Union[Value, ParameterSpec, None]] = Field(default_factory=dict)
    points: dict[str, PointSpec]
    bodies: dict[str, Union[list[str], BodySpec]]
    joints: list[JointSpec] = Field(default_factory=list)
    drivers: list[DriverSpec] = Field(default_factory=list)
    ask: Optional[list[QuestionSpec]] = None
    sweep: Optional[SweepSpec] = None
    simulate: Optional[SimulateSpec] = None
    move: Optional[dict[str, Value]] = None
    draw_at: Optional[dict[str, Union[StrictInt, StrictFloat]]] = None   # figures: symbols' values
    up: Optional[list[Union[StrictInt, StrictFloat]]] = None             # figures: the vertical (3D)
    exercise: Optional[ExerciseSpec] = None                             # `kinematika exercise`
    names: Optional[dict[str, LanguageNames]] = None                     # words per language
    notation: Optional[dict[str, Union[str, dict[str, str]]]] = None     # how quantities are written
