"""What a sweep runs over: the driven joint, its increments, and how it relates to the drivers.

The contract: `joint` names a driven joint (a joint driver's, or the revolute or prismatic
joint of an `omega`/`velocity` driver's body to the frame); its coordinate (second body
relative to the first) advances by `by` (degrees or length) in `steps` equal increments.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from functools import cached_property
from typing import Any, Optional

import numpy as np

from .. import limits
from ..errors import KinematikaError, Names, Num, Said
from ..engine.instant import Instant
from ..joints.capabilities import Coordinate
from ..model.model import Driver, Joint, Model

DEFAULT_BY = 360.0
DEFAULT_STEPS = 360
MAX_STEPS = limits.SWEEP_STEPS


@dataclass
class Plan:
    """What a sweep does: the joint whose coordinate advances, the driver that drives it, by how
    much in all (`by`: degrees for a revolute, length for a prismatic) and in how many steps."""

    joint: Joint
    driver: Driver                 # the driver whose coordinate is swept
    by: float                      # degrees (revolute) or length (prismatic)
    steps: int

    @property
    def turns(self) -> bool:
        """The swept coordinate is an angle (in degrees; radians in the geometry)."""
        return self.joint.kind.coordinate is Coordinate.ANGLE

    @property
    def unit(self) -> str:
        """The swept coordinate's unit as the results name it: "deg" or "length"."""
        return "deg" if self.turns else "length"

    @cached_property
    def coordinate(self) -> np.ndarray:
        """The increments in the user's unit: 0, by/steps, ..., by (steps + 1 rows)."""
        return np.linspace(0.0, self.by, self.steps + 1)

    @cached_property
    def increments(self) -> np.ndarray:
        """The increments in radians (revolute) or length: what the geometry uses."""
        return np.radians(self.coordinate) if self.turns else self.coordinate


def make_plan(inst: Instant, joint: Optional[str] = None, by: Optional[float] = None,
              steps: Optional[int] = None) -> Plan:
    """The sweep of the model: its `sweep:` section with the given options overriding it."""
    model = inst.model
    section = model.sweep
    j, driver = swept_joint(model, joint if joint is not None else (section.joint if section else None))
    if by is None:
        if section is not None:
            by = float(inst.value(section.by, "sweep.by"))
        elif j.kind.coordinate is Coordinate.ANGLE:
            by = DEFAULT_BY
        else:
            raise KinematikaError("schema", "sweep-by-needed", "sweep.by", joint=j.id, kind=j.kind.name)
    steps = steps if steps is not None else (section.steps if section else DEFAULT_STEPS)
    check_steps(model, steps, MAX_STEPS, "sweep.steps", "steps-too-many-values")
    if isinstance(by, bool) or not isinstance(by, numbers.Real):
        raise KinematikaError("schema", "by-number", "sweep.by", got=repr(by))
    if not math.isfinite(by):
        raise KinematikaError("schema", "by-finite", "sweep.by")
    check_travel(float(by), j, inst.scale, "sweep.by", "by")
    return Plan(j, driver, float(by), int(steps))


def check_steps(model: Model, steps: Any, most: int, where: str, too_many: str) -> None:
    """A number of steps a motion can take: a whole number in 1..`most`, whose rows
    (steps + 1, each `values_per_row` numbers) fit in `limits.SWEEP_VALUES`; else a `schema`
    error at `where` (`too_many`: the key saying how many steps would fit)."""
    if isinstance(steps, bool) or not isinstance(steps, numbers.Integral):
        raise KinematikaError("schema", "steps-whole", where, got=repr(steps))
    count = int(steps)
    if not 1 <= count <= most:
        raise KinematikaError("schema", "steps-range", where, limit=most, got=count)
    per_row = values_per_row(model)
    if (count + 1) * per_row > limits.SWEEP_VALUES:
        raise KinematikaError("schema", too_many, where, steps=count, per_row=per_row,
                              limit=limits.SWEEP_VALUES, most=max(limits.SWEEP_VALUES // per_row - 1, 1))


def check_travel(amount: float, joint: Joint, scale: float, where: str, what: str) -> None:
    """A sweep's `by` or a move's amount within `limits.SWEEP_TRAVEL`: so many turns of a
    revolute (degrees), or so many times the mechanism's size along a prismatic; beyond, the
    angles and places would be round-off, so it is a `schema` error naming the limit."""
    turns = joint.kind.coordinate is Coordinate.ANGLE
    most = limits.SWEEP_TRAVEL * (360.0 if turns else scale)
    if not abs(amount) <= most:
        raise KinematikaError("schema", "travel-too-far", where, what=what, amount=Num(amount, ".6g"),
                              most=Num(most, ".6g"), turns=Num(limits.SWEEP_TRAVEL, ","), unit="angle" if turns else "length")


def values_per_row(model: Model) -> int:
    """The numbers a sweep keeps per row: each body's angle, ω and α, each material point's
    position, velocity and acceleration (vectors of the model's dimension)."""
    dim = model.dimension
    turn = 1 if dim == 2 else 3
    return 3 * turn * len(model.bodies) + 3 * dim * len(model.material_points())


def swept_joint(model: Model, joint: Optional[str]) -> tuple[Joint, Driver]:
    """The joint to sweep (the first driven one unless named) and the driver that drives it."""
    driven = driven_joints(model)
    if not driven:
        raise KinematikaError("schema", "sweep-no-driven-joint", "sweep.joint")
    if joint is None:
        jid, driver = next(iter(driven.items()))
    else:
        if joint not in {j.id for j in model.joints}:
            raise KinematikaError("schema", "unknown-joint", "sweep.joint", joint=joint,
                                  joints=[j.id for j in model.joints])
        if joint not in driven:
            raise KinematikaError("schema", "sweep-not-driven", "sweep.joint", joint=joint, driven=list(driven))
        jid, driver = joint, driven[joint]
    return model.joint(jid), driver


def driven_joints(model: Model) -> dict[str, Driver]:
    """Each driven joint (in driver order) with the driver that drives it."""
    out: dict[str, Driver] = {}
    frame = model.frame
    for d in model.drivers:
        if d.kind == "joint":
            j = model.joint(d.driven_joint())
            if j.kind.sweepable:
                out.setdefault(j.id, d)
            continue
        if d.relative_to not in (None, frame):
            continue
        coordinates: tuple[Coordinate, ...]
        if d.kind == "omega":        # a turning joint of the body to the frame
            bodies, coordinates = {d.driven_body()}, (Coordinate.ANGLE,)
        else:                        # every body whose point moves as the driven one there
            ref = d.driven_point()
            bodies = next(set(c) for c in model.motion_classes(ref.point, model.carriers(ref.point))
                          if ref.body in c)
            coordinates = (Coordinate.ANGLE, Coordinate.LENGTH)
        for j in model.joints:
            other = j.b if j.a == frame else j.a if j.b == frame else None
            if other in bodies and other != frame and j.kind.sweepable and j.kind.coordinate in coordinates:
                out.setdefault(j.id, d)
    return out


def bad_row(plan: Plan, k: int, kind: str, what: Names | str = "",
            at: Optional[float] = None) -> KinematikaError:
    """The error for row k (at coordinate `at`, else the plan's row k): `assembly` (cannot be
    assembled), `singular` (dead point), or `mobility` (assembled, but the drivers as written
    contradict the moved joints)."""
    value = plan.coordinate[k] if at is None else at
    where = Said("sweep-at", k=k, joint=plan.joint.id, value=Num(value, ".6g"), unit=plan.unit)
    if kind == "mobility":
        return KinematikaError(kind, "sweep-drivers-contradict", "sweep", at=where)
    return KinematikaError(kind, "sweep-singular" if kind == "singular" else "sweep-cannot-assemble", "sweep",
                           at=where, what=what or "", said=str(bool(what)).lower())
