"""The structure of the mechanism, before any motion: bodies, joints, degrees of freedom
(by the rank of the joints' velocity conditions, as the engine counts them) and the
order of solution."""
from __future__ import annotations

from typing import Any, Optional

from ..draw.names import body_numbers
from ..model.body_shapes import Circle, Disc
from ..point_pair import PointPair
from .freedom import by_data, dof_by_data
from .context import Ctx
from .kinds import crossed_by_a_slot, joint_kind, kind_key, knife_edge, on_fixed_line, rolls, welds
from .document import Arrow, Drawing, Equation, Figure, Inline, Lead, Msg, Name, Names, Section, Sym, Table, Value, body, msg, names, point
from .order import Step, as_found, merge_vehicles       # the order lists the steps as the text does them


def _points_on(ctx: Ctx, body: str) -> list[str]:
    """Every named point on `body`, as its row of the structure table lists them: the model's
    points, then the contact points of its touching joints (J, K, T1 …, `ctx.contact`), each
    once — the same for every body (twentieth round g: C5-1.6's moving pulley listed T2, the
    model's point, and the fixed pulley left out T1, its contact with the belt)."""
    parts = [body] + (welded_to_frame(ctx) if body == ctx.frame else [])
    names = [p for part in parts for p in ctx.model.bodies[part].points]
    if ctx.planar:
        names += [ctx.contact(j) for j in ctx.model.joints
                  if getattr(j.kind, "touches", False) and (j.a in parts or j.b in parts)]
    slid = _sliding_points(ctx, parts)
    return [p for p in dict.fromkeys(names) if p not in slid]


def _sliding_points(ctx: Ctx, parts: list[str]) -> set[str]:
    """The points that slide along a line of `parts` (a slot's or a sliding contact's point,
    `crossed_by_a_slot`, on the joint's other body): the other body's points, not the line's
    (twenty-ninth round (b): C5-1.2's ground row listed J, the bar's end that slides on it)."""
    return {j.at for j in ctx.model.joints if j.at and crossed_by_a_slot(j) and j.a in parts
            and j.b not in parts and j.at in ctx.model.bodies[j.b].points}


def _points_cell(ctx: Ctx, body: str) -> list:
    """A body's cell of the points column. The fixed body lists a point it carries only as the
    contact of a wheel or rolling joint as the contact it is, "contact points under C1,
    C2, F" (twenty-third round (a): C5-2.1's ground row "C1, C2, F" was read as the wheels'
    centres, which they also name), whether or not the model lists the point on it (C5-2.2's
    ground lists none; its row was empty); its own points, and every other body's, by name."""
    names = _points_on(ctx, body)
    if body != ctx.frame or not ctx.planar:
        return [point(p) for p in names]
    joints = [j for j in ctx.model.joints if body in (j.a, j.b)]
    wheels = [j.at or ctx.contact(j) for j in joints if knife_edge(j)]
    rolling = [j.at or ctx.contact(j) for j in joints if rolls(j) and not knife_edge(j)]
    other = {j.at for j in joints if not knife_edge(j) and not rolls(j)}      # a pin there too: its own point
    contacts = {p for p in wheels + rolling if p not in other}
    cell: list = [point(p) for p in names if p not in contacts]
    for key, group in (("structure.contacts_wheel", wheels), ("structure.contacts_rolling", rolling)):
        # the row's own order, then the contacts at points the frame does not list (C5-2.2's
        # ground lists none: its four wheels touch it all the same)
        said = [p for p in names if p in group and p in contacts] + \
            [p for p in dict.fromkeys(group) if p not in names and p in contacts]
        if said:
            cell.append(msg(key, points=Names([point(p) for p in said])))
            contacts -= set(said)
    return cell


def structure_section(ctx: Ctx, steps: list[Step]) -> Section:
    """The section on structure, before any motion: the bodies (numbered as the figures number
    them) with their points and shapes, the joints with their bodies and places, the degrees of
    freedom (counted by the rank of the joints' conditions, `dof_counts`, but said as the
    mobility alone: the notes write no count of unknowns or independent conditions), the
    drawing, and the order of solution `steps`."""
    model = ctx.model
    sec = Section(msg("sec.structure"))
    numbers = body_numbers(model)
    # a body welded to the frame is the frame: its row (`_frame_cell`), never one of its own
    bodies = [[Name(name, "index"), _shaped(ctx, name, _body_cell(ctx, name)), _points_cell(ctx, name)]
              for name in sorted(model.bodies, key=lambda n: numbers[n]) if name not in welded_to_frame(ctx)]
    sec.add(Table([msg("col.number"), msg("col.body"), msg("col.points")], bodies))
    sec.add(msg("structure.subscripts",          # ω_t: which body (render); a part welded to the frame has no rate
                bodies=[b for b in ctx.model.bodies if b not in welded_to_frame(ctx)]))
    # a joint is said by what it is, the bodies it joins and where: never by its id (j3); a
    # part welded to the frame is part of it (its row says so, and the sentence below), not a
    # joint of the mechanism (the notes' inclined planes are "el terra inclinat")
    # a table's cell names the two bodies bare, as the bodies' table does (no article)
    joints = [[joint_kind(ctx, j),
               Inline([Name(j.a, "body", bare=True), " – ", Name(j.b, "body", bare=True)]), _where(ctx, j)]
              for j in model.joints if not (welds(j) and ctx.fixed(j.a) and ctx.fixed(j.b))]
    sec.add(Table([msg("col.joint"), msg("col.bodies"), msg("col.where")], joints))
    welded = welded_to_frame(ctx)
    if welded:
        sec.add(msg("structure.welded", bodies=names(welded, "body"), bodies_n=len(welded), frame=body(ctx.frame)))
    counts = dof_counts(ctx)
    if dof_by_data(ctx, counts):        # C5-1.5: a datum's direction is part of the statement
        sec.add(msg("structure.dof_data", **by_data(ctx)))
    else:
        sec.add(msg("structure.dof", **counts))
    sec.add(drawing(ctx, "fig.mechanism", velocities=True, accelerations=False, centres=False, curvature=False))
    if not steps:
        return sec
    sec.add(order_section(ctx, steps))
    return sec


def order_section(ctx: Ctx, steps: list[Step]) -> Section:
    """The order of solution: one item a step, its bodies and sources as the step's equations
    find and read them once the velocities are written (`order.as_found`; the builder makes
    this section again then, `reorder`)."""
    order = Section(msg("sec.order"), level=3)
    order.add(msg("order.assur" if _dyads(steps) else "order.blocks"))
    for i, s in enumerate([s for s in merge_vehicles(ctx, steps) if not all(ctx.fixed(b) for b in s.bodies)], 1):
        order.add(order_item(i, as_found(ctx, s)))
    return order


def reorder(ctx: Ctx, structure: Section, steps: list[Step]) -> None:
    """The structure section's order of solution made again from the steps as written (the
    velocities record the order their equations find the bodies in, `Ctx.found_order`)."""
    for i, b in enumerate(structure.blocks):
        if isinstance(b, Section) and b.title.key == "sec.order":
            structure.blocks[i] = order_section(ctx, steps)


def _dyads(steps: list) -> bool:
    """Whether the order is the slides' decomposition into inputs and dyads: decomposed so
    and with a dyad among its steps. Otherwise the sentence names no decomposition (a wheel
    alone, gears: the bodies in order, each from those known) — never how the program
    failed to find dyads."""
    return bool(steps) and steps[0].source == "assur" and any(s.kind in DYADS for s in steps)


DYADS = ("RRR", "RRP", "RPR", "PRP")


def step_title(n: int, step: Step) -> Msg:
    """A step's title: its number and the bodies it finds, after the course's name for the
    group when it has one (input, RRR dyad …); a group that is no named kind is titled by its
    bodies alone, as a teacher writes it ("Step 1: rear wheel and sprocket"), not by the
    program's "group solved together". After the colon every title goes on in lower case,
    the kind's word or the first name alike ("Pas 1: entrada (sòlid motor) — la corredora",
    "Pas 2: la palanca N"): sentence case, one style for every step of a page, where a
    capital on the name alone made the titles of one page disagree."""
    key = "step.title_group" if step.kind == "other" else "step.title"
    bodies = names(step.bodies, "body")
    return msg(key, n=n, kind=msg(f"kind.{step.kind}"), bodies=bodies)


def order_item(n: int, step: Step) -> Msg:
    """One line of the order of solution: the bodies a step finds and the bodies they are
    found from, after the course's name for the group when it has one (RRR dyad …). Its
    joints are left to the step itself, and a group that is no named kind is said by its
    bodies alone ("1. rear wheel and sprocket, from ground"), as a teacher writes it. A step
    found from no other body (C5-E.4's chassis, which translates at the given velocity) is
    found "from the data", never from an empty list ("1. The chassis, from —.")."""
    group = step.kind == "other"
    bodies = names(step.bodies, "body")
    keys = {(True, True): "order.item_group", (True, False): "order.item_group_data",
            (False, True): "order.item", (False, False): "order.item_data"}
    key = keys[(group, bool(step.known))]
    return msg(key, n=n,
               kind=Lead(msg(f"kind.{step.kind}")), bodies=Lead(bodies) if group else bodies,
               known=names(step.known, "body", each="order.from"))


def welded_to_frame(ctx: Ctx) -> list[str]:
    """The bodies welded to the frame (directly or through other welds: C5-1.2's inclined
    planes): they are part of the fixed body, not moving bodies — a weld leaves no relative
    motion, so what is welded to the ground is ground."""
    return [b for b in ctx.model.moving_bodies if ctx.fixed(b)]


def dof_counts(ctx: Ctx) -> dict:
    """The degrees-of-freedom sentence's numbers, the bodies welded to the frame counted with
    it: each such body takes away its k velocity components (3 in the plane, 6 in space) and
    the k independent conditions of its weld, which pin exactly those components — so the
    unknowns n and the rank fall by k for each, and the degrees of freedom stay n − rank."""
    d = ctx.sol.diagnosis
    moving = len(ctx.model.moving_bodies)
    k = d.n // moving if moving else 0
    welded = len(welded_to_frame(ctx))
    n = d.n - k * welded
    return {"n": n, "moving": moving - welded, "rank": n - d.dof, "dof": d.dof, "conditions": d.conditions}


def _shaped(ctx: Ctx, name: str, cell: Any) -> Any:
    """The body's cell with its round shape folded in ("*wheel*, circle of radius 0.5 m"): a
    teacher prints a body's shape only where it matters — a wheel's, a pulley's, a disc's
    radius, which the rolling conditions use — and never an empty "shapes" column (the
    readers' top item, round 16a). A line (a strand, the floor) says nothing the body's name
    and the Data's shape table do not; every shape stays stated there (`data.shape_rows`)."""
    round_ = [(s, inst) for s, inst in zip(ctx.model.bodies[name].shapes, ctx.inst.shapes.get(name, []))
              if isinstance(s, (Circle, Disc))]
    if len(round_) > 1:     # C5-E.1: "two welded wheels of radii R and 2R", not a list of circles
        return msg("structure.shaped_welded", body=cell, n=len(round_),
                   radii=Names([Value(ctx.clean(shape.radius, "len"), "len") for _, shape in round_]))
    for spec, shape in round_:
        cell = msg("structure.shaped", body=cell, shape=msg(f"shape.{type(spec).__name__.lower()}"),
                   radius=Value(ctx.clean(shape.radius, "len"), "len"))
    return cell


def _body_cell(ctx: Ctx, name: str):
    """The structure table's body: the frame by its own name, marked fixed, with the parts
    welded to it (`_frame_cell`); the text names it so wherever it is the reference of a
    motion, "relative to the *fixed pulley*" (twenty-ninth round (b): "*polea fija* (*suelo*)"
    and "respecto del *suelo*" sent the reader after a ground the problem does not have; the
    twenty-seventh round (e) had said it for a shapeless frame, "*bastidor* (fijo)")."""
    if name == ctx.frame:
        return _frame_cell(ctx, name)
    if ctx.fixed(name):
        return msg("structure.fixed_part", body=Name(name, "body", bare=True), frame=body(ctx.frame))
    return Name(name, "body", bare=True)


def _frame_cell(ctx: Ctx, name: str) -> Msg:
    """The frame's cell, with the parts welded to it named in it ("*ground* (fixed), with the
    *left plane* and the *right plane*"): they are the frame (its lines, its axles), one row
    with its points (`_points_on`), never bodies of their own "fixed to the ground"
    (twenty-ninth round (b): C5-1.2's planes were bodies 2 and 3)."""
    cell = msg("structure.frame_named", body=Name(name, "body", bare=True))
    welded = welded_to_frame(ctx)
    if not welded:
        return cell
    return msg("structure.frame_parts", body=cell, parts=names(welded, "body"), parts_n=len(welded))


def _where(ctx: Ctx, j) -> Inline | Msg | str:
    """The joint's point and, for a guide, its direction in a teacher's words (issue 30, round
    29 c: never "J ∥ (1, 0)"): "J slides along a horizontal line", "the wheel at F rolls along
    (1, 1), at 45° to the horizontal", "… along PO" (evaluated: never the model's text)."""
    parts: list = []
    if j.at:
        parts.append(point(j.at))
    elif rolls(j) and ctx.planar and ctx.sol.geometry(j.id).contact is not None:
        parts.append(point(ctx.contact(j)))          # the contact, as the text names it
    if j.along is None:
        return Inline(parts) if parts else "—"
    if isinstance(j.along, PointPair):
        towards: Any = msg("along.line", line=Inline([point(j.along.start), point(j.along.end)]))
    else:
        towards = along_words(ctx, ctx.clean(ctx.inst.vector(j.along, j.where), ""))
    verb = "rolls" if knife_edge(j) else "slides" if parts else "only"     # a block's guide: no point
    return msg("along.joint", verb=verb, point=Inline(parts), dir=towards)


def along_words(ctx: Ctx, vec: tuple) -> Msg:
    """A guide's direction as a teacher says it: a horizontal or a vertical line, or the
    direction and its angle to the horizontal, (1, 1) at 45° (the angle when numbers give it):
    the vector's own angle, atan2(y, x) in (−180°, 180°], so that the two agree — (3, −1) at
    −18.4°, never the line's 161.6° beside it (the seventh reading, C5-1.3)."""
    import math

    try:
        x, y = (float(c) for c in vec)
    except (TypeError, ValueError):
        return msg("along.vector", vec=Value(vec, ""))
    size = math.hypot(x, y) or 1.0
    if abs(y) < 1e-9 * size:
        return msg("along.horizontal")
    if abs(x) < 1e-9 * size:
        return msg("along.vertical")
    deg = math.degrees(math.atan2(y, x))
    return msg("along.angle", vec=Value(vec, ""), deg=Value(round(deg, 1) if abs(deg - round(deg)) > 1e-6 else round(deg), ""))


# inches: an explanation's drawing is set at its own size, 432 pt, under the 482 pt of an A4 page's
# text (2 cm margins): its 9 pt labels print at 9 pt (docs/explain.md, "Printing")
PRINT_WIDTH = 6.0


def drawing(ctx: Ctx, caption: str, **options) -> Drawing:
    """The `draw` figure of the solution with these options (for LaTeX, the mechanism as
    TikZ when planar); for a symbolic model, the numbers it is drawn at."""
    from ..draw.scene import drawing_values

    fallback = mechanism_figure(ctx) if ctx.planar and caption == "fig.mechanism" else None
    values = {str(k): v for k, v in sorted(drawing_values(ctx.inst).items(), key=lambda kv: str(kv[0]))}
    options.setdefault("width", PRINT_WIDTH)
    args: dict = {"dim": ctx.space.dim}
    if caption == "fig.centres":
        kennedy, joints, radii = _lines_drawn(ctx, options)
        args["normals"] = Names([msg(f"fig.normal.{k}") for k in _normal_lines(ctx, joints)]
                                + ([msg("fig.normal.radius")] if radii else []))
        args["kennedy"] = int(kennedy)
    if caption == "fig.mechanism":
        args.update(_arrows_drawn(ctx, options))
    return Drawing(msg(caption, **args), ctx.sol, options, fallback, values)


def moduli_units(ctx: Ctx, doc: Any, length_unit: str) -> None:
    """The unit of the magnitudes a numeric page's mechanism figure writes beside its arrows
    (v_B = 11), said once in its caption — "with its magnitude, in m/s" — as the text gives
    every value with its unit (issue 30, fourteenth round (d)). Once in the caption, not in
    each label: C5-1.3's figure sets v_ar,E = 0,287 beside v_E = 4,43, and " m/s" after each
    would crowd them (docs/explain.md, "Fourteenth round (d)"). A symbolic page's labels are
    formulas of the symbols, and their unit is the symbols'."""
    if ctx.symbolic:
        return
    for b in doc.blocks():
        if isinstance(b, Drawing) and b.caption.key == "fig.mechanism" and b.caption.args.get("moduli") == 1:
            b.caption.args.update(moduli=2, unit=length_unit)
        elif isinstance(b, Drawing) and b.caption.key == "fig.contact" and b.caption.args.get("moduli") == 1:
            # the coincident points' figure (`contacts.coincident_drawing`): its level's unit whole
            b.caption.args.update(moduli=2, unit=f"{length_unit}/s" + ("" if b.caption.args["level"] == "v" else "²"))


def derived_arrows(ctx: Ctx, doc: Any, velocities: Optional[Any]) -> None:
    """A mechanism's figure that would draw the velocity of every moving point (the model
    asks about no point: C5-E.3 asks the centres and the rates) draws those whose velocity
    the page derives — the targets of the velocity section's equations — and its caption
    names just those: "the arrows are the velocities of A and B", never "of C1, A, C2 and
    B" over a page that never writes v_C1 or v_C2 (a sentence lists only what the page
    derives, issue 30, twentieth round (d))."""
    from ..questions import QUESTIONS

    if velocities is None or any(QUESTIONS[q.kind].about == "point" for q in ctx.model.questions):
        return
    refs: list[str] = []
    for eq in _velocity_equations(velocities):
        if eq.point is not None and eq.relative_to in (None, ctx.frame) and eq.target.kind == "point" \
                and eq.point.point in ctx.model.points:      # a contact the page names (N) is not drawn
            ref = f"{eq.point.point}@{eq.point.body}"
            if ref not in refs:
                refs.append(ref)
    if not refs:
        return
    for b in doc.blocks():
        if isinstance(b, Drawing) and b.caption.key == "fig.mechanism" and b.options.get("velocities") \
                and not b.options.get("points"):
            b.options["points"] = refs
            b.caption.args.update(_arrows_drawn(ctx, b.options))


def _velocity_equations(sec: Any) -> list:
    out: list = []
    for b in sec.blocks:
        out += _velocity_equations(b) if isinstance(b, Section) else [b] if isinstance(b, Equation) else []
    return out


def name_contacts(ctx: Ctx, doc: Any, named: dict[str, str]) -> None:
    """Every figure of the mechanism labels the contact points the page names (joint id ->
    J, K, T2 …: `data.contact_rows`) with the page's letter, and no other: a reader told
    "the pulley rolls on the strand at J" finds J in the figure (issue 30, thirteenth round:
    C5-1.1's J and K were dots without letters). The drawings get them as `DrawOptions`'
    contacts, the LaTeX mechanism's figure as labelled points."""
    if not named or not ctx.planar:
        return
    for b in doc.blocks():
        if isinstance(b, Drawing):
            b.options["contacts"] = dict(named)
            if b.fallback is not None and b.fallback.points:
                have = {label for label, _, _ in b.fallback.points}
                b.fallback.points += [(name, ctx.num(ctx.pos(name)), "point")
                                      for name in dict.fromkeys(named.values()) if name not in have]


def _arrows_drawn(ctx: Ctx, options: dict) -> dict:
    """What the mechanism's figure draws of the velocities, read off the figure itself, for
    its caption to say just that: `arrows` 1 (one arrow: "the arrow is the velocity of B"),
    2 (several: "the arrows are the velocities of B and E"), 3 (only points at rest, whose
    zero velocity is written beside them: C5-E.4's v_P = 0), 4 (a list of the arrows, each
    said whole) or 0 (none); `points` which — never "the arrows are the velocities of its
    points" over one arrow or none. One source: every arrow drawn, a relative velocity's
    too, is named in the caption (issue 30, sixteenth round (f): 001's prismatic pair drew
    v_B∈N rel. M under a caption that named two arrows)."""
    from ..draw.build import build_scene
    from ..draw.options import DrawOptions

    scene = build_scene(ctx.inst, ctx.sol, DrawOptions(**options))
    drawn = [v for v in scene.vectors if v.kind == "velocity"]
    moving = [v for v in drawn if v.magnitude > 1e-9 * max(ctx.inst.scale, 1e-12)]
    shown = moving or drawn
    points: Any = Names([_arrow_point(ctx, v.ref) for v in shown])
    arrows = (min(len(moving), 2) if moving else 3) if drawn else 0
    own = _own_drag(ctx, [v.ref for v in shown], [v.relative_to for v in shown])
    if arrows == 2 and own is not None:         # one point's velocity and its drag: the point said once
        arrows, points = 4, msg("fig.own_drag", point=Name(own), sym=Sym("v", own, sub_key="sub.drag"))
    elif moving and any(v.relative_to or v.ref.endswith(":drag") for v in shown):
        arrows, points = 4, Names([_arrow_named(ctx, v) for v in sorted(shown, key=_composition_order)])
    # a symbolic page's label too long to set names the vector alone (`draw.vectors`): the
    # caption then promises no magnitude
    moduli = int(all(not v.text.startswith("≈") for v in shown))
    centre = _centre_of(ctx, [v.ref for v in shown]) if arrows == 3 else None
    # beside arrows, a point whose velocity is zero has "v_P = 0" written by it: said after
    # them, with the body whose instant centre it is (C5-E.4's P, beside the given v_U drawn
    # since the twenty-seventh round (f))
    still = [v for v in drawn if not any(v is m for m in moving)] if moving else []
    at = _centre_of(ctx, [v.ref for v in still]) if still else None
    rest = msg("fig.rest", points=Names([_arrow_point(ctx, v.ref) for v in still]), count=len(still),
               centre=msg("fig.rest_centre", body=Name(at, "body")) if at else "") if still else ""
    return {"arrows": arrows, "points": points, "moduli": moduli,
            "centre": msg("fig.rest_centre", body=Name(centre, "body")) if centre else "", "rest": rest}


def _centre_of(ctx: Ctx, refs: list[str]) -> Optional[str]:
    """The one moving body whose instant centre the figure's only drawn point is, for the
    caption to say so: a point of a turning body with no velocity at this instant is its
    instant centre, never a point "at rest" (issue 30, twenty-seventh round (e): C5-E.4's P,
    whose acceleration is v²/R). None for several points, a point of several moving bodies
    (a pin), or a body that does not turn."""
    if len(refs) != 1:
        return None
    point, _, body = refs[0].partition(":")[0].partition("@")
    bodies = [body] if body else [b for b in ctx.model.carriers(point) if not ctx.fixed(b)]
    if len(bodies) != 1 or ctx.fixed(bodies[0]):
        return None
    w = ctx.num(ctx.omega(bodies[0]))
    turning = any(abs(float(c)) > 1e-12 for c in (w if isinstance(w, tuple) else (w,)))
    return bodies[0] if turning else None


def _composition_order(v: Any) -> int:
    """An arrow's place in a caption's list, the composition's order v = v_ar + v_rel: a
    point's velocity, then the drag velocity, then the relative one."""
    return 2 if v.relative_to else 1 if v.ref.endswith(":drag") else 0


def _arrow_named(ctx: Ctx, v: Any) -> Msg:
    """One arrow of a figure that draws a composition, said whole: "the velocity of B∈N",
    "the drag velocity (v_ar,B)", "the relative velocity (v_B∈N rel. M)" — each by the
    symbol its label in the figure writes, so the caption's list and the arrows are one."""
    ref, _, part = v.ref.partition(":")
    point, _, body = ref.partition("@")
    if part == "drag":
        return msg("fig.arrow.drag", sym=Sym("v", point, sub_key="sub.drag"))
    if v.relative_to:
        from .terms import relative_name
        return msg("fig.arrow.relative", sym=Sym("v", relative_name(point, body, v.relative_to)))
    return msg("fig.arrow.velocity", point=_arrow_point(ctx, v.ref))


def _own_drag(ctx: Ctx, refs: list[str], relative: Optional[list] = None) -> Optional[str]:
    """The point when a figure's two arrows are one point's velocity and its drag velocity
    (001's rolling pair: v_A and v_ar,A): the caption then names the point once, "the
    velocity of A and its drag velocity (v_ar,A)", never "the velocities of A and A
    (v_ar,A, drag velocity)" — a list that names one point twice. None otherwise."""
    if len(refs) != 2 or any(relative or []):
        return None
    parts = [r.partition(":") for r in refs]
    drags = [head for head, _, part in parts if part == "drag"]
    plain = [head for head, _, part in parts if not part]
    if len(drags) != 1 or len(plain) != 1:
        return None
    point = drags[0].partition("@")[0]
    at, _, body = plain[0].partition("@")
    label = ctx.point_label(at, body) if body else at        # as the arrow's own label says it
    return point if label == point else None


def _arrow_point(ctx: Ctx, ref: str) -> Any:
    """What an arrow of the mechanism's figure is the velocity of, as its label on the page
    says it: B∈rocker where two bodies' points meet and move apart (never "the velocities of
    B and B")."""
    point, _, body = ref.partition(":")[0].partition("@")
    return Name(ctx.point_label(point, body) if body else point)


def _lines_drawn(ctx: Ctx, options: dict) -> tuple[bool, set, bool]:
    """What lines the centres' figure draws, read off the figure itself, for its caption to
    name only those (issue 30, fourteenth round (d): C5-2.1's and C5-2.2's captions promised
    "lines through two centres" where none is drawn): whether it draws an Aronhold–Kennedy
    line (through two centres), the joints whose normals it draws, and whether it draws a
    centre's line to a pin, perpendicular to the pin's velocity (`draw.results._radii`)."""
    from ..draw.build import build_scene
    from ..draw.options import DrawOptions

    scene = build_scene(ctx.inst, ctx.sol, DrawOptions(**options))
    kennedy = any(k.key.startswith("kennedy:") for k in scene.kennedy)
    radii = any(k.key.startswith("radius:") for k in scene.kennedy)
    return kennedy, {k.key.split(":", 1)[1] for k in scene.normals}, radii


def _normal_lines(ctx: Ctx, joints: Optional[set] = None) -> list[str]:
    """The kinds of line, other than Aronhold–Kennedy's, that the centres' figure draws
    centres on, in the model's order: each joint that puts its bodies' centre on a line
    (`Centre.NORMAL`) says which (`centre_line`: a wheel's axle, a slot's normal, a contact's
    common normal), and a slot in the frame is a point sliding on a fixed line (C5-1.2's
    floor), not a slot — so the caption names only the contacts the mechanism has."""
    from ..joints.capabilities import Centre

    kinds = [kind_key(j, ctx.frame) if on_fixed_line(j, ctx.frame) else j.kind.centre_line
             for j in ctx.model.joints if j.kind.centre is Centre.NORMAL and (joints is None or j.id in joints)]
    return list(dict.fromkeys(kinds))


def mechanism_figure(ctx: Ctx) -> Figure:
    """The mechanism at the instant: bodies as lines between their points, shapes, labels."""
    fig = Figure(msg("fig.mechanism", dim=2, arrows=0, points=Names([]), centre="", rest=""), unit="len",
                 sample=ctx.symbolic)
    pos = {name: ctx.num(p) for name, p in ctx.inst.points.items()}
    for name, carrier in ctx.model.bodies.items():
        pts = [pos[p] for p in carrier.points]
        if name != ctx.frame:
            if len(pts) == 2:
                fig.segments.append((pts[0], pts[1]))
            elif len(pts) > 2:
                fig.segments += [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
        for shape in ctx.inst.shapes[name]:
            if hasattr(shape, "radius"):
                fig.circles.append((ctx.num(shape.center), float(ctx.num(shape.radius))))
            elif hasattr(shape, "direction"):
                p, d, k = ctx.num(shape.through), ctx.num(shape.direction), ctx.inst.scale
                fig.lines.append((tuple(a - k * b for a, b in zip(p, d)), tuple(a + k * b for a, b in zip(p, d))))
    grounded = set(ctx.model.bodies[ctx.frame].points)
    for name, p in pos.items():
        fig.points.append((name, p, "ground" if name in grounded else "point"))
    speeds = list(dict.fromkeys((pos[p], ctx.num(ctx.vel(name, p))) for name, carrier in ctx.model.bodies.items()
                                if name != ctx.frame for p in carrier.points))
    top = max([sum(c * c for c in v) ** 0.5 for _, v in speeds] + [0.0])
    if top > 0:
        k = 0.35 * ctx.inst.scale / top
        fig.arrows += [Arrow(p, tuple(a + k * b for a, b in zip(p, v)), None, "velocity")
                       for p, v in speeds if sum(c * c for c in v) ** 0.5 > 1e-6 * top]
    return fig


def values_table(ctx: Ctx, accelerations: bool = True, runs: frozenset = frozenset(),
                 ground: bool = False) -> Table:
    """ω (and α, when accelerations are explained) of every moving body, the solver's values:
    every body whose rate a step finds is listed, but the `runs` of belts and chains, to which
    the notes give no rate (issue 30, round 29 c; round 20g had listed them); the ground, when
    a drive wraps it (`ground`), with its 0, which the drive's step uses (ω_pulley1 = 0)."""
    def value(x, unit: str) -> Value:
        return Value(ctx.clean(x if ctx.planar else tuple(x), unit), unit)

    # the ground first when a drive wraps it (`ground`: C5-1.6's fixed pulley, whose 0 the step uses)
    listed = ([ctx.frame] if ground else []) + list(ctx.model.moving_bodies)
    rows = [[Name(b, "body", bare=True), value(ctx.omega(b), "rate")]
            + ([value(ctx.alpha(b), "rate2")] if accelerations else []) for b in listed
            if b == ctx.frame or (not ctx.fixed(b) and b not in runs)]   # a weld to the frame: part of it
    return Table([msg("col.body"), msg("col.omega")] + ([msg("col.alpha")] if accelerations else []), rows)
