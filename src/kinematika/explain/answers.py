"""The model's questions answered, and the curvature of paths worked out (seed 002):
a = aᵗ + aⁿ with aᵗ ∥ v and aⁿ ⊥ v, then ℜ = v² / |aⁿ| (the notes' ℜ: ρ is a circle's radius)."""
from __future__ import annotations

from typing import Any

from ..model.model import PointRef
from ..questions import QUESTIONS, answer
from ..questions.curvature import intrinsic
from .asked import worked
from .context import Ctx, alpha_sym, composed, omega_sym, segment
from .context import fixed_sign as _sign_fixed
from .document import Ann, Derived, Equation, Inline, Msg, Name, Section, Sym, Table, Term, Told, Value, msg, point as point_name
from .paths import circle_about
from .terms import KNOWN
from .words import ExplainWords

UNITS = {"velocity": "speed", "acceleration": "accel", "omega": "rate", "alpha": "rate2",
         "drag": None, "relative": None, "coriolis": None, "total": None, "point": "len",
         "center": "len", "radius": "len", "direction": "", "speed": "speed", "tangent": "",
         "tangential": "accel", "normal": "accel", "tangential_vector": "accel",
         "normal_vector": "accel", "omega_axis": "rate", "slide": "speed", "pole": "len",
         "diameter": "len", "inflection_pole": "len", "pole_velocity": "speed"}


def answers_section(ctx: Ctx) -> Section:
    """The model's questions, each named as a textbook names it (v_C, ω_rocker, the
    composition of the motion of A…) with its answer's parts labelled by their symbols."""
    sec = Section(msg("sec.answers"))
    rows: list = []
    for q in ctx.model.questions:
        items = answer_items(ctx, q, answer(ctx.sol, q))
        if QUESTIONS[q.kind].placed and ctx.planar:
            items += centre_from_point(ctx, q)
        for row in question_rows(ctx, q, items):
            if row not in rows:    # a fixed point asked of every body it belongs to: once
                rows.append(row)
    if ctx.planar:                 # the spins the notes ask of a vehicle's wheels (notation spin(j))
        from .vehicles import spin_values

        rows += [[spin, [("", value)]] for _, _, spin, value in spin_values(ctx)]
    if rows:
        sec.add(Table([msg("col.question"), msg("col.answer")], rows))
    else:
        sec.add(msg("answers.none"))
    sec.add(Told("notes"))
    return sec


def centre_from_point(ctx: Ctx, q) -> list:
    """An instant centre placed on a line through a known point is also said as its distance
    from that point, as the notes give it: C5-1.4's planet centre "(2/5)r from the centre"
    (A1, on the line A1N), C5-E.6's pedals' centre d = R_roda R/r below C (on the
    perpendicular to v_C through C), C5-1.5's r/2 from C3. The point is the one the centre
    was placed from (`CentreNote`: the field's or the rate's Q, the parallel velocities' Q),
    or, between two turning points, the nearer one (`centres._nearer`, which the centre's
    own sentence says too); none for a centre at a joint, by Aronhold–Kennedy's lines, or at
    infinity."""
    import sympy

    from .centres import _notes

    key = frozenset((ctx.rel(q.relative_to) or ctx.frame, q.target))
    note = _notes(ctx)[0].get(key)
    if note is None or note.value.get("point") is None:
        return []
    if note.how in ("field", "rate", "parallel") and note.witnesses and note.distance is not None:
        point, distance = note.witnesses[-1][0], note.distance
    elif note.how == "proportional" and note.near and note.distance is not None:    # centres._nearer
        point, distance = note.near, note.distance
    else:
        return []
    return [(msg("ans.from", point=Name(point)), Value(ctx.clean(sympy.simplify(distance), "len"), "len"))]


def question_rows(ctx: Ctx, q, items: list) -> list[list]:
    """The question's rows of the answers table: one, labelled by what is asked; or, for a
    kind whose parts are quantities of their own (`rows_by_part`: the three coincident
    points of a contact), a row for each part labelled by its symbol, as the notes list
    point), after a row with what is asked and the parts without a symbol, if any answers
    something: the contact's position is the Data's (the points' table gives it), and a row
    "the three coincident points at the contact J | position = (0, 2·r)" answers nothing
    (issue 30, twenty-eighth round (d): the symbols v_{J∈wheel}, v_{J^geom} say whose rows
    follow)."""
    if not QUESTIONS[q.kind].rows_by_part:
        return [[question_label(ctx, q), items]]
    own = [(label, value) for label, value in items if isinstance(label, Sym)]
    rest = [(label, value) for label, value in items if not isinstance(label, Sym) and not _given_position(label)]
    return ([[question_label(ctx, q), rest]] if rest else []) + [[label, [("", value)]] for label, value in own]


def _given_position(label: Any) -> bool:
    """A part that is the asked point's position (`ans.point`): a datum of the points' table,
    not an answer."""
    return isinstance(label, Msg) and label.key == "ans.point"


def question_label(ctx: Ctx, q) -> Any:
    """The asked quantity as a symbol, or a sentence for the compound questions (the kind's
    `label`)."""
    return QUESTIONS[q.kind].label(ExplainWords(ctx), q)


def answer_items(ctx: Ctx, q, value: Any) -> list:
    """The answer as [(label, Value)]: a label is a symbol or a message, never a raw key."""
    if not isinstance(value, dict):
        found = _value(ctx, value, UNITS.get(QUESTIONS[q.kind].unit_kind) or "")
        return [("", _sensed(ctx, q, found))]
    if value.get("rest"):
        return [("", msg("ans.rest"))]
    if value.get("translation"):
        return [("", msg("ans.translation"))]
    out: list[tuple[Any, Any]] = []
    for key, v in value.items():
        if key in QUESTIONS[q.kind].working:        # derived in a step before (`intrinsic_lines`)
            continue
        if key == "center" and isinstance(getattr(q, "target", None), PointRef):
            label = ctx.point_label(q.target.point, q.target.body)
            where = centre_from(ctx, q.target, label, value)
            if where is not None:           # said from its point, as the curvature section says it
                out.append(("", msg("ans.center_from", where=where)))
                continue
        if isinstance(v, dict):
            for sub, w in v.items():
                out.append((_part_label(ctx, q, key, sub), _value(ctx, w, UNITS.get(sub) or UNITS[key] or "")))
        elif v is not None and key != "rest":
            out.append((_part_label(ctx, q, key, None), _value(ctx, v, UNITS.get(key) or "")))
    return out


def _sensed(ctx: Ctx, q, found: Value) -> Any:
    """A planar body's ω or α with its sense, counter-clockwise or clockwise, as the notes ask
    it ("el valor i sentit de la precessió", C5-2.1: ψ̇ = √2·v₀/(2·L) (counter-clockwise)):
    the sign of a number, or of a formula whose sign its symbols fix (the model's positive
    parameters, v₀ and L: −v/R is clockwise; −2·θ̈ with θ̈ of either sign has no sense to
    say); a zero rate has none."""
    kind = QUESTIONS[q.kind]
    if not ctx.planar or kind.unit_kind not in ("omega", "alpha") or kind.about != "body":
        return found
    sign = _sign_fixed(ctx, found.value)
    if sign == 0:
        return found
    return msg("ans.sensed", value=Value(found.value, found.unit, True), sense=msg("sense.ccw" if sign > 0 else "sense.cw"))


def _part_label(ctx: Ctx, q, key: str, sub: str | None) -> Any:
    """A part's label as the kind writes it (`part`), else the field's word."""
    found = QUESTIONS[q.kind].part(ExplainWords(ctx), q, key, sub)
    return found if found is not None else msg(f"ans.{key}")


def _value(ctx: Ctx, value: Any, unit: str) -> Value:
    if isinstance(value, (tuple, list)):
        return Value(ctx.clean(tuple(value), unit or "len"), unit)
    if value is None or isinstance(value, (bool, str)):
        return Value(value, "")
    return Value(ctx.clean(value, unit or "len"), unit)


def relative_rates(ctx: Ctx) -> list[Derived]:
    """Each ω (α) asked relative to a moving body, from the absolute ones (planar):
    ω_b/a = ω_b − ω_a, as the composition of rotations gives it."""
    out: list[Derived] = []
    for q in ctx.model.questions:
        rel = ctx.rel(q.relative_to)
        kind = QUESTIONS[q.kind]                  # a body's ω or α (its table's column)
        if not (kind.column and kind.about == "body") or rel is None or not ctx.planar:
            continue
        body = q.target
        assert isinstance(body, str), f"{q.where}: a question about a body names the body"
        if f"relative:{body}/{rel}" in ctx.worked:
            continue            # a step found it (a belt seen from its arm): not again, backwards
        ctx.worked.add(f"rate:{'v' if kind.unit_kind == 'omega' else 'a'}:{body}/{rel}")    # said here
        sym, get = (omega_sym, ctx.omega) if kind.unit_kind == "omega" else (alpha_sym, ctx.alpha)
        unit = UNITS[kind.unit_kind] or ""      # omega and alpha: each has its unit
        out.append(Derived(sym(body, rel), [sym(body), " − ", sym(rel)], ctx.value(get(body, rel), unit),
                           kind=kind.unit_kind, sense=not ctx.symbolic,
                           lead=composed(sym(body), sym(body, rel), sym(rel), body == ctx.frame)))
    return out


def curvature_section(ctx: Ctx) -> Section | None:
    """Each `curvature` question: the acceleration split along and across the velocity; and
    each `intrinsic` question's working (`intrinsic_lines`), after its point's split, so that
    the answers table gives only the asked aᵗ and aⁿ (round 24d: C5-1.7's answer row carried
    |v_P|, t, aᵗ · t and |aⁿ|, symbols the page never derived)."""
    asked = [q for q in worked(ctx).curvatures if ctx.planar]
    split = [q for q in ctx.model.questions if QUESTIONS[q.kind].working and ctx.planar]
    if not asked and not split:
        return None
    sec = Section(msg("sec.curvature"))
    sec.add(msg("curvature.intro", rho=Inline([Sym("ℜ", vector=False), " = |", Sym("v"), "|² / |",
                                               Sym("a", sup="n"), "|"])))
    for q in asked:
        sec.blocks += curvature_steps(ctx, q)
    for q in split:
        at = next((k for k, b in enumerate(sec.blocks) if isinstance(b, Equation) and b.point == q.target
                   and b.relative_to == q.relative_to), None)
        lines = intrinsic_lines(ctx, q)
        if at is None:                      # no curvature asked of the point: its split first
            kept = [b for b in curvature_steps(ctx, q)
                    if isinstance(b, Equation) or getattr(b, "key", "") == "curvature.point"]
            first = next((k for k, b in enumerate(kept) if isinstance(b, Equation)), len(kept))
            sec.blocks += kept[:first] + lines + kept[first:]
        else:                               # the derivation before the split it gives
            sec.blocks[at:at] = lines
    return sec


def intrinsic_lines(ctx: Ctx, q) -> list:
    """The intrinsic components of a point's acceleration, worked out from its velocity: |v|,
    the unit tangent t = v/|v|, aᵗ = (a · t) t with a · t signed, and aⁿ = a − aᵗ with |aⁿ|;
    said as the derivation it is, before the split a = aᵗ + aⁿ it gives (twenty-fifth round
    (a): after the split's bullets it read as their repetition)."""
    result = answer(ctx.sol, q)
    if result.get("rest"):
        return []
    label = ctx.point_label(q.target.point, q.target.body)
    v, t = Sym("v", label), Sym("t")
    speed = Value(ctx.clean(result["speed"], "speed"), "speed")
    tangent = Value(ctx.clean(tuple(result["tangent"]), ""), "")
    along = Value(ctx.clean(result["tangential"], "accel"), "accel")
    across = Value(ctx.clean(result["normal"], "accel"), "accel")
    return [msg("curvature.intrinsic", point=Name(label),
                speed=Inline(["|", v, "| = ", speed]),
                tangent=Inline([t, " = ", v, "/|", v, "| = ", tangent]),
                split=Inline([Sym("a", label, "t"), " = (", Sym("a", label), " · ", t, ") ", t]),
                tangential=Inline([Sym("a", label), " · ", t, " = ", along]),
                rest=Inline([Sym("a", label, "n"), " = ", Sym("a", label), " − ", Sym("a", label, "t")]),
                normal=Inline(["|", Sym("a", label, "n"), "| = ", across]))]


def curvature_steps(ctx: Ctx, q) -> list:
    """The curvature of a point's path as the notes work it out: its velocity, then a = aᵗ + aⁿ
    with aᵗ ∥ v and aⁿ ⊥ v (the solver's split), then ℜ = |v|² / |aⁿ| and the centre of
    curvature; a point at rest or a straight path (aⁿ = 0) is said so instead."""
    ref: PointRef = q.target
    rel = q.relative_to
    v, a = ctx.sol.velocity(ref, rel), ctx.sol.acceleration(ref, rel)
    result = answer(ctx.sol, q)
    label = ctx.point_label(ref.point, ref.body)
    if result.get("rest"):
        return [msg("curvature.rest", point=Name(label))]
    origin = circle_about(ctx, ref) if rel in (None, ctx.frame) and result.get("radius") is not None else None
    if origin is not None:                    # a circle the structure gives: read off, not derived again
        return circle_steps(ctx, label, origin, result)
    split = intrinsic(ctx.sol, q)             # the solver's aᵗ and aⁿ of the same point
    at, an = split["tangential_vector"], split["normal_vector"]
    target = Term(Sym("a", label), ctx.clean(a, "accel"), *KNOWN, kind="point")
    tangential = Term(Sym("a", label, "t"), ctx.clean(at, "accel"), Ann("?"),
                      Ann("para", Sym("v", label)), unknown=True, kind="tangential")
    normal = Term(Sym("a", label, "n"), ctx.clean(an, "accel"), Ann("?"),
                  Ann("perp", Sym("v", label)), unknown=True, kind="normal")
    out: list = [msg("curvature.point", point=Name(label), v=Value(ctx.clean(v, "speed"), "speed")),
                 Equation(target, [[tangential, normal]], "a", ref, rel, figure=False)]
    if result.get("radius") is None:
        out.append(msg("curvature.straight", point=Name(label)))
        return out
    radius = Value(ctx.clean(result["radius"], "len"), "len")
    out.append(Derived(Sym("ℜ", label, vector=False), ["|", Sym("v", label), "|² / |", Sym("a", label, "n"), "|"],
                       radius, kind="radius", source=normal, arm=ctx.clean(v, "speed")))
    out += named_length(ctx, label, result["radius"])
    where = centre_from(ctx, ref, label, result)
    if where is not None:
        out.append(msg("curvature.centre_from", point=Name(label), where=where))
    else:
        out.append(msg("curvature.centre", point=Name(label), centre=Value(ctx.clean(result["center"], "len"), "len")))
    return out


def named_length(ctx: Ctx, label: str, radius: Any) -> list:
    """A symbolic radius of curvature written again with a length the page has found before,
    when that shortens it: an instant centre's distance from its point (C5-E.6: the pedals'
    centre d = CI_chainring = R·R_roda/r below C gives ℜ_P = (d − L)²/L, the notes' form, for
    (R·R_roda − L·r)²/(L·r²)). The length is called d, as the notes call it, unless the model
    has a d of its own; none when no found length shortens the radius by a few operations."""
    import sympy

    from .centres import _notes

    if not ctx.symbolic or not ctx.planar:
        return []
    d = sympy.Symbol("d", positive=True)
    if "d" in ctx.model.parameters or "d" in {str(x) for x in sympy.sympify(radius).free_symbols}:
        return []
    shown = sympy.sympify(ctx.clean(radius, "len"))
    best = None
    for note in _notes(ctx)[0].values():
        if note.how not in ("field", "rate") or note.distance is None or not note.witnesses:
            continue
        dist = sympy.simplify(sympy.sympify(note.distance))
        if dist.is_number or "d" in {str(x) for x in dist.free_symbols}:
            continue
        for x in sorted(dist.free_symbols, key=str):
            sol = sympy.solve(sympy.Eq(dist, d), x)
            if len(sol) != 1:
                continue
            new = sympy.factor(sympy.simplify(shown.subs(x, sol[0])))
            if x in new.free_symbols or sympy.count_ops(new) > sympy.count_ops(shown) - 3:
                continue
            if best is None or sympy.count_ops(new) < sympy.count_ops(best[0]):
                body = next(b for b in note.pair if b != ctx.frame)
                best = (new, note.witnesses[-1][0], body, dist)
    if best is None:
        return []
    new, q, body, dist = best
    return [msg("curvature.named", rho=Sym("ℜ", label, vector=False), d=Name("d", "param"),
                arm=Inline([Name(q), Sym("I", body, vector=False)]), length=Value(ctx.clean(dist, "len"), "len"),
                value=Value(new, "len"))]


# a symbolic centre of curvature whose coordinates take more operations than this is said
# from its point ("ℜ_P above P"), not by its coordinates (C5-E.6's (b; R_roda + r + … − R))
LONG_CENTRE = 8


def centre_from(ctx: Ctx, ref: PointRef, label: str, result: dict) -> Msg | None:
    """Where a symbolic centre of curvature is, said from its point along the normal — "at ℜ_P
    above P" — when its coordinates are past reading (issue 30, round 29 c: C5-E.6's
    "(b; R_roda + r + (R·R_roda − L·r)²/(L·r²) − L − R)"); None when they are short, or the
    model is numeric, which the coordinates then say best."""
    import sympy

    centre = result.get("center")
    if not ctx.symbolic or centre is None or result.get("radius") is None:
        return None
    shown = ctx.clean(centre, "len")
    if sum(sympy.count_ops(sympy.sympify(c)) for c in shown) <= LONG_CENTRE:
        return None
    at = ctx.pos(ref.point)
    dx, dy = (float(ctx.num(c)) - float(ctx.num(p)) for c, p in zip(centre, at))
    size = max(abs(dx), abs(dy)) or 1.0
    side = ("up" if dy > 0 else "down") if abs(dx) < 1e-9 * size else \
        ("right" if dx > 0 else "left") if abs(dy) < 1e-9 * size else "other"
    return msg("curvature.from", side=side, rho=Sym("ℜ", label, vector=False), point=Name(label),
               an=Sym("a", label, "n"))


def circle_steps(ctx: Ctx, label: str, origin: str, result: dict) -> list:
    """The curvature of a path the structure makes a circle about the fixed point O
    (`paths.circle_about`): ℜ_C = OC and the centre of curvature is O, as the notes read it
    (C5-1.7: "trajectòria circular de radi 3r") — not ℜ = |v|² / |aⁿ| with the aⁿ = v² / OC
    a step already wrote, which would give OC back from OC."""
    oc = point_name(str(segment(origin, label)))
    radius = Value(ctx.clean(result["radius"], "len"), "len")
    return [msg("curvature.circle", point=Name(label), o=point_name(origin), radius=oc),
            Derived(Sym("ℜ", label, vector=False), [oc], radius, kind="radius"),
            msg("curvature.circle_centre", point=Name(label), o=point_name(origin),
                centre=Value(ctx.clean(result["center"], "len"), "len"))]
