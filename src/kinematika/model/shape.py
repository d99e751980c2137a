"""The model file's shape checked in plain Python, for the files that are right.

`schema` (pydantic) says what a model file may hold; building its validators costs more
than reading, checking and solving a small model. `spec_of` checks a tree against the same
rules with plain type tests and returns records with the same fields and defaults as
`schema`'s classes. It accepts only what it is sure pydantic accepts unchanged (exact
types, known keys); for anything else it returns None and `build` lets pydantic check the
tree, so that every error message comes from one place. Tests compare both on the examples
and on random trees, and the field tables with `schema`'s.
"""
from __future__ import annotations

from typing import Any, Callable, Optional

from ..joints import KINDS

QUESTION_KINDS = ("velocity", "acceleration", "omega", "alpha", "icr", "curvature", "decompose",
                  "contact", "axis", "pole", "intrinsic")
JOINT_TYPES = tuple(KINDS)

Check = Callable[[Any], Any]       # returns the checked value, or raises _Refused


class _Refused(Exception):
    """Not certainly valid: pydantic decides."""


class Record:
    """A checked section of a model file: its fields as attributes (as `schema`'s classes)."""

    FIELDS: tuple[str, ...] = ()

    def __init__(self, **fields: Any) -> None:
        self.__dict__.update(fields)

    def model_dump(self, exclude_none: bool = False) -> dict[str, Any]:
        """The fields in `schema`'s order (as pydantic's `model_dump`)."""
        return {k: getattr(self, k) for k in self.FIELDS
                if not (exclude_none and getattr(self, k) is None)}


# plain values -------------------------------------------------------------------------------
def exact(*types: type) -> Check:
    """A value of exactly one of `types` (never a subclass: a bool is not an int here)."""
    def check(x: Any) -> Any:
        if type(x) in types:
            return x
        raise _Refused
    return check


value = exact(int, float, str)      # a number or an expression (StrictInt, StrictFloat or str)
text = exact(str)
flag = exact(bool)
integer = exact(int)
real = exact(int, float)            # a number (StrictInt or StrictFloat: not an expression)


def vector(x: Any) -> list:
    if type(x) is list:
        return [value(v) for v in x]
    raise _Refused


def texts(x: Any) -> list:
    if type(x) is list:
        return [text(v) for v in x]
    raise _Refused


def either(*checks: Check) -> Check:
    def check(x: Any) -> Any:
        for c in checks:
            try:
                return c(x)
            except _Refused:
                continue
        raise _Refused
    return check


def optional(check: Check) -> Check:
    return lambda x: None if x is None else check(x)


def listed(check: Check) -> Check:
    def check_all(x: Any) -> list:
        if type(x) is not list:
            raise _Refused
        return [check(v) for v in x]
    return check_all


def mapping(check: Check) -> Check:
    def check_all(x: Any) -> dict:
        if type(x) is not dict:
            raise _Refused
        return {text(k): check(v) for k, v in x.items()}
    return check_all


def record(name: str, fields: dict[str, tuple[Check, Any]],
           keys: Optional[dict[str, str]] = None) -> tuple[type, Check]:
    """A record class and its check; a field's default is `REQUIRED`, a value or a factory.
    `keys` gives the file's key of a field whose name differs (`from` for `from_`)."""
    cls = type(name, (Record,), {"FIELDS": tuple(fields),
                                 "DEFAULTS": {k: d for k, (_, d) in fields.items()}})
    in_file = {(keys or {}).get(f, f): f for f in fields}

    def check(x: Any) -> Record:
        if type(x) is not dict or not all(k in in_file for k in x):
            raise _Refused
        out = {}
        for key, field in in_file.items():
            check_field, default = fields[field]
            if key in x:
                out[field] = check_field(x[key])
            elif default is REQUIRED:
                raise _Refused
            else:
                out[field] = default() if callable(default) else default
        return cls(**out)
    return cls, check


def sized(check: Check, n: int) -> Check:
    """A list of exactly `n` items, each checked."""
    def check_all(x: Any) -> list:
        if type(x) is not list or len(x) != n:
            raise _Refused
        return [check(v) for v in x]
    return check_all


def one_of(*choices: str) -> Check:
    def check(x: Any) -> str:
        if type(x) is str and x in choices:
            return x
        raise _Refused
    return check


REQUIRED = object()
center_or_point = either(text, vector)
value_or_vector = either(value, vector)

ParameterSpec, parameter = record("ParameterSpec", {
    "value": (optional(value), None), "positive": (flag, True), "symbolic": (flag, False),
    "description": (optional(text), None)})
CircleSpec, circle = record("CircleSpec", {"center": (center_or_point, REQUIRED),
                                           "radius": (value, REQUIRED)})
LineSpec, line = record("LineSpec", {"through": (center_or_point, REQUIRED),
                                     "direction": (vector, REQUIRED)})
DiscSpec, disc = record("DiscSpec", {"center": (center_or_point, REQUIRED), "radius": (value, REQUIRED),
                                     "axis": (vector, REQUIRED)})
PlaneSpec, plane = record("PlaneSpec", {"through": (center_or_point, REQUIRED),
                                        "normal": (vector, REQUIRED)})

# points by construction (planar), as `schema`'s specs --------------------------------------
location = either(text, vector)                 # a point's name, or coordinates
PolarSpec, polar = record("PolarSpec", {
    "from_": (location, REQUIRED), "distance": (value, REQUIRED), "angle": (value, REQUIRED),
    "reference": (optional(sized(location, 2)), None)}, keys={"from_": "from"})
FrameSpec, frame = record("FrameSpec", {"frame": (sized(location, 2), REQUIRED),
                                        "at": (sized(value, 2), REQUIRED)})
circle_ref = sized(either(text, vector, real), 2)
line_ref = either(sized(location, 2), line)
CirclesSpec, circles = record("CirclesSpec", {
    "circles": (sized(circle_ref, 2), REQUIRED), "side": (optional(one_of("left", "right")), None),
    "near": (optional(vector), None)})
CircleLineSpec, circle_line = record("CircleLineSpec", {
    "circle": (circle_ref, REQUIRED), "line": (line_ref, REQUIRED),
    "side": (optional(one_of("ahead", "behind")), None), "near": (optional(vector), None)})
LinesSpec, lines = record("LinesSpec", {"lines": (sized(line_ref, 2), REQUIRED)})
CONSTRUCTIONS = (("from", polar), ("frame", frame), ("circles", circles), ("circle", circle_line),
                 ("lines", lines))


def point(x: Any) -> Any:
    """Coordinates, or a construction told by its first key of `CONSTRUCTIONS` (as `schema`)."""
    if type(x) is dict:
        for key, check in CONSTRUCTIONS:
            if key in x:
                return check(x)
        raise _Refused
    return vector(x)


def pydantic_decides(x: Any) -> Any:
    """A section only `schema` checks (curves and cams: their errors come from one place)."""
    raise _Refused


BodySpec, body = record("BodySpec", {
    "points": (texts, list), "circle": (optional(circle), None), "line": (optional(line), None),
    "disc": (optional(disc), None), "plane": (optional(plane), None),
    "curve": (optional(pydantic_decides), None), "cam": (optional(pydantic_decides), None),
    "description": (optional(text), None)})


def joint_type(x: Any) -> str:
    if type(x) is str and x in JOINT_TYPES:
        return x
    raise _Refused


def two_names(x: Any) -> list:
    names = texts(x)
    if len(names) != 2:
        raise _Refused
    return names


JointSpec, joint = record("JointSpec", {
    "type": (joint_type, REQUIRED), "bodies": (two_names, REQUIRED), "id": (optional(text), None),
    "at": (optional(text), None), "along": (optional(vector), None), "axis": (optional(vector), None),
    "internal": (optional(flag), None), "description": (optional(text), None)})
OmegaDriver, omega_driver = record("OmegaDriver", {
    "omega": (text, REQUIRED), "value": (value_or_vector, REQUIRED), "alpha": (value_or_vector, 0),
    "relative_to": (optional(text), None)})
JointDriver, joint_driver = record("JointDriver", {
    "joint": (text, REQUIRED), "rate": (value, REQUIRED), "accel": (value, 0)})
VelocityDriver, velocity_driver = record("VelocityDriver", {
    "velocity": (text, REQUIRED), "value": (value_or_vector, REQUIRED),
    "acceleration": (value_or_vector, 0), "along": (optional(vector), None),
    "relative_to": (optional(text), None)})


def driver(x: Any) -> Record:
    """The driver kind is its first key of omega, joint, velocity (as `schema._driver_kind`)."""
    if type(x) is dict:
        for key, check in (("omega", omega_driver), ("joint", joint_driver),
                           ("velocity", velocity_driver)):
            if key in x:
                return check(x)
    raise _Refused


QuestionSpec, question = record("QuestionSpec", {
    **{kind: (optional(text), None) for kind in QUESTION_KINDS},
    "relative_to": (optional(text), None), "moving": (optional(text), None)})
SweepSpec, sweep = record("SweepSpec", {"joint": (optional(text), None), "by": (value, 360),
                                        "steps": (integer, 360)})


def dimension(x: Any) -> int:
    if type(x) is int and x in (2, 3):
        return x
    raise _Refused


ModelSpec, model = record("ModelSpec", {
    "name": (optional(text), None), "description": (optional(text), None),
    "dimension": (optional(dimension), None), "frame": (text, "ground"),
    "parameters": (mapping(either(value, lambda x: None if x is None else parameter(x))), dict),
    "points": (mapping(point), REQUIRED),
    "bodies": (mapping(either(texts, body)), REQUIRED),
    "joints": (listed(joint), list), "drivers": (listed(driver), list),
    "ask": (optional(listed(question)), None), "sweep": (optional(sweep), None),
    "move": (optional(mapping(value)), None),
    "draw_at": (optional(mapping(real)), None), "up": (optional(listed(real)), None)})

RECORDS = (ParameterSpec, CircleSpec, LineSpec, DiscSpec, PlaneSpec, PolarSpec, FrameSpec, CirclesSpec,
           CircleLineSpec, LinesSpec, BodySpec, JointSpec, OmegaDriver, JointDriver, VelocityDriver,
           QuestionSpec, SweepSpec, ModelSpec)


def spec_of(tree: Any) -> Optional[Record]:
    """The checked model file, or None when pydantic must look at it (it may be wrong)."""
    try:
        return model(tree)
    except _Refused:
        return None
    except RecursionError:
        return None
