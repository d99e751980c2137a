"""The cam-design file's shape (pydantic) and its translation into a cam, with one-line errors.

The same `CamSpec`, `FollowerSpec` and program (`list[SegmentSpec]`) are meant for the model
file's `cam:` shape and `cam` joint: everything about a cam's geometry and motion program is
checked here, once. Units: lengths in the file's unit (`units`, a label: mm by default),
angles in degrees (segment spans `over`; an oscillating follower's displacement `to`), speeds
in rad/s (`omega`) or rev/min (`rpm`); a translating cam's spans and speed are lengths and
length/s. Boundary conditions of a `polynomial` segment are derivatives of the displacement
with respect to the cam angle, per radian (d s/dθ, d²s/dθ², d³s/dθ³, in the displacement's
unit: length, or degrees for an oscillating follower); for a translating cam, per unit of travel.

A file (YAML, TOML or JSON)::

    title: Norton's double-dwell cam
    units: mm
    cam: {base: 40, rotation: ccw}              # disc cam, base circle R_b
    follower: {motion: translating, contact: roller, radius: 10, offset: 0}
    speed: {rpm: 60}
    program:
      - {law: dwell, over: 90}
      - {law: cycloidal, over: 90, to: 25}
      - {law: dwell, over: 90}
      - {law: 3-4-5, over: 90, to: 0}

or, for a cam known by points of its profile, `profile: [[x, y], …]` instead of `program`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any, Literal, Optional, Union

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, StrictFloat, StrictInt, ValidationError

from ..errors import KinematikaError, Num, Said, pydantic_choices, pydantic_problem, said_of
from ..text import brief
from . import laws as law_table
from .follower import Contact, Flat, Follower, Knife, Oscillating, Roller, Translating
from .profile import DiscCam, PlateCam
from .program import Program, Step, build

Number = Union[StrictInt, StrictFloat]
Positive = Annotated[Number, Field(gt=0)]
if TYPE_CHECKING:
    LawName = str       # a Literal built from the laws' table at run time: a type checker sees a name
else:
    LawName = Literal[tuple(law_table.names())]     # pydantic checks it is one of the table's


class Strict(BaseModel):
    """No unknown keys; a value's type as written (no '3' for 3)."""

    model_config = ConfigDict(extra="forbid")


class ConditionsSpec(Strict):
    """Derivatives of the displacement at one end of a polynomial segment, per radian of cam
    angle (or unit of travel): ds = ds/dθ, d2s = d²s/dθ², d3s = d³s/dθ³."""

    ds: Optional[Number] = None
    d2s: Optional[Number] = None
    d3s: Optional[Number] = None


class SegmentSpec(Strict):
    """One segment: a `law` over `over` (degrees, or travel), ending at displacement `to`
    (a dwell keeps the last one); a polynomial also takes `start`/`end` conditions."""

    law: LawName
    over: Positive
    to: Optional[Number] = None
    start: Optional[ConditionsSpec] = None
    end: Optional[ConditionsSpec] = None


class FollowerSpec(Strict):
    """The follower: how it moves, what touches the cam, and its dimensions."""

    motion: Literal["translating", "oscillating"] = "translating"
    contact: Literal["knife", "roller", "flat"] = "roller"
    radius: Optional[Positive] = None       # roller
    offset: Number = 0                      # translating: its axis is x = offset
    pivot: Optional[Positive] = None        # oscillating: the pivot's distance from the cam's centre
    arm: Optional[Positive] = None          # oscillating roller or knife: pivot to trace point
    face: Number = 0                        # oscillating flat face: moved towards the cam by this


class CamSpec(Strict):
    """The cam: a disc turning about its centre, or a plate translating along x."""

    kind: Literal["disc", "translating"] = "disc"
    base: Optional[Positive] = None         # base circle radius (disc), height at s = 0 (plate)
    rotation: Literal["ccw", "cw"] = "ccw"


class SpeedSpec(Strict):
    """The cam's constant speed: omega (rad/s) or rpm for a disc, velocity for a plate."""

    omega: Optional[Positive] = None
    rpm: Optional[Positive] = None
    velocity: Optional[Positive] = None


class CamFileSpec(Strict):
    """A cam-design file (`kinematika cam`)."""

    title: Optional[str] = None
    units: str = "mm"
    cam: CamSpec
    follower: FollowerSpec
    speed: SpeedSpec = SpeedSpec(omega=1.0)
    program: Optional[Annotated[list[SegmentSpec], Field(min_length=1, max_length=1000)]] = None
    profile: Optional[Annotated[list[Annotated[list[Number], Field(min_length=2, max_length=2)]],
                                Field(min_length=3, max_length=100_000)]] = None
    samples: Annotated[StrictInt, Field(ge=36, le=100_000)] = 720


@dataclass(frozen=True)
class CamDesign:
    """A checked cam-design file: the cam, its speed (rad/s, or length/s), and how to show it."""

    cam: DiscCam
    speed: float
    units: str
    samples: int
    title: str
    spec: CamFileSpec

    @property
    def angular(self) -> bool:
        """Whether the follower's displacement is an angle (oscillating)."""
        return self.cam.follower.angular

    @property
    def plate(self) -> bool:
        """Whether the cam translates."""
        return isinstance(self.cam, PlateCam)


# --- translation ----------------------------------------------------------------------------

def follower(spec: FollowerSpec, where: str = "follower") -> Follower:
    """The follower a spec describes (errors name `where`'s keys)."""
    contact = _contact(spec, where)
    if spec.motion == "translating":
        for key in ("pivot", "arm"):
            if getattr(spec, key) is not None:
                raise KinematikaError("schema", "cam-translating-no-key", f"{where}.{key}", key=key)
        return Translating(contact, float(spec.offset))
    if spec.offset:
        raise KinematikaError("schema", "cam-oscillating-no-offset", f"{where}.offset")
    if spec.pivot is None:
        raise KinematikaError("schema", "cam-oscillating-pivot", where)
    if spec.arm is None and not contact.touches_with_face:
        raise KinematikaError("schema", "cam-oscillating-arm", where)
    return Oscillating(contact, float(spec.pivot), float(spec.arm or spec.pivot))


def _contact(spec: FollowerSpec, where: str) -> Contact:
    if spec.contact == "roller":
        if spec.radius is None:
            raise KinematikaError("schema", "cam-roller-radius", where)
        return Roller(float(spec.radius))
    if spec.radius is not None:
        raise KinematikaError("schema", "cam-no-radius", f"{where}.radius", contact=spec.contact)
    if spec.contact == "flat":
        return Flat(float(spec.face))
    return Knife()


def program(segments: list[SegmentSpec], angular: bool, periodic: bool, where: str = "program") -> Program:
    """The motion program of a list of segments: spans in degrees (or travel); displacements in
    length, or degrees for an `angular` (oscillating) follower, made radians."""
    unit = math.pi / 180 if angular else 1.0
    span_unit = math.pi / 180 if periodic else 1.0
    steps: list[Step] = []
    s = 0.0
    for i, seg in enumerate(segments):
        place = f"{where}[{i}]"
        beta = float(seg.over) * span_unit
        if seg.law != "polynomial":
            for key in ("start", "end"):
                if getattr(seg, key) is not None:
                    raise KinematikaError("schema", "cam-polynomial-only", f"{place}.{key}", key=key)
        end = s if seg.to is None else float(seg.to) * unit
        if seg.law == "dwell":
            if seg.to is not None and abs(end - s) > 1e-12 * max(1.0, abs(s)):
                raise KinematikaError("schema", "cam-dwell-to", f"{place}.to")
            steps.append((law_table.DWELL, beta, 0.0, "dwell"))
            continue
        if seg.to is None:
            raise KinematikaError("schema", "cam-segment-to", place, law=seg.law)
        if end < -1e-12:
            raise KinematikaError("schema", "cam-below-lowest", f"{place}.to")
        rise = end - s
        if seg.law == "polynomial":
            steps.append(_polynomial(seg, beta, rise, unit, place))
        elif rise == 0:
            raise KinematikaError("schema", "cam-segment-still", f"{place}.to", law=seg.law)
        else:
            steps.append((law_table.law_named(seg.law), beta, rise, "rise" if rise > 0 else "return"))
        s = end
    built = build(steps, periodic)
    if periodic:
        total = sum(float(seg.over) for seg in segments)
        if abs(total - 360.0) > 1e-6:
            raise KinematikaError("schema", "cam-span", where, total=total)
        if abs(s) > 1e-9 * max([1.0] + [abs(st[2]) for st in steps]):
            raise KinematikaError("schema", "cam-program-ends", f"{where}[{len(segments) - 1}].to", end=s / unit)
    return built


def _polynomial(seg: SegmentSpec, beta: float, rise: float, unit: float, place: str) -> Step:
    """The polynomial through S(0) = 0, S(1) = rise/scale and the given derivatives made
    normalised: S⁽ᵏ⁾ = β^k·(d^k s/dθ^k)/scale (scale = rise, or 1 for a segment that returns to
    where it began)."""
    scale = rise if rise != 0 else 1.0
    ends: list[dict[int, float]] = [{0: 0.0}, {0: rise / scale}]
    for side, given in enumerate((seg.start, seg.end)):
        for k, key in enumerate(("ds", "d2s", "d3s"), start=1):
            value = getattr(given, key) if given is not None else None
            if value is not None:
                ends[side][k] = float(value) * unit * beta**k / scale
    try:
        law = law_table.Polynomial.through(ends[0], ends[1])
    except Exception:       # a singular system cannot happen for conditions at two ends
        raise KinematikaError("schema", "cam-no-polynomial", place) from None
    return (law, beta, rise, "polynomial", scale)


def design(spec: CamFileSpec) -> CamDesign:
    """The cam a checked file describes (geometry checked: the follower can touch the base
    circle, the arm stays clear of the line of centres, …)."""
    if (spec.program is None) == (spec.profile is None):
        raise KinematikaError("schema", "cam-program-or-profile")
    if spec.profile is not None:
        return measured_design(spec)
    if spec.cam.base is None:
        raise KinematikaError("schema", "cam-base-missing", "cam")
    plate = spec.cam.kind == "translating"
    moving = follower(spec.follower)
    motion = program(spec.program or [], moving.angular, not plate)
    speed = _speed(spec, plate)
    sense = 1 if spec.cam.rotation == "ccw" else -1
    check_layout(moving, float(spec.cam.base), motion, plate)
    kind = PlateCam if plate else DiscCam
    cam = kind(motion, moving, float(spec.cam.base), sense)
    return CamDesign(cam, speed, spec.units, spec.samples, spec.title or "", spec)


def measured_design(spec: CamFileSpec) -> CamDesign:
    """A `CamDesign` from a file with `profile:` points (the cam through them: `measured.measured_cam`)."""
    from .measured import measured_cam          # scipy.interpolate, for measured profiles only

    if spec.cam.kind != "disc":
        raise KinematikaError("schema", "cam-profile-disc", "cam.kind")
    if spec.cam.base is not None:
        raise KinematikaError("schema", "cam-profile-base", "cam.base")
    moving = follower(spec.follower)
    try:
        cam = measured_cam(np.array(spec.profile, dtype=float), moving, 1 if spec.cam.rotation == "ccw" else -1,
                           spec.samples)
    except ValueError as err:
        raise KinematikaError("geometry", said_of(err), "profile") from None
    return CamDesign(cam, _speed(spec, False), spec.units, spec.samples, spec.title or "", spec)


def _speed(spec: CamFileSpec, plate: bool) -> float:
    given = {k: v for k, v in spec.speed.model_dump().items() if v is not None}
    if len(given) != 1:
        raise KinematikaError("schema", "cam-speed-once", "speed")
    (key, value), = given.items()
    if plate != (key == "velocity"):
        raise KinematikaError("schema", "cam-speed-translating" if plate else "cam-speed-disc", f"speed.{key}")
    return float(value) * (2 * math.pi / 60 if key == "rpm" else 1.0)


def check_layout(moving: Follower, base: float, motion: Program | None, plate: bool) -> None:
    """The follower's dimensions fit the cam (one-line errors naming the follower's key)."""
    if plate:
        if not isinstance(moving, Translating):
            raise KinematikaError("schema", "cam-plate-translating", "follower.motion")
        if moving.contact.touches_with_face:
            raise KinematikaError("schema", "cam-plate-flat", "follower.contact")
        if moving.offset:
            raise KinematikaError("schema", "cam-plate-offset", "follower.offset")
        return
    rp = moving.prime(base)
    if isinstance(moving, Translating):
        if abs(moving.offset) >= rp:
            raise KinematikaError("schema", "cam-offset-prime", "follower.offset", offset=float(moving.offset),
                                  radius=float(rp))
        return
    a, l = moving.pivot, moving.arm
    if isinstance(moving.contact, Flat):
        if base + moving.contact.face >= a or base + moving.contact.face <= 0:
            raise KinematikaError("schema", "cam-face-base", "follower.pivot")
    elif not abs(a - l) < rp < a + l:
        raise KinematikaError("schema", "cam-arm-reach", "follower.arm", radius=float(rp))
    if motion is not None:
        top = float(np.max(motion.motion(np.linspace(0, motion.period, 2001))[0]))
        reach = math.pi / 2 if moving.contact.touches_with_face else math.pi
        if moving.start(base) + top >= reach:
            raise KinematikaError("schema", "cam-arm-past", "program", turn=math.degrees(top),
                                  start=Num(math.degrees(moving.start(base)), ".4g"), reach=math.degrees(reach))


# --- reading --------------------------------------------------------------------------------

def parse(tree: Any) -> CamFileSpec:
    """A file's tree checked; a schema error names the place (`program[2].over`)."""
    if not isinstance(tree, dict):
        raise KinematikaError("schema", "cam-file-mapping")
    try:
        return CamFileSpec.model_validate(tree)
    except ValidationError as err:
        raise _schema_error(err) from None


def _schema_error(err: ValidationError) -> KinematikaError:
    order = {"extra_forbidden": 0, "missing": 1, "literal_error": 2}
    first = min(err.errors(), key=lambda e: (order.get(e["type"], 5), len(e["loc"])))
    where = ""
    for part in first["loc"]:
        if isinstance(part, int):
            where += f"[{part}]"
        elif not any(c in str(part) for c in "[]") and part not in ("int", "float", "str"):
            where += ("." if where else "") + str(part)
    kind, last = first["type"], (first["loc"][-1] if first["loc"] else "")
    if kind == "extra_forbidden":
        message = Said("unknown-key", key=last)
    elif kind == "missing":
        message = Said("missing-key", key=last)
    elif kind == "literal_error":
        message = Said("not-one-of", value=brief(first['input']), expected=pydantic_choices(first['ctx']['expected']))
    else:
        message = Said("value-problem", value=brief(first.get('input')), problem=pydantic_problem(first, lower=True))
    return KinematikaError("schema", message, where)
