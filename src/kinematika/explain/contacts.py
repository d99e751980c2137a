"""The three coincident points of a rolling contact, as the notes build them (seed 002, C5-1.8).

At the contact J of two profiles there are three points: the material point of each body
and the geometric contact point J^geom, which belongs to neither and shows where the
contact is. J^geom moves as a point of a bar hinged at the two circles' centres (it stays
on the line of centres, at a fixed fraction of it: the notes' bar OC, ω_OC = ω₀/3), or, on a
line, as the foot of the perpendicular from the circle's centre (it turns with the line):

    v_C2 = v_C1 + ω_C1C2 × C1C2          v_J^geom = v_C1 + ω_C1C2 × C1J

Rolling without slip keeps the material points' velocities equal at every instant, at the
moving J^geom; differentiating that condition along J^geom gives the accelerations' rule
used in the acceleration steps: their tangential components are equal and

    a_J∈b − a_J∈a = ω_b/a × (v_J∈a − v_J^geom)       (along the common normal).

So v_J^geom is derived here wherever that term is used, and the answer to a `contact`
question is reached point by point.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import add, scale, sub
from .asked import worked
from .context import Ctx, composed, magnitude, omega_sym, read_along, read_off, segment
from .document import (Ann, Derived, Drawing, Equation, Msg, Name, Names, Section, Sym, Term, Value, geometric_name,
                       joint as joint_name, msg)
from .kinds import rolls
from .terms import pair_name, point_term, rotation_terms

KNOWN = (Ann("M"), Ann("D"))
FOUND = (Ann("?"), Ann("?"))


def geometric_sym(level: str, name: str) -> Sym:
    """v_{J^{geom}} (a_{J^{geom}}): the geometric contact point's motion, its name
    (`document.geometric_name`) as the subscript."""
    return Sym(level, geometric_name(name))


def geometric_point(name: str) -> Name:
    """J^{geom}, the geometric contact point, in a sentence (`document.geometric_name`)."""
    return Name(geometric_name(name))


def _rate_of(ctx: Ctx, r: tuple, dv: tuple) -> Any:
    """ω with dv = ω k × r: (r × dv)·k / |r|²."""
    value = (r[0] * dv[1] - r[1] * dv[0]) / (r[0] ** 2 + r[1] ** 2)
    return _simplified(ctx, value)


def _simplified(ctx: Ctx, x: Any) -> Any:
    if not ctx.symbolic:
        return x
    import sympy

    return sympy.simplify(x)


def centre_name(ctx: Ctx, body: str, centre: tuple) -> str:
    """The name of a circle's centre: the model's point there, else a name made for it."""
    for p in ctx.model.bodies[body].points + list(ctx.inst.points):
        if p in ctx.inst.points and ctx.num(ctx.pos(p)) == ctx.num(tuple(centre)):
            return p
    return ctx.name_position(f"C{body}", tuple(centre))


class Bar:
    """The geometric point's carrier: a bar from C1 to C2 (circles), or a circle's centre C
    with the radius CJ turning with a line body (circle on a line)."""

    def __init__(self, ctx: Ctx, j) -> None:
        self.ctx, self.j = ctx, j
        self.contact = ctx.sol.geometry(j.id).contact
        self.name = ctx.contact(j)
        (b1, c1), *rest = self.contact.centres
        self.c1, self.b1 = centre_name(ctx, b1, c1), b1
        self.c2: Optional[str]              # the second circle's centre and body (circles), else None
        self.b2: Optional[str]
        self.turning: Optional[str]         # the line's body (a circle on a line), else None
        if rest:
            (b2, c2), = rest
            self.c2, self.b2 = centre_name(ctx, b2, c2), b2
            r = ctx.r(self.c1, self.c2)
            dv = sub(ctx.vel(b2, self.c2), ctx.vel(b1, self.c1))
            self.omega = _rate_of(ctx, r, dv)
            dr = sub(ctx.acc(b2, self.c2), ctx.acc(b1, self.c1))
            centripetal = scale(self.omega ** 2, r)
            self.alpha = _rate_of(ctx, r, add(dr, centripetal))
            self.turning = None
        else:
            self.c2 = self.b2 = None
            self.turning = self.contact.line_body
            self.omega, self.alpha = ctx.omega(self.turning), ctx.alpha(self.turning)

    def second(self) -> tuple[str, str]:
        """The second circle's centre and body (a bar between two circles)."""
        assert self.c2 is not None and self.b2 is not None, "a circle on a line has one centre"
        return self.c2, self.b2

    def line_body(self) -> str:
        """The body of the line the circle is on (a circle on a line)."""
        assert self.turning is not None, "a bar between two circles turns with no line"
        return self.turning

    @property
    def sym(self) -> Sym:
        """ω_C1C2, the bar's angular velocity (ω of the line body for a circle on a line):
        written ω beside its α_C1C2, as every angular velocity of the page (one letter for
        one kind of quantity; the notes' Ω is the page's ω)."""
        return Sym("ω", segment(self.c1, self.c2), vector=False) if self.c2 else omega_sym(self.line_body())

    @property
    def alpha_sym(self) -> Sym:
        """α_C1C2, the bar's angular acceleration (α of the line body)."""
        return Sym("α", segment(self.c1, self.c2), vector=False) if self.c2 else Sym("α", self.line_body(), vector=False)

    def rotation(self, level: str, q: str, p: str, unknown: bool) -> list[Term]:
        """The bar's ω × QP (or its normal and tangential accelerations), by value."""
        ctx, r = self.ctx, self.ctx.r(q, p)
        seg, back = segment(q, p), segment(p, q)
        name = pair_name(p, q)
        if p == self.name:              # J^{geom} about C: not the material points' v_JC (one symbol, one value)
            name = pair_name(geometric_name(p), q)
        if level == "v":
            mag = Ann("?") if unknown else Ann("M", magnitude(ctx, self.sym, self.omega) + [f"·{back}"])     # the term's own segment (`terms.rotation_terms`)
            return [Term(Sym("v", name), ctx.clean(ctx.space.cross(self.omega, r), "speed"), mag, Ann("perp", back),
                         [self.sym, f" × {seg}"], unknown, "rotation")]
        normal = scale(-self.omega ** 2, r)
        return [Term(Sym("a", name, "n"), ctx.clean(normal, "accel"), Ann("M", [self.sym, f"²·{back}"]),
                     Ann("para", back), [self.sym, f"² · {back}"], False, "normal"),
                Term(Sym("a", name, "t"), ctx.clean(ctx.space.cross(self.alpha, r), "accel"),
                     Ann("?") if unknown else Ann("M", magnitude(ctx, self.alpha_sym, self.alpha) + [f"·{back}"]),
                     Ann("perp", back),
                     [self.alpha_sym, f" × {seg}"], unknown, "tangential")]

    def blocks(self, level: str, with_bar: bool = True) -> list:
        """How J^geom moves: the bar's ω (α) from its two ends (unless worked out already:
        `with_bar` False), then J^geom as its point."""
        ctx = self.ctx
        out: list[Msg | Equation | Derived] = []
        start = point_term(ctx, level, self.c1, self.b1)
        if self.c2 is not None:
            if level == "v":
                told = f"neither:{self.j.id}" in ctx.worked    # the contact's intro said it belongs to neither body
                out.append(msg("geom.bar_told" if told else "geom.bar", geom=geometric_point(self.name), c1=Name(self.c1), c2=Name(self.c2),
                               joint=joint_name(self.j.id), part=Name(str(segment(self.c1, self.name))),
                               whole=Name(str(segment(self.c1, self.c2))), ratio=Value(self.fraction())))
        if self.c2 is not None and with_bar and level == "a" and self.constant():
            # the notes: α_OC = 0 because ω_OC = −ω0/3 is constant (C5-1.8), not read off a_C
            out.append(Derived(self.alpha_sym, [], Value(ctx.clean(self.alpha, "rate2"), "rate2"), "", "alpha", False,
                               remark=self.constant_reason()))
        elif self.c2 is not None and with_bar:
            end = point_term(ctx, level, *self.second())
            turn = self.rotation(level, self.c1, self.c2, True)
            out.append(Equation(end, [[start] + turn], level, figure=False))
            sym = self.sym if level == "v" else self.alpha_sym
            value = self.omega if level == "v" else self.alpha
            lead = read_along(ctx, turn[-1].sym, segment(self.c1, self.c2), sym, ctx.r(self.c1, self.c2))
            out.append(Derived(sym, [] if lead else read_off(ctx, turn[-1].sym, segment(self.c1, self.c2), value),
                               Value(ctx.clean(value, "rate" if level == "v" else "rate2"),
                                     "rate" if level == "v" else "rate2"),
                               "", "omega" if level == "v" else "alpha", not ctx.symbolic, turn[-1],
                               ctx.clean(ctx.r(self.c1, self.c2), "len"), lead=lead))
        elif self.c2 is None and level == "v":
            out.append(msg("geom.foot", geom=geometric_point(self.name), centre=Name(self.c1),
                           line=Name(self.line_body(), "body"), radius=Name(segment(self.c1, self.name)),
                           joint=joint_name(self.j.id)))
        arm = self.rotation(level, self.c1, self.name, False)
        target = Term(geometric_sym(level, self.name), self.geometric(level), *FOUND, unknown=True, kind="point")
        out.append(Equation(target, [[start] + arm], level, figure=False, position=ctx.pos(self.name)))
        return out

    def constant(self) -> bool:
        """Whether the bar's ω is constant over the motion, as the model knows it: two circles
        rolling on each other keep C1C2 = r1 ± r2, so the bar turns at a fixed combination
        of the circles' rates, (r1 ω1 ± r2 ω2)/(r1 ± r2); each circle's body is fixed or
        driven at a rate whose acceleration is zero, so ω_C1C2 is constant and α_C1C2 = 0
        is said from that, as the notes do (C5-1.8: "ω_OC constant"), never read off an
        equation ("α_OC = |a_CO^t| / OC = 0")."""
        ctx = self.ctx
        if not ctx.is_zero(self.alpha, "rate2"):
            return False
        return all(ctx.fixed(b) or _steady(ctx, b) for b in (self.b1, self.second()[1]))

    def constant_reason(self) -> Msg:
        """Why the bar's ω is constant, as the notes say it (C5-1.8): with one end on a fixed
        body, the other runs on the circle of radius OC about it at a constant speed,
        |v_C| = rω₀, so ω_OC = v_C / OC is constant; with both ends moving, the driven rates
        that set it."""
        import sympy

        ctx = self.ctx
        c2, b2 = self.second()
        ends = [(self.c1, self.b1), (c2, b2)]
        fixed = [e for e in ends if ctx.fixed(e[1])]
        args = dict(sym=self.sym, value=Value(ctx.clean(self.omega, "rate"), "rate"),
                    line=Name(str(segment(self.c1, c2))))
        if len(fixed) != 1:
            return msg("how.constant_rate", rates=self.steady_rates(), **args)
        (centre, _), (point, body) = fixed[0], next(e for e in ends if e not in fixed)
        v = ctx.vel(body, point)
        speed = sympy.sqrt(sum(sympy.sympify(x) ** 2 for x in v))
        speed = sympy.simplify(speed) if ctx.symbolic else float(speed)
        d = sympy.sqrt(sum(sympy.sympify(x) ** 2 for x in ctx.r(centre, point)))
        length = Value(ctx.clean(sympy.simplify(d) if ctx.symbolic else float(d), "len"), "len")
        return msg("how.constant_speed", point=Name(point), centre=Name(centre), length=length,
                   v=Sym("v", ctx.point_label(point, body), vector=False), speed=Value(ctx.clean(speed, "speed"), "speed"),
                   **args)

    def steady_rates(self) -> Any:
        """The driven rates the bar's ω is set by (ω_wheel; "ω_1 and ω_2" when both turn)."""
        from .document import Inline

        syms = [omega_sym(b) for b in (self.b1, self.second()[1]) if not self.ctx.fixed(b)]
        items: list = []
        for k, w in enumerate(syms):
            items += ([", "] if k else []) + [w]
        return Inline(items)

    def fraction(self) -> Any:
        """Where J^geom is on the line of centres, C1J / C1C2 (signed: beyond C2 when above
        1), as a number the student can check: the notes' "a 2/3 d'OC des d'O" (C5-1.8),
        never "at the same fraction". Two circles touching at J divide C1C2 in their radii's
        ratio, r1 / (r1 ± r2), so the fraction holds at every instant."""
        ctx = self.ctx
        whole, part = ctx.r(self.c1, self.second()[0]), ctx.r(self.c1, self.name)
        value = (part[0] * whole[0] + part[1] * whole[1]) / (whole[0] ** 2 + whole[1] ** 2)
        return _simplified(ctx, value)

    def geometric(self, level: str) -> Any:
        """v_J^geom (a_J^geom): the motion of the bar's point at J, from its first end C1,
        v_C1 + ω × C1J (a_C1 − ω²·C1J + α × C1J)."""
        ctx = self.ctx
        start = point_term(ctx, level, self.c1, self.b1)
        arm = self.rotation(level, self.c1, self.name, False)
        moved = add(start.value, arm[0].value) if level == "v" else add(start.value, add(arm[0].value, arm[1].value))
        return ctx.clean(moved, "speed" if level == "v" else "accel")


def _steady(ctx: Ctx, body: str) -> bool:
    """Whether a driver gives `body`'s ω relative to the frame with a zero acceleration: its
    rate is constant over the motion (C5-1.8's wheel at ω0)."""
    for d in ctx.model.drivers:
        if d.kind == "omega" and d.body == body and d.relative_to in (None, ctx.frame):
            if d.accel is None:
                return True
            given = d.given(accel=True)
            parts = given if isinstance(given, tuple) else (given,)      # a spatial ω is a vector
            return all(ctx.is_zero(ctx.inst.value(p, d.where), "rate2") for p in parts)
    return False


def geometric_blocks(ctx: Ctx, j, done: set, pair: Optional[tuple[str, str]] = None) -> list:
    """Where an acceleration step uses the contact term of joint j between the bodies of
    `pair` (body, other; j.b, j.a unless told): the rule that gives the term (said once, in
    the orientation the equation uses), the geometric point's velocity (its bar's ω worked
    out once per pair of centres), and ω_body/other = ω_body − ω_other."""
    if j.id in done:
        return []
    done.add(j.id)
    b, a = pair or (j.b, j.a)
    bar = Bar(ctx, j)
    w = omega_sym(b, a)
    ctx.worked.add(f"rate:v:{b}/{a}")              # said here: a composition does not say it again
    rel = Derived(w, [omega_sym(b), " − ", omega_sym(a)], ctx.value(ctx.omega(b, a), "rate"),
                  lead=None if a == ctx.frame else composed(omega_sym(b), w, omega_sym(a), b == ctx.frame))
    out: list = []
    if "rule" not in done:
        done.add("rule")
        term = [Sym("a", f"{bar.name}∈{b}"), " − ", Sym("a", f"{bar.name}∈{a}"), " = ", w, " × (",
                Sym("v", f"{bar.name}∈{a}"), " − ", geometric_sym("v", bar.name), ")"]
        from .document import Inline

        out.append(msg("geom.rule", joint=joint_name(j.id), geom=geometric_point(bar.name), rule=Inline(term)))
    key = f"bar:{bar.c1}:{bar.c2 or bar.turning}"
    blocks = bar.blocks("v", with_bar=key not in ctx.worked)
    ctx.worked.update({key, f"geom:v:{j.id}"})
    return out + blocks + [rel]


def contact_section(ctx: Ctx, written: Optional[dict[tuple[str, str], int]] = None) -> Optional[Section]:
    """Each `contact` question: the velocities and accelerations of the three coincident
    points, each from an equation (C5-1.8: the wheel's point, the ground's, and J^geom on
    the bar OC). A material point a step already wrote (`written`: (level, label) -> the
    step's number) is referred to with its value, not written again (001's rolling pair:
    v_F∈N and a_F∈N, step 3)."""
    asked = [q for q in worked(ctx).contacts if ctx.planar and rolls(ctx.model.joint(q.target))]
    if not asked:
        return None
    sec = Section(msg("sec.contact"))
    for q in asked:
        j = ctx.model.joint(q.target)
        bar = Bar(ctx, j)
        sec.add(msg("contact.intro", joint=joint_name(j.id), point=Name(bar.name), a=Name(j.a, "body"),
                    b=Name(j.b, "body"), geom=geometric_point(bar.name)))
        ctx.worked.add(f"neither:{j.id}")       # said once: the bar's sentence does not say it again
        for level in ("v", "a"):
            for body in (j.a, j.b):
                step = (written or {}).get((level, ctx.point_label(bar.name, body)))
                if step is not None and not ctx.fixed(body):
                    sec.add(_written(ctx, bar.name, body, level, step))
                    continue
                sec.blocks += _material(ctx, bar, body, level)
            if f"geom:{level}:{j.id}" in ctx.worked:     # worked out for an acceleration step
                sec.add(msg("contact.above", sym=geometric_sym(level, bar.name),
                            value=Value(bar.geometric(level), "speed" if level == "v" else "accel")))
            else:
                key = f"bar:{bar.c1}:{bar.c2 or bar.turning}" + ("" if level == "v" else ":a")
                sec.blocks += bar.blocks(level, with_bar=key not in ctx.worked)
                ctx.worked.update({key, f"geom:{level}:{j.id}"})
            sec.add(coincident_drawing(ctx, j, bar.name, level))
    return sec


def coincident_drawing(ctx: Ctx, j, name: str, level: str) -> Drawing:
    """The figure of the three points that coincide at the contact `name` of joint j, after
    the level's equations: the mechanism at the instant with J marked, and at J the velocity
    (acceleration) of each body's point and of J^{geom} as arrows named as the text names
    them (`DrawOptions.coincident`), a zero one written "= 0" beside J — as the notes draw
    C5-1.8's J∈roda, J∈terra and J^{geom} (issue 30, twenty-eighth round (a): four teachers
    found the page had no figure of them). Any model asking a rolling contact's points gets
    it; its caption says which arrows are drawn and which are zero, read off the figure
    itself (`coincident_caption`)."""
    from .structure import drawing

    kind = "velocity" if level == "v" else "acceleration"
    fig = drawing(ctx, "fig.contact", velocities=False, accelerations=False, centres=False, curvature=False,
                  coincident=kind, contacts={j.id: name})
    fig.caption.args.update(coincident_caption(ctx, j, name, level, fig.options))
    return fig


def coincident_caption(ctx: Ctx, j, name: str, level: str, options: dict) -> dict:
    """What the figure of the coincident points draws, read off the figure itself (`draw`'s
    scene), for its caption to say just that: the contact, its two bodies and J^{geom}; the
    points whose arrows are drawn (`moving`, `arrows`: their symbols, as the labels write
    them) and those whose vector is zero, written beside J (`still`, `zeros`)."""
    from ..draw.build import build_scene
    from ..draw.options import DrawOptions

    kind = options["coincident"]
    scene = build_scene(ctx.inst, ctx.sol, DrawOptions(**options))
    drawn = [v for v in scene.vectors if v.kind == kind]
    top = max([v.magnitude for v in drawn] + [0.0])
    moving = [_drawn_sym(v.ref, level, j) for v in drawn if v.magnitude > 1e-9 * top]
    zeros = [_drawn_sym(v.ref, level, j) for v in drawn if not v.magnitude > 1e-9 * top]
    return {"point": Name(name), "a": Name(j.a, "body"), "b": Name(j.b, "body"), "geom": geometric_point(name),
            "level": level, "accel": int(level == "a"), "moving": len(moving), "arrows": Names(moving), "still": len(zeros),
            "zeros": Names(zeros), "moduli": 1, "unit": ""}


def _drawn_sym(ref: str, level: str, j) -> Sym:
    """The symbol of an arrow of the coincident points' figure, from its ref (J@body, J:geom):
    v_{J∈body} or v_{J^{geom}}, as the text writes it."""
    name, _, body = ref.partition("@")
    if not body:
        return geometric_sym(level, ref.partition(":")[0])
    return Sym(level, f"{name}∈{body}")


def _written(ctx: Ctx, name: str, body: str, level: str, step: int) -> Msg:
    """A material point at the contact a step already found, referred to with its value; a
    moving body's point with no velocity is that body's instant centre, and the step said so
    (C5-1.8: "v_J∈wheel = 0, found in Step 1: J is the instant centre of the wheel") — not
    v_J∈wheel = v_C + v_JC derived again."""
    value = ctx.vel(body, name) if level == "v" else ctx.acc(body, name)
    args = dict(sym=Sym(level, ctx.point_label(name, body)), step=step,
                value=Value(ctx.clean(value, "speed" if level == "v" else "accel"), "speed" if level == "v" else "accel"))
    if level == "v" and ctx.is_zero(value, "speed"):
        return msg("contact.written_centre", point=Name(name), body=Name(body, "body"), **args)
    return msg("contact.written", **args)


def _material(ctx: Ctx, bar: Bar, body: str, level: str) -> list:
    """The body's material point at J from its circle's centre (or a point of it): the
    rigid-body field; a point of the fixed body has neither velocity nor acceleration."""
    name = bar.name
    if ctx.fixed(body):
        return [msg("contact.fixed", point=Name(name), body=Name(body, "body"),
                    sym=Sym(level, f"{name}∈{body}"))]
    centre = bar.c1 if body == bar.b1 else bar.c2 if body == bar.b2 else None
    if centre is None:
        centre = next((p for p in ctx.model.bodies[body].points), None)
    target = point_term(ctx, level, name, body, False)
    if centre is None:
        return []
    side = [point_term(ctx, level, centre, body)] + rotation_terms(ctx, level, body, centre, name, False)
    return [Equation(target, [side], level, ctx.ref(name, body), figure=False, position=ctx.pos(name))]
