"""More degrees of freedom than data (issue 30: C5-1.5).

The statement of C5-1.5 gives two data, the velocities of the lower pulleys' centres, and
the mechanism has three degrees of freedom: its datum v_C3 = (0; −2v) gives a point's whole
velocity in the plane, two conditions (the magnitude, and the direction: the notes' "no
pendulum motion"). The notes say nothing of the count there. Three readers of the page
agreed: "3 degrees of freedom" under two data reads as a datum missing (the fourth audit),
and a sentence explaining which motion the direction takes away reads as bookkeeping (the
fifth and sixth). So the page leaves the count unsaid when data giving whole velocities make
up the difference, and says the mobility, as the notes do, everywhere else."""
from __future__ import annotations

from .context import Ctx


def _whole(ctx: Ctx) -> list:
    """The velocity drivers that give a point's whole velocity (two conditions in the plane)."""
    return [d for d in ctx.model.drivers if d.kind == "velocity" and d.along is None
            and isinstance(d.value, tuple) and d.point is not None]


def dof_unsaid(ctx: Ctx, counts: dict) -> bool:
    """Whether the structure section leaves the degrees of freedom unsaid: a planar
    mechanism with more of them than data, the difference made up exactly by the data that
    give a point's whole velocity (each counts twice)."""
    drivers = ctx.model.drivers
    if not ctx.planar or counts["dof"] <= len(drivers):
        return False
    whole = _whole(ctx)
    return bool(whole) and counts["dof"] == len(drivers) + len(whole)
