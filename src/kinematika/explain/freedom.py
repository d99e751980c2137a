"""Degrees of freedom against the data (issue 30: C5-1.5).

The statement of C5-1.5 gives two data, the velocities of the lower pulleys' centres, and
the mechanism's joints leave three degrees of freedom: its datum v_C3 = (0; −2v) gives a
point's whole velocity in the plane, two conditions (the magnitude, and the direction: the
notes' "no pendulum motion", which the joints alone do not impose). Three readers of the
page agreed that "3 degrees of freedom" under two data reads as a datum missing (the fourth
audit), and that a sentence explaining which motion the direction takes away reads as
bookkeeping (the fifth and sixth); the page then said no count at all, the only page
without one, and two teachers asked for it (twenty-seventh round (e): "El mecanismo tiene
dos grados de libertad (se dan v_C1 y v_C3)"). So where data that give whole velocities make
up the difference, the page says the mobility the statement leaves, one degree for each
datum. Not that the statement gives a datum's direction too (twenty-eighth round (e): "el
enunciado da también la dirección de v_C3" read as if v_C1 had none, both given downwards
in the Data's own lines; the Basque teacher asked for the clause to go)."""
from __future__ import annotations

from typing import Any, Optional

from .context import Ctx, omega_sym
from .document import Sym


def _whole(ctx: Ctx) -> list:
    """The velocity drivers that give a point's whole velocity (two conditions in the plane)."""
    return [d for d in ctx.model.drivers if d.kind == "velocity" and d.along is None
            and isinstance(d.value, tuple) and d.point is not None]


def dof_by_data(ctx: Ctx, counts: dict) -> bool:
    """Whether the structure section counts the degrees of freedom by the data: a planar
    mechanism with more of them than data, the difference made up exactly by the data that
    give a point's whole velocity (each counts twice: its direction is a condition of the
    statement), every datum named by a symbol (`datum_sym`)."""
    drivers = ctx.model.drivers
    if not ctx.planar or counts["dof"] <= len(drivers):
        return False
    whole = _whole(ctx)
    return (bool(whole) and counts["dof"] == len(drivers) + len(whole)
            and all(datum_sym(ctx, d) is not None for d in drivers))


def datum_sym(ctx: Ctx, d: Any) -> Optional[Sym]:
    """A datum's symbol as the Data write it: v_C3 for a point's velocity, ω_arm for a
    body's rate; None for a joint's rate."""
    if d.kind == "velocity" and d.point is not None:
        return Sym("v", ctx.point_label(d.point.point, d.point.body))
    if d.kind == "omega" and d.body is not None:
        return omega_sym(d.body)
    return None


def by_data(ctx: Ctx) -> dict:
    """The sentence's arguments: the mobility the statement leaves (one a datum) and the data."""
    from .document import Names

    drivers = ctx.model.drivers
    return {"dof": len(drivers), "data": Names([datum_sym(ctx, d) for d in drivers])}
