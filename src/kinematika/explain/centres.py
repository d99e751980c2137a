"""Instant centres as the notes find them (seed 002): at a joint, by Aronhold–Kennedy, or
where the perpendiculars to two velocities meet. The centres are the engine's
(`questions.centres.all_centres`); this module only says how each one follows."""
from __future__ import annotations

from itertools import combinations

from ..questions.centres import all_centres
from .context import Ctx
from .document import CentreNote, Section, msg

MAX_ALL = 10        # above this many pairs, only the centres relative to the frame (and what they need)


def centres_section(ctx: Ctx) -> Section:
    sec = Section(msg("sec.centres"))
    sec.add(msg("centres.intro"))
    found = {frozenset(c.pair): c for c in all_centres(ctx.sol)}
    for key in _chosen(ctx, found):
        c = found[key]
        note = CentreNote(c.pair, _clean(ctx, c.value), c.how, list(c.via))
        if c.how == "joint":
            note.joint_type = ctx.model.joint(c.via[0]).type
        if c.how == "kennedy":
            a, b = c.pair
            note.lines = [(_clean(ctx, found[frozenset((a, k))].value),
                           _clean(ctx, found[frozenset((k, b))].value)) for k in c.via]
        elif c.how == "velocities" and c.finite:
            note.witnesses = _witnesses(ctx, c.pair[1], c.pair[0])
        sec.blocks.append(note)
    return sec


def _chosen(ctx: Ctx, found: dict) -> list[frozenset]:
    """Every pair for small mechanisms; else the frame's pairs and the centres they need."""
    keys = list(found)
    if len(keys) <= MAX_ALL:
        return keys
    wanted = [k for k in keys if ctx.frame in k]
    i = 0
    while i < len(wanted):
        c = found[wanted[i]]
        if c.how == "kennedy":
            a, b = c.pair
            for k in c.via:
                for key in (frozenset((a, k)), frozenset((k, b))):
                    if key not in wanted:
                        wanted.append(key)
        i += 1
    return [k for k in keys if k in wanted]


def _clean(ctx: Ctx, value: dict) -> dict:
    out = dict(value)
    for key in ("point", "direction"):
        if out.get(key) is not None:
            out[key] = ctx.clean(tuple(out[key]), "len")
    return out


def _witnesses(ctx: Ctx, body: str, frame: str) -> list[tuple[str, tuple]]:
    """Two points of `body` whose velocities relative to `frame` are not parallel."""
    moving = [(p, ctx.vel(body, p, frame)) for p in ctx.model.bodies[body].points]
    moving = [(p, v) for p, v in moving if not ctx.is_zero(v, "speed")]
    for (p, v), (q, u) in combinations(moving, 2):
        if abs(ctx.num(v[0] * u[1] - v[1] * u[0])) > 1e-6 * _size(ctx, v) * _size(ctx, u):
            return [(p, ctx.clean(v, "speed")), (q, ctx.clean(u, "speed"))]
    return [(p, ctx.clean(v, "speed")) for p, v in moving[:1]]


def _size(ctx: Ctx, v: tuple) -> float:
    return sum(x * x for x in ctx.num(v)) ** 0.5
