"""Joint constraints as rows of the velocity and acceleration systems.

Each formula is the time derivative of the joint's geometric condition, written once:
at the velocity level it is linear in (ω, v₀); at the acceleration level the same
coefficients multiply (α, a₀) and `lv.accel` adds the terms quadratic in the known
velocities (centripetal terms come with `lv.point`, Coriolis terms are added here).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from ..algebra.vectors import dot, sub
from ..errors import KinematikaError
from ..model.model import Joint, PointPair
from .contact import Contact, find_contact
from .instant import Instant
from .levels import Level
from .linear import Lin

AXES = "xyz"


@dataclass
class Row:
    """One scalar condition that must vanish, with a label for messages and explanations."""

    lin: Lin
    label: str
    where: str
    driver: bool = False


@dataclass
class JointGeometry:
    """What a joint's rows need at this instant, evaluated once."""

    joint: Joint
    at: Optional[tuple] = None
    along: Optional[tuple] = None           # unit; fixed in body a (b for a `wheel`)
    axis: Optional[tuple] = None            # unit; fixed in body a
    perps: list = field(default_factory=list)   # unit normals to `along` or `axis`
    contact: Optional[Contact] = None


def joint_geometry(inst: Instant, joint: Joint) -> JointGeometry:
    """Evaluate a joint's point and directions and check its geometry holds (else `geometry`)."""
    sp, bk = inst.space, inst.backend
    geo = JointGeometry(joint)
    if joint.at is not None:
        geo.at = inst.points[joint.at]
    if joint.along is not None:
        fixed_in = joint.b if joint.type == "wheel" else joint.a
        geo.along = inst.body_direction(fixed_in, joint.along, f"{joint.where}.along")
        geo.perps = sp.perpendiculars(geo.along, bk.sqrt)
    if joint.axis is not None:
        geo.axis = inst.direction(joint.axis, f"{joint.where}.axis")
        if joint.type in ("revolute", "cylindrical"):
            geo.perps = sp.perpendiculars(geo.axis, bk.sqrt)
    if joint.type == "prismatic" and sp.dim == 3 and geo.along is None:
        geo.along = geo.axis
        geo.perps = sp.perpendiculars(geo.along, bk.sqrt)
    if joint.type == "slot" and isinstance(joint.along, PointPair):
        start = inst.points[joint.along.start]
        gap = inst.num(dot(sub(geo.at, start), geo.perps[0]))
        if abs(gap) > 1e-6 * inst.scale:
            raise KinematikaError("geometry", f"slot point {joint.at!r} is off the line "
                                  f"{joint.along.start}{joint.along.end}: gap {gap:.6g}"
                                  + rounding_hint(gap, inst.scale, joint.at), joint.where)
    if joint.type in ("rolling", "gear"):
        geo.contact = find_contact(inst, joint)
    return geo


def rounding_hint(gap: float, scale: float, point: str) -> str:
    """For a gap small next to the model (coordinates rounded by hand, most likely): the
    tolerance, and how to avoid the rounding."""
    if abs(gap) > 1e-3 * scale:
        return ""
    return (f", more than the tolerance {1e-6 * scale:.2g} (1e-6 of the model's size): write "
            f"{point} by construction, or with more digits")


# shared derivatives ------------------------------------------------------------------------
def coincident(lv: Level, a: str, b: str, p: tuple) -> tuple:
    """v_P(b) − v_P(a) (or the accelerations): zero when both bodies share P."""
    return sub(lv.point(b, p), lv.point(a, p))


def sliding(lv: Level, a: str, b: str, q: tuple, e: tuple) -> Lin:
    """d/dt [(Q_b − Q_a)·e], e fixed in a: the relative motion of Q along e.

    Velocity: v_rel·e. Acceleration: (a_Qb − a_Qa)·e + 2 v_rel·(ω_a × e), the Coriolis term.
    """
    row = dot(coincident(lv, a, b, q), e)
    if lv.accel:
        v_rel = sub(lv.v(b, q), lv.v(a, q))
        row = row + 2 * dot(v_rel, lv.space.cross(lv.w(a), e))
    return row


def turning(lv: Level, a: str, b: str, e: tuple) -> Lin:
    """d/dt [(ω_b − ω_a)·e], e fixed in a (3D): (α_b − α_a)·e + ω_rel·(ω_a × e)."""
    sp = lv.space
    row = sp.rot_dot(sp.rot_sub(lv.omega(b), lv.omega(a)), e)
    if lv.accel:
        w_rel = sp.rot_sub(lv.w(b), lv.w(a))
        row = row + dot(w_rel, sp.cross(lv.w(a), e))
    return row


def same_rotation(lv: Level, a: str, b: str) -> list:
    """ω_b − ω_a (α_b − α_a) component by component."""
    sp = lv.space
    return list(sp.rot_components(sp.rot_sub(lv.omega(b), lv.omega(a))))


# the joint types ---------------------------------------------------------------------------
def _revolute(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    rows = [(c, f"{j.at}@{j.b} moves with {j.at}@{j.a} ({AXES[i]})")
            for i, c in enumerate(coincident(lv, j.a, j.b, geo.at))]
    rows += [(turning(lv, j.a, j.b, p), f"relative rotation only about the axis ({k + 1})")
             for k, p in enumerate(geo.perps)]
    return rows


def _spherical(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    return [(c, f"{j.at}@{j.b} moves with {j.at}@{j.a} ({AXES[i]})")
            for i, c in enumerate(coincident(lv, j.a, j.b, geo.at))]


def _prismatic(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    q = geo.at if geo.at is not None else lv.ref
    rows = [(c, "no relative rotation" + (f" ({AXES[i]})" if lv.space.dim == 3 else ""))
            for i, c in enumerate(same_rotation(lv, j.a, j.b))]
    rows += [(sliding(lv, j.a, j.b, q, n), f"no relative motion across the guide ({k + 1})")
             for k, n in enumerate(geo.perps)]
    return rows


def _slot(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    return [(sliding(lv, j.a, j.b, geo.at, geo.perps[0]), f"{j.at}@{j.b} stays on the slot of {j.a}")]


def _cylindrical(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    rows = [(turning(lv, j.a, j.b, p), f"relative rotation only about the axis ({k + 1})")
            for k, p in enumerate(geo.perps)]
    rows += [(sliding(lv, j.a, j.b, geo.at, p), f"relative sliding only along the axis ({k + 1})")
             for k, p in enumerate(geo.perps)]
    return rows


def _wheel(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    """Knife edge: v_rel(Q_b)·n_b = 0 with n_b fixed in the second body b.

    Acceleration: (a_Qb − a_Qa − ω_a × v_rel)·n + v_rel·(ω_b × n) = 0.
    """
    j, sp = geo.joint, lv.space
    n = geo.perps[0]
    row = dot(coincident(lv, j.a, j.b, geo.at), n)
    if lv.accel:
        v_rel = sub(lv.v(j.b, geo.at), lv.v(j.a, geo.at))
        row = row - dot(sp.cross(lv.w(j.a), v_rel), n) + dot(v_rel, sp.cross(lv.w(j.b), n))
    return [(row, f"{j.at}@{j.b} has no sideways velocity relative to {j.a}")]


def _rolling(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    """v_J(b) = v_J(a); a_J(b) − a_J(a) = ω_rel × (v_J − J̇)."""
    j, sp = geo.joint, lv.space
    c = geo.contact
    diff = coincident(lv, j.a, j.b, c.point)
    if lv.accel:
        w_rel = sp.rot_sub(lv.w(j.b), lv.w(j.a))
        rolling_velocity = sub(lv.v(j.a, c.point), c.jdot(lv.motion))
        diff = sub(diff, sp.cross(w_rel, rolling_velocity))
    return [(x, f"no slip at the contact of {j.a} and {j.b} ({AXES[i]})") for i, x in enumerate(diff)]


def _weld(geo: JointGeometry, lv: Level) -> list[tuple[Any, str]]:
    j = geo.joint
    rows = [(c, f"{j.b} turns with {j.a}") for c in same_rotation(lv, j.a, j.b)]
    rows += [(c, f"{j.b} moves with {j.a} ({AXES[i]})")
             for i, c in enumerate(coincident(lv, j.a, j.b, lv.ref))]
    return rows


ROWS: dict[str, Callable[[JointGeometry, Level], list[tuple[Any, str]]]] = {
    "revolute": _revolute, "spherical": _spherical, "prismatic": _prismatic, "slot": _slot,
    "cylindrical": _cylindrical, "wheel": _wheel, "rolling": _rolling, "gear": _rolling,
    "weld": _weld,
}


def joint_rows(geo: JointGeometry, lv: Level) -> list[Row]:
    """The joint's conditions at level `lv`, each a `Row` that must vanish."""
    out = []
    for lin, label in ROWS[geo.joint.type](geo, lv):
        if not isinstance(lin, Lin):
            lin = Lin(const=lin)
        out.append(Row(lin, f"{geo.joint.id}: {label}", geo.joint.where))
    return out


def joint_rate(geo: JointGeometry, lv: Level) -> Lin:
    """The rate of a joint's coordinate (second body relative to the first), or its derivative."""
    j, sp = geo.joint, lv.space
    if j.type == "revolute":
        if sp.dim == 2:
            return sp.rot_sub(lv.omega(j.b), lv.omega(j.a))
        return turning(lv, j.a, j.b, geo.axis)
    if j.type == "cylindrical":
        raise KinematikaError("schema", "a cylindrical joint has two coordinates; drive the body's "
                              "omega or a point's velocity", j.where)
    q = geo.at if geo.at is not None else lv.ref
    return sliding(lv, j.a, j.b, q, geo.along)
