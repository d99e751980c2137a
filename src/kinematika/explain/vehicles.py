"""Velocities of bodies on knife-edge wheels, as the notes' vehicle section (seed 002, C5.2).

A wheel that does not slip has no velocity across its plane, so the centre of the body
that carries it lies on the perpendicular to the wheel's plane at its contact (its axle
line). Two such lines — or one, with the perpendicular to a point's known velocity — meet
at the body's instant centre I; a known speed then gives ω (v_P = ω × IP) and every
other point follows (v_Q = ω × IQ). An asked point on a wheel's axle moves along the
wheel's plane: its speed follows from a known point Q of the body by equiprojectivity,
(v_P − v_Q) · QP = 0, before the centre, and ω from it (the notes' C5-2.2: "la propietat
d'equiprojectivitat permet obtenir la velocitat del punt mig de l'eix"). A body pinned to
one already known with a given joint rate turns at ω_known + rate.
"""
from __future__ import annotations

from typing import Optional

from .context import Ctx, magnitude, omega_sym, read_along, read_off, segment
from .document import Ann, Derived, Equation, Inline, Name, Sym, Term, Value, centre_point, msg
from .given import whole_along
from .kinds import knife_edge, pin_only, pins

TOL = 1e-9


def wheel_route(ctx: Ctx, group: list[str], known: set[str], level: str) -> Optional[list]:
    """The blocks of the instant-centre route for `group` (velocities), or None when the
    route does not reach every body of the group."""
    if level != "v":
        return None
    wheels = [j for j in ctx.model.joints if knife_edge(j) and ctx.frame in (j.a, j.b)
              and ({j.a, j.b} & set(group))]
    if not wheels:
        return None
    out: list = []
    speeds = _known_speeds(ctx, known)
    for d in ctx.model.drivers:
        out += _driven_wheel(ctx, d, group, speeds)
    solved: set[str] = set()
    progress = True
    while progress and len(solved) < len(group):
        progress = False
        for b in group:
            if b in solved:
                continue
            made = _centre(ctx, b, wheels, speeds) or _pinned(ctx, b, known | solved)
            if made is not None:
                out += made
                solved.add(b)
                for p in ctx.model.bodies[b].points:
                    speeds.setdefault(p, ctx.vel(b, p))
                progress = True
    return out if len(solved) == len(group) else None


def spins(ctx: Ctx, bodies: list[str]) -> list:
    """The spin of each wheel of `bodies` whose radius the model gives (`notation: spin(j3)`):
    it rolls without slipping, so its centre's speed along its plane is r φ̇ (the notes'
    tricycle, C5-2.1: φ̇ = v₀ (L − s)/(√2 L r)). The spin is read off as a magnitude over a
    length, φ̇ = |v_C1| / r (`read_off`), never a vector over a length."""
    out: list = []
    for jid, body, spin, value in spin_values(ctx):
        if body not in bodies:
            continue
        j = ctx.model.joint(jid)
        radius = ctx.model.wording.spins[jid][1]
        out.append(msg("vehicle.spin", joint=Name(j.id, "joint"), point=Name(j.point_at()), radius=Name(radius, "param"),
                       spin=spin, product=Inline([Name(radius, "param"), " ", spin])))
        speed = Sym("v", ctx.point_label(j.point_at(), body), vector=False)
        # the sign at the sample values: a formula's written form (−s + L) says nothing of it
        out.append(Derived(spin, read_off(ctx, speed, Name(radius, "param"), ctx.num(value.value)),
                           value, body, "spin", not ctx.symbolic))
    return out


def spin_values(ctx: Ctx) -> list[tuple]:
    """(joint, body, symbol, value) of each wheel spin the model's notation asks for: the
    speed of the wheel's centre along its plane over its radius."""
    from ..algebra.vectors import dot
    from .render.names import written

    out = []
    for jid, (symbol, radius) in ctx.model.wording.spins.items():
        j = ctx.model.joint(jid)
        body = j.b if j.a == ctx.frame else j.a
        if not j.at:
            continue
        speed = dot(ctx.vel(body, j.at), ctx.sol.geometry(j.id).along)
        r = ctx.inst.env[radius]
        value = ctx.inst.backend.simplify(speed / r) if ctx.symbolic else speed / r
        w = written(symbol)
        out.append((jid, body, Sym(w.base, w.sub, vector=False, fixed=True), ctx.value(value, "rate")))
    return out


def _known_speeds(ctx: Ctx, known: set[str]) -> dict[str, tuple]:
    """Velocities already known: every point of a known body (shared points by name)."""
    out = {}
    for b in known:
        if b == ctx.frame:
            continue
        for p in ctx.model.bodies[b].points:
            if ctx.shared(p):
                out[p] = ctx.vel(b, p)
    return out


def _driven_wheel(ctx: Ctx, d, group: list[str], speeds: dict) -> list:
    """A speed given along a wheel's plane at its contact: with no velocity across the
    plane, the whole velocity of that point is known."""
    if d.kind != "velocity" or d.along is None or d.point.body not in group:
        return []
    p = d.point.point
    for j in ctx.model.joints:
        if knife_edge(j) and j.at == p and d.point.body in (j.a, j.b):
            e = ctx.num(ctx.sol.geometry(j.id).along)
            along = ctx.num(ctx.inst.direction(d.along, d.where))
            if abs(e[0] * along[1] - e[1] * along[0]) <= 1e-9:
                v = ctx.vel(d.point.body, p)
                speeds[p] = v
                if whole_along(ctx, d, "v"):     # the datum is stated whole already (given.py)
                    return []
                return [msg("vehicle.driven", point=Name(p), joint=Name(j.id, "joint"),
                            sym=Sym("v", p), value=Value(ctx.clean(v, "speed"), "speed"))]
    return []


def _lines(ctx: Ctx, b: str, wheels: list, speeds: dict) -> list[tuple]:
    """(point, direction, reason) of the lines the centre of b lies on."""
    out = []
    for j in wheels:
        if b in (j.a, j.b):
            e = ctx.num(ctx.sol.geometry(j.id).along)
            out.append((ctx.num(ctx.pos(j.at)), (-e[1], e[0]),
                        msg("vehicle.line.wheel", joint=Name(j.id, "joint"), point=Name(j.at))))
    for p in ctx.model.bodies[b].points:
        v = speeds.get(p)
        if v is not None and _size(ctx.num(v)) > TOL * ctx.scale_of("speed"):
            vn = ctx.num(v)
            out.append((ctx.num(ctx.pos(p)), (-vn[1], vn[0]),
                        msg("vehicle.line.velocity", point=Name(p), sym=Sym("v", p))))
    return out


def _centre(ctx: Ctx, b: str, wheels: list, speeds: dict) -> Optional[list]:
    """The centre of b from two of its lines that meet, then ω from a known speed."""
    lines = _lines(ctx, b, wheels, speeds)
    witness = next((p for p in ctx.model.bodies[b].points if p in speeds
                    and _size(ctx.num(speeds[p])) > TOL * ctx.scale_of("speed")), None)
    if witness is None:
        return None
    said = _equiprojective(ctx, b, wheels, speeds, witness)
    if said:
        witness = said[0].args["p"].text
        lines = _on_axle(ctx, _witness_first(ctx, _lines(ctx, b, wheels, speeds), witness, speeds), witness)
    for i, (p1, d1, why1) in enumerate(lines):
        for p2, d2, why2 in lines[i + 1:]:
            det = d1[0] * d2[1] - d1[1] * d2[0]
            if abs(det) <= 1e-9 * _size(d1) * _size(d2):
                continue
            t = ((p2[0] - p1[0]) * d2[1] - (p2[1] - p1[1]) * d2[0]) / det
            centre = (p1[0] + t * d1[0], p1[1] + t * d1[1])
            return said + _from_centre(ctx, b, centre, [why1, why2], witness, speeds)
    if len(lines) >= 2 and ctx.is_zero(ctx.omega(b), "rate"):
        twin = _twin(ctx, b, witness, speeds)
        reason = (msg("vehicle.translation_equal", body=Name(b, "body"), p=Name(witness), q=Name(twin),
                      vp=Sym("v", witness), vq=Sym("v", twin), value=Value(ctx.clean(speeds[witness], "speed"), "speed"))
                  if twin else msg("vehicle.translation", body=Name(b, "body"), point=Name(witness), v=Sym("v", witness)))
        return [reason,
                Derived(omega_sym(b), [], ctx.value(ctx.omega(b), "rate"), b, "omega", False,
                        remark=msg("how.translation"))] + _carried(ctx, b, witness)
    return None


def _own_line(why, witness: str) -> bool:
    """Whether a line is the perpendicular to the witness's velocity."""
    return why.key == "vehicle.line.velocity" and why.args["point"].text == witness


def _witness_first(ctx: Ctx, lines: list, witness: str, speeds: dict) -> list:
    """The lines with the wheels' axles first, then the perpendicular to the velocity the step
    has just found (the notes' C5-2.2: "la direcció perpendicular a la velocitat del punt P i
    ... l'eix de les rodes"), then the other known velocities': the centre is taken from the
    first two that meet."""
    wheels = [x for x in lines if x[2].key == "vehicle.line.wheel"]
    own = [x for x in lines if _own_line(x[2], witness)]
    return wheels + own + [x for x in lines if x not in wheels and x not in own]


def _on_axle(ctx: Ctx, lines: list, witness: str) -> list:
    """The lines with the perpendicular to the witness's velocity folded into the wheel's
    axle when it is that axle itself: the witness lies on the axle and moves along the
    wheel's plane (C5-2.2's P, the axle's midpoint: the notes' "perpendicular a la velocitat
    de P" and "l'eix de les rodes" are one line), so the axle is said once, with that
    coincidence in its own words, and the second line is another known velocity's (round
    15a: a separate sentence said it before the centre's sentence said the lines again).
    The lines unchanged when the witness's line is not an axle, or no other line meets it."""
    own = next((x for x in lines if _own_line(x[2], witness)), None)
    axle = next((x for x in lines if x[2].key == "vehicle.line.wheel"), None)
    if own is None or axle is None:
        return lines
    (p1, d1, _), (p2, d2, why) = own, axle
    if abs(d1[0] * d2[1] - d1[1] * d2[0]) > 1e-9 * _size(d1) * _size(d2) or \
            abs((p1[0] - p2[0]) * d2[1] - (p1[1] - p2[1]) * d2[0]) > 1e-9 * _size(d2) * ctx.inst.scale:
        return lines
    if not any(x[2].key == "vehicle.line.velocity" and not _own_line(x[2], witness)
               and abs(x[1][0] * d2[1] - x[1][1] * d2[0]) > 1e-9 * _size(x[1]) * _size(d2) for x in lines):
        return lines
    told = msg("vehicle.line.wheel_own", joint=why.args["joint"], point=why.args["point"],
               sym=Sym("v", witness), witness=Name(witness))
    return [(p2, d2, told) if x is axle else x for x in lines if x is not own]


def _twin(ctx: Ctx, b: str, witness: str, speeds: dict) -> Optional[str]:
    """Another point of b whose known velocity equals the witness's: two points of a plane
    body with one velocity (v_Q = v_P + ω × PQ, so ω × PQ = 0 and ω = 0) make it translate —
    the reason to give where its lines coincide rather than run parallel (C5-2.2's chassis,
    its two wheels on one axle). None when no such point is known."""
    vw = ctx.num(speeds[witness])
    pw = ctx.num(ctx.pos(witness))
    for p in ctx.model.bodies[b].points:
        if p == witness or p not in speeds or _size([a - z for a, z in zip(ctx.num(ctx.pos(p)), pw)]) <= TOL:
            continue
        if _size([a - z for a, z in zip(ctx.num(speeds[p]), vw)]) <= TOL * ctx.scale_of("speed"):
            return p
    return None


def _equiprojective(ctx: Ctx, b: str, wheels: list, speeds: dict, q: str) -> list:
    """The speed of an asked point P of b on a wheel's axle (the line through the contact
    perpendicular to the wheel's plane e): v_P = s e, and equiprojectivity with the known
    point Q, v_P · QP = v_Q · QP, gives s = (v_Q · QP) / (e · QP). Only where b's wheels give
    one axle line and Q's velocity was carried from a body found before (C5-2.2's trailing
    chassis, hitched at O to the one ahead): where Q's velocity is a datum (the tricycle's
    front wheel, C5-2.1) the notes place the centre from it and turn every point about it.
    Empty when no asked point is there, or QP is across the plane."""
    from ..questions import QUESTIONS

    asked = {ctx.model.resolve_point(x.target).point if isinstance(x.target, str) else x.target.point
             for x in ctx.model.questions if QUESTIONS[x.kind].about == "point"}
    key = ctx.motion_key(q, b)
    if _axles(ctx, b, wheels) != 1 or any(d.kind == "velocity" and ctx.motion_key(d.driven_point().point, d.driven_point().body) == key
                                          for d in ctx.model.drivers):
        return []                           # a given velocity turns the body about its centre at once (C5-2.1)
    for j in wheels:
        if b not in (j.a, j.b):
            continue
        e = ctx.num(ctx.sol.geometry(j.id).along)
        c = ctx.num(ctx.pos(j.at))
        for p in ctx.model.bodies[b].points:
            if p == q or p not in asked or p in speeds:
                continue
            x, qp = ctx.num(ctx.pos(p)), [a - z for a, z in zip(ctx.num(ctx.pos(p)), ctx.num(ctx.pos(q)))]
            if abs((x[0] - c[0]) * e[0] + (x[1] - c[1]) * e[1]) > TOL * ctx.inst.scale:
                continue                     # not on the axle
            if abs(qp[0] * e[0] + qp[1] * e[1]) <= TOL * _size(qp):
                continue
            v = ctx.clean(ctx.vel(b, p), "speed")
            speeds[p] = ctx.vel(b, p)
            seg = Name(segment(q, p))
            unit, along, proj, cos = _projection(ctx, q, p, ctx.vel(b, q), ctx.vel(b, p))
            if ctx.num(cos) < 0:        # the segment the other way: every number positive, never (−a) / (−1)
                seg = Name(segment(p, q))
                unit, proj, cos = ctx.clean(tuple(-c for c in unit), ""), ctx.clean(-proj, "speed"), ctx.clean(-cos, "")
            key = "vehicle.equiprojective_along" if ctx.is_zero(cos - 1, "") else "vehicle.equiprojective"
            return [msg(key, q=Name(q), p=Name(p), body=Name(b, "body"), joint=Name(j.id, "joint"),
                        seg=seg, vp=Sym("v", p), vq=Sym("v", q), value=Value(v, "speed"),
                        speed=Value(_magnitude(ctx, v), "speed", True), unit=Value(unit), along=Value(along),
                        proj=Value(proj, "speed"), cos=Value(cos))]
    return []


def _projection(ctx: Ctx, q: str, p: str, vq: tuple, vp: tuple) -> tuple:
    """The numbers of the equiprojectivity equation a student redoes, v_P · u = v_Q · u with
    u = QP/|QP|: (u, e, v_Q · u, e · u), e the unit vector along v_P (the wheel's plane), so
    |v_P| = (v_Q · u) / (e · u) (C5-2.2: u = (−√2/2, −√2/2), v_O · u = −rω/√2, e · u = −1,
    |v_P| = rω/√2)."""
    if ctx.symbolic:
        import sympy

        def simp(x):
            return sympy.simplify(x)
        root = sympy.sqrt
    else:
        def simp(x):
            return x
        root = _sqrt
    qp = tuple(y - x for x, y in zip(ctx.pos(q), ctx.pos(p)))
    size = simp(root(sum(c ** 2 for c in qp)))
    u = tuple(simp(c / size) for c in qp)
    speed = _magnitude(ctx, vp)
    e = tuple(simp(c / speed) for c in vp)
    proj = simp(sum(a * z for a, z in zip(vq, u)))
    cos = simp(sum(a * z for a, z in zip(e, u)))
    return ctx.clean(u, ""), ctx.clean(e, ""), ctx.clean(proj, "speed"), ctx.clean(cos, "")


def _sqrt(x):
    return x ** 0.5


def _axles(ctx: Ctx, b: str, wheels: list) -> int:
    """How many distinct axle lines b's wheels give (the two wheels of one axle give one)."""
    lines: list[tuple] = []
    for j in wheels:
        if b not in (j.a, j.b):
            continue
        e, c = ctx.num(ctx.sol.geometry(j.id).along), ctx.num(ctx.pos(j.at))
        same = any(abs(e[0] * f[1] - e[1] * f[0]) <= TOL and abs((c[0] - d[0]) * f[0] + (c[1] - d[1]) * f[1])
                   <= TOL * ctx.inst.scale for f, d in lines)
        if not same:
            lines.append((e, c))
    return len(lines)


def _magnitude(ctx: Ctx, v: tuple):
    """|v|, a formula for a symbolic model."""
    if ctx.symbolic:
        import sympy

        return sympy.simplify(sympy.sqrt(sympy.expand(v[0] ** 2 + v[1] ** 2)))
    return _size(v)


def _carried(ctx: Ctx, b: str, witness: str) -> list:
    """v_P = v_W of each pin b shares with another body (C5-2.2's O: "la velocitat del punt
    d'articulació O també és rω"): a translating body moves its points alike."""
    value = ctx.clean(ctx.vel(b, witness), "speed")
    out = []
    for p in ctx.model.bodies[b].points:
        if p != witness and len(ctx.model.carriers(p)) > 1:
            target = Term(Sym("v", ctx.point_label(p, b)), value, Ann("?"), Ann("?"), unknown=True, kind="point")
            side = Term(Sym("v", ctx.point_label(witness, b)), value, Ann("M"), Ann("D"), kind="point")
            out.append(Equation(target, [[side]], "v", ctx.ref(p, b), figure=False))
    return out


def _from_centre(ctx: Ctx, b: str, centre: tuple, why: list, witness: str, speeds: Optional[dict] = None) -> list:
    ident = Sym("I", f"{ctx.frame},{b}", vector=False)
    w = omega_sym(b)
    ctx.worked.add(f"centre:{b}")       # its velocities come from the centre: no check of it by them
    out: list = _pin_shared(ctx, b, witness) + [msg("vehicle.centre", body=Name(b, "body"), first=why[0], second=why[1], centre=ident,
                     where=Value(ctx.clean(_exact_centre(ctx, b, centre), "len"), "len"),
                     rest=Sym("v", centre_point(b)))]
    known = set(speeds or ()) - {witness}
    # the composition the notes write about the centre, v_P = v_{I_b} + v_{P I_b} with
    # v_{I_b} = 0 (002's v_T(I) = v_T(C) + Ω × CI), the centre named in full in every
    # subscript (v_{F I_xassís}, never v_FI, which reads as a point I of the model)
    centre_pt = centre_point(b)
    rest = Term(Sym("v", centre_pt), ctx.clean((0,) * len(ctx.vel(b, witness)), "speed"), Ann("M"), Ann("D"),
                kind="point")
    for k, p in enumerate([witness] + [q for q in ctx.model.bodies[b].points if q != witness and q not in known]):
        arm = segment(centre_pt, p)             # the segment I_{S2}P, the centre's full symbol
        rel = Sym("v", segment(p, centre_pt))
        value = ctx.clean(ctx.vel(b, p), "speed")
        own = segment(p, centre_pt)             # magnitude and direction in the term's own order
        term = Term(rel, value, Ann("?") if k == 0 else Ann("M", magnitude(ctx, w, ctx.omega(b)) + ["·", own]),
                    Ann("perp", own), [w, " × ", arm], k == 0, "rotation")
        target = Term(Sym("v", ctx.point_label(p, b)), value, Ann("M"), Ann("D"), kind="point")
        out.append(Equation(target, [[rest, term]], "v", ctx.ref(p, b), figure=False))
        if k == 0:
            lead = read_along(ctx, rel, arm, w, _arm(ctx, b, p))
            out.append(Derived(w, [] if lead else read_off(ctx, rel, arm, ctx.omega(b)), ctx.value(ctx.omega(b), "rate"),
                               b, "omega", not ctx.symbolic, term, ctx.clean(_arm(ctx, b, p), "len"), lead=lead))
    return out


def _pin_shared(ctx: Ctx, b: str, witness: str) -> list:
    """The sentence that the witness is the pin common to b and the body its velocity is
    given on, so the given velocity is b's point's too: v_{F∈chassis} = v_{F∈fork} (C5-2.1:
    only v_{F∈fork} is given, the equation starts from v_{F∈chassis}). Empty when the
    velocity is given on b itself, or no pin joins the two bodies there."""
    for d in ctx.model.drivers:
        if d.kind != "velocity":
            continue
        given = d.driven_point()
        other = given.body
        if given.point != witness or other in (None, b):
            continue
        if any(pins(j) and j.at == witness and {j.a, j.b} == {b, other} for j in ctx.model.joints):
            sym, given_sym = Sym("v", ctx.point_label(witness, b)), Sym("v", ctx.point_label(witness, other))
            # one point of the two bodies, one label (twenty-first round (e)): "v_F is the velocity of both"
            key = "vehicle.pin_shared_one" if sym == given_sym else "vehicle.pin_shared"
            return [msg(key, point=Name(witness), a=Name(other, "body"), b=Name(b, "body"), sym=sym, other=given_sym)]
    return []


def _exact_centre(ctx: Ctx, b: str, approx: tuple):
    """The solver's centre (exact for symbolic models) where the construction put it."""
    from ..questions.icr import instant_centre
    found = instant_centre(ctx.sol, b, ctx.frame)
    return tuple(found["point"]) if found.get("point") is not None else approx


def _arm(ctx: Ctx, b: str, p: str) -> tuple:
    from ..questions.icr import instant_centre
    c = instant_centre(ctx.sol, b, ctx.frame)["point"]
    return tuple(x - y for x, y in zip(ctx.pos(p), c))


def _pinned(ctx: Ctx, b: str, solved: set[str]) -> Optional[list]:
    """ω of a body pinned to a known one whose joint rate is given: ω = ω_known + rate."""
    for d in ctx.model.drivers:
        if d.kind != "joint":
            continue
        j = ctx.model.joint(d.driven_joint())
        if pin_only(j) and b in (j.a, j.b):
            other = j.a if j.b == b else j.b
            if other in solved:
                rate = Value(ctx.clean(ctx.inst.value(d.rate(), d.where), "rate"), "rate")
                return [Derived(omega_sym(b), [omega_sym(other), " + ", omega_sym(b, other), " = ",
                                               omega_sym(other), " + ", rate],
                                ctx.value(ctx.omega(b), "rate"), b, "omega", not ctx.symbolic)]
    return None


def _size(v) -> float:
    return sum(c * c for c in v) ** 0.5
