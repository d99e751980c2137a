"""A 3D ω driver along a revolute's axis, read for a motion as that joint's rate.

A vector ω driver, `{omega: X, relative_to: Y, value: [w₁, w₂, w₃]}`, is a vector in the
ground's axes. At the drawing it may lie along the axis e of the revolute that joins X and
Y (the notes' fan: the blades turning about the hub's axis relative to the motor block), and
then it says no more than that joint's rate: ω_X − ω_Y = s e with s = w·e. Once the
mechanism has moved, though, e has turned with its body while the written vector has not,
and the two would contradict each other (a sweep's "the drivers as written contradict the
joints"). A motion — a sweep, `move`, a motion in time — so reads such a driver as the
joint's rate s, and its `alpha` as the rate's derivative α·e (the component along e of the
relative angular acceleration, the derivative seen from Y or from the ground alike, since
ω_Y × s e has none along e): the same instant at the drawing, carried along as the joint
turns.

Only a driver whose value and `alpha` both lie along the joint's axis (to round-off) is
read so; any other vector driver stays as written.
"""
from __future__ import annotations

import dataclasses
from typing import Any, Optional

from ..expressions import Expr, parse
from ..joints.capabilities import Coordinate
from ..model.model import Driver, Joint, Model

PARALLEL = 1e-9            # |w × e| over |w|: a vector this close to the axis lies along it


def with_joint_rates(model: Model, inst: Optional[Any] = None) -> Model:
    """`model` with each 3D ω driver along the axis of the revolute joining its two bodies
    written as that joint's rate (see the module); `model` itself when there is none. `inst`
    is the model's instant (`engine.instant.instantiate`), made here when not given."""
    if model.dimension != 3 or not any(d.kind == "omega" and isinstance(d.value, tuple) for d in model.drivers):
        return model
    if inst is None:
        from ..engine.instant import instantiate

        inst = instantiate(model, False)
    drivers = [as_joint_rate(model, inst, d) or d for d in model.drivers]
    if all(a is b for a, b in zip(drivers, model.drivers)):
        return model
    return dataclasses.replace(model, drivers=drivers)


def as_joint_rate(model: Model, inst: Any, d: Driver) -> Optional[Driver]:
    """Driver `d` as the rate of the revolute joining its bodies (`inst` the drawn instant),
    or None when it is not one."""
    if d.kind != "omega" or not isinstance(d.value, tuple):
        return None
    other = d.relative_to or model.frame
    joint = _revolute(model, d.body, other)
    if joint is None:
        return None
    try:                       # numbers (a model with symbols is moved at its draw_at numbers)
        axis = [float(c) for c in inst.direction(joint.axis, f"{joint.where}.axis")]
        value = [float(c) for c in inst.vector(d.value, f"{d.where}.value")]
        accel = [float(c) for c in inst.vector(d.accel, f"{d.where}.alpha")] if isinstance(d.accel, tuple) else None
    except (TypeError, ValueError):
        return None
    if not all(_along(v, axis) for v in (value, accel) if v is not None):
        return None
    sign = 1.0 if joint.b == d.body else -1.0         # the joint's coordinate: b relative to a
    k = max(range(3), key=lambda i: abs(axis[i]))     # w = s e: s = w_k / e_k
    rate = _component(d.value[k], sign / axis[k])
    acc = _component(d.accel[k], sign / axis[k]) if isinstance(d.accel, tuple) else d.accel
    return dataclasses.replace(d, kind="joint", body=None, joint=joint.id, value=rate, accel=acc,
                               relative_to=None)


def _revolute(model: Model, a: Optional[str], b: str) -> Optional[Joint]:
    """The one revolute joint between bodies a and b (None if there is none, or several): a
    pin about an axis whose own coordinate is its angle (asked of the kind, not its name)."""
    found = [j for j in model.joints if _turns_about_axis(j) and {j.a, j.b} == {a, b} and j.axis is not None]
    return found[0] if len(found) == 1 else None


def _turns_about_axis(joint: Joint) -> bool:
    """A revolute: the bodies share a pin, turn about one axis only (not a ball), and the
    joint's coordinate is that angle."""
    kind = joint.kind
    return kind.pins and not kind.ball and not kind.slides and kind.coordinate is Coordinate.ANGLE


def _along(v: list[float], axis: list[float]) -> bool:
    """Whether v lies along the unit `axis` (a zero vector does)."""
    size = sum(c * c for c in v) ** 0.5
    cross = (v[1] * axis[2] - v[2] * axis[1], v[2] * axis[0] - v[0] * axis[2], v[0] * axis[1] - v[1] * axis[0])
    return sum(c * c for c in cross) ** 0.5 <= PARALLEL * size


def _component(expr: Expr, factor: float) -> Expr:
    """The expression `expr` times `factor` (written out, so that a rate in `t` stays one)."""
    if factor == 1.0:
        return expr
    return parse(f"({expr.text})*({factor!r})")
