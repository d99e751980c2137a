"""Instant centres as the notes find them (seed 002), from the structure first: at a joint,
shared across a weld, by Aronhold–Kennedy, on the normal to a slot or the axle of a wheel.
A centre the structure does not reach is found from the velocities, and the text says so:
where the perpendiculars to two velocities meet, or from the velocity of one point and the
angular velocity, 0 = v_Q + ω × QI (the notes' bicycle: the pedals' centre at the depth
d = R_roda R / r). An asked centre found through other centres is checked that way too.
The centres are the engine's (`questions.centres.all_centres`); this module only says how
each one follows."""
from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import combinations
from typing import Any, Literal, Optional, overload

from ..joints.capabilities import Centre
from ..questions.centres import all_centres, centre_line, same_line
from .asked import worked
from .context import Ctx
from .kin import kin
from .kinds import guided, knife_edge, line_kind, on_fixed_line, roller, rolls
from .document import CentreNote, Msg, Name, Section, Sym, msg

MAX_ALL = 10        # above this many pairs, only the centres relative to the frame (and what they need)


STRUCTURAL = ("joint", "weld", "kennedy", "lines")     # placed before any velocity is known


@overload
def centres_section(ctx: Ctx, part: Literal["all", "first"] = "all") -> Section: ...
@overload
def centres_section(ctx: Ctx, part: Literal["rest"]) -> Optional[Section]: ...
def centres_section(ctx: Ctx, part: str = "all") -> Optional[Section]:
    """The section of instant centres: the drawing with the centres, then, for each pair of
    bodies (what the questions name and what it is found from; else those with the frame,
    and what they need, when there are many), how its centre follows — at a joint, by
    Aronhold–Kennedy from two lines that meet, or where the perpendiculars to two velocities
    meet. When the notes place the centres first (`centres_first`), `part` "first" is the
    centres the structure places, before the velocities, and "rest" those found from the
    velocities, after them (None when there are none)."""
    from .structure import drawing

    made, chosen, asked = _notes(ctx)
    first = [k for k in chosen if _placed(ctx, made[k])]
    keys = {"all": chosen, "first": first, "rest": [k for k in chosen if k not in first]}[part]
    if part == "rest" and not keys:
        return None
    sec = Section(msg("sec.centres" if part != "rest" else "sec.centres_v"))
    if part != "rest":
        first_body = _example_body(ctx, [made[k].pair for k in chosen])
        sec.add(msg("centres.intro", example=Sym("I", "13", vector=False),
                    pair=Sym("I", f"{ctx.frame},{first_body}", vector=False), body=Name(first_body, "body"),
                    frame=Name(ctx.frame, "body", reference=True)))
    if part == "all" or (part == "first") == (len(first) == len(chosen)) or part == "rest":
        sec.add(drawing(ctx, "fig.centres", velocities=False, accelerations=False, centres=True, curvature=False,
                        centre_pairs=used_pairs(made, chosen), construction=construction(ctx, made, chosen)))
    # each centre once: a centre placed (at a joint, by Aronhold–Kennedy, where two lines
    # meet) is not placed again "as a check" from the velocities — the notes never re-derive
    # a centre they have found, and the second derivation reads as a second answer
    sec.blocks += [_once(ctx, made[key]) for key in keys]
    return sec


def _example_body(ctx: Ctx, pairs: list) -> str:
    """The body whose centre the section's first sentence takes as its example (I_OC): one
    the section then places relative to the frame, so the intro names only a symbol the page
    uses (issue 30, sixteenth round: C5-E.1's intro named I_OC, never placed); else a moving
    body, not a part of the frame."""
    for a, b in pairs:
        if ctx.frame in (a, b) and not ctx.fixed(b if a == ctx.frame else a):
            return b if a == ctx.frame else a
    return next((b for b in ctx.model.bodies if b != ctx.frame and not ctx.fixed(b)),
                next(b for b in ctx.model.bodies if b != ctx.frame))


def _once(ctx: Ctx, note: CentreNote):
    """The centre's note, or, when a velocity step placed the centre already (a vehicle's
    chassis where its axle and a velocity's perpendicular meet: `vehicles`), its value with
    where it was found: the construction is said once on a page (C5-2.1 wrote the same
    paragraph in step 1 and again here)."""
    a, b = note.pair
    body = b if a == ctx.frame else a if b == ctx.frame else None
    point = note.value.get("point")
    if body is None or point is None or f"centre:{body}" not in ctx.worked:
        return note
    from .document import Value

    return msg("centres.found_above", centre=Sym("I", f"{ctx.frame},{body}", vector=False),
               value=Value(point, "len"), body=Name(body, "body"))


def centres_in_steps(ctx: Ctx, velocities: Section) -> None:
    """A centre found from two parallel velocities (`_parallel`) is said in the velocity step
    that finds its body's ω, where both velocities are known, when a later step goes on from
    that body: the notes' order (C5-1.5: "el CIR d'aquesta politja estarà en el punt mig
    entre aquests dos punts. A partir d'aquí ... el bloc pujarà amb celeritat 6v"), the
    third pulley's centre before the block's speed, never in a section after every step.
    The closing section then refers to it (`_once`: "found above")."""
    from .document import Derived

    made, chosen, _ = _notes(ctx)
    steps = [b for b in velocities.blocks if isinstance(b, Section)]
    for key in chosen:
        note = made[key]
        a, b = note.pair
        if _placed(ctx, note) or note.how != "parallel" or a != ctx.frame:
            continue
        found = next((i for i, sub in enumerate(steps) if any(
            isinstance(x, Derived) and x.body == b and x.kind == "omega" for x in sub.blocks)), None)
        if found is not None and found + 1 < len(steps):
            steps[found].blocks.append(note)
            ctx.worked.add(f"centre:{b}")


def used_pairs(made: dict, chosen: list) -> list[tuple[str, str]]:
    """The pairs whose centres the text writes, which are all the centres' figure shows: a
    figure of every pair (C5-1.5's 36) hides the few the step needs, and a ring the text never
    names (a relative centre at a point the text names otherwise, C5-1.4's A1 and N, C5-1.2's
    O) is a symbol the student cannot find in the text. The centres a construction is found
    from are written when it writes their symbols (`_chosen`), and so drawn."""
    return [tuple(sorted(k)) for k in dict.fromkeys(chosen) if len(k) == 2 and k in made]


def construction(ctx: Ctx, made: dict, chosen: list) -> list[tuple[tuple, tuple]]:
    """The lines each written centre is said to lie on, as (pair, a point of the line) for the
    centres' figure to draw from the point on to the centre (`DrawOptions.construction`): by
    Aronhold–Kennedy, through the two centres of each third body (the point W the notes name,
    "the perpendicular to v_W through W"), the same for a centre where such a line meets a
    joint's normal (C5-1.2's I_OJ on the line through I_OQ and O, which stopped past K1; the
    normal is drawn on to its centre by `draw.results._normals`); from velocities, through each witness point,
    perpendicular to its velocity; from a body's ω and one point's velocity (`_field`), through
    that point; from two parallel velocities (`_parallel`, the proportional construction),
    through both points. A sentence that says "these lines meet" there, over a
    figure with the lines stopping short of the ring, left the reader to draw them (issue 30,
    nineteenth round (d): C5-1.1's strands' lines and I_pulley)."""
    out: list[tuple[tuple, tuple]] = []
    for key in dict.fromkeys(chosen):
        note = made.get(key)
        if note is None or note.value.get("point") is None:
            continue
        if note.how in ("kennedy", "lines"):
            out += [(note.pair, tuple(c["point"])) for line in note.lines for c in line
                    if c.get("point") is not None]
        elif note.how == "velocities" and len(note.witnesses) >= 2:
            out += [(note.pair, tuple(ctx.pos(p))) for p, *_ in note.witnesses]
        elif note.how == "proportional" and note.witnesses:      # (name, place, velocity) of each
            out += [(note.pair, tuple(where)) for _, where, _ in note.witnesses]
        elif note.how in ("field", "rate", "parallel") and note.witnesses:
            # from ω and one point's velocity: on the perpendicular to v_Q through Q, at
            # |v_Q|/|ω|; from two parallel velocities: on the line through their points — the
            # line the text puts it on, drawn from each point (a bare ring, far off, was all
            # C5-1.6's, C5-E.5's and C5-E.6's figures showed: twenty-seventh round (f))
            out += [(note.pair, tuple(ctx.pos(p))) for p, *_ in note.witnesses]
    return out


def _placed(ctx: Ctx, note: CentreNote) -> bool:
    """Whether the structure places the centre, with no velocity (the engine's way, before
    the explanation reads a wheel's axle off a velocity), or the data do (`_from_data`)."""
    return (note.how in STRUCTURAL or _from_data(ctx, note)) and ctx.centre_how.get(frozenset(note.pair)) in STRUCTURAL


def _from_data(ctx: Ctx, note: CentreNote) -> bool:
    """Whether a centre found from two parallel velocities (`_kennedy`'s proportional
    construction) takes only the data: each witness point turns with a body whose rate the
    statement gives about a point at rest. Then the notes place the centre first and read the
    body's ω off it, ω = v / distance (C5-1.4: the carrier and the ring given, the planet's
    centre at (2/5)r from its axle, "el CIR es troba entre els dos"), not the other way round."""
    if note.how != "proportional" or not note.pivots or ctx.frame not in note.pair:
        return False
    given = {d.body for d in ctx.model.drivers if d.kind == "omega" and d.relative_to in (None, ctx.frame)}
    return all(k in given for k in note.via)


def _joint_said(ctx: Ctx, pair: tuple, kind: Any) -> str:
    """The joint's kind as the centre's line says it. A pin to the fixed body is a fixed pivot,
    a permanent centre (the notes' point in C5-E.2: "I_braç is the axis O, a permanent
    centre"), "revolute_fixed"; a strand pinned there (a straight body that a pulley rolls on)
    is tied to it, and its centre is the point where it is tied (C5-1.1: "el punt on estan
    agafats del sostre"), "revolute_tied" — never "the axis of the hinge G1" (twenty-ninth
    round (b))."""
    if kind.centre is not Centre.PIN or not any(ctx.fixed(b) for b in pair) or all(ctx.fixed(b) for b in pair):
        return kind.name
    moving = next(b for b in pair if not ctx.fixed(b))
    straight = any(type(s).__name__ == "Line" for s in ctx.model.bodies[moving].shapes)
    rolled = any(j.kind.rolls and moving in (j.a, j.b) for j in ctx.model.joints)
    return "revolute_tied" if straight and rolled else "revolute_fixed"


def _notes(ctx: Ctx) -> tuple[dict, list, set]:
    """Every centre's note (how it follows), the pairs to write, the pairs asked; once."""
    if ctx.centre_notes is not None:
        return ctx.centre_notes
    order = all_centres(ctx.sol)
    found = {frozenset(c.pair): c for c in order}
    ctx.centre_how = {key: c.how for key, c in found.items()}
    made = {}
    deps: dict[frozenset, list[frozenset]] = {}
    for key in found:
        c = found[key]
        note = CentreNote(c.pair, _clean(ctx, c.value), c.how, list(c.via))
        if c.how == "joint":
            note.joint_type = _joint_said(ctx, c.pair, ctx.model.joint(c.via[0]).kind)
        elif c.how == "weld":
            weld = ctx.model.joint(c.via[0])
            welded = next(b for b in c.pair if b in (weld.a, weld.b) and b != c.via[1])
            x = next(b for b in c.pair if b != welded)
            part = found[frozenset((x, c.via[1]))]
            if welded == ctx.frame and ctx.fixed(c.via[1]) and part.how == "joint":
                # a part welded to the frame is the frame (the notes' inclined planes are "el
                # terra inclinat"): the contact with it is the centre, said once, at the joint
                note.how, note.via = "joint", list(part.via)
                note.joint_type = ctx.model.joint(part.via[0]).kind.name
            else:
                note.same = {"pair": (x, c.via[1]), "welded": welded, **_clean(ctx, part.value)}
                deps[key] = [frozenset((x, c.via[1]))]
        elif c.how == "kennedy":
            _kennedy(ctx, note, found, order[:order.index(c)])
        elif c.how == "lines":
            note.via = [_line_reason(ctx, c, kind, name, found) for kind, name in c.lines]
            note.lines = [(_clean(ctx, found[frozenset((c.pair[0], name))].value),
                           _clean(ctx, found[frozenset((name, c.pair[1]))].value))
                          for kind, name in c.lines if kind == "third"]     # drawn on to the centre
            deps[key] = [frozenset(p) for (kind, name), why in zip(c.lines, note.via) if kind == "third"
                         for p in ((c.pair[0], name), (name, c.pair[1]))
                         if ctx.frame in p or why.key == "centre.line.kennedy"]
        elif c.how == "velocities" and c.finite:
            note.witnesses = _witnesses(ctx, c.pair[1], c.pair[0])
            _axles(ctx, note)
            if note.how == "velocities" and len(note.witnesses) < 2 and not _parallel(ctx, note):
                _field(ctx, note)
        if note.how in ("kennedy", "lines", "velocities", "proportional") and ctx.frame in key and \
                any(f"drive:{b}" in ctx.worked for b in key if b != ctx.frame):
            by_rate = CentreNote(note.pair, note.value, "velocities")    # a belt's wheel: from the rate
            if _field(ctx, by_rate):        # the drive gave (C5-1.6, E.6: 0 = v_Q + ω × QI)
                from .drives import drives

                by_rate.how = "rate"
                from .drives import pairs

                by_rate.via = ([d.line for d in drives(ctx) if set(key) & {d.a, d.b}]      # the belt, the chain
                               + [d.a if d.b in key else d.b for d in pairs(ctx)
                                  if set(key) & {d.a, d.b} and f"pair:{d.joint}" in ctx.worked])[:1]   # the other wheel
                note = by_rate
                deps.pop(key, None)
        made[key] = note
        if note.how in ("kennedy", "proportional"):
            a, b = note.pair
            deps[key] = [frozenset(p) for k in note.via for p in ((a, k), (k, b))
                         if (note.how == "kennedy" and not note.perps) or ctx.frame in p]
    asked = {frozenset((ctx.rel(q.relative_to) or ctx.frame, q.target)) for q in worked(ctx).centres}
    asked |= kin_centres(ctx, asked)
    ctx.centre_notes = (made, _chosen(ctx, made, deps, asked | axle_centres(ctx, made, asked)), asked)
    return ctx.centre_notes


def axle_centres(ctx: Ctx, made: dict, asked: set[frozenset]) -> set[frozenset]:
    """On a page that writes centres relative to the frame (some are asked), the centres of
    the other bodies whose rates the questions ask relative to the frame (ω, α: a question
    about a body that `needs_rate`) and that turn about a fixed axle, a pin on the frame:
    the notes name them with the rest ("Els CIRs
    respecte al terra del portador, de la corona i de la roda central coincideixen amb el
    punt central", C5-1.4), and a page that listed the carrier's and the ring's centres at O
    but not the sun wheel's, whose ω it asks, left the student to wonder why (issue 30,
    twenty-eighth round (c)). One line each; they are not "asked" (the answers list only the
    questions; the order of the page does not change). A wheel rolling on the frame is not
    added: its velocity step says already that its contact is its instant centre."""
    if not any(ctx.frame in key for key in asked):
        return set()
    from ..questions import QUESTIONS

    bodies = {q.target for q in ctx.model.questions if QUESTIONS[q.kind].about == "body"
              and QUESTIONS[q.kind].needs_rate and isinstance(q.target, str)
              and (ctx.rel(q.relative_to) or ctx.frame) == ctx.frame}
    keys = {frozenset((ctx.frame, b)) for b in bodies if b != ctx.frame}
    return {k for k in keys if k in made and made[k].how == "joint"
            and ctx.model.joint(made[k].via[0]).kind.centre is Centre.PIN}


def kin_centres(ctx: Ctx, asked: set[frozenset]) -> set[frozenset]:
    """The centres relative to the frame of the bodies of one kind (`kin.kin`) with a body
    whose centre relative to the frame is asked: the notes find each planet's centre the same
    way ("el CIR de cada rodeta s'ha de trobar entre els dos", C5-1.4), and a page that
    placed the first planet's centre and then read the second's rate off the sun wrote one
    kind of body two ways (issue 30, twenty-seventh round (b)). Each such centre is placed
    as the asked one is, in its body's step; the answers list only what is asked."""
    return {frozenset((ctx.frame, k)) for key in asked if ctx.frame in key
            for b in key if b != ctx.frame for k in kin(ctx, b)}


def centres_first(ctx: Ctx, steps: Optional[list] = None) -> bool:
    """Whether the explanation places the instant centres before the velocities and finds
    the velocities from them, as the notes do where they ask for centres the structure
    gives (C5-1.1's pulley where the strands meet, C5-E.3's rod, C5-E.2's planets at their
    contacts with the fixed sun): the questions name a centre relative to the frame that
    the structure places. Not where a belt or chain gives a wheel's rate: the notes find
    that rate by composing from the arm, and the wheel's centre from it (C5-1.6); nor where
    the body is solved by a dyad (a four-bar's coupler: the dyad's equation gives its ω, and
    its centre follows). `steps` is the order of solution; without it, every body counts."""
    from .drives import drives

    if ctx.model.default_questions or not ctx.planar or drives(ctx):
        return False
    if ctx.centre_first_memo is not None:
        return ctx.centre_first_memo
    grouped = None if steps is None else {b for st in steps if st.kind == "other" for b in st.bodies}
    made, _, asked = _notes(ctx)
    ctx.centre_first_memo = any(ctx.frame in key and key in made and _placed(ctx, made[key])
                                and (grouped is None or (set(key) - {ctx.frame}) <= grouped) for key in asked)
    return ctx.centre_first_memo


def placed_at_contact(ctx: Ctx, body: str, joint_id: str) -> bool:
    """Whether the centres section, written before the velocities, already placed `body`'s
    instant centre relative to the frame at the contact of joint `joint_id` (C5-1.3's
    "I_suport: el punt de contacte J"): a velocity step then refers to that section, as it
    does for every centre placed there, and does not derive it again (a result is derived
    once, round 17a)."""
    if not centres_first(ctx):
        return False
    made, chosen, _ = _notes(ctx)
    key = frozenset((ctx.frame, body))
    note = made.get(key)
    return key in chosen and note is not None and note.how == "joint" and list(note.via[:1]) == [joint_id]


def centre_sites(ctx: Ctx) -> tuple[dict[str, tuple[str, tuple]], dict[str, CentreNote]]:
    """The centres relative to the frame that the first centres section places by a
    construction (Aronhold–Kennedy, a joint's line), for the velocity steps to start from:
    {name: (body, point)} of those at a point (a point of the body there keeps its name,
    else the centre's own symbol, I_pulley), and {body: note} of those at infinity (the body translates)."""
    if not centres_first(ctx):       # decided by the builder with the order of solution
        return {}, {}
    from .document import centre_point

    made, chosen, _ = _notes(ctx)
    points: dict[str, tuple[str, tuple]] = {}
    still: dict[str, CentreNote] = {}
    found: list[tuple[str, tuple, Optional[str]]] = []
    for key in chosen:
        note = made[key]
        if ctx.frame not in key or note.how not in ("kennedy", "lines", "proportional") or not _placed(ctx, note):
            continue
        body = next(b for b in note.pair if b != ctx.frame)
        where = note.value.get("point")
        if where is None:
            if note.value.get("direction") is not None:
                still[body] = note
            continue
        found.append((body, tuple(where), _point_name(ctx, body, where)))
    for body, where, name in found:
        if name is None:
            # a centre at no point of the model is its own symbol throughout (I_OQ, never a
            # number: `document.centre_point`), one centre or several: a page that placed
            # I_pulley never renames it I (one symbol for one point, round 15a)
            name = centre_point(body)
            while name in ctx.inst.points:          # never a point's name
                name += "'"
        ctx.name_position(name, where)
        points[name] = (body, where)
    return points, still


def _field(ctx: Ctx, note: CentreNote) -> bool:
    """The centre from one point Q of the body and its angular velocity, as the notes find
    the bicycle's pedals' centre: 0 = v_Q + ω × QI, so QI = ω × v_Q / ω²: the centre lies on
    the perpendicular to v_Q through Q, on the side v_Q turned 90° in the sense of ω points
    to, at the distance |QI| = |v_Q| / |ω| (how the notes say it, C5-1.5, 1.6, 2.1). False when
    the body does not turn (a translation has its centre at infinity)."""
    a, b = note.pair
    w = ctx.omega(b, a)
    if ctx.is_zero(w, "rate") or note.value.get("point") is None:
        return False
    q = _field_point(ctx, b, a)
    if q is None:
        return False
    if note.how != "check":
        note.how = "field"
    note.witnesses = [(q, ctx.clean(ctx.vel(b, q, a), "speed"))]
    note.rate = ctx.clean(w, "rate")
    note.arm = ctx.clean(tuple(c - p for c, p in zip(note.value["point"], ctx.pos(q))), "len")
    note.distance = ctx.clean(_length(ctx, note.arm), "len")
    note.side = side_of(ctx.num(note.arm))
    return True


# the sides `side_of` names (message side.NAME in each catalogue)
SIDES = ("above", "below", "left", "right", "above_left", "above_right", "below_left", "below_right")


def side_of(arm: Sequence[Any]) -> str:
    """The side of Q the centre lies on, named as the notes' figures show it (x to the right,
    y up): `below`, `above`, `left`, `right`, or two of them (`below_left`), from the arm QI.
    A sentence names it ("below A") instead of "the side to which v_A points when turned 90°
    in the sense of ω", which the readers of stop 41 found roundabout; QI = ω × v_Q / ω² is
    that side, so the name is the notes' construction said in one word."""
    x, y = float(arm[0]), float(arm[1])
    size = math.hypot(x, y)
    tol = 1e-9 * size
    up = "above" if y > tol else "below" if y < -tol else ""
    across = "right" if x > tol else "left" if x < -tol else ""
    return "_".join(w for w in (up, across) if w)


def _parallel(ctx: Ctx, note: CentreNote) -> bool:
    """The centre from two points P and Q of the body whose velocities are parallel and
    perpendicular to the line PQ, by the notes' proportional construction (the second way to
    find a CIR, "el triangle de velocitats ... té el CIR com a un dels seus vèrtex"): the
    velocity grows linearly with the distance from the centre along that line, so the centre
    is where it falls to zero, between P and Q when they move in opposite senses (at the
    midpoint when their speeds are equal: C5-1.5's third pulley, its contact rising at 2v and
    its centre falling at 2v), beyond the slower one when in the same sense:
    QI = |v_Q| · PQ / |v_P ∓ v_Q|. The body's points and its rolling contacts are tried, its
    own points (a wheel's centre) as Q. False when no such pair is there."""
    a, b = note.pair
    where = note.value.get("point")
    if where is None:
        return False
    own = list(ctx.model.bodies[b].points)
    contacts = [ctx.contact(j) for j in ctx.model.joints if rolls(j) and b in (j.a, j.b)]
    points = [p for p in dict.fromkeys(own + contacts) if p in ctx.inst.points]
    speeds = {p: ctx.vel(b, p, a) for p in points}
    moving = [p for p in points if not ctx.is_zero(speeds[p], "speed")]
    for q in (p for p in moving if p in own):
        for p in (x for x in moving if x != q):
            vp, vq = ctx.num(speeds[p]), ctx.num(speeds[q])
            pq = [y - x for x, y in zip(ctx.num(ctx.pos(q)), ctx.num(ctx.pos(p)))]
            size = _size(ctx, speeds[p]) * _size(ctx, speeds[q])
            if abs(vp[0] * vq[1] - vp[1] * vq[0]) > 1e-6 * size or abs(vp[0] * pq[0] + vp[1] * pq[1]) > \
                    1e-6 * _size(ctx, speeds[p]) * (pq[0] ** 2 + pq[1] ** 2) ** 0.5:
                continue
            note.how = "parallel"
            note.side = "between" if vp[0] * vq[0] + vp[1] * vq[1] < 0 else "outside"
            note.witnesses = [(p, ctx.clean(speeds[p], "speed")), (q, ctx.clean(speeds[q], "speed"))]
            # each point named as the steps write its velocity, seen from the reference: the
            # sentence says whose points move relative to what (round 27b: C5-1.5's "respecte
            # del terra, T4 es mou amb (0; 2·v)" named neither the pulley nor the symbol)
            note.symbols = [Sym("v", ctx.point_label(x, b) if a == ctx.frame else f"{x}∈{b}/{a}") for x in (p, q)]
            note.arm = ctx.clean(tuple(c - x for c, x in zip(where, ctx.pos(q))), "len")
            note.distance = ctx.clean(_length(ctx, note.arm), "len")
            return True
    return False


def _length(ctx: Ctx, v: tuple):
    """|v| = √(Σ v_i²), a formula for a symbolic model."""
    if ctx.symbolic:
        import sympy

        return sympy.simplify(sympy.sqrt(sympy.expand(sum(c ** 2 for c in v))))
    return sum(float(c) ** 2 for c in v) ** 0.5


def _field_point(ctx: Ctx, body: str, frame: str) -> str | None:
    """The body's point to start from: a pin it shares with another body (the bicycle's
    crank axle K), a shape's centre, else any of its points that moves."""
    model = ctx.model
    points = model.bodies[body].points
    pinned = [p for p in points if len(model.carriers(p)) > 1]
    centres = [getattr(s, "center_point", None) for s in model.bodies[body].shapes]
    for p in pinned + [c for c in centres if c] + list(points):
        if not ctx.is_zero(ctx.vel(body, p, frame), "speed"):
            return p
    return None


def _line_reason(ctx: Ctx, c, kind: str, name: str, found: dict):
    """Why the centre lies on a line: a Kennedy line through two centres (third body
    `name`), or the normal a joint gives at its point (a slot, a knife-edge wheel)."""
    from .document import Name, msg

    a, b = c.pair
    if kind == "third":
        perp = _perpendicular(ctx, found, a, name, b)
        if perp is not None:
            return perp
        return msg("centre.line.kennedy", l=[Sym("I", f"{a},{name}", vector=False), Sym("I", f"{name},{b}", vector=False)],
                   k=Name(name, "body"))
    j = ctx.model.joint(name)
    kind = "slot_fixed" if on_fixed_line(j, ctx.frame) else line_kind(j)
    return msg(f"centre.line.{kind}", joint=Name(j.id, "joint"), point=Name(j.at or ctx.contact(j)),
               a=Name(j.a, "body"))


def _kennedy(ctx: Ctx, note: CentreNote, found: dict, before: list) -> None:
    """Two Aronhold–Kennedy lines that really meet; when every pair of lines is one line
    (the planet of an epicyclic: O, its centre and its contacts are collinear), the
    notes' reasoning instead: speeds proportional to the distance from the centre."""
    a, b = note.pair
    earlier = {frozenset(c.pair) for c in before}
    thirds = [k for k in ctx.model.bodies if k not in (a, b) and frozenset((a, k)) in earlier
              and frozenset((k, b)) in earlier]
    thirds = list(dict.fromkeys(note.via + thirds))
    drawn = {k: centre_line(ctx.inst, found[frozenset((a, k))].value, found[frozenset((k, b))].value)
             for k in thirds}
    lines = {k: l for k, l in drawn.items() if l is not None}
    for i, k1 in enumerate(lines):
        for k2 in list(lines)[i + 1:]:
            if not same_line(ctx.inst, lines[k1], lines[k2]):
                note.via = [k1, k2]
                note.lines = [(_clean(ctx, found[frozenset((a, k))].value),
                               _clean(ctx, found[frozenset((k, b))].value)) for k in (k1, k2)]
                perps = [_perpendicular(ctx, found, a, k, b) for k in (k1, k2)]
                note.perps = perps if all(perps) else []
                return
    ks = list(lines)[:2] or note.via
    for k1, k2 in combinations(lines, 2):       # the notes' choice: two points moving in opposite senses
        u, w = (_witness_velocity(ctx, found, a, b, k) for k in (k1, k2))
        if u is not None and w is not None and u[0] * w[0] + u[1] * w[1] < 0:
            ks = [k1, k2]
            break
    note.via = ks
    note.lines = [(_clean(ctx, found[frozenset((a, k))].value), _clean(ctx, found[frozenset((k, b))].value))
                  for k in ks]
    note.how = "proportional"
    note.witnesses = []
    note.pivots = []
    for k in ks:
        where = found[frozenset((k, b))].value.get("point")
        if where is not None:
            note.witnesses.append((_site_name(ctx, where, (b, k)) or f"I:{k},{b}", ctx.clean(tuple(where), "len"),
                                   ctx.clean(_velocity_at(ctx, b, a, where), "speed")))
            note.pivots.append(_pivot(ctx, found, a, k))
            note.slips.append(_carried_slip(ctx, note.witnesses[-1][0], k, b))
    if a != ctx.frame or not all(note.pivots):
        note.pivots, note.slips = [], []
    if len(note.witnesses) == 2:
        u, w = (ctx.num(v) for _, _, v in note.witnesses)
        note.side = "between" if u[0] * w[0] + u[1] * w[1] < 0 else "outside"
        _nearer(ctx, note)
    else:
        note.how = "velocities"


def _carried_slip(ctx: Ctx, w: str, k: str, b: str) -> Optional[Msg]:
    """Why b's point W, a witness of the proportional construction, moves with k: at a
    rolling contact of b on k it is the no-slip condition (C5-1.4: "Q with the *ring* about
    O (*planet 1* does not slip on the *ring*, so its point Q has the ring's velocity
    there)"), said as `centre.line.rolls` says it (twentieth round (g)); None at a pin, where
    W simply moves with k, or for a witness with no name."""
    if _no_slip(ctx, k, b) != "rolls" or w.startswith("I:"):
        return None
    return msg("centre.carried.slip", b=Name(b, "body"), body=Name(k, "body"), point=Name(w))


def _nearer(ctx: Ctx, note: CentreNote) -> None:
    """A centre between (or beyond) two points turning about known pivots is also placed as
    its distance from the nearer named one, as the notes give it: C5-1.4's planet centre
    "a (2/5)r del centre" A1, said where the centre is found and in the answers (the
    eleventh round put it in the answers only: the sentence gave coordinates alone)."""
    import sympy

    centre = note.value.get("point")
    named = [(p, at) for p, at, _ in note.witnesses if not str(p).startswith("I:")]
    if not note.pivots or centre is None or not named:
        return
    far = {p: sympy.sqrt(sum((sympy.sympify(a) - sympy.sympify(b)) ** 2 for a, b in zip(at, centre)))
           for p, at in named}
    note.near = min(far, key=lambda p: float(ctx.inst.num(far[p])))
    note.distance = ctx.clean(sympy.simplify(far[note.near]), "len")


def _perpendicular(ctx: Ctx, found: dict, a: str, k: str, b: str) -> Optional[Msg]:
    """The line through the centre of b relative to the frame a that the third body k
    gives, as the notes draw it (C5-1.2, 1.3, E.3, E.4), who never name Aronhold–Kennedy:
    the centre I_kb is a point W that moves with k, and k turns about I_ak, so v_W ⊥ I_ak-W
    and the centre of b lies on the perpendicular to v_W through W (when k translates, v_W
    is k's one velocity). When b slides on k (I_kb at infinity), the point of b on the
    perpendicular to the guide through I_ak slides along the guide relative to k and is
    carried by k about I_ak along the guide too (the notes' v_REL ∥ v_ar, C5-1.3): its
    velocity is along the guide, and the centre lies on that perpendicular. None for a
    centre between two moving bodies (the notes construct none; there the three-centres
    theorem says it), or when a point has no name to say it by."""
    if b == ctx.frame:
        a, b = b, a
    if a != ctx.frame:
        return None
    pivot, site = found[frozenset((a, k))].value, found[frozenset((k, b))].value
    if site.get("point") is not None:
        w = _site_name(ctx, site["point"], (b, k))
        if w is None:
            return None
        v = Sym("v", ctx.point_label(w, k))
        ctx.witnessed.setdefault(b, set()).add(w)     # the velocity step then uses this point too
        why = _no_slip(ctx, k, b)
        if pivot.get("point") is None:
            if pivot.get("direction") is None:
                return None
            return msg("centre.line.rolls_still" if why == "rolls" else "centre.line.moves_still", v=v, point=Name(w), body=Name(k, "body"), **_slip_names(ctx, k, b))
        centre = _pivot(ctx, found, a, k)
        return None if centre is None else msg("centre.line.rolls" if why == "rolls" else "centre.line.moves", v=v, point=Name(w), body=Name(k, "body"),
                                              pivot=centre, **_slip_names(ctx, k, b))
    guide = next((j for j in ctx.model.joints if {j.a, j.b} == {k, b} and guided(j)), None)
    centre = _pivot(ctx, found, a, k) if pivot.get("point") is not None else None
    if guide is None or centre is None:
        return None
    return msg("centre.line.guide", joint=Name(guide.id, "joint"), pivot=centre, b=Name(b, "body"),
               body=Name(k, "body"))


def _rolling(ctx: Ctx, k: str, b: str) -> Any:
    """The rolling (no-slip) joint between k and b, or None."""
    return next((j for j in ctx.model.joints if {j.a, j.b} == {k, b} and rolls(j)), None)


def _no_slip(ctx: Ctx, k: str, b: str) -> str:
    """Why b's point W has k's velocity: at a rolling contact the reason is the no-slip
    condition (the notes' C5-1.1: "la politja no llisca al damunt del cable", so the pulley's
    point J has the strand's velocity), said as such ("rolls"); at a pin W simply moves with
    k ("moves")."""
    return "rolls" if _rolling(ctx, k, b) is not None else "moves"


def _slip_names(ctx: Ctx, k: str, b: str) -> dict[str, Name]:
    """The names a no-slip reason says: the body that rolls, the one it rolls on (the notes'
    order: the pulley on its cable, `kinds.roller`) and b, whose point W is meant."""
    j = _rolling(ctx, k, b)
    if j is None:
        return {}
    rolling, on = roller(ctx.model, j)
    return {"roller": Name(rolling, "body"), "on": Name(on, "body"), "b": Name(b, "body")}


def _pivot(ctx: Ctx, found: dict, a: str, k: str):
    """What k turns about relative to a, by its name: the point there (a pin O, a wheel's
    contact J3), else the centre's symbol I_ak; None when k translates."""
    where = found[frozenset((a, k))].value.get("point")
    if where is None:
        return None
    name = _site_name(ctx, where, (k, a))
    return Name(name) if name is not None else Sym("I", f"{a},{k}", vector=False)


def _site_name(ctx: Ctx, where, bodies: tuple) -> Optional[str]:
    """The name of the point at `where` of one of `bodies`: a model point there (a pin), else
    the contact of a rolling joint of theirs there (J4); None when nothing is named there."""
    for b in bodies:
        name = _point_name(ctx, b, where)
        if name is not None:
            return name
    x = ctx.num(tuple(where))
    for j in ctx.model.joints:
        if rolls(j) and set(bodies) & {j.a, j.b}:
            contact = ctx.sol.geometry(j.id).contact
            if contact is not None and sum((u - v) ** 2 for u, v in zip(x, ctx.num(tuple(contact.point)))) ** 0.5 \
                    <= 1e-9 * ctx.inst.scale:
                return ctx.contact(j)
    return None


def _witness_velocity(ctx: Ctx, found: dict, a: str, b: str, k: str):
    """As floats, the velocity relative to a of b's point at the centre I_k,b (None at infinity)."""
    where = found[frozenset((k, b))].value.get("point")
    return None if where is None else ctx.num(_velocity_at(ctx, b, a, where))


def _velocity_at(ctx: Ctx, body: str, frame: str, where) -> tuple:
    """The velocity relative to `frame` of the material point of `body` at `where`."""
    sol = ctx.sol
    return sol.motion.velocity(sol.state(body, ctx.rel(frame)), tuple(where))


def _point_name(ctx: Ctx, body: str, where) -> str | None:
    """The model's name of the point of `body` at `where`, if it has one."""
    x = ctx.num(tuple(where))
    for p in ctx.model.bodies[body].points:
        y = ctx.num(ctx.pos(p))
        if sum((u - v) ** 2 for u, v in zip(x, y)) ** 0.5 <= 1e-9 * ctx.inst.scale:
            return p
    return None


def _chosen(ctx: Ctx, notes: dict, deps: dict, asked: set) -> list[frozenset]:
    """The centres to write: when the questions name centres, those; else the centres
    relative to the frame (every pair for small mechanisms); then the centres those are
    found from (`_notes`' deps: those relative to the frame, and the others only where the
    construction writes their symbols, Aronhold–Kennedy's I_12 and I_23, a weld's other centre).
    A centre of two moving bodies that no question asks and no written construction names
    is a line that adds nothing (C5-1.2's "I_{OQ rel. roda esquerra}: l'eix de
    l'articulació O", never used again), so it is not written. Two parallel velocities
    (`proportional`, C5-1.4's planet from the carrier and the ring) and a perpendicular to a
    velocity (C5-1.2's "O es mou amb la roda esquerra") name the points, A1, N, O, not the
    relative centres there: neither the text nor the figure (`used_pairs`) lists them."""
    keys = list(notes)
    if asked and not ctx.model.default_questions:
        wanted = [k for k in keys if k in asked]
    elif len(keys) <= MAX_ALL:
        wanted = [k for k in keys if ctx.frame in k or k in asked]
    else:
        wanted = [k for k in keys if ctx.frame in k]
    i = 0
    while i < len(wanted):
        for key in deps.get(wanted[i], []):
            if key in notes and key not in wanted:
                wanted.append(key)
        i += 1
    return [k for k in keys if k in wanted]


def _axles(ctx: Ctx, note: CentreNote) -> None:
    """A body on knife-edge wheels: its centre where its wheels' axles (the perpendiculars to
    their planes at the contacts) meet, or an axle and the perpendicular to a known
    velocity, as the notes construct it (seed 002, C5.2)."""
    from .vehicles import _lines

    frame, b = note.pair
    wheels = [j for j in ctx.model.joints if knife_edge(j) and {j.a, j.b} == {frame, b}]
    if not wheels:
        return
    speeds = {p: ctx.vel(b, p, frame) for p in ctx.model.bodies[b].points}
    lines = _lines(ctx, b, wheels, speeds)
    for i, (_, d, why) in enumerate(lines):
        for _, e, other in lines[i + 1:]:
            if abs(d[0] * e[1] - d[1] * e[0]) > 1e-6 * _size(ctx, d) * _size(ctx, e):
                note.how, note.via = "lines", [why, other]
                return


def _clean(ctx: Ctx, value: dict) -> dict:
    out = dict(value)
    for key in ("point", "direction"):
        if out.get(key) is not None:
            out[key] = ctx.clean(tuple(out[key]), "len")
    return out


def _witnesses(ctx: Ctx, body: str, frame: str) -> list[tuple[str, tuple]]:
    """Two points of `body` whose velocities relative to `frame` are not parallel."""
    moving = [(p, ctx.vel(body, p, frame)) for p in ctx.model.bodies[body].points]
    moving = [(p, v) for p, v in moving if not ctx.is_zero(v, "speed")]
    for (p, v), (q, u) in combinations(moving, 2):
        if abs(ctx.num(v[0] * u[1] - v[1] * u[0])) > 1e-6 * _size(ctx, v) * _size(ctx, u):
            return [(p, ctx.clean(v, "speed")), (q, ctx.clean(u, "speed"))]
    return [(p, ctx.clean(v, "speed")) for p, v in moving[:1]]


def _size(ctx: Ctx, v: tuple) -> float:
    return sum(x * x for x in ctx.num(v)) ** 0.5
