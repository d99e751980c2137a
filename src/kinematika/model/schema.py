"""The shape of a model file (the contract's model format), checked by pydantic.

This module only says which keys exist and what type each value has. Names are resolved
and expressions parsed afterwards, in `build`, which turns a checked file into a `Model`.
"""
from __future__ import annotations

from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Discriminator, Field, StrictBool, StrictFloat, StrictInt, Tag

from ..cams.spec import FollowerSpec, SegmentSpec
from ..joints import KINDS

Value = Union[StrictInt, StrictFloat, str]
Vector = list[Value]


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)


class ParameterSpec(Strict):
    value: Optional[Value] = None
    positive: StrictBool = True
    symbolic: StrictBool = False   # TOML has no null: `{symbolic = true}` keeps it a symbol
    description: Optional[str] = None


class CircleSpec(Strict):
    center: Union[str, Vector]
    radius: Value


class LineSpec(Strict):
    through: Union[str, Vector]
    direction: Vector


class DiscSpec(Strict):
    center: Union[str, Vector]
    radius: Value
    axis: Vector


class PlaneSpec(Strict):
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


CONSTRUCTION_KEYS = {"from": "polar", "frame": "frame", "circles": "circles", "circle": "circle-line",
                     "lines": "lines"}


def _construction_kind(data: Any) -> str | None:
    if isinstance(data, dict):
        for key, kind in CONSTRUCTION_KEYS.items():
            if key in data:
                return f"construction:{kind}"
    return None


ConstructionSpec = Annotated[
    Union[Annotated[PolarSpec, Tag("construction:polar")], Annotated[FrameSpec, Tag("construction:frame")],
          Annotated[CirclesSpec, Tag("construction:circles")],
          Annotated[CircleLineSpec, Tag("construction:circle-line")],
          Annotated[LinesSpec, Tag("construction:lines")]],
    Discriminator(_construction_kind, custom_error_type="construction_kind",
                  custom_error_message="a point is coordinates [x, y] or a construction with one of "
                                       "the keys from, frame, circles, circle, lines"),
]


def _point_kind(data: Any) -> str | None:
    if isinstance(data, dict):
        return "construction"
    return "coordinates" if isinstance(data, list) else None


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


class BodyCamSpec(Strict):
    """A cam's profile fixed in the body: its motion program (or measured profile) and follower
    as in a cam-design file (`kinematika.cams.spec`), placed at `center`, turned by `angle`
    (the cam angle at this instant: where the program is) in the design frame, itself turned
    by `layout` in the model's axes (a translating follower rises along the frame's y axis)."""

    center: Location
    angle: Value = 0
    layout: Value = 0
    kind: Literal["disc", "translating"] = "disc"
    base: Optional[Union[StrictInt, StrictFloat]] = None
    rotation: Literal["ccw", "cw"] = "ccw"
    follower: FollowerSpec
    program: Optional[Annotated[list[SegmentSpec], Field(min_length=1, max_length=1000)]] = None
    profile: Optional[Annotated[list[Annotated[list[Union[StrictInt, StrictFloat]], Field(min_length=2, max_length=2)]],
                                Field(min_length=3, max_length=100_000)]] = None


class BodySpec(Strict):
    points: list[str] = Field(default_factory=list)
    circle: Optional[CircleSpec] = None
    line: Optional[LineSpec] = None
    disc: Optional[DiscSpec] = None
    plane: Optional[PlaneSpec] = None
    curve: Optional[CurveSpec] = None
    cam: Optional[BodyCamSpec] = None
    description: Optional[str] = None


JointType = Literal[tuple(KINDS)]          # type: ignore[valid-type]  # the registered kinds


class JointSpec(Strict):
    type: JointType
    bodies: Annotated[list[str], Field(min_length=2, max_length=2)]
    id: Optional[str] = None
    at: Optional[str] = None
    along: Optional[Vector] = None
    axis: Optional[Vector] = None
    internal: Optional[StrictBool] = None
    description: Optional[str] = None


class OmegaDriver(Strict):
    omega: str
    value: Union[Value, Vector]
    alpha: Union[Value, Vector] = 0
    relative_to: Optional[str] = None


class JointDriver(Strict):
    joint: str
    rate: Value
    accel: Value = 0


class VelocityDriver(Strict):
    velocity: str
    value: Union[Value, Vector]
    acceleration: Union[Value, Vector] = 0
    along: Optional[Vector] = None
    relative_to: Optional[str] = None


def _driver_kind(data: Any) -> str | None:
    if isinstance(data, dict):
        for key in ("omega", "joint", "velocity"):
            if key in data:
                return key
    return None


DriverSpec = Annotated[
    Union[Annotated[OmegaDriver, Tag("omega")], Annotated[JointDriver, Tag("joint")],
          Annotated[VelocityDriver, Tag("velocity")]],
    Discriminator(_driver_kind, custom_error_type="driver_kind",
                  custom_error_message="a driver needs one of the keys omega, joint or velocity"),
]

QUESTION_KINDS = ("velocity", "acceleration", "omega", "alpha", "icr", "curvature", "decompose",
                  "contact", "axis", "pole", "intrinsic")


class QuestionSpec(Strict):
    """One question; exactly one of the question keys is set (checked in `build`)."""

    velocity: Optional[str] = None
    acceleration: Optional[str] = None
    omega: Optional[str] = None
    alpha: Optional[str] = None
    icr: Optional[str] = None
    curvature: Optional[str] = None
    decompose: Optional[str] = None
    contact: Optional[str] = None
    axis: Optional[str] = None
    pole: Optional[str] = None
    intrinsic: Optional[str] = None
    relative_to: Optional[str] = None
    moving: Optional[str] = None


class SweepSpec(Strict):
    joint: Optional[str] = None
    by: Value = 360
    steps: StrictInt = 360


class ModelSpec(Strict):
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
    move: Optional[dict[str, Value]] = None
    draw_at: Optional[dict[str, Union[StrictInt, StrictFloat]]] = None   # figures: symbols' values
    up: Optional[list[Union[StrictInt, StrictFloat]]] = None             # figures: the vertical (3D)
