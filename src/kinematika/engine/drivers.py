"""Drivers as rows: the known motion, at the velocity level (values) and acceleration level."""
from __future__ import annotations

from ..algebra.vectors import dot, sub
from ..errors import Said
from ..model.model import Direction, Driver
from .instant import Instant
from ..joints import AXES, JointGeometry
from .joints import Row, joint_rate
from .levels import Level
from .linear import as_lin


def driver_rows(inst: Instant, d: Driver, geos: dict[str, JointGeometry], lv: Level) -> list[Row]:
    """The driver's conditions: (its motion) − (its value) = 0."""
    where = d.where
    if d.kind == "omega":
        return _omega(inst, d, lv, where)
    if d.kind == "joint":
        joint, given = d.driven_joint(), d.rate(lv.accel)
        value = inst.value(given, where)
        return [Row(as_lin(joint_rate(geos[joint], lv) - value), Said("row-joint-rate", joint=joint,
                                                                      value=given.text), where, True)]
    return _velocity(inst, d, lv, where)


def _omega(inst: Instant, d: Driver, lv: Level, where: str) -> list[Row]:
    sp = lv.space
    rel, body = d.relative_to, d.driven_body()
    motion = sp.rot_sub(lv.omega(body), lv.omega(rel)) if rel else lv.omega(body)
    name = "α" if lv.accel else "ω"
    label = Said("row-rate-relative", name=name, body=body, relative=rel) if rel else Said("row-rate", name=name,
                                                                                            body=body)
    if sp.dim == 2:
        rate = d.rate(lv.accel)
        value = inst.value(rate, where)
        return [Row(as_lin(motion - value), Said("row-equals", label=label, value=rate.text), where, True)]
    given = d.vector(lv.accel)
    value = inst.vector(given, where)
    if rel and lv.accel:
        # α_rel = α − α_F − ω_F × ω_rel, the derivative seen from F
        w_rel = sp.rot_sub(lv.w(body), lv.w(rel))
        motion = sub(motion, sp.cross_ww(lv.w(rel), w_rel))
    return [Row(as_lin(m - v), Said("row-component", label=label, axis=AXES[i], value=given[i].text), where, True)
            for i, (m, v) in enumerate(zip(motion, value))]


def _velocity(inst: Instant, d: Driver, lv: Level, where: str) -> list[Row]:
    sp = lv.space
    ref, rel = d.driven_point(), d.relative_to
    p = inst.points[ref.point]
    motion = lv.point(ref.body, p)
    if rel:
        motion = sub(motion, lv.point(rel, p))
        if lv.accel:
            v_rel = sub(lv.v(ref.body, p), lv.v(rel, p))
            motion = sub(motion, tuple(lv.terms.coriolis_factor() * c for c in sp.cross(lv.w(rel), v_rel)))
    name = "a" if lv.accel else "v"
    if d.along is not None:
        u = _reference_direction(inst, rel or inst.model.frame, d.along, f"{where}.along")
        rate = d.rate(lv.accel)
        value = inst.value(rate, where)
        return [Row(as_lin(dot(motion, u) - value), Said("row-point-along", name=name, point=str(ref),
                                                         value=rate.text), where, True)]
    given = d.vector(lv.accel)
    value = inst.vector(given, where)
    label = Said("row-point", name=name, point=str(ref))
    return [Row(as_lin(m - v), Said("row-component", label=label, axis=AXES[i], value=given[i].text), where, True)
            for i, (m, v) in enumerate(zip(motion, value))]


def _reference_direction(inst: Instant, body: str, d: Direction, where: str) -> tuple:
    """A velocity driver's `along`, fixed in its frame of reference `body`: as drawn, turned
    with that body in a moved model (`Model.turns`) or a sweep's pose (`Instant.body_turn`);
    two points give it at the instant anyway."""
    if inst.body_turn is not None and isinstance(d, tuple):      # written, not two points
        return tuple(inst.body_turn(body, inst.direction(d, where)))
    return inst.body_direction(body, d, where)
