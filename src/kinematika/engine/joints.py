"""Joint constraints as rows of the velocity and acceleration systems.

Each kind of joint writes its condition once, in its own module (`kinematika.joints`): at the
velocity level linear in (ω, v₀); at the acceleration level the same coefficients multiply
(α, a₀) and the terms quadratic in the known velocities are added. Here the rows become
`Row`s of the engine's linear forms.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import Said
from ..joints import JointGeometry
from ..model.model import Joint
from .instant import Instant
from .levels import Level
from .linear import Lin


@dataclass
class Row:
    """One scalar condition that must vanish, with a label for messages (a message of the
    errors' catalogue, said in the language in use) and the joint it belongs to."""

    lin: Lin
    label: Any
    where: str
    driver: bool = False
    joint: str = ""


def joint_geometry(inst: Instant, joint: Joint) -> JointGeometry:
    """What the joint's rows need at this instant (its kind's `prepare`)."""
    return joint.kind.prepare(inst, joint)


def joint_rows(geo: JointGeometry, lv: Level) -> list[Row]:
    """The joint's conditions at level `lv`, each a `Row` that must vanish."""
    joint = geo.joint
    where, name = joint.where, joint.id
    out = []
    for lin, label in joint.kind.rows(geo, lv):
        if not isinstance(lin, Lin):
            lin = Lin(const=lin)
        out.append(Row(lin, Said("row-joint", id=name, label=label), where, joint=name))
    return out


def joint_known_terms(geo: JointGeometry, lv: Level) -> list[tuple[Any, Said]]:
    """The joint's conditions at level `lv` as (minus the row's constant, its label): the
    right side b of `joint_rows`'s rows with their labels, without the `Row`s. What the
    acceleration level needs, whose matrix is the velocity level's (half the work of its
    rows on a 1000-body chain)."""
    joint = geo.joint
    name = joint.id
    return [(-(lin.const if isinstance(lin, Lin) else lin), Said("row-joint", id=name, label=label))
            for lin, label in joint.kind.rows(geo, lv)]


def joint_rate(geo: JointGeometry, lv: Level) -> Lin:
    """The rate of a joint's coordinate (second body relative to the first), or its derivative."""
    return geo.joint.kind.rate(geo, lv)
