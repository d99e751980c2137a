"""What a joint kind receives from the rest of kinematika: the seam between `joints` and the
engine, the sweeps, the figures and the builder, written as `Protocol`s.

A kind's hooks (`JointKind.prepare`, `rows`, `residual`, `rate`, `symbol`, `add`, …) are
given these objects and only call the members listed here; the classes that fill them live
in the layers above (`engine.instant.Instant`, `engine.levels.Level`, `engine.motion.Motion`,
`sweep.poses.Poses`, `model.model.Joint`, `draw.scene.JointView`, `draw.context.Context`,
`model.builder.Mechanism`) and are checked against them by mypy where they are passed in.
So a joint module imports nothing of the engine (as sympy's `Joint` is given its frames
and pinocchio's joint models their data), and what a new kind may ask of the engine is
this page.

Values are `Scalar`s: a float, a sympy expression (symbolic models), a linear form of the
unknowns (`algebra.linear.Lin`, in the rows) or an array over many designs (compiled
sweeps) — the same formulas serve all four, so they stay untyped by name (`Scalar`,
`Vector`), never by `Any` at the seam.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any, ClassVar, Optional, Protocol

import numpy as np

from ..algebra.vectors import Space
from ..expressions import Direction

Scalar = Any
"""A number, a sympy expression, a linear form of the unknowns or an array over designs."""
Vector = tuple
"""A point or direction: a tuple of `Scalar`s (2 or 3), or a numpy array of floats."""


class Backend(Protocol):
    """The instant's arithmetic: floats, or sympy for a symbolic model."""

    @property
    def symbolic(self) -> bool: ...

    def sqrt(self, x: Scalar) -> Scalar: ...

    def simplify(self, x: Scalar) -> Scalar: ...


class ModelJoint(Protocol):
    """A joint as the model holds it (`model.model.Joint`): its bodies `a` and `b`, its point
    `at` (a point's name), its directions `along` and `axis` as written, `internal` (circles
    inside circles), its kind's name (`type`) and where it is written (`where`, for errors)."""

    __dataclass_fields__: ClassVar[dict[str, Any]]   # a dataclass: `dataclasses.replace` makes a variant

    @property
    def id(self) -> str: ...
    @property
    def type(self) -> str: ...
    @property
    def a(self) -> str: ...
    @property
    def b(self) -> str: ...
    @property
    def at(self) -> Optional[str]: ...
    @property
    def along(self) -> Optional[Direction]: ...
    @property
    def axis(self) -> Optional[Direction]: ...
    @property
    def internal(self) -> Optional[bool]: ...
    @property
    def where(self) -> str: ...


class Instant(Protocol):
    """The model evaluated at one instant (`engine.instant.Instant`): its points and shapes,
    its arithmetic and its space, its scale (a characteristic length), where twists are
    taken (`ref`), and its directions made unit."""

    @property
    def backend(self) -> Backend: ...
    @property
    def space(self) -> Space: ...
    @property
    def points(self) -> Mapping[str, tuple]: ...
    @property
    def shapes(self) -> Mapping[str, list]: ...
    @property
    def scale(self) -> float: ...
    @property
    def ref(self) -> tuple: ...
    @property
    def symbolic(self) -> bool: ...

    def num(self, x: Scalar) -> float:
        """A scalar as a float (a symbolic one at the probe values)."""
        ...

    def numvec(self, v: tuple) -> tuple:
        """A vector as floats."""
        ...

    def direction(self, d: Direction, where: str) -> tuple:
        """A direction as written, made unit (a `geometry` error at `where` when zero)."""
        ...

    def body_direction(self, body: str, d: Direction, where: str) -> tuple:
        """A direction fixed in `body`, made unit (turned with the body in a sweep)."""
        ...


class BodyState(Protocol):
    """A body's solved ω and α (`engine.motion.BodyState`)."""

    @property
    def omega(self) -> Scalar: ...
    @property
    def alpha(self) -> Scalar: ...


class Motion(Protocol):
    """The bodies' solved motion (`engine.motion.Motion`): their states and the motion of
    their material points."""

    @property
    def space(self) -> Space: ...
    @property
    def states(self) -> Mapping[str, BodyState]: ...

    def point_velocity(self, body: str, p: tuple) -> tuple: ...

    def point_acceleration(self, body: str, p: tuple) -> tuple: ...


class Terms(Protocol):
    """The factors of the velocity-squared terms (`engine.terms.Terms`): mechanics' own, or a
    student's mistake modelled by a view."""

    def coriolis_factor(self) -> float: ...


class Level(Protocol):
    """The velocity or acceleration level a joint's rows are written at (`engine.levels`):
    `point` and `omega` the motion of a material point and a body's ω (α) as linear forms of
    the unknowns; at the acceleration level (`accel`) the solved velocities `w`, `v` for the
    centripetal and Coriolis terms, and the `motion` they come from."""

    @property
    def accel(self) -> bool: ...
    @property
    def space(self) -> Space: ...
    @property
    def ref(self) -> tuple: ...
    @property
    def motion(self) -> Optional[Motion]: ...
    @property
    def terms(self) -> Terms: ...

    def point(self, body: str, p: tuple) -> tuple: ...

    def omega(self, body: str) -> Scalar: ...

    def w(self, body: str) -> Scalar: ...

    def v(self, body: str, p: tuple) -> tuple: ...


class Pose(Protocol):
    """Where a sweep has moved the bodies (`sweep.poses.Poses`, `SpatialPoses`): the drawn
    point P carried by a body, a drawn
    direction turned with it, its rotation from the drawing, and the values a sweep
    remembers between steps (`aux`: continued angles, a contact's parameter)."""

    @property
    def aux(self) -> dict: ...

    def point(self, body: str, p0: tuple) -> tuple: ...

    def turn(self, body: str, vec: tuple) -> tuple: ...

    def angle(self, body: str) -> Scalar: ...

    def rotation_error(self, a: Optional[str], b: str) -> list:
        """b's rotation relative to a (its rows, one in the plane, three in space)."""
        ...

    def axis_angle_error(self, a: str, b: str, axis: Optional[tuple], target: float) -> Scalar: ...


class JointView(Protocol):
    """A joint on the page (`draw.scene.JointView`): its place, directions (unit), the page
    image of a 3D axis, a slot's two ends, the contact, a follower's roller radius."""

    @property
    def id(self) -> str: ...
    @property
    def a(self) -> str: ...
    @property
    def b(self) -> str: ...
    @property
    def at(self) -> Optional[np.ndarray]: ...
    @property
    def along(self) -> Optional[np.ndarray]: ...
    @property
    def axis(self) -> Optional[np.ndarray]: ...
    @property
    def span(self) -> Optional[tuple[np.ndarray, np.ndarray]]: ...
    @property
    def contact(self) -> Optional[np.ndarray]: ...
    @property
    def radius(self) -> float: ...


class DrawContext(Protocol):
    """What a symbol asks of its figure (`draw.context.Context`; see `joints.symbols`)."""

    @property
    def size(self) -> float: ...
    @property
    def frame(self) -> str: ...
    @property
    def still(self) -> bool: ...
    @property
    def dim(self) -> int: ...

    def centroid(self) -> np.ndarray: ...

    def points(self, body: str) -> list: ...

    def clip(self, p: np.ndarray, d: np.ndarray, inset: float) -> Optional[tuple]: ...

    def keep_out(self) -> list: ...


class Mechanism(Protocol):
    """The Python builder (`model.builder.Mechanism`): a joint of any kind added by name."""

    def joint(self, type: str, a: str, b: str, id: Optional[str] = None, **fields: Any) -> str: ...


__all__ = ["Backend", "BodyState", "DrawContext", "Instant", "JointView", "Level", "Mechanism", "ModelJoint",
           "Motion", "Pose", "Scalar", "Terms", "Vector"]
