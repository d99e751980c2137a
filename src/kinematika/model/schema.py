"""The shape of a model file (the contract's model format), checked by pydantic.

This module only says which keys exist and what type each value has. Names are resolved
and expressions parsed afterwards, in `build`, which turns a checked file into a `Model`.
"""
from __future__ import annotations

from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Discriminator, Field, StrictBool, StrictFloat, StrictInt, Tag

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


class BodySpec(Strict):
    points: list[str] = Field(default_factory=list)
    circle: Optional[CircleSpec] = None
    line: Optional[LineSpec] = None
    disc: Optional[DiscSpec] = None
    plane: Optional[PlaneSpec] = None
    description: Optional[str] = None


JointType = Literal["revolute", "prismatic", "slot", "wheel", "rolling", "gear", "spherical",
                    "weld", "cylindrical"]


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
    parameters: dict[str, Union[Value, None, ParameterSpec]] = Field(default_factory=dict)
    points: dict[str, Vector]
    bodies: dict[str, Union[list[str], BodySpec]]
    joints: list[JointSpec] = Field(default_factory=list)
    drivers: list[DriverSpec] = Field(default_factory=list)
    ask: Optional[list[QuestionSpec]] = None
    sweep: Optional[SweepSpec] = None
