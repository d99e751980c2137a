"""Bodies of one kind in one mechanism: the same round shapes, the same kinds of joint with
the same bodies (C5-1.4's three planets, each pinned to the carrier and rolling on the sun
and the ring; C5-E.4's two lower wheels). The notes solve such bodies by one method ("el CIR
de cada rodeta s'ha de trobar entre els dos"): a page that finds one planet's centre from
two velocities and the next planet's rate from the sun reads as two methods for one thing
(issue 30, twenty-seventh round (b)). The concept lives here; the centres (`centres._notes`)
and the pruning (`needs.prune`) ask it.
"""
from __future__ import annotations

from .context import Ctx
from .given import driven


def placing(ctx: Ctx, b: str) -> tuple:
    """What places body b: its round shapes' radii, its joints' kinds with the bodies they
    join it to, and the kinds of the drivers that move it, as sorted tuples (two bodies with
    one placing are of one kind; a wheel the statement drives is not of the kind of one it
    leaves free: C5-E.3's two wheels on the rod, the left one driven)."""
    radii = sorted(str(ctx.clean(s.radius, "len")) for s in ctx.inst.shapes.get(b, []) if hasattr(s, "radius"))
    joints = sorted((j.kind.name, j.b if j.a == b else j.a) for j in ctx.model.joints if b in (j.a, j.b))
    moved = sorted(d.kind for d in ctx.model.drivers if b in driven(ctx, d))
    return tuple(radii), tuple(joints), tuple(moved)


def kin(ctx: Ctx, b: str) -> list[str]:
    """The other moving bodies of b's kind (`placing`), in the model's order; none for the
    frame or a body fixed to it."""
    if ctx.fixed(b):
        return []
    mine = placing(ctx, b)
    return [k for k in ctx.model.bodies if k != b and not ctx.fixed(k) and placing(ctx, k) == mine]
