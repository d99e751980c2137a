"""What a joint kind receives from the rest of kinematika: the seam between `joints` and the
engine, the sweeps, the figures and the builder, written as `Protocol`s.

A kind's hooks (`JointKind.prepare`, `rows`, `residual`, `rate`, `symbol`, `add`, …) are
given these objects and only call the members listed here; the classes that fill them live
in the layers above (`engine.instant.Instant`, `engine.levels.Level`, `engine.motion.Motion`,
`sweep.poses.Poses`, `draw.scene.JointView`, `draw.context.Context`,
`model.builder.Mechanism`) and are checked against them by mypy (tests/joints/seam_types.py).
The joint itself, as the model holds it, is `base.ModelJoint` (beside `JointKind`, which it
names).
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
from typing import Any, Optional, Protocol

import numpy as np

from ..algebra.vectors import Space
from ..expressions import Direction

Scalar = Any
"""A number, a sympy expression, a linear form of the unknowns or an array over designs."""
Vector = tuple
"""A point or direction: a tuple of `Scalar`s (2 or 3), or a numpy array of floats."""


class Backend(Protocol):
    """The instant's arithmetic: floats, or sympy for a symbolic model."""

    symbolic: bool

    def sqrt(self, x: Scalar) -> Scalar:
        """√x, exactly in a symbolic model."""
        ...

    def simplify(self, x: Scalar) -> Scalar:
        """x in its simplest form (a symbolic model's; a number as it is)."""
        ...


class Instant(Protocol):
    """The model evaluated at one instant (`engine.instant.Instant`): its points and shapes,
    its arithmetic and its space, its scale (a characteristic length), where twists are
    taken (`ref`), and its directions made unit."""

    backend: Backend
    space: Space
    points: dict[str, tuple]
    shapes: dict[str, list]
    scale: float
    ref: tuple

    @property
    def symbolic(self) -> bool:
        """Whether its values are formulas (sympy), not numbers."""
        ...

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
    def omega(self) -> Scalar:
        """ω: a number in the plane, a vector in space."""
        ...

    @property
    def alpha(self) -> Scalar:
        """α, likewise."""
        ...


class Motion(Protocol):
    """The bodies' solved motion (`engine.motion.Motion`): their states and the motion of
    their material points."""

    space: Space

    @property
    def states(self) -> Mapping[str, BodyState]:
        """Each moving body's state (the frame has none)."""
        ...

    def point_velocity(self, body: str, p: tuple) -> tuple:
        """The velocity of `body`'s material point at `p`."""
        ...

    def point_acceleration(self, body: str, p: tuple) -> tuple:
        """The acceleration of `body`'s material point at `p`."""
        ...


class Terms(Protocol):
    """The factors of the velocity-squared terms (`engine.terms.Terms`): mechanics' own, or a
    student's mistake modelled by a view."""

    def coriolis_factor(self) -> float:
        """The factor of the Coriolis term 2 ω × v_rel (1: mechanics)."""
        ...

    def normal_part(self, vector: Any) -> Any:
        """n · ω × (ω × r), given ω × (ω × r) (a tuple of numbers or of arrays; n = 1: mechanics)."""
        ...


class Level(Protocol):
    """The velocity or acceleration level a joint's rows are written at (`engine.levels`):
    `point` and `omega` the motion of a material point and a body's ω (α) as linear forms of
    the unknowns; at the acceleration level (`accel`) the solved velocities `w`, `v` for the
    centripetal and Coriolis terms, and the `motion` they come from."""

    accel: bool
    space: Space
    ref: tuple

    @property
    def motion(self) -> Optional[Motion]:
        """The solved velocities (at the acceleration level)."""
        ...

    @property
    def terms(self) -> Terms:
        """The velocity-squared terms' factors."""
        ...

    def point(self, body: str, p: tuple) -> tuple:
        """The velocity (acceleration) of `body`'s material point at `p`, as linear forms."""
        ...

    def omega(self, body: str) -> Scalar:
        """ω (α) of `body`, as linear forms."""
        ...

    def column(self, body: str) -> Optional[int]:
        """The first column of `body`'s unknowns (its ω; v₀ follows), None for the frame."""
        ...

    def w(self, body: str) -> Scalar:
        """The solved ω of `body`, for the acceleration level's terms."""
        ...

    def v(self, body: str, p: tuple) -> tuple:
        """The solved velocity of `body`'s material point at `p`, likewise."""
        ...


class Pose(Protocol):
    """Where a sweep has moved the bodies (`sweep.poses.Poses`, `SpatialPoses`): the drawn
    point P carried by a body, a drawn direction turned with it, its rotation from the
    drawing, and the values a sweep remembers between steps (`aux`: continued angles, a
    contact's parameter)."""

    aux: dict

    def point(self, body: str, p0: tuple) -> tuple:
        """The material point of `body` drawn at `p0`, now."""
        ...

    def turn(self, body: str, vec: tuple) -> tuple:
        """A direction fixed in `body`, drawn as `vec`, now."""
        ...

    def angle(self, body: str) -> Scalar:
        """`body`'s rotation from its drawn pose (an angle; a rotation vector in space)."""
        ...

    def rotation_error(self, a: Optional[str], b: str) -> list:
        """b's rotation relative to a (its rows, one in the plane, three in space)."""
        ...

    def axis_angle_error(self, a: str, b: str, axis: Optional[tuple], target: float) -> Scalar:
        """b's rotation relative to a about `axis` (fixed in a; None in the plane), less `target`."""
        ...


class JointView(Protocol):
    """A joint on the page (`draw.scene.JointView`): its place, directions (unit), the page
    image of a 3D axis, a slot's two ends, the contact, a follower's roller radius."""

    id: str
    a: str
    b: str
    at: Optional[np.ndarray]
    along: Optional[np.ndarray]
    axis: Optional[np.ndarray]
    span: Optional[tuple[np.ndarray, np.ndarray]]
    contact: Optional[np.ndarray]
    radius: float


class DrawContext(Protocol):
    """What a symbol asks of its figure (`draw.context.Context`; see `joints.symbols`)."""

    size: float
    frame: str
    still: bool
    dim: int

    def centroid(self) -> np.ndarray:
        """The centroid of the moving bodies' points: "away from the mechanism"."""
        ...

    def points(self, body: str) -> list:
        """`body`'s points on the page."""
        ...

    def joined(self, body: str, but: str = "") -> list:
        """Where the figure's joints other than `but` hold `body` (pins and contacts), on the page."""
        ...

    def clip(self, p: np.ndarray, d: np.ndarray, inset: float) -> Optional[tuple]:
        """The part of the line through p along d inside the figure's reach, less `inset`."""
        ...

    def keep_out(self) -> list:
        """Closed outlines that fixed guides stop short of (moving wheels and cams)."""
        ...

    def hub(self, p: np.ndarray) -> float:
        """The radius of the largest moving disc turning about `p` (0: none)."""
        ...

    def crowded(self, pts: Any, hub: np.ndarray) -> int:
        """How many of `pts` lie on a moving body (a disc not centred at `hub`, a bar)."""
        ...


class Mechanism(Protocol):
    """The Python builder (`model.builder.Mechanism`): a joint of any kind added by name."""

    def joint(self, type: str, a: str, b: str, id: Optional[str] = None, **fields: Any) -> str:
        """Add a joint of kind `type` between `a` and `b`; its id."""
        ...


__all__ = ["Backend", "BodyState", "DrawContext", "Instant", "JointView", "Level", "Mechanism", "Motion", "Pose",
           "Scalar", "Terms", "Vector"]
