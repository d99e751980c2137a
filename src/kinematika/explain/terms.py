"""The terms of the relative-motion method (seed 001), each with its value and annotations.

    v_P = v_Q + ω × QP                       a_P = a_Q + aⁿ_PQ + aᵗ_PQ
    v_P = v_P∈F + v_rel                      a_P = a_P∈F + a_rel + 2 ω_F × v_rel

A term knows its magnitude (M) and direction (D) or not (?): rotation terms are ⊥ QP,
normal terms ∥ PQ, relative terms ∥ the guide, Coriolis terms ⊥ the guide.
"""
from __future__ import annotations

from ..algebra.vectors import scale
from ..model.model import Joint
from ..point_pair import PointPair
from .context import Ctx, alpha_sym, magnitude, omega_sym, segment
from .document import Ann, Msg, Name, Sym, Term, Value, body, joint, msg

UNIT = {"v": "speed", "a": "accel"}


def acceleration_terms(equations: list) -> str:
    """Which kinds of acceleration terms the `equations` contain: "coriolis" (normal,
    tangential, relative and Coriolis), "relative" (no Coriolis) or "normal" (normal and
    tangential only), for choosing the message that names them: a sentence or a caption about the
    acceleration terms names only the kinds written — a four-bar has no Coriolis term, and
    saying its Coriolis terms are known tells a student of terms that are not there."""
    kinds = {t.kind for eq in equations if eq.level == "a" for side in eq.sides for t in side}
    if "coriolis" in kinds:
        return "coriolis"
    return "relative" if kinds & {"slide", "relative"} else "normal"
KNOWN = (Ann("M"), Ann("D"))
UNKNOWN = (Ann("?"), Ann("?"))


def point_term(ctx: Ctx, level: str, point: str, body: str, known: bool = True) -> Term:
    """v_P (or a_P) of the material point P of `body`."""
    value = ctx.vel(body, point) if level == "v" else ctx.acc(body, point)
    mag, dir_ = KNOWN if known else UNKNOWN
    return Term(Sym(level, ctx.point_label(point, body)), ctx.clean(value, UNIT[level]), mag, dir_,
                unknown=not known, kind="point")


def pair_name(p: str, q: str) -> str:
    """The subscript of p's motion about q on one body, the slides' v_BA: the two labels run
    together (v_AB, v_{A1O}) as every segment is (`context.segment`)."""
    return segment(p, q)


def rotation_terms(ctx: Ctx, level: str, body: str, q: str, p: str, unknown: bool,
                   relative_to: str | None = None) -> list[Term]:
    """ω × QP at the velocity level; ω × (ω × QP) and α × QP at the acceleration level.

    A term's magnitude and direction are written with the term's own segment, the order of
    its subscript (v_AO1: ω·AO1, ⊥ AO1; a_JC^n: ω²·JC, ∥ JC), in the annotation above it and
    in the line below alike; only the vector product keeps the vector QP (ω × O1A), whose
    order is its sense (twenty-fourth round (c): "ω_O1A² · AO1" under "ω_O1A²·O1A", and
    "ω_roda²·CJ" over "a_JC^n ∥ JC", read as two segments)."""
    sp, r, seg, back = ctx.space, ctx.r(q, p), segment(q, p), segment(p, q)
    w = omega_sym(body, relative_to, vector=not ctx.planar)
    # a relative term names its segment and the frame it is seen from, v_{AF rel N}: the
    # equation's own target (v_{A∈R rel N}) and the annotation above it (ω_{R rel N}·FA) name
    # the body, and "v_{AF,R rel N}" was a subscript of six parts a reader could not parse
    # (twenty-fourth round (c)); as the absolute terms, v_AB, which name no body either
    name = pair_name(p, q) + (f"/{relative_to}" if relative_to else "")
    if level == "v":
        value = sp.cross(ctx.omega(body, relative_to), r)
        mag = Ann("?") if unknown else Ann("M", magnitude(ctx, w, ctx.omega(body, relative_to)) + [f"·{back}"]
                                           if ctx.planar else "")
        return [Term(Sym("v", name), ctx.clean(value, "speed"), mag, Ann("perp", back),
                     [w, f" × {seg}"], unknown, "rotation")]
    om = ctx.omega(body, relative_to)
    normal = sp.cross(om, sp.cross(om, r))
    tangential = sp.cross(ctx.alpha(body, relative_to), r)
    al = alpha_sym(body, relative_to, vector=not ctx.planar)
    how_n = [w, " × (", w, f" × {seg})"] if not ctx.planar else [w, f"² · {back}"]
    # in space ω × (ω × r) points to the axis of ω, along r only in the plane
    return [Term(Sym("a", name, "n"), ctx.clean(normal, "accel"), Ann("M", [w, f"²·{back}"] if ctx.planar else ""),
                 Ann("para", back) if ctx.planar else Ann("D"), how_n, False, "normal"),
            Term(Sym("a", name, "t"), ctx.clean(tangential, "accel"),
                 Ann("?") if unknown else Ann("M", magnitude(ctx, al, ctx.alpha(body, relative_to)) + [f"·{back}"]
                                              if ctx.planar else ""), Ann("perp", back),
                 [al, f" × {seg}"], unknown, "tangential")]


def guide(j: Joint) -> Msg | str:
    """The direction of joint `j`'s guide, said once: by the line that gives it when the model
    gives one (the slides' "∥ XX", the structure table's "∥ AB"), else named by the body that
    carries it ("guide of the support") — never by the joint's id, and never the guide's name
    twice ("∥ M gida solidoaren gida" where the guide body is itself called a guide)."""
    if isinstance(j.along, PointPair):
        return segment(j.along.start, j.along.end)
    return msg("dir.guide", holder=body(j.a), joint=joint(j.id))      # the joint: for checks, not written


def slide_terms(ctx: Ctx, level: str, frame: str, moving: str, point: str, guide: Msg | Value | str,
                tag: str = "", unknown: bool = True) -> list[Term]:
    """The motion of P∈moving relative to `frame` along a guide, v_P∈moving/frame (named with
    both bodies, so that its sense is the written one); with Coriolis for accelerations."""
    v_rel = ctx.vel(moving, point, frame)
    name = relative_name(point, moving, frame)
    rel = Sym("v", name)
    mag = Ann("?") if unknown else Ann("M")
    if level == "v":
        return [Term(rel, ctx.clean(v_rel, "speed"), mag, Ann("para", guide), [], unknown, "slide")]
    a_rel = ctx.acc(moving, point, frame)
    w = omega_sym(frame, vector=not ctx.planar)
    coriolis = scale(2, ctx.space.cross(ctx.omega(frame), v_rel))
    return [Term(Sym("a", name), ctx.clean(a_rel, "accel"), mag,
                 Ann("para", guide), [], unknown, "slide"),
            Term(Sym("a", name, sub_key="sub.cor"), ctx.clean(coriolis, "accel"),
                 Ann("M", ["2·"] + (magnitude(ctx, w, ctx.omega(frame)) if ctx.planar else [w]) + ["·", rel]),
                 Ann("perp", guide), ["2 ", w, " × ", rel], False,
                 "coriolis")]


def target_term(ctx: Ctx, level: str, point: str, body: str, known: bool,
                relative_to: str | None = None) -> Term:
    """The left-hand side v_P: known before the step, or solved by it."""
    t = point_term(ctx, level, point, body, known)
    if relative_to is not None:
        value = ctx.vel(body, point, relative_to) if level == "v" else ctx.acc(body, point, relative_to)
        t.value = ctx.clean(value, UNIT[level])
        t.sym = Sym(level, relative_name(point, body, relative_to))
    return t


def relative_name(point: str, body: str, relative_to: str) -> str:
    """The subscript of the motion of `body`'s point `point` relative to `relative_to`:
    A∈4/2, written with both bodies (never v_A/2, which reads as half of v_A)."""
    return f"{point}∈{body}/{relative_to}"


def contact_term(ctx: Ctx, name: str, body: str, other: str, unknown: bool = False) -> Term:
    """a_J∈body − a_J∈other at a rolling contact without slip: along the common normal,
    ω_body/other × (v_J∈other − v_J^geom), with v_J^geom the velocity of the geometric contact
    point (derived where the term is used: `contacts.geometric_blocks`); `unknown`, the
    slides' way (4.4): only the tangential components are equal, the normal difference is
    one of the equation's two unknowns."""
    how = [] if unknown else [omega_sym(body, other), " × (", Sym("v", f"{name}∈{other}"), " − ",
                              Sym("v", name, "geom"), ")"]
    return Term(Sym("a", relative_name(name, body, other)), ctx.clean(ctx.acc(body, name, other), "accel"),
                Ann("?") if unknown else Ann("M"), Ann("para", contact_normal(ctx, name, body, other)), how,
                unknown, "contact")


def contact_normal(ctx: Ctx, name: str, body: str, other: str) -> Msg | str:
    """The common normal at the contact `name` of `body` and `other`, named as the notes name
    a line: the segment from the contact to a circle's centre on it (a circle's centre lies
    on the normal at its contact; the slides' rolling pair writes ∥_BF, ∥_AF, 001 4.4), the
    centre of `other`'s circle first, else `body`'s; "the normal at J" when neither has a
    circle with a named centre on that normal. "∥ normal" alone left a student to guess
    which normal (issue 30, twenty-eighth round (c))."""
    joint_ = next((j for j in ctx.model.joints if {j.a, j.b} == {body, other}
                   and getattr(ctx.sol.geometry(j.id), "contact", None) is not None
                   and ctx.contact(j) == name), None)
    normal = getattr(ctx.sol.geometry(joint_.id).contact, "normal", ()) if joint_ is not None else ()
    if len(normal) >= 2:
        n = ctx.num(normal)
        at = ctx.num(ctx.pos(name))
        for b in (other, body):
            for shape in ctx.model.bodies[b].shapes:
                centre = getattr(shape, "center_point", None)      # a circle's, an arc's
                if not centre or centre == name or centre not in ctx.inst.points:
                    continue
                r = [c - a for a, c in zip(at, ctx.num(ctx.pos(centre)))]
                if abs(r[0] * n[1] - r[1] * n[0]) <= 1e-9 * (abs(r[0]) + abs(r[1])):
                    return segment(name, centre)
    return msg("dir.normal_at", point=Name(name))
