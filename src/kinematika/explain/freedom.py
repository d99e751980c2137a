"""More degrees of freedom than data (issue 30, sixth round: C5-1.5).

The statement of C5-1.5 gives two data, the velocities of the lower pulleys' centres, and
the mechanism has three degrees of freedom: "the mechanism has 3 degrees of freedom" under
two data reads as a datum missing. The third is counted by a datum that gives a point's
whole velocity in the plane, v_C3 = (0; −2v): its magnitude is one condition and its
direction a second — the notes' "no pendulum motion": without it the lower pulley could
swing sideways with the strands it hangs from. The sentence says so, with the bodies that
move in the motion the direction takes away, read off the joints' velocity conditions."""
from __future__ import annotations

from typing import Optional

import numpy as np

from .context import Ctx
from .document import Msg, Sym, msg, names


def _whole(ctx: Ctx) -> list:
    """The velocity drivers that give a point's whole velocity (two conditions in the plane)."""
    return [d for d in ctx.model.drivers if d.kind == "velocity" and d.along is None
            and isinstance(d.value, tuple) and d.point is not None]


def _moved(ctx: Ctx, index: int) -> list[str]:
    """The moving bodies the direction of driver `index`'s velocity alone keeps still: the
    motion left by the joints, the other drivers and this driver's magnitude (along its
    velocity), if it is one motion."""
    s = ctx.sol.solver
    a = np.array(s.a_num, dtype=float)
    mine = [i for i, w in enumerate(s.wheres) if w == f"drivers[{index}]"]
    at = ctx.model.drivers[index].point
    if at is None or len(mine) != 2:
        return []
    along = np.array([float(ctx.sol.inst.num(c)) for c in ctx.vel(at.body, at.point)])
    if not np.linalg.norm(along):
        return []
    magnitude = along[0] * a[mine[0]] + along[1] * a[mine[1]]
    rows = np.vstack([a[[i for i in range(len(a)) if i not in mine]], magnitude])
    _, sv, vt = np.linalg.svd(rows)
    rank = int(np.sum(sv > sv[0] * 1e-10))
    free = vt[rank:]
    if len(free) != 1:
        return []
    _, body_of = s.unknowns.layout()
    moving = {b for x, b in zip(free[0], body_of) if abs(x) > 1e-9 and not ctx.fixed(b)}
    return [b for b in ctx.model.moving_bodies if b in moving]


def dof_sentence(ctx: Ctx, counts: dict) -> Optional[Msg]:
    """The degrees-of-freedom sentence when the data are fewer than the degrees of freedom
    and a datum gives a whole velocity: it counts two conditions, and its direction takes
    away the motion of the bodies `_moved` finds. None otherwise (the plain sentence)."""
    drivers = ctx.model.drivers
    if not ctx.planar or counts["dof"] <= len(drivers):
        return None
    whole = _whole(ctx)
    if not whole or counts["dof"] != len(drivers) + len(whole):
        return None
    d = whole[0]
    bodies = _moved(ctx, drivers.index(d))
    if not bodies or d.point is None:
        return None
    return msg("structure.dof_whole", dof=counts["dof"], data=len(drivers),
               sym=Sym("v", ctx.point_label(d.point.point, d.point.body)), bodies=names(bodies, "body"))
