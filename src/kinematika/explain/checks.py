"""The checks a teacher adds below a solution: the same result by another road.

- Willis' formula for every epicyclic train (a carrier pivoted at O carrying planets that
  mesh with wheels turning about O, the frame's wheel included): seen from the carrier
  the train is an ordinary one, so (ω_s1 − ω_c)/(ω_s2 − ω_c) = ∓ρ_s2/ρ_s1 (minus through
  one external and one internal mesh, the sun and the ring: −3 in C5-1.4 and C5-E.2).
- The ratio of a belt or chain drive, seen from the body that carries both axles: the belt
  does not slip on either wheel, so ρ_a ω_a = ρ_b ω_b (the pulley train's ω₄/ω₁ =
  (r₁/r₂)(r₃/r₄), through a weld) — unless the relation itself found the rate in a step
  (`drives`: the notes' bicycle, r Ω_pinyó = R Ω_plat, and C5-1.6), where a check of it
  by itself would be circular.
- The time ratio of a quick-return (a crank pin in the slot of a lever pivoted on the
  frame): the lever is at an end of its swing when the slot is tangent to the crank's
  circle, so the two strokes take the crank angles 360° − 2θ and 2θ, cos θ = r/d.

Every value is computed from the geometry and the rates found; the check says they agree.
"""
from __future__ import annotations

import math
from typing import Optional

from .context import Ctx, omega_sym
from .document import Inline, Name, Section, Value, msg
from .drives import circle, drives, pivot, radius, rho, same_place, simplified, wheel_circle
from .kinds import crossed_by_a_slot, pins, rolls, welds


def checks_section(ctx: Ctx) -> Optional[Section]:
    """The teacher's checks that apply to the mechanism, or None."""
    if not ctx.planar:
        return None
    blocks = willis(ctx) + belts(ctx) + quick_return(ctx)
    if not blocks:
        return None
    sec = Section(msg("sec.checks"))
    sec.blocks += blocks
    return sec


# geometry read off the model (drives.py) ------------------------------------------------------
_circle = circle
_pivot = pivot
_simplified = simplified
_same = same_place


# Willis -------------------------------------------------------------------------------------
def willis(ctx: Ctx) -> list:
    """Willis' formula for each carrier whose planets mesh with two wheels turning about
    the carrier's pivot."""
    out: list = []
    frame = ctx.frame
    for carrier in ctx.model.bodies:
        o = _pivot(ctx, carrier, frame)
        if carrier == frame or o is None:
            continue
        planets = [b for b in ctx.model.bodies if b not in (carrier, frame) and _pivot(ctx, b, carrier) is not None]
        for planet in planets:
            central = []
            for j in ctx.model.joints:
                if not rolls(j) or planet not in (j.a, j.b):
                    continue
                other = j.a if j.b == planet else j.b
                circle = _circle(ctx, other)
                if circle is None or not _same(ctx, circle[0], o):
                    continue
                at = _pivot(ctx, other, frame) if other != frame else None
                if other == frame or (at is not None and _same(ctx, at, o)):
                    central.append((other, j))
            if len(central) >= 2:
                out += _willis_blocks(ctx, carrier, planet, central[0], central[1], _pivot_name(ctx, carrier, frame))
                break            # one planet says it for the train
    return out


def _pivot_name(ctx: Ctx, body: str, on: str) -> str:
    """The point where `body` is pinned to `on` (the carrier's fixed axis: O)."""
    return next(j.at for j in ctx.model.joints if pins(j) and {j.a, j.b} == {body, on} and j.at)


def _willis_blocks(ctx: Ctx, carrier: str, planet: str, first: tuple, second: tuple, axis: str) -> list:
    """Willis' formula for one planet meshing with two wheels about the carrier's fixed axis
    (`axis`, the carrier's pivot). The carrier carries the planet's axle only: the two central
    wheels turn about the fixed axis through `axis`, the frame's (the readers of stop 41 read
    "whose axles the carrier carries" said of the sun and the ring). A fixed wheel does not
    turn: where one of the two is fixed (E.2's central wheel), the axis is said as theirs,
    "whose axis is the fixed axis through O", never "which turn about" it."""
    (s1, j1), (s2, j2) = first, second
    r1, r2 = wheel_circle(ctx, s1)[1], wheel_circle(ctx, s2)[1]
    sign = _mesh_sign(ctx, j1) * _mesh_sign(ctx, j2)
    train = _simplified(ctx, sign * r2 / r1)
    w1, w2, wc = ctx.omega(s1), ctx.omega(s2), ctx.omega(carrier)
    ratio = _simplified(ctx, (w1 - wc) / (w2 - wc)) if not ctx.is_zero(w2 - wc, "rate") else None
    ws = [omega_sym(b) for b in (s1, carrier, s2, carrier)]
    formula = Inline(["(", ws[0], " − ", ws[1], ") / (", ws[2], " − ", ws[3], ")"])
    radii = Inline(["−" if sign < 0 else "", radius(ctx, s2, True), " / ", radius(ctx, s1, True)])
    written = ctx.symbolic              # the radii written in the ratio: no "with ρ = …" after it
    values = Inline(["(", Value(ctx.clean(w1, "rate"), ""), " − ", Value(ctx.clean(wc, "rate"), ""), ") / (",
                     Value(ctx.clean(w2, "rate"), ""), " − ", Value(ctx.clean(wc, "rate"), ""), ")"])
    return [msg("check.willis", carrier=Name(carrier, "body"), planet=Name(planet, "body"), s1=Name(s1, "body"),
                s2=Name(s2, "body"), axis=axis, formula=formula, radii=radii,
                fixed=int(any(ctx.fixed(b) for b in (s1, s2))),
                r1=0 if written else Inline([rho(s1), " = ", Value(r1, "len")]),
                r2=0 if written else Inline([rho(s2), " = ", Value(r2, "len")]), train=Value(train, ""),
                values=values, ratio=Value(ratio if ratio is not None else train, ""))]


def _mesh_sign(ctx: Ctx, j) -> int:
    """−1 for an external contact (the wheels turn in opposite senses), +1 internal."""
    contact = ctx.sol.geometry(j.id).contact
    return 1 if contact is not None and contact.kind == "internal" else -1


# belts and chains ---------------------------------------------------------------------------
def belts(ctx: Ctx) -> list:
    """Each belt or chain drive (`drives.drives`) whose relation no step used to find a rate:
    ρ_a ω_a/K = ρ_b ω_b/K checked against the rates found; a train of them through welds,
    its ratio."""
    out: list = []
    links: list[tuple] = []
    for d in drives(ctx):
        a, b, holder, sign = d.a, d.b, d.holder, d.sign
        ra, rb = wheel_circle(ctx, a)[1], wheel_circle(ctx, b)[1]
        ratio = _simplified(ctx, sign * ra / rb)
        links.append((a, b, ratio, holder))
        if f"drive:{b}" in ctx.worked or f"drive:{a}" in ctx.worked:
            continue                # the relation found the rate: no check of it by itself
        wa, wb = ctx.omega(a, holder), ctx.omega(b, holder)
        rel = [omega_sym(x, ctx.rel(holder)) for x in (a, b)]
        out.append(msg("check.belt", line=Name(d.line, "body"), a=Name(a, "body"), b=Name(b, "body"),
                       holder=Name(holder, "body"),
                       equation=Inline([radius(ctx, a, True), " ", rel[0], " = ", "" if sign > 0 else "−",
                                        radius(ctx, b, True), " ", rel[1]]),
                       ratio=Inline([rel[1], " / ", rel[0], " = ", "" if sign > 0 else "−", radius(ctx, a, True),
                                     " / ", radius(ctx, b, True), " = ", Value(ratio, "")]),
                       values=Inline([rel[1], " = ", Value(ctx.clean(wb, "rate"), "rate"), ", ", rel[0], " = ",
                                      Value(ctx.clean(wa, "rate"), "rate")])))
    out += _train(ctx, links)
    return out


def _train(ctx: Ctx, links: list) -> list:
    """Two belts or more in a row, through welds (pulley 2 and pulley 3 on one axle): the
    train's ratio is the product of the belts'."""
    if len(links) < 2:
        return []
    welded = {frozenset((j.a, j.b)) for j in ctx.model.joints if welds(j)}
    chain = [links[0]]
    for link in links[1:]:
        last = chain[-1]
        if link[3] == last[3] and (link[0] == last[1] or frozenset((link[0], last[1])) in welded):
            chain.append(link)
    if len(chain) < 2:
        return []
    first, last = chain[0][0], chain[-1][1]
    product = _simplified(ctx, math.prod(x[2] for x in chain))
    holder = chain[0][3]
    w0, w1 = omega_sym(first, ctx.rel(holder)), omega_sym(last, ctx.rel(holder))
    factors: list = []
    for i, (a, b, _, _) in enumerate(chain):
        factors += (["·"] if i else []) + ["(", radius(ctx, a, True), " / ", radius(ctx, b, True), ")"]
    value = _simplified(ctx, ctx.omega(last, holder) / ctx.omega(first, holder))
    return [msg("check.train", ratio=Inline([w1, " / ", w0, " = "] + factors + [" = ", Value(product, "")]),
                value=Value(value, ""))]


# quick-return -------------------------------------------------------------------------------
def quick_return(ctx: Ctx) -> list:
    """A driven crank whose pin slides in the slot of a lever pivoted on the frame, the slot
    through the lever's pivot: the time ratio of its two strokes."""
    out: list = []
    frame = ctx.frame
    driven = {d.body for d in ctx.model.drivers if d.kind == "omega"}
    for j in ctx.model.joints:
        if not crossed_by_a_slot(j) or not j.at:
            continue
        lever, crank = j.a, j.b
        if crank not in driven:
            continue
        o2, o4 = _pivot(ctx, crank, frame), _pivot(ctx, lever, frame)
        if o2 is None or o4 is None:
            continue
        r = math.dist(ctx.num(o2), ctx.num(ctx.pos(j.at)))
        d = math.dist(ctx.num(o2), ctx.num(o4))
        if not 0 < r < d:
            continue
        theta = math.degrees(math.acos(r / d))
        slow, fast = 360 - 2 * theta, 2 * theta
        names = [n for n in ctx.model.bodies[crank].points if ctx.num(ctx.pos(n)) == ctx.num(o2)]
        pivot = names[0] if names else ""
        lever_pivot = next((n for n in ctx.model.bodies[lever].points if ctx.num(ctx.pos(n)) == ctx.num(o4)), "")
        out.append(msg("check.quick", crank=Name(crank, "body"), lever=Name(lever, "body"), pin=Name(j.at),
                       o2=Name(pivot), o4=Name(lever_pivot), r=Value(r, "len"), d=Value(d, "len"),
                       theta=Value(round(theta, 2), "deg"), slow=Value(round(slow, 2), "deg"),
                       fast=Value(round(fast, 2), "deg"), ratio=Value(slow / fast, "")))
    return out



