"""The position constraints: the integrals of the engine's joint and driver rows.

The engine writes each joint as the time derivative of a geometric condition (its rows);
here are the conditions themselves, row for row in the engine's order, so that the
engine's velocity matrix is their Jacobian in the pose coordinates of `poses`:

- joints: each kind's `residual` (`kinematika.joints`, e.g. a pin's two material points
  coincide; a rolling pair keeps its contact and rolls equal arcs);
- drivers: each driver's coordinate keeps its drawn value, except the swept one, which
  advances by the increment;
- the idle spin of a link between two spherical joints has no position form (ω·AB = 0 is
  not integrable): its residual is 0, so that each Newton step carries no such spin.
"""
from __future__ import annotations

from typing import Any, Callable, Optional, Protocol, TypeGuard

import numpy as np

from ..engine.instant import Instant
from ..engine.idle import idle_links
from ..joints import JointGeometry
from ..joints.capabilities import Coordinate
from ..model.model import Driver
from .plan import Plan
from .poses import AnyPoses, Poses, SpatialPoses, exp_rotation

Rows = Callable[[AnyPoses, float], list]       # (poses, increment) -> residual rows


class Remembering(Protocol):
    """A residual that carries a value from one assembled pose to the next (a rolling pair's
    continued angle, a cam contact's curve parameter): `aux(q)`, kept in `q.aux[key]`."""

    key: Any

    def __call__(self, q: AnyPoses, dq: float) -> list:
        ...

    def aux(self, q: AnyPoses) -> Any:
        """The value to remember at the assembled poses `q`."""
        ...


def remembers(f: Rows) -> TypeGuard[Remembering]:
    """Whether the residual `f` carries a value to remember (it has `aux`)."""
    return hasattr(f, "aux")


def residual_functions(inst: Instant, geos: dict[str, JointGeometry], plan: Plan) -> list[tuple[str, Rows]]:
    """(where, rows) for every joint then every driver, in the engine's row order."""
    out: list[tuple[str, Rows]] = []
    ref = inst.ref
    for j in inst.model.joints:
        out.append((j.where, j.kind.residual(inst, geos[j.id], ref)))
    for d in inst.model.drivers:
        out.append((d.where, _driver(inst, d, geos, plan)))
    for body, _, _ in idle_links(inst):
        out.append((f"bodies.{body}", lambda q, dq: [0.0]))
    return out


def _driver(inst: Instant, d: Driver, geos: dict[str, JointGeometry], plan: Plan) -> Rows:
    """The driver's coordinate minus its drawn value, minus the increment when it is swept."""
    swept = d is plan.driver
    spatial = inst.space.dim == 3
    j = plan.joint
    sign = 1.0 if j.a == inst.model.frame else -1.0      # the coordinate is j.b relative to j.a
    if d.kind == "joint":
        geo = geos[d.driven_joint()]
        return geo.joint.kind.displacement(geo, inst.ref, swept)
    if d.kind == "omega":
        return _turning(d.relative_to, d.driven_body(), sign, swept, spatial, geos[j.id].axis)
    point = d.driven_point()
    p0 = inst.points[point.point]
    body, rel = point.body, d.relative_to
    along = None
    if d.along is not None:        # fixed in the frame of reference (given as numbers or two points)
        along = tuple(float(c) for c in inst.direction(d.along, f"{d.where}.along"))

    def target(dq: float) -> list:
        """The drawn point's displacement when the swept joint has turned or slid by dq."""
        if not swept or dq == 0.0:
            return [0.0] * len(p0)
        if j.kind.coordinate is Coordinate.LENGTH:
            return [sign * dq * c for c in geos[j.id].unit_along()]
        r = np.subtract(p0, geos[j.id].point_at())
        axis = np.asarray(geos[j.id].axis if spatial else (0.0, 0.0, 1.0))
        if not spatial:
            r = np.append(r, 0.0)
        moved = exp_rotation(sign * dq * axis) @ r - r
        return moved[:len(p0)].tolist()

    def velocity(q: AnyPoses, dq: float) -> list:
        """The point's displacement relative to the frame of reference (along `along`, which
        turns with that frame: v_rel·u's integral, u fixed in it)."""
        moved = _sub(_sub(q.point(body, p0), q.point(rel, p0) if rel else p0), target(dq))
        if along is None:
            return moved
        return [_dot(moved, q.turn(rel, along) if rel else along)]

    return velocity


def _turning(rel: Optional[str], body: str, sign: float, swept: bool, spatial: bool,
             axis: Optional[tuple]) -> Rows:
    """An omega driver's rows: `body`'s rotation relative to `rel` (the frame: None), less the
    increment (about the swept joint's `axis` in space) when it is the swept driver."""
    if not spatial:
        def planar(q: AnyPoses, dq: float) -> list:
            assert isinstance(q, Poses)
            return q.rotation_error(rel, body, sign * dq if swept else 0.0)
        return planar
    turn = np.asarray(axis if swept else (0, 0, 1), dtype=float)

    def spatial_rows(q: AnyPoses, dq: float) -> list:
        assert isinstance(q, SpatialPoses)
        return q.rotation_error(rel, body, exp_rotation(sign * dq * turn) if swept else None)
    return spatial_rows


def _sub(p, r) -> list:
    return [x - y for x, y in zip(p, r)]


def _dot(p, r) -> float:
    return sum(x * y for x, y in zip(p, r))
