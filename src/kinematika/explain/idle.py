"""Bodies no step works out: a moving body the structure lists whose rate no equation of
the steps finds. Since round 27b a listed body keeps the equation its step finds its rate
with (`needs.listed_bodies`: C5-1.2's two wheels, C5-1.4's third planet and C5-E.6's front
wheel are written as their kind is, with their vector equations), so what is left here is
the fallback for a body the planner never reaches. A student who reads the structure table
asks for it, so the page says it once, the way the notes would (round 17a):

- a body rolling without slipping on a fixed one, its centre a point whose velocity the
  page knows: its contact is its instant centre, so ω = |v_O| / r (the notes' "el CIR
  respecte del terra de les rodes és el punt de contacte amb el terra ... la velocitat
  angular d'aquests elements és immediata", C5-E.6), and its row is in the table;
- a body placed like one the page worked out (same round shape, same joints with the same
  bodies) and turning with it: ω is that body's, by symmetry (C5-1.4's planets), in the
  table too;
- any other: one sentence that it does not enter the question.

A body given its rate is worked out in a numbered step of its own, in the velocities and in
the accelerations, and the order of solution lists it ("4. The *front wheel*, from the
*ground* and the *frame*."): the summary after the steps only collects what they found
(round 24d; the readers found C5-E.6's v_F = v_H and ω_{front wheel} derived under "Angular
velocities", outside any step, and missing from the order).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

from .context import Ctx, alpha_sym, omega_sym, radius_formula, read_along, read_off, segment
from .document import Derived, Name, Names, Sym, Value, centre_point, msg
from .kin import placing
from .kinds import rolls


def idle_blocks(ctx: Ctx, idle: list[str], worked: list[str], accel: bool,
                written: Optional[set[tuple[str, str]]] = None) -> tuple[list[IdleStep], list, set[str]]:
    """The steps for the `idle` bodies given a rate (no step of the solver works their ω
    out), the lines for the others (one sentence: they do not enter the question), and the
    bodies given a rate (their rows stay in the table, α too when `accel`); `worked` are the
    bodies the table lists; `written` the (v or a, subscript) of the motions the page writes
    before these lines (`written_motions`): a line uses no velocity the page has not written
    (round 20a)."""
    steps: list[IdleStep] = []
    rated: set[str] = set()
    left: list[str] = []
    for b in idle:
        step = _rolling(ctx, b, worked, accel, written or set()) or _symmetric(ctx, b, worked, accel)
        if step is None:
            left.append(b)
            continue
        steps.append(step)
        rated.add(b)
    out: list = []
    if left:
        out.append(msg("idle.unused", bodies=Names([Name(b, "body") for b in left]), count=len(left)))
    return steps, out, rated


@dataclass
class IdleStep:
    """A body given its rate in a step of its own: its velocity lines, its acceleration lines
    and the bodies it is found from (the fixed body it rolls on and the body that carries its
    centre, or the body it is placed like)."""

    body: str
    velocity: list
    acceleration: list
    known: list[str]
    centre: str = ""             # the rolling body's centre, whose motion the step reads


def _rolling(ctx: Ctx, b: str, worked: list[str], accel: bool,
             written: set[tuple[str, str]]) -> Optional[IdleStep]:
    """ω = ±|v_O| / r of a body rolling on a fixed one, O its centre, a point of a body the
    page worked out (or of the frame); α = ±|a_O^t| / r with accelerations (|v_O| = |ω| r
    at every instant, differentiated along the path), ±|a_O| / r when O's path is straight
    (a_O has no normal part: C5-E.6's front wheel on the road). A velocity (acceleration) of
    O the page has not written is written first, from the body that carries O
    (`_centre_motion`: v_Q = ω_OQ × I_{OQ}Q, v_F = v_H), round 20a."""
    for j in ctx.model.joints:
        if b not in (j.a, j.b) or not rolls(j):
            continue
        other = j.a if j.b == b else j.b
        contact = ctx.sol.geometry(j.id).contact
        if not ctx.fixed(other) or contact is None:
            continue
        centre = _centre(ctx, b, contact)
        if centre is None:
            continue
        name, radius, unit = centre
        if not any(k in worked or ctx.fixed(k) for k in ctx.model.carriers(name) if k != b):
            continue
        r = Value(radius, unit)          # the model's symbol r (no unit), or a plain number's length
        carrier = next((k for k in ctx.model.carriers(name) if k != b and (k in worked or ctx.fixed(k))), "")
        said = msg("idle.rolling", body=Name(b, "body"), fixed=Name(other, "body"), point=Name(ctx.contact(j)))
        out: list = _centre_motion(ctx, carrier, name, "v", written)
        out.append(said)
        arm = ctx.r(ctx.contact(j), name)         # from the contact, the instant centre, to O
        lead = read_along(ctx, Sym("v", name), r, omega_sym(b), arm)
        out.append(Derived(omega_sym(b), [] if lead else read_off(ctx, Sym("v", name), r, ctx.omega(b)),
                           ctx.value(ctx.omega(b), "rate"), b, "omega", not ctx.symbolic, lead=lead))
        acc: list = []
        if accel:
            acc += _centre_motion(ctx, carrier, name, "a", written)
            acc.append(msg("idle.rolling", body=Name(b, "body"), fixed=Name(other, "body"),
                           point=Name(ctx.contact(j))))
            straight = _straight(ctx, carrier, name)
            term = Sym("a", name, "" if straight else "t")
            lead = read_along(ctx, term, r, alpha_sym(b), arm)
            acc.append(Derived(alpha_sym(b), [] if lead else read_off(ctx, term, r, ctx.alpha(b)),
                               ctx.value(ctx.alpha(b), "rate2"), b, "alpha", not ctx.symbolic, lead=lead))
        return IdleStep(b, out, acc, [other] + ([carrier] if carrier and carrier != other else []), name)
    return None


def written_motions(blocks: list) -> set[tuple[str, str]]:
    """The motions a list of blocks writes: ("v" or "a", subscript) of every equation's
    target and terms and of every value read off (`Derived`), sections included; ("I",
    "a,b") for every instant centre placed."""
    from .document import CentreNote, Equation, Section

    out: set[tuple[str, str]] = set()
    for blk in blocks:
        if isinstance(blk, CentreNote):
            out |= {("I", ",".join(blk.pair)), ("I", ",".join(reversed(blk.pair)))}
        elif isinstance(blk, Section):
            out |= written_motions(blk.blocks)
        elif isinstance(blk, Equation):
            for t in [blk.target] + [t for side in blk.sides for t in side]:
                if t.sym.base in ("v", "a") and not t.sym.sup:
                    out.add((t.sym.base, str(t.sym.sub)))
        elif isinstance(blk, Derived) and blk.sym.base in ("v", "a") and not blk.sym.sup:
            out.add((blk.sym.base, str(blk.sym.sub)))
    return out


def _centre_motion(ctx: Ctx, k: str, name: str, level: str, written: set[tuple[str, str]]) -> list:
    """The line that writes the velocity (acceleration) of the centre `name` of a rolling
    body from the body k that carries it, when the page has not written it: v_F = v_H (k
    translates, H a point of k whose motion the page writes), v_Q = ω_k × I_kQ (k's instant
    centre placed on the page), else v_Q = v_P + ω_k × PQ (a = a_P + α_k × PQ − ω_k² PQ).
    Empty when it is written, or k is not known."""
    if (level, name) in written or not k:
        return []
    unit = "speed" if level == "v" else "accel"
    value = ctx.value(ctx.vel(k, name) if level == "v" else ctx.acc(k, name), unit)
    if ctx.fixed(k):
        return [Derived(Sym(level, name), [], value, k)]
    still = ctx.is_zero(ctx.omega(k), "rate") and (level == "v" or ctx.is_zero(ctx.alpha(k), "rate2"))
    known = [p for p in ctx.model.bodies[k].points if p != name and (level, ctx.point_label(p, k)) in written]
    if still and known:
        return [Derived(Sym(level, name), [Sym(level, ctx.point_label(known[0], k))], value, k)]
    if level == "v" and (f"centre:{k}" in ctx.worked or ("I", f"{ctx.frame},{k}") in written):
        return [Derived(Sym("v", name), [omega_sym(k), " × ", segment(centre_point(k), name)], value, k)]
    if not known:
        return []
    p = known[0]
    arm = segment(p, name)
    if level == "v":
        how = [Sym("v", ctx.point_label(p, k)), " + ", omega_sym(k), " × ", arm]
    else:
        how = [Sym("a", ctx.point_label(p, k)), " + ", alpha_sym(k), " × ", arm, " − ", omega_sym(k), "² ", arm]
    return [Derived(Sym(level, name), how, value, k)]


def _straight(ctx: Ctx, k: str, name: str) -> bool:
    """Whether the centre's acceleration has no normal part (a_O ∥ v_O, or v_O = 0): its
    path is straight at the instant, so α is read off |a_O| itself."""
    v, a = ctx.vel(k, name), ctx.acc(k, name)
    return ctx.is_zero(v[0] * a[1] - v[1] * a[0], "accel") if len(v) == 2 else False


def _centre(ctx: Ctx, b: str, contact: Any) -> Optional[tuple[str, Any, str]]:
    """The named centre of b's circle in the contact (a point of b), its radius (the model's
    symbol when it has one, ω = |v_O| / r, else the length) and the radius's unit kind."""
    from .contacts import centre_name

    for body, c in getattr(contact, "centres", []):
        if body != b:
            continue
        name = centre_name(ctx, body, c)
        if name not in ctx.model.bodies[b].points:
            return None
        for spec, shape in zip(ctx.model.bodies[b].shapes, ctx.inst.shapes.get(b, [])):
            if hasattr(shape, "radius") and ctx.num(tuple(shape.center)) == ctx.num(tuple(c)):
                formula = radius_formula(ctx, spec)    # the model's symbol r, its value in the Data
                return (name, ctx.clean(shape.radius, "len"), "len") if formula is None else (name, formula, "")
    return None


def _symmetric(ctx: Ctx, b: str, worked: list[str], accel: bool) -> Optional[IdleStep]:
    """ω_b = ω_w of a worked body w placed like b: the same round shapes and the same kinds
    of joint with the same bodies, and the same angular velocity (C5-1.4's third planet,
    like the first)."""
    mine = placing(ctx, b)
    for w in worked:
        if w == b or placing(ctx, w) != mine or not ctx.is_zero(ctx.omega(b) - ctx.omega(w), "rate"):
            continue
        if accel and not ctx.is_zero(ctx.alpha(b) - ctx.alpha(w), "rate2"):
            continue
        out: list = [msg("idle.symmetry", body=Name(b, "body"), like=Name(w, "body")),
                     Derived(omega_sym(b), [omega_sym(w)], ctx.value(ctx.omega(b), "rate"), b, "omega", not ctx.symbolic)]
        acc: list = []
        if accel:
            acc.append(Derived(alpha_sym(b), [alpha_sym(w)], ctx.value(ctx.alpha(b), "rate2"), b, "alpha",
                               not ctx.symbolic))
        return IdleStep(b, out, acc, [w])
    return None

