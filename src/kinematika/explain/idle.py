"""Bodies the question does not need: a moving body the structure lists whose rate no step
works out (C5-1.2's two wheels, C5-1.4's third planet, C5-E.6's front wheel). A student
who reads the structure table asks for it, so the page says it once, the way the notes
would, after the table of rates (round 17a):

- a body rolling without slipping on a fixed one, its centre a point whose velocity the
  page knows: its contact is its instant centre, so ω = |v_O| / r (the notes' "el CIR
  respecte del terra de les rodes és el punt de contacte amb el terra ... la velocitat
  angular d'aquests elements és immediata", C5-E.6), and its row is in the table;
- a body placed like one the page worked out (same round shape, same joints with the same
  bodies) and turning with it: ω is that body's, by symmetry (C5-1.4's planets), in the
  table too;
- any other: one sentence that it does not enter the question.
"""
from __future__ import annotations

from typing import Any, Optional

from .context import Ctx, alpha_sym, omega_sym, radius_formula, read_off
from .document import Derived, Name, Names, Sym, Value, msg
from .kinds import rolls


def idle_blocks(ctx: Ctx, idle: list[str], worked: list[str], accel: bool) -> tuple[list, set[str]]:
    """The lines for the `idle` bodies (no step works their ω out), and those of them given a
    rate (their rows stay in the table, α too when `accel`); `worked` are the bodies the
    table lists."""
    out: list = []
    rated: set[str] = set()
    left: list[str] = []
    for b in idle:
        lines = _rolling(ctx, b, worked, accel) or _symmetric(ctx, b, worked, accel)
        if not lines:
            left.append(b)
            continue
        out += lines
        rated.add(b)
    if left:
        out.append(msg("idle.unused", bodies=Names([Name(b, "body") for b in left]), count=len(left)))
    return out, rated


def _rolling(ctx: Ctx, b: str, worked: list[str], accel: bool) -> list:
    """ω = ±|v_O| / r of a body rolling on a fixed one, O its centre, a point of a body the
    page worked out (or of the frame); α = ±|a_O^t| / r with accelerations (|v_O| = |ω| r
    at every instant, differentiated along the path)."""
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
        out: list = [msg("idle.rolling", body=Name(b, "body"), fixed=Name(other, "body"), point=Name(ctx.contact(j))),
                     Derived(omega_sym(b), read_off(ctx, Sym("v", name), r, ctx.omega(b)),
                             ctx.value(ctx.omega(b), "rate"), b, "omega", not ctx.symbolic)]
        if accel:
            out.append(Derived(alpha_sym(b), read_off(ctx, Sym("a", name, "t"), r, ctx.alpha(b)),
                               ctx.value(ctx.alpha(b), "rate2"), b, "alpha", not ctx.symbolic))
        return out
    return []


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


def _symmetric(ctx: Ctx, b: str, worked: list[str], accel: bool) -> list:
    """ω_b = ω_w of a worked body w placed like b: the same round shapes and the same kinds
    of joint with the same bodies, and the same angular velocity (C5-1.4's third planet,
    like the first)."""
    mine = _placing(ctx, b)
    for w in worked:
        if w == b or _placing(ctx, w) != mine or not ctx.is_zero(ctx.omega(b) - ctx.omega(w), "rate"):
            continue
        if accel and not ctx.is_zero(ctx.alpha(b) - ctx.alpha(w), "rate2"):
            continue
        out: list = [msg("idle.symmetry", body=Name(b, "body"), like=Name(w, "body")),
                     Derived(omega_sym(b), [omega_sym(w)], ctx.value(ctx.omega(b), "rate"), b, "omega", not ctx.symbolic)]
        if accel:
            out.append(Derived(alpha_sym(b), [alpha_sym(w)], ctx.value(ctx.alpha(b), "rate2"), b, "alpha",
                               not ctx.symbolic))
        return out
    return []


def _placing(ctx: Ctx, b: str) -> tuple:
    """What places body b: its round shapes' radii and its joints' kinds with the bodies they
    join it to, as a sorted tuple."""
    radii = sorted(str(ctx.clean(s.radius, "len")) for s in ctx.inst.shapes.get(b, []) if hasattr(s, "radius"))
    joints = sorted((j.kind.name, j.b if j.a == b else j.a) for j in ctx.model.joints if b in (j.a, j.b))
    return tuple(radii), tuple(joints)

