"""Bodies carried by bodies (seed 000, the fan): absolute rates, point fields, composition.

    ω = ω₁ + ω₂                      α = α₁ + α₂ + ω₁ × ω₂
    v_P = v_C + ω × CP               a_P = a_C + α × CP + ω × (ω × CP)
    v_P = v_drag + v_rel             a_P = a_drag + a_rel + 2 ω₁ × v_rel

Each body is taken from the body it is jointed to (its carrier), in order from the frame.
"""
from __future__ import annotations

from typing import Optional

from ..algebra.vectors import dot
from ..model.model import PointRef
from ..model.question import Question
from ..questions.decompose import KIND as DECOMPOSE, decompose
from .asked import worked
from .context import Ctx, alpha_sym, composed, omega_sym
from .document import Ann, Derived, Equation, Inline, Name, Names, Section, Sym, Term, Value, msg
from .terms import KNOWN, point_term, relative_name, rotation_terms, target_term
from .kinds import guided, pin_only, rolls, slider


def carriers(ctx: Ctx) -> list[tuple[str, Optional[str], Optional[str]]]:
    """(body, carrier, joint point) from the frame outwards along the joints."""
    known = {ctx.frame}
    out: list[tuple[str, Optional[str], Optional[str]]] = []
    progress = True
    while progress:
        progress = False
        for j in ctx.model.joints:
            for parent, child in ((j.a, j.b), (j.b, j.a)):
                if parent in known and child not in known:
                    known.add(child)
                    out.append((child, parent, j.at))
                    progress = True
    out += [(b, None, None) for b in ctx.model.moving_bodies if b not in known]
    return out


def rates_section(ctx: Ctx, accel: bool = True) -> Section:
    """ω = ω_carrier + ω_rel and α = α_carrier + α_rel + ω_carrier × ω_rel, body by body
    (the angular velocities only when nothing asked needs accelerations, as the notes stop)."""
    sec = Section(msg("sec.rates" if accel else "sec.rates_summary_v"))
    vec = not ctx.planar
    # in words, drag and relative: indices 1, 2 would read as bodies (the frame is body 1)
    w1, w2 = Sym("ω", sub_key="sub.drag", vector=vec), Sym("ω", sub_key="sub.rel", vector=vec)
    a1, a2 = Sym("α", sub_key="sub.drag", vector=vec), Sym("α", sub_key="sub.rel", vector=vec)
    w = Inline([omega_sym("", vector=vec), " = ", w1, " + ", w2])
    if accel:
        sec.add(msg("rates.intro", w=w, a=Inline([alpha_sym("", vector=vec), " = ", a1, " + ", a2, " + ", w1,
                                                  " × ", w2])))
    else:
        sec.add(msg("rates.intro_v", w=w))
    levels = ("w", "al") if accel else ("w",)
    sec.blocks += loop_blocks(ctx, levels)
    rates = ((omega_sym, ctx.omega, "rate", "omega"), (alpha_sym, ctx.alpha, "rate2", "alpha"))[:len(levels)]
    for body, parent, _ in carriers(ctx):
        if parent is None:
            continue
        if parent == ctx.frame:
            sec.add(*[Derived(sym(body, vector=vec), [], Value(_rot(ctx, get(body), unit), unit), body, kind)
                      for sym, get, unit, kind in rates])
            continue
        for level in levels:
            sec.blocks.append(_rate_equation(ctx, body, parent, level, vec))
    return sec


def loop_blocks(ctx: Ctx, levels: tuple[str, ...] = ("w", "al")) -> list:
    """Closed loops of revolute joints: the relative angular velocities add to zero around
    the loop, each along its joint's axis (three scalar equations for the unknown rates);
    differentiated, α_rel + ω_carrier × ω_rel add to zero too."""
    model = ctx.model
    parent: dict[str, tuple] = {ctx.frame: (None, None)}
    queue, closing = [ctx.frame], []
    while queue:
        x = queue.pop(0)
        for j in model.joints:
            if x not in (j.a, j.b):
                continue
            y = j.b if j.a == x else j.a
            if y not in parent:
                parent[y] = (x, j)
                queue.append(y)
            elif parent[x][1] is not j and j not in closing and parent[y][1] is not j:
                closing.append(j)
    out: list = []
    for j in closing:
        loop = _loop(ctx, parent, j)
        if loop is None:
            continue
        out.append(msg("loop.intro", bodies=Names([Name(b, "body") for b, _, _ in loop]),
                       rate=Sym("ω", "j", vector=False), axis=Sym("u", "j")))
        driven = {d.joint for d in model.drivers if d.kind == "joint"}
        for level in levels:
            if level == "al":
                out.append(msg("loop.solve_alpha", cross=Inline([Sym("ω", ""), " × ", Sym("ω", "", sub_key="sub.rel")]),
                               rate=Sym("α", "j", vector=False)))
            out.append(_loop_equation(ctx, loop, driven, level))
            if level == "w":
                out.append(msg("loop.solve"))
            for x, y, jj in loop:
                if jj.id not in driven:
                    axis = ctx.sol.geometry(jj.id).axis
                    rel = ctx.omega(x, y) if level == "w" else ctx.alpha(x, y)
                    rate = dot(tuple(ctx.space.rot_components(rel)), tuple(axis))
                    unit = "rate" if level == "w" else "rate2"
                    out.append(Derived(Sym("ω" if level == "w" else "α", jj.id, vector=False), [],
                                       ctx.value(rate, unit)))
    return out


def _loop(ctx: Ctx, parent: dict, j) -> Optional[list]:
    """[(x, y, joint)]: ω_x/y around the loop closed by j, from the frame and back."""
    def up(b: str) -> list:
        out = []
        while parent[b][0] is not None:
            out.append((b, parent[b][0], parent[b][1]))
            b = parent[b][0]
        return out
    down = list(reversed(up(j.a)))
    back = [(p, c, jj) for c, p, jj in up(j.b)]
    loop = down + [(j.b, j.a, j)] + back
    if not all(pin_only(jj) for _, _, jj in loop):
        return None
    return loop


def _loop_equation(ctx: Ctx, loop: list, driven: set, level: str) -> Equation:
    unit = "rate" if level == "w" else "rate2"
    side = []
    for x, y, j in loop:
        known = j.id in driven
        along = Ann("para", msg("dir.axis", joint=Name(j.id, "joint")))
        if level == "w":
            value = _rot(ctx, ctx.omega(x, y), unit)
            side.append(Term(omega_sym(x, y, vector=True), value, Ann("M") if known else Ann("?"), along,
                             [Sym("ω", j.id, vector=False), " ", Sym("u", j.id)], not known, "rate"))
            continue
        value = _rot(ctx, ctx.alpha(x, y), unit)
        side.append(Term(alpha_sym(x, y, vector=True), value, Ann("M") if known else Ann("?"), along,
                         [Sym("α", j.id, vector=False), " ", Sym("u", j.id)], not known, "rate"))
        if y == ctx.frame:
            continue
        cross = ctx.space.cross_ww(ctx.omega(y), ctx.omega(x, y))
        side.append(Term(Sym("ω×ω", f"{y},{x}", vector=True), _rot(ctx, cross, unit), *KNOWN,
                         [omega_sym(y, vector=True), " × ", omega_sym(x, y, vector=True)], kind="rate"))
    zero = Term(Sym("0", vector=True), tuple(0.0 for _ in range(3)), *KNOWN, kind="rate")
    return Equation(zero, [side], level, figure=False)


def _rate_equation(ctx: Ctx, body: str, parent: str, level: str, vec: bool) -> Equation:
    sp = ctx.space
    unit = "rate" if level == "w" else "rate2"
    sym = omega_sym if level == "w" else alpha_sym
    get = ctx.omega if level == "w" else ctx.alpha

    def term(b: str, rel: Optional[str], value, how=None) -> Term:
        return Term(sym(b, rel, vector=vec), _rot(ctx, value, unit), *KNOWN, how or [], kind="rate")

    target = term(body, None, get(body))
    side = [term(parent, None, get(parent)), term(body, parent, get(body, parent))]
    if level == "al":
        w1, w2 = ctx.omega(parent), ctx.omega(body, parent)
        cross = sp.cross_ww(w1, w2)
        side.append(Term(Sym("ω×ω", f"{parent},{body}", vector=vec), _rot(ctx, cross, unit), *KNOWN,
                         [omega_sym(parent, vector=vec), " × ", omega_sym(body, parent, vector=vec)],
                         kind="rate"))
    return Equation(target, [side], level, figure=False)


def _rot(ctx: Ctx, value, unit: str):
    """An angular quantity as a cleaned tuple (3D) or scalar (planar)."""
    comps = ctx.clean(tuple(ctx.space.rot_components(value)), unit)
    return comps[0] if ctx.planar else comps


def fields_section(ctx: Ctx, level: str) -> Section:
    """Every point from its body's joint point: v_P = v_C + ω × CP (a_P likewise)."""
    sec = Section(msg("sec.velocities" if level == "v" else "sec.accelerations"))
    sec.add(msg("fields.intro_v" if level == "v" else "fields.intro_a"))
    done: set[str] = set()
    order = carriers(ctx)
    order = [c for c in order if c[2]] + [c for c in order if not c[2]]   # joint points first
    for body, _, at in order:
        points = ctx.model.bodies[body].points
        if not points:
            continue
        reached = [p for p in points if ctx.point_label(p, body) in done]
        anchor = at if at in points else (reached or points)[0]
        done.add(ctx.point_label(anchor, body))
        for p in points:
            label = ctx.point_label(p, body)
            if label in done:
                continue
            done.add(label)
            side = [point_term(ctx, level, anchor, body)] + rotation_terms(ctx, level, body, anchor, p, False)
            sec.blocks.append(Equation(target_term(ctx, level, p, body, True), [side], level,
                                       PointRef(p, body), figure=ctx.planar))
    return sec


def composition_section(ctx: Ctx, pairs: list[tuple[PointRef, str, Optional[str]]]) -> Optional[Section]:
    """Drag + relative (+ Coriolis) for each (point, moving frame, its pivot point)."""
    if not pairs:
        return None
    sec = Section(msg("sec.composition"))
    sec.add(msg("composition.intro", cor=Names(coriolis_forms(ctx, pairs))))
    for ref, moving, pivot in pairs:
        sec.blocks += composition(ctx, ref, moving, pivot)
    return sec


def coriolis_forms(ctx: Ctx, pairs: list[tuple[PointRef, str, Optional[str]]]) -> list[Inline]:
    """The Coriolis term 2 ω_M × v_{B∈N rel M} of each composed point, in the symbols its
    equations write (twenty-fourth round (c)): the notes' generic "2 ω × v_rel" named a
    vector the page never writes (the relative velocity is v_{B∈N rel M} on the page), and a
    reader looked for it. One form a distinct (point, body, moving frame)."""
    out: list[Inline] = []
    seen: set[tuple[str, str, str]] = set()
    for ref, moving, _ in pairs:
        key = (ref.point, ref.body, moving)
        if key not in seen:
            seen.add(key)
            out.append(_coriolis_form(ctx, ref, moving))
    return out


def _coriolis_form(ctx: Ctx, ref: PointRef, moving: str) -> Inline:
    """2 ω_M × v_{B∈N rel M}: the moving frame's angular velocity and the point's relative velocity."""
    return Inline(["2 ", omega_sym(moving, vector=not ctx.planar), " × ",
                   Sym("v", relative_name(ref.point, ref.body, moving))])


def composition(ctx: Ctx, ref: PointRef, moving: str, pivot: Optional[str]) -> list:
    """The decomposition of the engine's `decompose`, with its drag and relative parts expanded."""
    q = Question(DECOMPOSE.name, -1, ref, {}, None, moving)
    parts = decompose(ctx.sol, q)
    p, body = ref.point, ref.body
    out: list = [msg("composition.point", point=Name(p), body=Name(body, "body"), frame=Name(moving, "body"))]
    for level, key in (("v", "velocity"), ("a", "acceleration")):
        unit = "speed" if level == "v" else "accel"
        got = parts[key]
        drag = Term(Sym(level, p, sub_key="sub.drag"), ctx.clean(got["drag"], unit), *KNOWN, kind="drag")
        # the relative motion written as the steps and the answers write it, both bodies named
        # (v_{B∈N rel M}): one vector, one symbol on the page (round 19a)
        rel = Term(Sym(level, relative_name(p, body, moving)), ctx.clean(got["relative"], unit), *KNOWN,
                   kind="relative")
        side = [drag, rel]
        if level == "a":
            side.append(Term(Sym("a", p, sub_key="sub.cor"), ctx.clean(got["coriolis"], unit), Ann("M"),
                             Ann("D"), list(_coriolis_form(ctx, ref, moving).items), kind="coriolis"))
        target = Term(Sym(level, p), ctx.clean(got["total"], unit), *KNOWN, kind="point")
        out += [msg("composition.drag", kind=unit)] + _drag(ctx, level, p, moving, pivot, drag.sym)
        # one symbol for the relative motion (the notes' v_REL), its frame said in words, never
        # "v_REL = v_{P∈b rel m}": two names of one vector read as two vectors (round 16b)
        out += [msg("composition.relative", sym=rel.sym, frame=Name(moving, "body"))]
        out += _relative(ctx, level, ref, moving, pivot, rel.sym)
        out.append(Equation(target, [side], level, ref, figure=ctx.planar))   # the parts found, their sum
    return out


def _apart(ctx: Ctx, q: Optional[str], p: str) -> bool:
    """Whether q names a point at another place than p (a segment QP that is not zero)."""
    if q is None or q == p:
        return False
    d = ctx.num(ctx.r(q, p))
    return sum(c * c for c in d) ** 0.5 > 1e-9 * ctx.inst.scale


def _known_point(ctx: Ctx, body: str, p: str, prefer: Optional[str]) -> Optional[str]:
    """A point of `body` away from p whose motion is known: the preferred one (the joint
    with the carrier), a pivot on the frame, a pin shared with another body, any other."""
    model = ctx.model
    points = model.bodies[body].points
    pivots = [j.at for j in model.joints if {j.a, j.b} == {body, ctx.frame} and j.at]
    shared = [q for q in points if len(model.carriers(q)) > 1]
    for q in [prefer] + pivots + shared + list(points):
        if _apart(ctx, q, p) and (q in points or q == prefer):
            return q
    return None


def _drag(ctx: Ctx, level: str, p: str, moving: str, pivot: Optional[str], sym: Sym) -> list:
    """The drag motion: that of the moving frame's point at P, from a known point Q of the
    moving body away from P (O4 for the quick-return's rocker): v_Q + ω × QP."""
    q = (_still_centre(ctx, moving) if level == "v" else None) or _known_point(ctx, moving, p, pivot)
    target = _relabel(point_term(ctx, level, p, moving), sym)
    if q is None:
        return [Equation(target, [[point_term(ctx, level, p, moving)]], level, PointRef(p, moving), figure=False)]
    side = [point_term(ctx, level, q, moving)] + rotation_terms(ctx, level, moving, q, p, False)
    return [Equation(target, [side], level, PointRef(p, moving), figure=False)]


def _still_centre(ctx: Ctx, moving: str) -> Optional[str]:
    """The contact where the moving frame rolls on a fixed body: its point there is at rest,
    the frame's instant centre, so the drag velocity is a rotation about it, as the notes
    write C5-1.3's ("si terra = AB i suport = REL, el moviment d'arrossegament és de rotació
    al voltant de J"): v_ar,E = v_J∈support + v_EJ, never from the sleeve S. Velocities only:
    the contact point has an acceleration, and the drag acceleration stays from a point
    whose acceleration a step wrote."""
    if not ctx.planar:
        return None
    for j in ctx.model.joints:
        if not rolls(j) or moving not in (j.a, j.b) or ctx.sol.geometry(j.id).contact is None:
            continue
        other = j.a if j.b == moving else j.b
        if ctx.fixed(other):
            return ctx.contact(j)
    return None


def _relative(ctx: Ctx, level: str, ref: PointRef, moving: str, pivot: Optional[str], sym: Sym) -> list:
    """The relative motion seen from the moving body: along the guide when P slides in it,
    zero when P is the pin joining them, else a rotation about their joint."""
    p, body = ref.point, ref.body
    unit = "speed" if level == "v" else "accel"
    value = ctx.clean(ctx.vel(body, p, moving) if level == "v" else ctx.acc(body, p, moving), unit)
    joint = next((j for j in ctx.model.joints if {j.a, j.b} == {body, moving}), None)
    if joint is not None and guided(joint):
        seen = ctx.slides_seen.get((level, body, moving)) if slider(joint) else None
        if seen is not None:            # a slider does not turn on its guide: one relative motion, found above
            return [msg("composition.slide_seen", sym=sym, seen=seen, value=Value(value, unit), kind=unit,
                        joint=Name(joint.id, "joint"), point=Name(p), body=Name(body, "body"),
                        frame=Name(moving, "body"))]
        return [msg("composition.slide", sym=sym, value=Value(value, unit), joint=Name(joint.id, "joint"),
                    point=Name(p))]
    if joint is not None and joint.at and not _apart(ctx, joint.at, p):
        return [msg("composition.pin", sym=sym, point=Name(p), joint=Name(joint.id, "joint"))]
    q = joint.at if joint is not None and joint.at else pivot
    said: list = []
    if joint is not None and rolls(joint) and ctx.sol.geometry(joint.id).contact is not None:
        # rolling without slip: seen from the moving body the contact is the body's centre
        q = ctx.contact(joint)
        if level == "v":
            said = [msg("composition.rolls", body=Name(body, "body"), frame=Name(moving, "body"), point=Name(q),
                        sym=Sym("v", relative_name(q, body, moving)))]
    target = _relabel(target_term(ctx, level, p, body, True, moving), sym)
    if q is None or not _apart(ctx, q, p):
        return said + [Equation(target, [[target_term(ctx, level, p, body, True, moving)]], level, ref, moving,
                                figure=False)]
    side = [target_term(ctx, level, q, body, True, moving)] + rotation_terms(ctx, level, body, q, p, False, moving)
    return said + relative_rate(ctx, level, body, moving) + [Equation(target, [side], level, ref, moving,
                                                                         figure=False)]


def relative_rate(ctx: Ctx, level: str, body: str, moving: str) -> list:
    """ω_{b rel a} (α at accelerations) worked out before an equation whose terms use it
    (ω_{R rel N}·FA): from the absolute rates found above, composed the notes' way,
    ω_b = ω_{b rel a} + ω_a ⇒ ω_{b rel a} = ω_b − ω_a — a product a student cannot evaluate
    is never written. Planar (in space α_b/a is not α_b − α_a); once a page (`said_rate`)."""
    if not ctx.planar or moving == ctx.frame or said_rate(ctx, level, body, moving):
        return []
    sym, get, unit, kind = ((omega_sym, ctx.omega, "rate", "omega") if level == "v"
                            else (alpha_sym, ctx.alpha, "rate2", "alpha"))
    return [Derived(sym(body, moving), [sym(body), " − ", sym(moving)], ctx.value(get(body, moving), unit),
                    kind=kind, sense=not ctx.symbolic,
                    lead=composed(sym(body), sym(body, moving), sym(moving), body == ctx.frame))]


def said_rate(ctx: Ctx, level: str, body: str, frame: str) -> bool:
    """Whether the page has already worked out ω_{body rel frame} (α at accelerations), and
    marks it worked out from here on: a relative rate is derived once."""
    key = f"rate:{level}:{body}/{frame}"
    said = key in ctx.worked or f"relative:{body}/{frame}" in ctx.worked
    ctx.worked.add(key)
    return said


def _relabel(term: Term, sym: Sym) -> Term:
    term.sym = sym
    return term


def composition_pairs(ctx: Ctx) -> list[tuple[PointRef, str, Optional[str]]]:
    """The model's `decompose` questions (only what is asked: a composition nobody asked
    for, each point of each carried body, is noise)."""
    out = []
    for q in worked(ctx).compositions:
        if q.relative_to in (None, ctx.frame):
            ref = ctx.model.resolve_point(q.target) if isinstance(q.target, str) else q.target
            out.append((ref, q.moving, _pivot(ctx, ref.body, q.moving)))
    return out


def _pivot(ctx: Ctx, body: str, moving: str) -> Optional[str]:
    for j in ctx.model.joints:
        if {j.a, j.b} == {body, moving} and j.at:
            return j.at
    return None
