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

from typing import Callable

import numpy as np

from ..engine.instant import Instant
from ..engine.idle import idle_links
from ..joints import JointGeometry
from ..joints.capabilities import Coordinate
from ..model.model import Driver
from .plan import Plan
from .poses import Poses, exp_rotation

Rows = Callable[[Poses, float], list]          # (poses, increment) -> residual rows


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
        geo = geos[d.joint]
        return geo.joint.kind.displacement(geo, inst.ref, swept)
    if d.kind == "omega":
        rel = d.relative_to
        if not spatial:
            return lambda q, dq: q.rotation_error(rel, d.body, sign * dq if swept else 0.0)
        axis = np.asarray(geos[j.id].axis if swept else (0, 0, 1), dtype=float)
        return lambda q, dq: q.rotation_error(rel, d.body, exp_rotation(sign * dq * axis) if swept else None)
    p0 = inst.points[d.point.point]
    body, rel = d.point.body, d.relative_to
    along = None
    if d.along is not None:        # fixed in the frame of reference (given as numbers or two points)
        along = tuple(float(c) for c in inst.direction(d.along, f"{d.where}.along"))

    def target(dq: float) -> list:
        """The drawn point's displacement when the swept joint has turned or slid by dq."""
        if not swept or dq == 0.0:
            return [0.0] * len(p0)
        if j.kind.coordinate is Coordinate.LENGTH:
            return [sign * dq * c for c in geos[j.id].along]
        r = np.subtract(p0, geos[j.id].at)
        axis = np.asarray(geos[j.id].axis if spatial else (0.0, 0.0, 1.0))
        if not spatial:
            r = np.append(r, 0.0)
        moved = exp_rotation(sign * dq * axis) @ r - r
        return moved[:len(p0)].tolist()

    def velocity(q: Poses, dq: float) -> list:
        """The point's displacement relative to the frame of reference (along `along`, which
        turns with that frame: v_rel·u's integral, u fixed in it)."""
        moved = _sub(_sub(q.point(body, p0), q.point(rel, p0) if rel else p0), target(dq))
        if along is None:
            return moved
        return [_dot(moved, q.turn(rel, along) if rel else along)]

    return velocity


def _sub(p, r) -> list:
    return [x - y for x, y in zip(p, r)]


def _dot(p, r) -> float:
    return sum(x * y for x, y in zip(p, r))
