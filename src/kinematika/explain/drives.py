"""Belt and chain drives, as the notes use them to find a rate (C5-1.6, C5-E.6).

A line body (the belt's or chain's straight run) rolls without slipping on two circles
whose bodies turn on one body K, the carrier of both axles (the frame, the bicycle's
frame, the arm of C5-1.6). Seen from K both axles are fixed and the run translates, so
the belt's speed is the same on both wheels:

    ρ_a ω_a/K = ± ρ_b ω_b/K          (+ an open belt, − a crossed one)

With one wheel known, the other's rate relative to K follows, and its rate relative to the
frame by the composition of rotations, relative + drag = absolute (C5-1.6's ⊗2ω + ⊙ω = ⊗ω):

    ω_b = ω_b/K + ω_K

The run itself turns with K (ω_run = ω_K). At accelerations the same holds of α (the radii
do not change). Every value written is the solver's; the step only says how it follows.

Two wheels rolling on each other with their axles on one body K (C5-E.4's upper wheel on
the lower ones, all on the chassis) are a pair of gears seen from K: ρ_a ω_a/K = ∓ ρ_b ω_b/K
(− outside each other, + one inside the other) at every instant, so at accelerations the
notes differentiate it (α = v̇/R) rather than go through the contact's geometric point:

    ρ_a α_a/K = ∓ ρ_b α_b/K,   α_b = α_b/K + α_K
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional

from .context import Ctx, alpha_sym, composed, omega_sym
from .document import Derived, Inline, Name, Sym, Value, msg
from .kinds import pins, rolls, welds
from .needs import accelerations_asked


@dataclass(frozen=True)
class Drive:
    """A belt or chain `line` on the wheels `a` and `b`, whose axles `holder` carries;
    `sign` +1 for an open belt (both wheels turn alike), −1 for a crossed one."""

    line: str
    a: str
    b: str
    holder: str
    sign: int


def drives(ctx: Ctx) -> list[Drive]:
    """Every belt or chain drive of the mechanism (none in space)."""
    if not ctx.planar:
        return []
    out = []
    for line in ctx.model.bodies:
        if line == ctx.frame or not _is_line(ctx, line):
            continue                # the ground under two wheels is no belt
        wheels = [(j.a if j.b == line else j.b) for j in ctx.model.joints if rolls(j) and line in (j.a, j.b)]
        wheels = [w for w in wheels if circle(ctx, w) is not None]
        if len(wheels) != 2:
            continue
        a, b = wheels
        holder = _common_holder(ctx, a, b)
        if holder is not None:
            out.append(Drive(line, a, b, holder, 1 if _same_side(ctx, line, a, b) else -1))
    return out


def circle(ctx: Ctx, body: str) -> Optional[tuple]:
    """(centre, radius) of the body's circle (the first), else None."""
    for shape in ctx.inst.shapes.get(body, []):
        if hasattr(shape, "radius") and hasattr(shape, "center"):
            return shape.center, shape.radius
    return None


def wheel_circle(ctx: Ctx, body: str) -> tuple:
    """`circle` of a body known to have one: a drive's or a gear train's wheel, each chosen by
    having a circle."""
    found = circle(ctx, body)
    assert found is not None, f"{body}: no circle"
    return found


def rho(body: str) -> Sym:
    """ρ of a body's circle, the body written by its label (ρ_3, ρ_plat's index)."""
    return Sym("ρ", body, vector=False, of_body=True)


def radius(ctx: Ctx, body: str, factor: bool = False) -> Any:
    """A wheel's radius as a relation writes it: in a symbolic model the radius itself, as
    the notes write it (C5-E.6's r Ω_pinyó = R Ω_plat, C5-E.2's 2r Ω = 3r Ω), in brackets
    when it is a sum and a `factor`; in a numeric one ρ with the body's label (ρ_3), its
    number said after (`radii`)."""
    if not ctx.symbolic:
        return rho(body)
    value = ctx.clean(wheel_circle(ctx, body)[1], "len")
    if factor and getattr(value, "is_Add", False):
        return Inline(["(", Value(value, "len"), ")"])
    return Value(value, "len")


def radii(ctx: Ctx, *bodies: str) -> Any:
    """What the relation's "(with ρ_a = …, ρ_b = …)" says: the radii's values when the
    relation writes ρ (numeric), else 0 (the radii are written in it: `radius`)."""
    if ctx.symbolic:
        return 0
    parts: list = []
    for i, body in enumerate(bodies):
        parts += ([", "] if i else []) + [rho(body), " = ", Value(wheel_circle(ctx, body)[1], "len")]
    return Inline(parts)


def simplified(ctx: Ctx, x: Any) -> Any:
    """A ratio of radii as short as it goes (2, r/R)."""
    if not ctx.symbolic:
        return x
    import sympy

    return sympy.nsimplify(sympy.simplify(x)) if not getattr(x, "free_symbols", None) else sympy.simplify(x)


def drive_blocks(ctx: Ctx, bodies: list[str], known: set[str], level: str) -> tuple[list, set[str]]:
    """The drive relations that give rates of the step's `bodies` from bodies already
    `known`: the blocks (the relation, the known wheel's rate relative to the carrier, the
    other's, its rate by composition, the run's), and the bodies whose rate they give."""
    out: list = []
    found: set[str] = set()
    have = set(known) | {ctx.frame}
    for d in drives(ctx):
        if d.line not in bodies or d.holder not in have:
            continue
        a, b = (d.a, d.b) if d.a in have else (d.b, d.a) if d.b in have else (None, None)
        if a is None or b not in bodies:
            continue
        out += _relation(ctx, d, a, b, level)
        found |= {b, d.line}
    return out, found


@dataclass(frozen=True)
class Pair:
    """Wheels `a` and `b` rolling on each other at `joint`, their axles both on `holder`;
    `sign` −1 outside each other (they turn opposite ways seen from the holder), +1 inside."""

    joint: str
    a: str
    b: str
    holder: str
    sign: int


def pairs(ctx: Ctx) -> list[Pair]:
    """Every pair of moving wheels rolling on each other on one carrier's axles (none in
    space)."""
    if not ctx.planar:
        return []
    out = []
    for j in ctx.model.joints:
        contact = ctx.sol.geometry(j.id).contact if rolls(j) else None
        if contact is None or contact.kind not in ("external", "internal") or circle(ctx, j.a) is None \
                or circle(ctx, j.b) is None or ctx.fixed(j.a) or ctx.fixed(j.b):
            continue                # a wheel on a fixed profile goes by its centre's path (`group._centred`)
        holder = _common_holder(ctx, j.a, j.b)
        if holder is not None:
            out.append(Pair(j.id, j.a, j.b, holder, 1 if contact.kind == "internal" else -1))
    return out


def pair_blocks(ctx: Ctx, bodies: list[str], known: set[str], level: str) -> tuple[list, set[str]]:
    """The rates of the step's `bodies` that a pair of wheels on one carrier gives from a
    wheel already `known` (the carrier known too), as the notes compose them (C5-E.5: "la
    roda petita respecte del xassís és immediata, i una composició de moviments permet
    obtenir-la respecte del terra"): the relation seen from the carrier, then the rates
    (`Pair`); at accelerations the relation differentiated (C5-E.4's α = v̇/R). At
    velocities not for a wheel whose instant centre the structure placed first, on a page of
    velocities alone: the notes turn it about that centre. Where accelerations are explained
    the velocities compose too, so that the wheel is found one way at both levels (issue 30,
    twenty-seventh round (b): C5-E.4's upper wheel turned about P at velocities and composed
    from the chassis at accelerations); P's velocity then follows from U's (v_P = v_U + ω × UP
    = 0, the notes' "(→v) + (←v) = 0 ⇒ P = CIR")."""
    out: list = []
    found: set[str] = set()
    have = set(known) | {ctx.frame}
    for d in pairs(ctx):
        if d.holder not in have:
            continue
        a, b = (d.a, d.b) if d.a in have else (d.b, d.a) if d.b in have else (None, None)
        if a is None or b not in bodies or b in found:
            continue
        if level == "v" and b in ctx.centre_sites.values() and not accelerations_asked(ctx):
            continue
        out += _pair(ctx, d, a, b, level)
        found.add(b)
    return out, found


def _pair(ctx: Ctx, d: Pair, a: str, b: str, level: str) -> list:
    """ρ_a ω_a/K = ∓ ρ_b ω_b/K seen from K (differentiated at accelerations); the known
    wheel's rate relative to K, the other's, and its own by composition (relative + drag)."""
    k = ctx.rel(d.holder)
    ra, rb = wheel_circle(ctx, a)[1], wheel_circle(ctx, b)[1]
    minus = "" if d.sign > 0 else "−"
    sym = omega_sym if level == "v" else alpha_sym
    get = ctx.omega if level == "v" else ctx.alpha
    unit = "rate" if level == "v" else "rate2"
    kind = "omega" if level == "v" else "alpha"
    w_a, w_b = omega_sym(a, k), omega_sym(b, k)
    r_a, r_b = sym(a, k), sym(b, k)
    ctx.worked.update({f"relative:{a}/{d.holder}", f"relative:{b}/{d.holder}"})
    sense = not ctx.symbolic
    said = radii(ctx, a, b)
    rad_a, rad_b = radius(ctx, a, True), radius(ctx, b, True)
    relation = Inline([rad_a, " ", w_a, " = ", minus, rad_b, " ", w_b])
    derived = Inline([rad_a, " ", r_a, " = ", minus, rad_b, " ", r_b])
    names = dict(holder=Name(d.holder, "body"), joint=Name(d.joint, "joint"), a=Name(a, "body"), b=Name(b, "body"),
                 radii=said)
    if level == "v":
        ctx.worked.update({f"pair:{d.joint}", f"drive:{b}"})
        out: list = [msg("pair.relation_v", equation=relation, **names)]
    elif f"pair:{d.joint}" in ctx.worked:
        out = [msg("drive.relation_a", equation=derived, radii=said)]
    else:
        out = [msg("pair.relation", equation=relation, derived=derived, **names)]
    if k is not None:
        out.append(Derived(r_a, [sym(a), " − ", sym(d.holder)], ctx.value(get(a, d.holder), unit), "", kind, sense,
                           lead=composed(sym(a), r_a, sym(d.holder), a == ctx.frame)))
    ratio = simplified(ctx, d.sign * ra / rb)
    one = ctx.is_zero(ratio - 1, "") or ctx.is_zero(ratio + 1, "")
    how = ([] if ctx.is_zero(ratio - 1, "") else ["−"]) + [r_a] if one else [Value(ratio, ""), " · ", r_a]
    out.append(Derived(r_b, how, ctx.value(get(b, d.holder), unit), b if k is None else "", kind, sense))
    if k is not None:
        out.append(Derived(sym(b), [r_b, " + ", sym(d.holder)], ctx.value(get(b), unit), b, kind, sense))
    return out


def _relation(ctx: Ctx, d: Drive, a: str, b: str, level: str) -> list:
    """ρ_a ω_a/K = ρ_b ω_b/K, then ω_a/K, ω_b/K, ω_b and the run's ω (α at accelerations)."""
    sym = omega_sym if level == "v" else alpha_sym
    get = ctx.omega if level == "v" else ctx.alpha
    unit = "rate" if level == "v" else "rate2"
    kind = "omega" if level == "v" else "alpha"
    k = ctx.rel(d.holder)
    ra, rb = wheel_circle(ctx, a)[1], wheel_circle(ctx, b)[1]
    minus = "" if d.sign > 0 else "−"
    rel_a, rel_b = sym(a, k), sym(b, k)
    ctx.worked.update({f"relative:{a}/{d.holder}", f"relative:{b}/{d.holder}"})    # found here: not again
    out: list = [msg("drive.relation" if level == "v" else "drive.relation_a", holder=Name(d.holder, "body"),
                     line=Name(d.line, "body"), a=Name(a, "body"), b=Name(b, "body"),
                     equation=Inline([radius(ctx, a, True), " ", rel_a, " = ", minus, radius(ctx, b, True), " ", rel_b]),
                     radii=radii(ctx, a, b))]
    sense = not ctx.symbolic
    if k is not None:                  # ω_a = ω_a/K + ω_K: the known wheel's rate seen from K
        how = ["−", sym(d.holder)] if a == ctx.frame else [sym(a), " − ", sym(d.holder)]
        out.append(Derived(rel_a, how, ctx.value(get(a, d.holder), unit), "", kind, sense,    # relative: no body's own
                           lead=composed(sym(a), rel_a, sym(d.holder), a == ctx.frame)))
    ratio = simplified(ctx, d.sign * ra / rb)
    out.append(Derived(rel_b, [Value(ratio, ""), " · ", rel_a], ctx.value(get(b, d.holder), unit),
                       b if k is None else "", kind, sense))
    if k is not None:
        out.append(Derived(sym(b), [rel_b, " + ", sym(d.holder)], ctx.value(get(b), unit), b, kind, sense))
    # the run's own rate is not written: the notes give a belt or a chain no angular velocity
    # (its straight run translates with the carrier, and nothing asks it; issue 30, round 29 c —
    # this replaces round 20g's ω_run = ω_K)
    return out


# geometry read off the model ------------------------------------------------------------------
def same_place(ctx: Ctx, p: tuple, q: tuple) -> bool:
    """Whether two places are one, at the mechanism's scale."""
    a, b = ctx.num(tuple(p)), ctx.num(tuple(q))
    return math.dist(a, b) <= 1e-9 * ctx.inst.scale


def pivot(ctx: Ctx, body: str, on: str) -> Optional[tuple]:
    """Where `body` is pinned to `on` (a revolute between them), else None."""
    for j in ctx.model.joints:
        if pins(j) and {j.a, j.b} == {body, on} and j.at:
            return ctx.pos(j.at)
    return None


def _is_line(ctx: Ctx, body: str) -> bool:
    return any(hasattr(s, "direction") for s in ctx.inst.shapes.get(body, []))


def _common_holder(ctx: Ctx, a: str, b: str) -> Optional[str]:
    """The body both wheels turn on, each about its circle's centre (the frame, the bicycle's
    frame, the arm of C5-1.6 that carries the moving pulley and turns about the fixed one);
    a wheel welded to a pinned body (the sprocket on the rear wheel) turns with it."""
    for k in ctx.model.bodies:
        if k in (a, b):
            continue
        if all(_turns_on(ctx, w, k) for w in (a, b)):
            return k
    return None


def _turns_on(ctx: Ctx, wheel: str, k: str) -> bool:
    """Whether `wheel` (or a body welded to it) is pinned to k at the wheel's centre."""
    centre = wheel_circle(ctx, wheel)[0]
    same = {wheel} | {(j.b if j.a == wheel else j.a) for j in ctx.model.joints if welds(j) and wheel in (j.a, j.b)}
    for w in same:
        at = pivot(ctx, w, k)
        if at is not None and same_place(ctx, at, centre):
            return True
    return False


def _same_side(ctx: Ctx, line: str, a: str, b: str) -> bool:
    """Whether the two circles are on one side of the belt's line (an open belt)."""
    shape = next(s for s in ctx.inst.shapes[line] if hasattr(s, "direction"))
    d, p = ctx.num(tuple(shape.direction)), ctx.num(tuple(shape.through))

    def side(w: str) -> float:
        c = ctx.num(tuple(wheel_circle(ctx, w)[0]))
        return d[0] * (c[1] - p[1]) - d[1] * (c[0] - p[0])
    return side(a) * side(b) > 0
