"""The whole explanation of a solved instant, in the notes' order.

Planar: structure and order of solution, velocities and accelerations step by step,
instant centres, composition of motions asked for, curvature, answers. Spatial (the fan):
structure, absolute angular velocity and acceleration body by body, the fields of
velocities and accelerations, composition of motions, answers.
"""
from __future__ import annotations

import re
from typing import Any, Optional

from ..draw.names import body_numbers
from ..solution import Solution
from .answers import answers_section, curvature_section, relative_rates
from .asked import worked
from .checks import checks_section
from .contacts import contact_section
from .centres import centre_sites, centres_first, centres_in_steps, centres_section
from .found_first import centres_after_found
from .context import Ctx, omega_sym, point_labels
from .data import contact_rows, data_section
from .drives import drives
from .strands import strand_words
from .document import Ann, CentreNote, Derived, Document, Equation, Inline, Msg, Name, Names, Section, Sym, Term, Value, msg
from .group import refine
from .material import material_contacts
from .order import asked_order, solution_order
from .planar import PlanarSteps
from .marks import worded_marks
from .needs import accelerations_asked, centres_asked_first, prune
from .polygon import degenerate, level_polygon, polygon, term_steps
from .terms import acceleration_terms
from .positions import position_section
from .spatial import composition_pairs, composition_section, fields_section, rates_section
from .structure import derived_arrows, moduli_units, reorder, structure_section, values_table, name_contacts
from .translating import translations


def build(sol: Solution, length_unit: str = "m") -> Document:
    """The `Document` of `sol`: every value in it is read from the solution. Built once:
    pairs of points are run together (AB, OA1) whatever the labels (`context.segment`)."""
    ctx = Ctx(sol)
    if ctx.planar:                     # the contacts' names known before any segment is named
        for j in ctx.model.joints:
            if getattr(j.kind, "touches", False):
                ctx.contact(j)
    with point_labels(ctx.labels):
        return _build(ctx, length_unit)


def _build(ctx: Ctx, length_unit: str) -> Document:
    """The `Document` of the solution `ctx` reads."""
    sol = ctx.sol
    accel = accelerations_asked(ctx)
    wanted = ("v", "a") if accel else ("v",)
    levels: list[Section] = []
    doc = Document(sol.model.name, sol.symbolic, sol.space.dim, length_unit,
                   numbers=body_numbers(sol.model), wording=sol.model.wording)
    doc.sections.append(data_section(ctx, length_unit, accel))
    if ctx.planar:
        steps = asked_order(ctx, refine(ctx, solution_order(sol)))
        structure = structure_section(ctx, steps)
        doc.sections.append(structure)
        placed = position_section(ctx)
        if placed is not None:
            doc.sections.append(placed)
        first = centres_first(ctx, steps)
        if first:                          # the notes' order: the centres, then the velocities from them
            sites, ctx.translating = centre_sites(ctx)
            ctx.centre_sites = {name: b for name, (b, _) in sites.items()}
            ctx.centre_points = {name for name in sites if name not in ctx.inst.points}
            placed_first = centres_section(ctx, "first")
            doc.sections.append(placed_first)
        for level in wanted:
            sec = PlanarSteps(ctx, steps, level).section()
            levels.append(sec)
            doc.sections.append(sec)
        reorder(ctx, structure, steps)       # the order as the velocity steps found the bodies
        summary = Section(msg("sec.rates_summary" if accel else "sec.rates_summary_v"))
        wraps = drives(ctx)                # a belt's run gets no rate; a fixed pulley it wraps, its 0
        summary.add(values_table(ctx, accel, frozenset(d.line for d in wraps),
                                 any(ctx.frame in (d.a, d.b) for d in wraps)))
        summary.blocks += relative_rates(ctx)
        doc.sections.append(summary)
        contacts = contact_section(ctx, _written_points(levels, wanted))
        if contacts is not None:
            doc.sections.append(contacts)
        checked = checks_section(ctx)
        if checked is not None:
            doc.sections.append(checked)
        if first:
            for sec, level in zip(levels, wanted):
                if level == "v":
                    centres_after_found(ctx, placed_first, sec)     # a centre read off velocities, after them
                    centres_in_steps(ctx, sec)      # a centre from two parallel velocities, where they are known
            rest = centres_section(ctx, "rest")
            if rest is not None:
                doc.sections.append(rest)
        elif ctx.model.default_questions or worked(ctx).centres:
            ctx.centre_notes = None         # read again: a rate the steps found gives a centre (0 = v_Q + ω × QI)
            centres = centres_section(ctx)      # only what is asked (the slides ask none)
            if len(levels) > 1 and centres_asked_first(ctx):
                doc.sections.insert(doc.sections.index(levels[0]) + 1, centres)
            else:
                doc.sections.append(centres)
        for sec, level in zip(levels, wanted):
            for eq in _equations(sec):
                for t in (t for side in eq.sides for t in side if t.kind == "slide"):
                    m = RELATIVE.match(t.sym.sub)
                    if m:
                        ctx.slides_seen.setdefault((level, m.group(2), m.group(3)), t.sym)
        coriolis_by_point(ctx, doc.sections)
    else:
        doc.sections.append(structure_section(ctx, []))
        doc.sections.append(rates_section(ctx, accel))
        doc.sections += [fields_section(ctx, level) for level in wanted]
    extra = [composition_section(ctx, composition_pairs(ctx)), curvature_section(ctx)]
    doc.sections += [s for s in extra if s is not None]
    doc.sections.append(answers_section(ctx))
    for eq in doc.equations():
        found_forward(eq)
    prune(ctx, doc)
    refer_drags(ctx, doc, levels)
    refer_reverses(ctx, doc, levels)
    refer_rates(ctx, doc, levels)
    refer_placed(doc, levels)
    translations(ctx, doc)
    material_contacts(levels)
    derived_arrows(ctx, doc, next((s for s, lv in zip(levels, wanted) if lv == "v"), None))
    name_contacts(ctx, doc, contact_rows(ctx, doc))
    moduli_units(ctx, doc, length_unit)
    strand_words(ctx, doc.sections)
    said = relative_convention(doc)
    if said is not None:
        doc.sections[0].blocks.insert(2, said)
    for sec, level in zip(levels, wanted):
        level_polygons(ctx, sec, level)
        if level == "a":
            _name_terms(sec)
    in_levels = {id(e) for sec in levels for e in _equations(sec)}
    for eq in doc.equations():
        if id(eq) not in in_levels:
            eq.polygon = polygon(ctx, eq)
    doc.joints = joint_places(ctx)
    doc.parameters = tuple(ctx.model.parameters)
    doc.values = ctx.drawn_values() if ctx.symbolic else {}
    doc.worded_marks = worded_marks(ctx)
    for b in doc.blocks():              # the legend names the marks that are also points (`marks`)
        if isinstance(b, Msg) and b.key == "v.intro":
            b.args["marks"] = len(doc.worded_marks)
            b.args["clash"] = doc.worded_marks[0] if doc.worded_marks else ""
    return doc



def joint_places(ctx: Ctx) -> dict:
    """How the text names each joint, never by its id (j3): by its point (the pin A, the
    wheel RL), by its contact (J, F) when it touches, else by the two bodies it joins
    (body, other) — as the notes name a joint by what it is and where."""
    out: dict = {}
    for j in ctx.model.joints:
        if j.at:
            out[j.id] = j.at
        elif getattr(j.kind, "touches", False) and ctx.planar:
            out[j.id] = ctx.contact(j)
        else:
            out[j.id] = (j.b, j.a)
    return out


SPLIT = 14          # a level polygon with more arrows than this is drawn step by step


def level_polygons(ctx: Ctx, sec: Section, level: str) -> None:
    """The level's polygon at its end; one per step when a single one would be a star of
    overlapping arrows (the epicyclic train's accelerations); none when it is `degenerate`
    (its arrows on one line, its images piled up: C5-1.5's pulleys)."""
    whole = level_polygon(ctx, _equations(sec), level)
    if whole is None or degenerate(whole):         # a line of arrows with piled-up images: left out
        return
    whole.caption.args.update(drawn_steps(sec, level, term_steps(ctx, whole, [
        (n, [e for e in _equations(step) if e.level == level]) for n, step in _steps(sec)])))
    steps = [b for b in sec.blocks if isinstance(b, Section)]
    if len(whole.arrows) <= SPLIT or len(steps) < 2:
        sec.add(whole)
        return
    for step in steps:
        drawn = level_polygon(ctx, _equations(step), level, step=True)
        if drawn is not None:
            step.add(drawn)


def drawn_steps(sec: Section, level: str, terms: Optional[list[int]] = None) -> dict[str, object]:
    """The steps whose equations a level polygon draws, as its caption names them ("the terms of
    the equations of Steps 1 to 5", of Steps 1 and 2, of Step 1): a back-reference names the step,
    never "the equations above" (issue 30, seventeenth round b). `terms`: the steps whose
    equations draw its black arrows (`polygon.term_steps`), which the caption then names."""
    drawn = terms or [n for n, step in _steps(sec) if any(e.level == level for e in _equations(step))] or [0]
    first, last = min(drawn), max(drawn)
    span = min(last - first + 1, 3)             # 1 step, 2 steps ("1 and 2"), more ("1 to 5")
    return {"first": first, "last": last, "span": span}


RELATIVE = re.compile(r"^([^∈/,]+)∈([^∈/,]+)/([^∈/,]+)$")


def relative_convention(doc: Document) -> Optional[Msg]:
    """The one convention of relative quantities, said once in the Data section when the
    explanation writes any: v_A∈4/2 is the velocity of A as a point of 4 seen from 2 (never
    its opposite, whatever the equation's route), ω_4/2 = the rate of 4 relative to 2. The
    bodies are said by their names, with their articles (the *bar* seen from the *support*),
    where a language's phrase takes a noun ("of body bar" read as words with no article);
    Basque puts its case endings on the classifier noun (barra solidoaren)."""
    numbers = doc.numbers
    for eq in doc.equations():
        for t in eq.terms:
            m = RELATIVE.match(t.sym.sub)
            if m and m.group(2) in numbers and m.group(3) in numbers:
                point_, b, a = m.groups()
                return msg("data.relative", v=Sym("v", t.sym.sub), point=Name(point_), w=omega_sym(b, a),
                           body_b=Name(b, "body"), body_a=Name(a, "body"),
                           rate="yes" if writes_rate(doc, f"{b}/{a}") else "no")
    return None


def writes_rate(doc: Document, sub: str) -> bool:
    """Whether the explanation writes the relative rate ω (or α) with subscript `sub` (b/a)
    in an equation or a result: the Data's convention defines ω_{b rel a} only then (a reader
    met "ω_{N rel M} the angular velocity of the block N relative to the guide M" on a page
    that never wrote it; issue 30, stop 46)."""
    rates = [d.sym for d in doc.derived()]
    rates += [t.sym for eq in doc.equations() for t in eq.terms]
    return any(s.base in ("ω", "α") and s.sub == sub for s in rates)


def found_forward(eq: Equation) -> None:
    """One rule for every equation (seed 001's bookkeeping): an equation whose terms are all
    known finds its left side, which is marked as found (? ?, in red) — a forward
    evaluation reads the same in every explanation; an equation with unknown terms keeps its
    known left side (M D)."""
    if any(t.unknown for side in eq.sides for t in side):
        return
    eq.target.unknown = True
    eq.target.mag, eq.target.dir = Ann("?"), Ann("?")


def _name_terms(sec: Section) -> None:
    """The acceleration section's opening sentence names only the kinds of terms its
    equations contain (`acceleration_terms`), read once the equations nothing needs are
    pruned: no Coriolis term is said known where none is written."""
    for m in sec.blocks:
        if isinstance(m, Msg) and m.key == "a.intro":
            m.key = {"coriolis": "a.intro", "relative": "a.intro_relative",
                     "normal": "a.intro_normal"}[acceleration_terms(_equations(sec))]


def refer_drags(ctx: Ctx, doc: Document, levels: list[Section]) -> None:
    """A drag the steps already wrote is referred to, not written again: where the
    composition's v_arr,B (a_arr,B) is the motion of a material point whose equation a step
    kept (001's v_B∈M = v_A + v_BA), the section says v_arr,B = v_B∈M = (value), found in
    Step 1 — the same equation twice on one page reads as a new step. The reference names
    the step by its number (`step_of`), never "the steps above": a teacher's reader looks
    for Step 1, not for whatever is above."""
    kept: dict = {}
    sums: list = []                      # (each step side's terms, as written; the step's number)
    named: list = []                     # each drag a step named: (level, v_arr,B, v_B∈M, B)
    for sec in levels:
        for n, step in _steps(sec):
            for eq in _equations(step):
                if eq.point is not None and eq.relative_to in (None, ctx.frame) and eq.sides:
                    kept.setdefault((eq.level, ctx.motion_key(eq.point.point, eq.point.body)), (eq.target, n))
                sums += [([_written(t.sym) for t in side], n) for side in eq.sides]
    for sec in doc.sections:
        if not isinstance(sec.title, Msg) or sec.title.key != "sec.composition":
            continue
        moving = None                    # the moving frame of the point composed below
        for k, b in enumerate(sec.blocks):
            if isinstance(b, Msg) and b.key == "composition.point":
                moving = b.args["frame"]
            if not isinstance(b, Equation) or b.target.sym.sub_key != "sub.drag" or b.point is None:
                continue
            seen = kept.get((b.level, ctx.motion_key(b.point.point, b.point.body)))
            value = Value(b.target.value, "speed" if b.level == "v" else "accel")
            drag = [_written(t.sym) for t in b.sides[0]] if b.sides else []
            first = next((n for side, n in sums if len(drag) > 1 and side[:len(drag)] == drag), None)
            if seen is not None and moving is not None:
                # the quantity by its name and the point by what it is, the moving frame's point
                # that coincides with B — never "the motion of that point" for v and a alike
                sec.blocks[k] = msg("composition.drag_seen", sym=b.target.sym, seen=seen[0].sym, value=value,
                                    step=seen[1], kind="speed" if b.level == "v" else "accel",
                                    point=Name(b.point.point), frame=moving)
                named.append((b.level, b.target.sym, seen[0].sym, b.point.point))
            elif first is not None:
                terms: list = []           # the drag is the first terms of a step's sum: v_B + v_{A-B}
                for t in b.sides[0]:
                    terms += ([" + "] if terms else []) + [t.sym]
                sec.blocks[k] = msg("composition.drag_terms", sym=b.target.sym, terms=Inline(terms), value=value,
                                    step=first)
        _refer_sums(ctx, sec, levels)
        for said in (b for b in sec.blocks if isinstance(b, Msg) and b.key == "composition.slide_seen"):
            found = step_of(levels, said.args["seen"])
            if found is not None:
                said.key, said.args["step"] = "composition.slide_seen_step", found
    _name_drags(doc, named)


def _name_drags(doc: Document, named: list) -> None:
    """A drag velocity the steps wrote under its own name (001's v_B∈M) has two names on the
    page; their equality is said once, in the notation line under the structure, before the
    figure that draws v_arr,B and the steps that write v_B∈M, and the composition then writes
    v_arr,B alone (twenty-fourth round (c): "v_ar,B = v_B∈M" met only in the composition,
    after the caption had used v_ar,B). The legend's message carries them as `drags`."""
    if not named:
        return
    for sec in doc.sections:
        for b in sec.blocks:
            if isinstance(b, Msg) and b.key == "structure.subscripts":
                b.args["drags"] = list(named)


def _refer_sums(ctx: Ctx, sec: Section, levels: list[Section]) -> None:
    """The composition's sum v_P = v_arr,P + v_rel,P (+ a_Cor,P) where a step's equation was
    that very sum, the point's motion on its guide body plus its slide along the guide
    (001's v_{B∈rocker} = v_{B∈M} + v_{B∈N rel M}): the section refers to that step, "so
    v_{B∈rocker} = v_arr,B + v_rel,B is the equation of Step 2, which found v_{B∈rocker}",
    naming the point as the step does, and does
    not derive v_B again (a result is derived once, round 17a)."""
    found: dict = {}
    for level_sec in levels:
        for n, step in _steps(level_sec):
            for eq in _equations(step):
                if eq.point is None:
                    continue
                for side in eq.sides:
                    for t in side:
                        m = RELATIVE.match(t.sym.sub) if t.kind == "slide" else None
                        if m and m.group(1) == eq.point.point:
                            key = (eq.level, ctx.motion_key(eq.point.point, m.group(2)), m.group(2), m.group(3))
                            found.setdefault(key, (found_by(step, eq), n, eq.target.sym))
    moving = None
    for k, b in enumerate(sec.blocks):
        if isinstance(b, Msg) and b.key == "composition.point":
            moving = b.args["frame"].text
        if not isinstance(b, Equation) or b.point is None or b.target.kind != "point" or not b.sides:
            continue
        if not any(t.kind == "drag" for t in b.sides[0]):
            continue
        seen = found.get((b.level, ctx.motion_key(b.point.point, b.point.body), b.point.body, moving))
        if seen is None:
            continue
        terms: list = []
        for t in b.sides[0]:
            terms += ([" + "] if terms else []) + [t.sym]
        # the sum names the point as the step's equation does (twenty-first round (b): 001's
        # "So v_B = v_{drag,B} + …" beside Step 2's v_{B∈rocker}: one velocity, one name)
        sec.blocks[k] = msg("composition.sum_seen", sym=seen[2], terms=Inline(terms), seen=seen[0], step=seen[1])


def found_by(step: Section, eq: Equation) -> Names:
    """What a step's equation found: the target when it is unknown (001's v_{B∈rocker}), else
    its unknown terms, each said by the rate read off it (ω_N from v_AB) or by its own symbol.
    A datum on the left (001's rolling pair: v_A, a_A given) is not something the step found:
    "the equation of Step 2, which found ω_N and v_{A∈R rel N}", never "which found v_A"."""
    if eq.target.unknown:
        return Names([eq.target.sym])
    reads = {id(d.source): d.sym for d in _blocks(step) if isinstance(d, Derived) and d.source is not None}
    out: list = []
    for side in eq.sides:
        for t in side:
            if t.unknown:
                sym = reads.get(id(t), t.sym)
                if sym not in out:
                    out.append(sym)
    return Names(out or [eq.target.sym])


def _blocks(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += _blocks(b) if isinstance(b, Section) else [b]
    return out


def refer_reverses(ctx: Ctx, doc: Document, levels: list[Section]) -> None:
    """A relative motion a later section uses (001's rolling pair: a_{F∈R rel N} in the
    composition's relative equation) that no step wrote, where a step found its reverse
    (a_{F∈N rel R} in Step 3), is derived where it is first used, before its equation:
    a_{F∈R rel N} = −a_{F∈N rel R} = (value), from Step 3 — a number a student cannot trace
    is never written. v_{P∈b rel a} = v_{P∈b} − v_{P∈a} = −v_{P∈a rel b} always; for
    accelerations the two differ by 2 (ω_b − ω_a) × v_{P∈b rel a}, so the reverse is said
    only where the values are opposite (a rolling contact, v_rel = 0), checked here. An
    acceleration's reverse says why (round 18a): where v_{P∈b rel a} = 0 (a rolling contact)
    the Coriolis terms vanish, so the two relative accelerations are opposite — a reader who
    knows a_rel ≠ −a_rel in general is told the reason, not asked to trust it."""
    found = {_written(t.sym): (t, n) for sec in levels for n, step in _steps(sec) for eq in _equations(step)
             for t in [eq.target, *(t for side in eq.sides for t in side)]}
    for sec in doc.sections:
        if any(sec is level for level in levels):
            continue
        said: set = set()
        for eq in [b for b in sec.leaves() if isinstance(b, Equation)]:
            for t in (t for side in eq.sides for t in side if not t.unknown):
                m = RELATIVE.match(t.sym.sub)
                if m is None or _written(t.sym) in found or _written(t.sym) in said:
                    continue
                back = Sym(t.sym.base, f"{m.group(1)}∈{m.group(3)}/{m.group(2)}", t.sym.sup, t.sym.vector,
                           t.sym.sub_key)
                rev = found.get(_written(back))
                if rev is None or not _opposite(t.value, rev[0].value):
                    continue
                said.add(_written(t.sym))
                unit = "speed" if t.sym.base == "v" else "accel"
                key = "composition.reverse"
                extra: dict[str, Any] = {"kind": unit}          # the quantity, never "motion"
                if unit == "accel" and _at_rest(ctx, m.group(1), m.group(2), m.group(3)):
                    # no slip: v_rel = 0, no Coriolis term, hence the reverse (never the
                    # general 2 (ω_b − ω_a) × v_rel, beyond the course: issue 30, round 29 c)
                    key, extra = "composition.reverse_rolling", {"kind": unit, "vel": Sym("v", t.sym.sub)}
                _insert_before(sec, eq, msg(key, sym=t.sym, back=rev[0].sym,
                                            value=Value(t.value, unit), step=rev[1], **extra))


def _at_rest(ctx: Ctx, point: str, body: str, frame: str) -> bool:
    """Whether `body`'s material point at `point` has no velocity relative to `frame` (a
    rolling contact): then 2 ω × v_rel = 0 and a_{P∈b rel a} = −a_{P∈a rel b}."""
    try:
        v = [float(x) for x in ctx.vel(body, point, frame)]
    except Exception:        # a label the solution does not know: no reason claimed
        return False
    return max(abs(x) for x in v) < 1e-9


def _opposite(u: object, w: object) -> bool:
    """Whether two vectors (tuples of numbers) are each other's negative, to rounding."""
    try:
        a, b = [float(x) for x in u], [float(x) for x in w]     # type: ignore[attr-defined]
    except (TypeError, ValueError):
        return False
    scale = max([abs(x) for x in a + b] + [1e-12])
    return len(a) == len(b) and all(abs(x + y) <= 1e-9 * scale for x, y in zip(a, b))


def _insert_before(sec: Section, eq: Equation, block: Msg) -> None:
    """Put `block` just before `eq` in whichever (nested) section holds it."""
    for k, b in enumerate(sec.blocks):
        if b is eq:
            sec.blocks.insert(k, block)
            return
        if isinstance(b, Section):
            _insert_before(b, eq, block)


def refer_rates(ctx: Ctx, doc: Document, levels: list[Section]) -> None:
    """A centre placed from an angular velocity a step found (C5-1.6's moving pulley through
    the belt: 0 = v_Q + ω × QI) names that step by its number: "from the angular velocity found
    in Step 2 through the belt", never "found above" — the reader looks for Step 2. The step
    is the one whose blocks write ω of the body (a Derived ω_b = ω_b REL a + ω_a, or an
    equation's term), read after `prune` numbered the steps. So does a centre a vehicle's
    velocity step placed (C5-2.1's I_chassis = (0, L): placed in Step 1), named by the step
    that finds the body's ω there, without its value again (C5-1.5's "I_pulley3: found in
    Step 3", never "I_pulley3 = (9r/2, −4r): found in Step 3": a result is written once)."""
    for b in doc.blocks():
        if isinstance(b, CentreNote) and b.how == "rate":
            body = next((x for x in b.pair if x != ctx.frame), b.pair[-1])
            b.step = rate_step(levels, Sym("ω", body, vector=False))
        elif isinstance(b, Msg) and b.key == "centres.found_above":
            n = rate_step(levels, Sym("ω", b.args["body"].text, vector=False))
            if n is not None:
                # the value is written once, where the step found it (round 17a)
                b.key, b.args["step"] = "centres.found_above_step", n


def refer_placed(doc: Document, levels: list[Section]) -> None:
    """The number of the step a centre's paragraph was moved into, as the step's title reads
    after `prune` renumbered the steps: "I_planet1: placed in Step 3, from the velocities of
    A1 and Q" — the step of the body whose centre it is, where the paragraph stands."""
    for b in doc.blocks():
        if not (isinstance(b, Msg) and b.key == "centres.placed_in_step"):
            continue
        body = b.args["body"].text
        for sec in levels:
            for shown, step in _steps(sec):
                if any(isinstance(x, CentreNote) and body in x.pair for x in step.blocks):
                    b.args["step"] = shown


def rate_step(levels: list[Section], sym: Sym) -> Optional[int]:
    """The number of the step that finds the angular velocity `sym`: a value read off
    (`Derived`) or an equation's term (`step_of`)."""
    for sec in levels:
        for n, step in _steps(sec):
            if any(isinstance(b, Derived) and _written(b.sym) == _written(sym) for b in step.leaves()):
                return n
    return step_of(levels, sym)



def step_of(levels: list[Section], sym: Sym) -> Optional[int]:
    """The number of the step (as its title now reads, after `prune` renumbered the steps)
    whose equations write `sym`, a term or a left side: the step a later section refers to
    (the composition's relative motion of a slider, found in Step 2)."""
    for sec in levels:
        for n, step in _steps(sec):
            for eq in _equations(step):
                if any(_written(t.sym) == _written(sym) for t in [eq.target, *(t for side in eq.sides for t in side)]):
                    return n
    return None


def _steps(sec: Section) -> list[tuple[int, Section]]:
    """A level section's steps with the numbers their titles give."""
    out: list = []
    for n, step in enumerate((b for b in sec.blocks if isinstance(b, Section)), 1):
        shown = step.title.args.get("n")
        out.append((shown if isinstance(shown, int) else n, step))
    return out


def _written(sym: Sym) -> tuple:
    """What tells two symbols apart on the page."""
    return (sym.base, sym.sub, sym.sup, sym.sub_key)


def coriolis_by_point(ctx: Ctx, sections: list[Section]) -> None:
    """The Coriolis term named as the notes name it, a_Cor at its point (a_Cor,B: 4.3's a_cor,
    2 ω_M·v_rel), the same name in the steps, the composition of motions and the answers:
    one quantity, one name. A step's term keeps both bodies (a_Cor,B∈N/M) only where the
    page has Coriolis terms of one point for two different relative motions (a step's and
    a composition asked in another moving frame), which the point alone would not tell apart."""
    found: dict[str, list[tuple[Term, tuple]]] = {}
    for sec in sections:
        for eq in _equations(sec):
            for t in (t for side in eq.sides for t in side if t.kind == "coriolis"):
                m = RELATIVE.match(t.sym.sub)
                if m:
                    found.setdefault(m.group(1), []).append((t, (m.group(2), m.group(3))))
    asked = {(ref.point, (ref.body, moving)) for ref, moving, _ in composition_pairs(ctx)}
    for p, terms in found.items():
        pairs = {pair for _, pair in terms} | {pair for q, pair in asked if q == p}
        if len(pairs) == 1:
            for t, _ in terms:
                t.sym = Sym("a", p, sub_key="sub.cor")


def _written_points(levels: list[Section], wanted: tuple) -> dict[tuple[str, str], int]:
    """(level, point label) -> the number of the step whose equation wrote that point's
    velocity or acceleration (its left side), for later sections to refer to."""
    out: dict[tuple[str, str], int] = {}
    for sec, level in zip(levels, wanted):
        steps = [b for b in sec.blocks if isinstance(b, Section)]
        for n, step in enumerate(steps, 1):
            for eq in _equations(step):
                if not eq.target.sym.sup and eq.target.sym.base == level:
                    out.setdefault((level, eq.target.sym.sub), n)
            for m in _messages(step):        # a contact at rest said, not written: v_J∈wheel = 0
                if m.key in STILL_KEYS and level == "v":
                    out.setdefault((level, m.args["sym"].sub), n)
    return out


# the sentences that say a body's point at a contact is at rest (its instant centre): they
# find that point's velocity as an equation would (C5-1.8: v_J∈wheel = 0, Step 1)
STILL_KEYS = ("rolling.centre", "centre.site", "centre.site_s")


def _messages(sec: Section) -> list[Msg]:
    out: list = []
    for b in sec.blocks:
        out += _messages(b) if isinstance(b, Section) else [b] if isinstance(b, Msg) else []
    return out


def _equations(sec: Section) -> list[Equation]:
    out: list = []
    for b in sec.blocks:
        out += _equations(b) if isinstance(b, Section) else [b] if isinstance(b, Equation) else []
    return out
