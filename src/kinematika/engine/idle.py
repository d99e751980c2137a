"""Idle freedoms: a link held only by two spherical joints spins freely about the line
through their centres, and that spin moves nothing else (the coupler of an RSSR linkage,
the rod of a spatial slider-crank). It is taken as zero, as textbooks do:

    ω · AB = 0     and, differentiated,     α · AB + ω · (ω × AB) = α · AB = 0,

so that the rest of the mechanism is solved with the drivers a user would write.
"""
from __future__ import annotations

from ..algebra.vectors import dot, sub
from ..errors import Said
from .instant import Instant
from .joints import Row
from .levels import Level
from .linear import as_lin


def idle_links(inst: Instant) -> list[tuple[str, str, str]]:
    """(body, A, B) for each undriven moving body whose only joints are spherical at A ≠ B."""
    model = inst.model
    if model.dimension != 3:
        return []
    driven = {name for d in model.drivers
              for name in (d.body, d.relative_to, d.point.body if d.point else None) if name}
    out = []
    for body in model.moving_bodies:
        joints = [j for j in model.joints if body in (j.a, j.b)]
        if body in driven or len(joints) != 2 or not all(j.kind.ball for j in joints):
            continue
        a, b = (j.at for j in joints)
        if a != b and a is not None and b is not None:      # (a ball joint has its point)
            out.append((body, a, b))
    return out


def idle_rows(inst: Instant, lv: Level) -> list[Row]:
    """One row per idle link: its angular velocity (acceleration) has no component along AB."""
    rows = []
    for body, a, b in idle_links(inst):
        ab = sub(inst.points[b], inst.points[a])
        rows.append(Row(as_lin(dot(lv.omega(body), ab)),
                        Said("row-idle", body=body, axis=f"{a}{b}"), f"bodies.{body}"))
    return rows
