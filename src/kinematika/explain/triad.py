"""The triad (Assur group of class III) by its Assur point, as textbooks solve it.

A ternary link T is held by three binary links L1, L2, L3, each pinned to T (at J1, J2,
J3) and to a known body (at E1, E2, E3). No single vector equation has two unknowns, but
the point S where the lines E1J1 and E3J3 meet does: taken as a point of T,

    v_S = v_E1 + v_J1E1 + v_SJ1 = v_E3 + v_J3E3 + v_SJ3

where the two unknown terms of each side are both perpendicular to one line (E1, J1 and S
are collinear), so the equation has two unknowns. Then v_J2 = v_S + v_J2S = v_E2 + v_J2E2
(an RRR closure) gives ω_T and ω_L2, and the remaining links follow. Accelerations repeat
the same two equations with the normal terms known.
"""
from __future__ import annotations

from typing import Optional

from ..model.model import Joint
from .context import Ctx, segment
from .document import Equation, Figure, Name, msg, names
from .terms import point_term, rotation_terms, target_term
from .kinds import pin_only


def triad_parts(ctx: Ctx, bodies: list[str], joints: list[Joint]) -> Optional[tuple]:
    """(T, [(L, outer joint, inner joint, known body)]) when the group is a revolute triad."""
    if len(bodies) != 4 or not all(pin_only(j) for j in joints):
        return None
    group = set(bodies)
    for t in bodies:
        inner = [j for j in joints if t in (j.a, j.b) and ({j.a, j.b} - {t}) <= group]
        if len(inner) != 3:
            continue
        links = []
        for j in inner:
            link = j.a if j.b == t else j.b
            outer = [k for k in joints if link in (k.a, k.b) and k is not j]
            if len(outer) != 1 or ({outer[0].a, outer[0].b} - {link}) & group:
                break
            o = outer[0]
            links.append((link, o, j, o.a if o.b == link else o.b))
        if len(links) == 3:
            return t, links
    return None


def assur_point(ctx: Ctx, links: list) -> Optional[tuple]:
    """Two links whose lines meet, the third one, and the meeting point S (floats)."""
    for i in range(3):
        for k in range(i + 1, 3):
            (_, o1, j1, _), (_, o3, j3, _) = links[i], links[k]
            p1, d1 = _line(ctx, o1.at, j1.at)
            p3, d3 = _line(ctx, o3.at, j3.at)
            det = d1[0] * d3[1] - d1[1] * d3[0]
            if abs(det) <= 1e-6 * _size(d1) * _size(d3):
                continue
            t = ((p3[0] - p1[0]) * d3[1] - (p3[1] - p1[1]) * d3[0]) / det
            s = (p1[0] + t * d1[0], p1[1] + t * d1[1])
            middle = links[3 - i - k]
            return links[i], links[k], middle, s
    return None


def triad_steps(ps, step) -> Optional[list]:
    """The blocks of the triad's step at the level of `ps` (a PlanarSteps)."""
    ctx, lv = ps.ctx, ps.level
    joints = [ctx.model.joint(j) for j in step.joints]
    found = triad_parts(ctx, step.bodies, joints)
    if found is None:
        return None
    t, links = found
    chosen = assur_point(ctx, links)
    if chosen is None:
        return None
    (l1, o1, j1, k1), (l3, o3, j3, k3), (l2, o2, j2, k2), s_xy = chosen
    s = "S"
    while s in ctx.model.points:
        s += "'"
    if not ctx.symbolic:
        ctx.name_position(s, s_xy)
    else:
        return None          # the Assur point's position is numeric here; symbolic triads keep the general route
    e1, i1, e3, i3, e2, i2 = o1.at, j1.at, o3.at, j3.at, o2.at, j2.at
    out: list = []
    if lv == "v":
        out.append(msg("triad.intro", body=Name(t, "body"), links=names([l1, l2, l3], "body"),
                       point=Name(s), l1=_seg(e1, i1), l3=_seg(e3, i3)))
        out.append(_assur_figure(ctx, s, s_xy, (e1, i1), (e3, i3)))
    side1 = [point_term(ctx, lv, e1, k1)] + rotation_terms(ctx, lv, l1, e1, i1, True) + \
        rotation_terms(ctx, lv, t, i1, s, True)
    side3 = [point_term(ctx, lv, e3, k3)] + rotation_terms(ctx, lv, l3, e3, i3, True) + \
        rotation_terms(ctx, lv, t, i3, s, True)
    out.append(Equation(target_term(ctx, lv, s, t, False), [side1, side3], lv, ctx.ref(s, t), position=s_xy))
    out.append(msg("triad.collinear", point=Name(s), l1=_seg(e1, i1), l3=_seg(e3, i3)))
    side_s = [point_term(ctx, lv, s, t)] + rotation_terms(ctx, lv, t, s, i2, True)
    side_2 = [point_term(ctx, lv, e2, k2)] + rotation_terms(ctx, lv, l2, e2, i2, True)
    out.append(msg("triad.closure", point=Name(s), pin=Name(i2)))
    out.append(ps.equation(target_term(ctx, lv, i2, t, False), [side_s, side_2], i2, t))
    out += [ps.read(t, side_s[-1], s, i2), ps.read(l2, side_2[-1], e2, i2)]
    for link, e, i, k in ((l1, e1, i1, k1), (l3, e3, i3, k3)):
        carried = [point_term(ctx, lv, i2, t)] + rotation_terms(ctx, lv, t, i2, i, False)
        out.append(ps.equation(target_term(ctx, lv, i, t, True), [carried], i, t))
        side = [point_term(ctx, lv, e, k)] + rotation_terms(ctx, lv, link, e, i, True)
        out.append(ps.equation(target_term(ctx, lv, i, link, True), [side], i, link))
        out.append(ps.read(link, side[-1], e, i))
    ps.done.add(s)
    return out


def _assur_figure(ctx: Ctx, s: str, s_xy: tuple, line1: tuple, line3: tuple) -> Figure:
    """The mechanism with the lines of the two links drawn on to where they meet, S."""
    from .structure import mechanism_figure

    fig = mechanism_figure(ctx)
    fig.arrows = []
    fig.caption = msg("fig.assur", point=Name(s), l1=_seg(*line1), l3=_seg(*line3))
    for e, _ in (line1, line3):
        fig.lines.append((ctx.num(ctx.pos(e)), s_xy))
    fig.points.append((s, s_xy, "point"))
    return fig


def _seg(q: str, p: str) -> Name:
    return Name(segment(q, p), "segment")


def _line(ctx: Ctx, q: str, p: str) -> tuple:
    a, b = ctx.num(ctx.pos(q)), ctx.num(ctx.pos(p))
    return a, (b[0] - a[0], b[1] - a[1])


def _size(v) -> float:
    return (v[0] ** 2 + v[1] ** 2) ** 0.5
