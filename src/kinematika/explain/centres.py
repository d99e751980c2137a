"""Instant centres as the notes find them (seed 002), from the structure first: at a joint,
shared across a weld, by Aronhold–Kennedy, on the normal to a slot or the axle of a wheel.
A centre the structure does not reach is found from the velocities, and the text says so:
where the perpendiculars to two velocities meet, or from the velocity of one point and the
angular velocity, 0 = v_Q + ω × QI (the notes' bicycle: the pedals' centre at the depth
d = R_roda R / r). An asked centre found through other centres is checked that way too.
The centres are the engine's (`questions.centres.all_centres`); this module only says how
each one follows."""
from __future__ import annotations

from itertools import combinations

from ..questions.centres import all_centres, centre_line, same_line
from .asked import worked
from .context import Ctx
from .kinds import knife_edge, line_kind, on_fixed_line
from .document import CentreNote, Section, Sym, msg

MAX_ALL = 10        # above this many pairs, only the centres relative to the frame (and what they need)


def centres_section(ctx: Ctx) -> Section:
    """The section of instant centres: the drawing with the centres, then, for each pair of
    bodies (only those with the frame, and what they need, when there are many), how its centre
    follows — at a joint, by Aronhold–Kennedy from two lines that meet, or where the
    perpendiculars to two velocities meet."""
    from .structure import drawing

    sec = Section(msg("sec.centres"))
    sec.add(msg("centres.intro", example=Sym("I", "13", vector=False)))
    sec.add(drawing(ctx, "fig.centres", velocities=False, accelerations=False, centres=True, curvature=False))
    order = all_centres(ctx.sol)
    found = {frozenset(c.pair): c for c in order}
    made = {}
    for key in found:
        c = found[key]
        note = CentreNote(c.pair, _clean(ctx, c.value), c.how, list(c.via))
        if c.how == "joint":
            note.joint_type = ctx.model.joint(c.via[0]).kind.name
        elif c.how == "weld":
            weld = ctx.model.joint(c.via[0])
            welded = next(b for b in c.pair if b in (weld.a, weld.b) and b != c.via[1])
            x = next(b for b in c.pair if b != welded)
            note.same = {"pair": (x, c.via[1]), "welded": welded,
                         **_clean(ctx, found[frozenset((x, c.via[1]))].value)}
        elif c.how == "kennedy":
            _kennedy(ctx, note, found, order[:order.index(c)])
        elif c.how == "lines":
            note.via = [_line_reason(ctx, c, kind, name, found) for kind, name in c.lines]
        elif c.how == "velocities" and c.finite:
            note.witnesses = _witnesses(ctx, c.pair[1], c.pair[0])
            _axles(ctx, note)
            if note.how == "velocities" and len(note.witnesses) < 2:
                _field(ctx, note)
        made[key] = note
    asked = {frozenset((ctx.rel(q.relative_to) or ctx.frame, q.target)) for q in worked(ctx).centres}
    for key in _chosen(ctx, made):
        sec.blocks.append(made[key])
        if key in asked and made[key].how in ("kennedy", "lines", "weld") and made[key].value.get("point"):
            check = CentreNote(made[key].pair, made[key].value, "check")
            if _field(ctx, check):
                sec.blocks.append(check)
    return sec


def _field(ctx: Ctx, note: CentreNote) -> bool:
    """The centre from one point Q of the body and its angular velocity, as the notes find
    the bicycle's pedals' centre: 0 = v_Q + ω × QI, so QI = k × v_Q / ω. False when the
    body does not turn (a translation has its centre at infinity)."""
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
    return True


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
    lines = {k: centre_line(ctx.inst, found[frozenset((a, k))].value, found[frozenset((k, b))].value)
             for k in thirds}
    lines = {k: l for k, l in lines.items() if l is not None}
    for i, k1 in enumerate(lines):
        for k2 in list(lines)[i + 1:]:
            if not same_line(ctx.inst, lines[k1], lines[k2]):
                note.via = [k1, k2]
                note.lines = [(_clean(ctx, found[frozenset((a, k))].value),
                               _clean(ctx, found[frozenset((k, b))].value)) for k in (k1, k2)]
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
    for k in ks:
        where = found[frozenset((k, b))].value.get("point")
        if where is not None:
            note.witnesses.append((_point_name(ctx, b, where) or f"I:{k},{b}", ctx.clean(tuple(where), "len"),
                                   ctx.clean(_velocity_at(ctx, b, a, where), "speed")))
    if len(note.witnesses) == 2:
        u, w = (ctx.num(v) for _, _, v in note.witnesses)
        note.side = "between" if u[0] * w[0] + u[1] * w[1] < 0 else "outside"
    else:
        note.how = "velocities"


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


def _chosen(ctx: Ctx, notes: dict) -> list[frozenset]:
    """Every pair for small mechanisms; else the frame's pairs and the centres their notes
    are found from (the lines' third bodies), so that each centre named is explained."""
    keys = list(notes)
    if len(keys) <= MAX_ALL:
        return keys
    wanted = [k for k in keys if ctx.frame in k]
    i = 0
    while i < len(wanted):
        note = notes[wanted[i]]
        if note.how in ("kennedy", "proportional"):
            a, b = note.pair
            for k in note.via:
                for key in (frozenset((a, k)), frozenset((k, b))):
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
