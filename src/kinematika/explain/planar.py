"""Velocities and accelerations step by step, group by group, in the relative-motion method.

Each step writes the vector equation of seed 001 for the point where the group closes,
with the M/D/? of every term, reads the group's ω and α off the solved terms, and then
carries the motion to the other points of its bodies (v_P = v_Q + ω × QP). Groups that
are not dyads (gears, rolling pairs, triads) get their joint conditions, with the rolling
contact written as no slip (velocities) and contact kept (accelerations).
"""
from __future__ import annotations

from typing import Optional

from ..model.model import Joint
from ..point_pair import PointPair
from .context import Ctx, alpha_sym, fixed_sign, omega_sym, read_along, read_off, segment, split_pair
from .document import Ann, Derived, Equation, Inline, Msg, Section, Sym, Term, Value, body, joint, msg, point
from .group import centre_site, group_blocks, still_contact
from .said_first import conditions_first
from .shared import shared_rates
from .higher import higher_pair_steps
from .contacts import geometric_blocks
from .given import driven, sign_of, heading, speeding, whole_along
from .kinds import kind_key, meshes, pin_only, roller, rolls, turns
from .order import Step, as_found, merge_vehicles
from .structure import step_title
from .terms import contact_term, guide, point_term, relative_name, rotation_terms, slide_terms, target_term
from .triad import triad_steps
from .vehicles import spins, wheel_route

body_ = body

LEVEL_UNIT = {"v": "rate", "a": "rate2"}


class PlanarSteps:
    """Builds the velocity or the acceleration section of a planar mechanism."""

    def __init__(self, ctx: Ctx, steps: list[Step], level: str) -> None:
        self.ctx = ctx
        self.steps = steps
        self.level = level
        self.known = {ctx.frame}
        self.done: set[str] = set()          # point labels already explained
        self.used: set[str] = set()          # joints already written
        self.stated: set[int] = set()        # drivers already stated
        self.geometric: set[str] = set()     # rolling joints whose v_J^geom is derived
        self.found_in: dict[str, int] = {}   # point label -> the step that explained it (earlier steps)

    def section(self) -> Section:
        """The velocity (or acceleration) section: its introduction, then one subsection per
        step of the order of solution, each group's bodies known once it is written; a symbolic
        model's accelerations first say that ω is written by its name (ω_crank) in the formulas."""
        title = "sec.velocities" if self.level == "v" else "sec.accelerations"
        sec = Section(msg(title))
        sec.add(msg("v.intro", marks=0, clash="") if self.level == "v" else msg("a.intro"))
        i = 0
        written: list[tuple[Section, list[str]]] = []
        for step in merge_vehicles(self.ctx, self.steps):
            if all(self.ctx.fixed(b) for b in step.bodies):  # welded to the frame: part of it, said in Structure
                self.used.update(step.joints)
                self.known.update(step.bodies)
                continue
            i += 1
            blocks = shared_rates(conditions_first(self.step(step)))      # first: the title says the bodies as the step finds them
            sub = Section(step_title(i, as_found(self.ctx, step)), level=3)
            sub.blocks = blocks
            sec.blocks.append(sub)
            written.append((sub, list(step.bodies)))
            for label in self.done:          # later steps refer to it: "a_C, found in Step 1"
                self.found_in.setdefault(label, i)
            self.known.update(step.bodies)
        gather_own(self.ctx, written)
        if self.level == "a" and self.ctx.symbolic and self.ctx.inst.names:
            first = next(iter(self.ctx.model.moving_bodies))
            import sympy

            named = Value(sympy.Symbol(f"omega_{first}"), "")      # written as in the formulas: ω_crank
            sec.blocks.insert(1, msg("a.named", name=named, body=body(first)))
        return sec

    # one step ----------------------------------------------------------------------------
    def step(self, step: Step) -> list:
        """One step's blocks: the drivers it uses, then its group's equations — the input body,
        a dyad (RRR, RRP, RPR, PRP, or a pin in a slot), a higher pair, a vehicle's wheels, a
        triad, or a group planned equation by equation, else the joints' conditions — and the
        motion carried to the bodies' other points."""
        model = self.ctx.model
        joints = {j.id: j for j in model.joints}
        chain = [joints[j] for j in step.joints if j in joints]
        builder = {"input": self.input, "RRR": self.rrr, "RRP": self.dyad_rp, "RPR": self.rpr,
                   "PRP": self.prp}.get(step.kind)
        blocks = self.drivers(step)
        if step.kind == "other":
            higher = higher_pair_steps(self, step)
            if higher is not None:
                self.used.update(step.joints)
                return blocks + higher + self.carry(step)
            route = wheel_route(self.ctx, step.bodies, self.known, self.level)
            if route is None:
                triad = triad_steps(self, step)
                if triad is not None:
                    self.used.update(step.joints)
                    return blocks + triad + self.carry(step)
                planned = group_blocks(self, step)
                if planned is not None:
                    return blocks + planned + self.carry(step)
            if route is not None:
                self.used.update(step.joints)
                for b in step.bodies:
                    self.done.update(self.ctx.point_label(p, b) for p in self.ctx.model.bodies[b].points)
                return blocks + route + spins(self.ctx, step.bodies)
        if builder is not None and (step.source == "assur" or step.kind != "input"):
            made = builder(step, chain)
            if made is not None:
                self.used.update(step.joints)
                return blocks + made + self.carry(step)
        return blocks + self.other(step) + self.carry(step)

    def drivers(self, step: Step) -> list:
        """The drivers that act on the step's bodies, each stated once, at its first step; a
        held pin not at all (C5-2.1's steering, δ̇ = 0): a condition the Data say in words,
        which the step's composition recalls by its symbol (ω_fork = ψ̇ + δ̇ = ψ̇ + 0) — the
        sentence twice on one page was the fourteenth round's reader's edit."""
        out = []
        for d in self.ctx.model.drivers:
            if d.index not in self.stated and set(driven(self.ctx, d)) & set(step.bodies):
                self.stated.add(d.index)
                if d.kind == "joint" and d.joint is not None and turns(self.ctx.model.joint(d.joint)) \
                        and held(self.ctx, d, self.level):
                    continue            # a condition the Data said: the step's ω_b = ω_a + δ̇ recalls it
                out.append(driver_msg(self.ctx, d, self.level))
                if whole_along(self.ctx, d, self.level):      # stated whole: a written point to go from
                    self.done.add(self.ctx.point_label(d.driven_point().point, d.driven_point().body))
        return out

    def input(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """The input body: its given ω (α) about its pivot, or the slide along its guide, v_P =
        v_P∈frame + v_rel, for a prismatic input."""
        body, j = step.bodies[0], chain[0]
        given = any(d.kind == "omega" and d.body == body and d.relative_to in (None, self.ctx.frame)
                    for d in self.ctx.model.drivers)
        if not pin_only(j):
            out: list = [self.same(body, self.ctx.frame, j)]
        elif given:
            out = []            # "Given: ω_2 = …" says it all
        else:
            out = [self.rate(body)]
        if pin_only(j):
            self.done.add(self.ctx.point_label(j.point_at(), body))
            out.append(msg("input.revolute", body=body_(body), point=point(j.point_at())))
            return out
        p = self.ctx.model.bodies[body].points[0]
        holder = j.a if j.b == body else j.b
        out.append(msg("input.prismatic", body=body_(body), joint=joint(j.id)))
        if self.ctx.fixed(holder) and self.given_point(p, body):
            self.done.add(self.ctx.point_label(p, body))      # "Given: v_A …" along a fixed guide says it all
            return out
        side = [point_term(self.ctx, self.level, p, holder)] + \
            slide_terms(self.ctx, self.level, holder, body, p, guide(j), j.id, False)
        out.append(self.equation(self.target(p, body, True), [side], p, body))
        return out

    def given_point(self, p: str, body: str) -> bool:
        """Whether a driver gives the velocity of point p of `body` (and its acceleration)."""
        key = self.ctx.motion_key(p, body)
        return any(d.kind == "velocity" and self.ctx.motion_key(d.driven_point().point, d.driven_point().body) == key
                   for d in self.ctx.model.drivers)

    def rrr(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """RRR: B, the pin of the two bodies, from each pivot: v_B = v_A + ω₁ × AB = v_C + ω₂ ×
        CB (with α × r and ω × (ω × r) at accelerations); both ω (α) read off the terms."""
        (b1, b2), (j1, j2, j3) = step.bodies, chain
        a, b, c = j1.point_at(), j2.point_at(), j3.point_at()
        side1 = [self.point(a, b1)] + rotation_terms(self.ctx, self.level, b1, a, b, True)
        side2 = [self.point(c, b2)] + rotation_terms(self.ctx, self.level, b2, c, b, True)
        eq = self.equation(self.target(b, b1, known=False), [side1, side2], b, b1)
        return [eq, self.read(b1, side1[-1], a, b), self.read(b2, side2[-1], c, b)]

    def dyad_rp(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """RRP: B, the pin of the two bodies, turns about A and slides along the guide."""
        if len(chain) == 2:
            return self.slot_dyad(step, chain)
        (b1, b2), (j1, j2, j3) = step.bodies, chain
        k2 = step.known[-1]
        a, b = j1.point_at(), j2.point_at()
        side1 = [self.point(a, b1)] + rotation_terms(self.ctx, self.level, b1, a, b, True)
        side2 = [self.point(b, k2)] + slide_terms(self.ctx, self.level, k2, b2, b, guide(j3), j3.id)
        eq = self.equation(self.target(b, b1, known=False), [side1, side2], b, b1)
        return [eq, self.read(b1, side1[-1], a, b), self.same(b2, k2, j3)]

    def rpr(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """RPR: the pin A of the slider, seen from the guide body turning about C."""
        if len(chain) == 2:
            return self.slot_dyad(step, chain)
        (b1, b2), (j1, j2, j3) = step.bodies, chain
        a, c = j1.point_at(), j3.point_at()
        side = [self.point(c, b2)] + rotation_terms(self.ctx, self.level, b2, c, a, True) + \
            slide_terms(self.ctx, self.level, b2, b1, a, guide(j2), j2.id)
        eq = self.equation(self.target(a, b1, known=True), [side], a, b1)
        rot = next(t for t in side if t.kind in ("rotation", "tangential"))
        return [eq, self.read(b2, rot, c, a), self.same(b1, b2, j2)]

    def prp(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """PRP: the middle pin B slides along both guides, v_B = v_B∈k₁ + v_rel,1 = v_B∈k₂ +
        v_rel,2 (Coriolis at accelerations); each body shares ω with the body that guides it."""
        if len(chain) == 2:
            return self.slot_dyad(step, chain)
        (b1, b2), (j1, j2, j3) = step.bodies, chain
        k1, k2, b = step.known[0], step.known[-1], j2.point_at()
        side1 = [self.point(b, k1)] + slide_terms(self.ctx, self.level, k1, b1, b, guide(j1), j1.id)
        side2 = [self.point(b, k2)] + slide_terms(self.ctx, self.level, k2, b2, b, guide(j3), j3.id)
        eq = self.equation(self.target(b, b1, known=False), [side1, side2], b, b1)
        return [eq, self.same(b1, k1, j1), self.same(b2, k2, j3)]

    def slot_dyad(self, step: Step, chain: list[Joint]) -> Optional[list]:
        """One body with a revolute or prismatic joint and a pin in a slot."""
        body, (first, slot) = step.bodies[0], chain
        k1 = step.known[0]
        pin, holder = slot.point_at(), slot.a if slot.b == body else slot.b
        ctx, lv = self.ctx, self.level
        if slot.a == body:                      # the slot is cut in the body: RPR
            if not pin_only(first):
                return None
            c = first.point_at()
            side = [self.point(c, body)] + rotation_terms(ctx, lv, body, c, pin, True) + \
                slide_terms(ctx, lv, body, holder, pin, guide(slot), slot.id)
            eq = self.equation(self.target(pin, holder, known=True), [side], pin, holder)
            rot = next(t for t in side if t.kind in ("rotation", "tangential"))
            return [eq, self.read(body, rot, c, pin)]
        side2 = [self.point(pin, holder)] + slide_terms(ctx, lv, holder, body, pin, guide(slot), slot.id)
        if pin_only(first):                     # RRP: the pin turns about the body's pivot
            c = first.point_at()
            side1 = [self.point(c, body)] + rotation_terms(ctx, lv, body, c, pin, True)
            eq = self.equation(self.target(pin, body, known=False), [side1, side2], pin, body)
            return [eq, self.read(body, side1[-1], c, pin)]
        side1 = [self.point(pin, k1)] + slide_terms(ctx, lv, k1, body, pin, guide(first), first.id)
        eq = self.equation(self.target(pin, body, known=False), [side1, side2], pin, body)
        return [eq, self.same(body, k1, first)]

    # groups that are not dyads ------------------------------------------------------------
    def other(self, step: Step) -> list:
        """A group that is no dyad: its joints' conditions one by one (a rolling contact as no
        slip, then contact kept) and each body's ω (α) read from them."""
        ctx, group = self.ctx, set(step.bodies)
        scope = self.known | group
        out: list = [msg("other.intro")]
        for j in ctx.model.joints:
            if j.id in self.used or not ({j.a, j.b} <= scope and {j.a, j.b} & group):
                continue
            self.used.add(j.id)
            if rolls(j):
                out += self.rolling(j, group)
            else:
                out.append(condition_msg(j, self.level, self.ctx.frame))
        out += [self.read_from(b, out) for b in step.bodies]
        return out

    def read_from(self, body: str, blocks: list) -> Derived:
        """ω (α) of a body of the group, read off the first equation where its rotation
        term is unknown: ω = v_PQ / QP; stated from the solution when no equation has it."""
        sym = omega_sym(body) if self.level == "v" else alpha_sym(body)
        for eq in (b for b in blocks if isinstance(b, Equation)):
            for t in (t for side in eq.sides for t in side):
                if t.unknown and t.kind in ("rotation", "tangential") and t.how and t.how[0] == sym \
                        and isinstance(t.dir.ref, str):
                    q, p = split_segment(t.dir.ref)
                    return self.read(body, t, q, p)
        return self.rate(body)

    def rolling(self, j: Joint, group: set[str]) -> list:
        """A rolling contact J of joint `j`: no slip, v_J∈b = v_J∈a (each side from a known
        point of its body), at velocities; at accelerations the contact kept, a_J∈b = a_J∈a plus
        the contact's term along the normal."""
        ctx, lv = self.ctx, self.level
        contact = ctx.sol.geometry(j.id).contact
        name = self.contact_name(j)
        ctx.name_position(name, contact.point)
        sides = [self.via(body, name, body in group) for body in (j.b, j.a)]
        if lv == "v":
            target = Term(Sym("v", name), ctx.clean(ctx.vel(j.b, name), "speed"), Ann("?"), Ann("?"),
                          unknown=True, kind="point")
            eq = Equation(target, sides, "v", ctx.ref(name, j.b), position=contact.point)
            rolling, on = roller(ctx.model, j)
            return [msg("rolling.noslip", joint=joint(j.id), a=body(on), b=body(rolling), point=point(name),
                        gear=meshes(j)), eq]
        rel = contact_term(ctx, name, j.b, j.a)
        target = Term(Sym("a", f"{name}∈{j.b}"), ctx.clean(ctx.acc(j.b, name), "accel"),
                      Ann("?"), Ann("?"), unknown=True, kind="point")
        eq = Equation(target, [sides[0], sides[1] + [rel]], "a", ctx.ref(name, j.b), position=contact.point)
        rolling, on = roller(ctx.model, j)
        return [msg("rolling.kept", joint=joint(j.id), a=body(on), b=body(rolling), point=point(name),
                    vrel=Sym("v", relative_name(name, j.b, j.a)))] + \
            geometric_blocks(ctx, j, self.geometric) + [eq]

    def contact_name(self, j: Joint) -> str:
        """The name the explanation gives joint `j`'s contact point (J, J1 …; `Ctx.contact`)."""
        return self.ctx.contact(j)

    def via(self, body: str, point: str, unknown: bool) -> list[Term]:
        """The motion of `point` of `body` from a point of the body: v_Q + ω × QP."""
        q = self.start(body)
        if q is None:
            return [point_term(self.ctx, self.level, point, body, True)]
        return [self.point(q, body)] + rotation_terms(self.ctx, self.level, body, q, point, unknown)

    def start(self, body: str) -> Optional[str]:
        """The body's best-known point: a shape's centre, a pin shared with another body, any."""
        ctx = self.ctx
        if body == ctx.frame:
            return None
        for shape in ctx.model.bodies[body].shapes:
            centre = getattr(shape, "center_point", None)
            if centre:
                return centre
        points = ctx.model.bodies[body].points
        pinned = [p for p in points if len(ctx.model.carriers(p)) > 1 and ctx.shared(p)]
        chosen = pinned or points
        return chosen[0] if chosen else None

    # pieces ------------------------------------------------------------------------------
    def point(self, p: str, body: str) -> Term:
        """The known motion of point `p` of `body` as a term (v_P or a_P)."""
        return point_term(self.ctx, self.level, p, body, True)

    def target(self, p: str, body: str, known: bool) -> Term:
        """The term an equation is written for: the motion of `p` of `body`, known or solved in
        this step."""
        return target_term(self.ctx, self.level, p, body, known)

    def equation(self, target: Term, sides: list[list[Term]], p: str, body: str) -> Equation:
        """The equation target = side₁ = side₂ … at the section's level; its points are marked
        explained."""
        self.done.add(self.ctx.point_label(p, body))
        self.done.update(t.sym.sub for side in sides for t in side if t.kind == "point")
        return Equation(target, sides, self.level, self.ctx.ref(p, body))

    def read(self, body: str, term: Term, q: str, p: str) -> Derived:
        """ω = v_PQ / QP (or α = aᵗ_PQ / QP), signed counter-clockwise."""
        ctx = self.ctx
        seg = segment(q, p)
        if self.level == "v":
            sym, value = omega_sym(body), ctx.omega(body)
        else:
            sym, value = alpha_sym(body), ctx.alpha(body)
        lead = read_along(ctx, term.sym, seg, sym, ctx.r(q, p))
        return Derived(sym, [] if lead else read_off(ctx, term.sym, seg, value), ctx.value(value, LEVEL_UNIT[self.level]),
                       body, "omega" if self.level == "v" else "alpha", not ctx.symbolic, term,
                       ctx.clean(ctx.r(q, p), "len"), lead=lead)

    def same(self, body: str, other: str, j: Joint) -> Derived:
        """Bodies joined by a prismatic pair share ω and α."""
        ctx = self.ctx
        if self.level == "v":
            sym, ref, value = omega_sym(body), omega_sym(other), ctx.omega(body)
        else:
            sym, ref, value = alpha_sym(body), alpha_sym(other), ctx.alpha(body)
        return Derived(sym, [ref, " ", msg("how.prismatic", joint=joint(j.id))],
                       ctx.value(value, LEVEL_UNIT[self.level]), body,
                       "omega" if self.level == "v" else "alpha", not ctx.symbolic)

    def rate(self, body: str) -> Derived:
        """`body`'s ω (or α) as given, signed counter-clockwise for numbers."""
        ctx = self.ctx
        if self.level == "v":
            sym, value = omega_sym(body), ctx.omega(body)
        else:
            sym, value = alpha_sym(body), ctx.alpha(body)
        return Derived(sym, [], ctx.value(value, LEVEL_UNIT[self.level]), body,
                       "omega" if self.level == "v" else "alpha", not ctx.symbolic)

    def carry(self, step: Step, fallback: bool = True) -> list:
        """The motion of the other points of the step's bodies: v_P = v_Q + ω × QP, each
        body from a point already written (bodies whose points follow from another's last);
        without `fallback`, a body with no point written is left to the bodies pinned to it
        (a planet said to be the same as another: its centre is the carrier's)."""
        ctx, out = self.ctx, []
        pending = [b for b in step.bodies if ctx.model.bodies[b].points]
        while pending:
            ready = [b for b in pending if self.anchor(b) is not None]
            body = ready[0] if ready else pending[0]
            pending.remove(body)
            found = self.anchor(body)
            if found is None and not fallback:
                continue
            q, owner = found if found is not None else (ctx.model.bodies[body].points[0], body)
            if found is not None:
                out += self.at_rest(q, owner)
            if found is None:                   # nothing written of it: the group's value
                self.done.add(ctx.point_label(q, body))
                unit = "speed" if self.level == "v" else "accel"
                out.append(msg("carry.anchor", sym=Sym(self.level, ctx.point_label(q, body)),
                               value=ctx.value(point_term(ctx, self.level, q, body).value, unit)))
            for p in ctx.model.bodies[body].points:
                label = ctx.point_label(p, body)
                if label in self.done or p == q:
                    continue
                self.done.add(label)
                side = [self.point(q, owner)] + rotation_terms(ctx, self.level, body, q, p, False)
                out.append(Equation(self.target(p, body, known=True), [side], self.level, ctx.ref(p, body)))
        return out

    def anchor(self, body: str) -> Optional[tuple[str, str]]:
        """(point, body it was written as) of a point of `body` already written: one of
        its points, or one pinned to it (B∈rocker for B∈N), else another material point of
        it (a contact J∈body); None when none is."""
        ctx = self.ctx
        if self.level == "v":                   # its instant centre, placed before the velocities
            for name, b in ctx.centre_sites.items():
                if b == body and f"drive:{body}" not in ctx.worked:     # a composed rate: from its pin
                    return name, body
        written: dict[str, tuple[str, str]] = {}
        for label in sorted(self.done):
            name, _, owner = label.partition("∈")
            if owner and owner not in ctx.model.bodies:
                continue
            written.setdefault(ctx.motion_key(name, owner) if owner else name, (name, owner))
        for p in ctx.model.bodies[body].points:
            name, owner = written.get(ctx.motion_key(p, body), ("", ""))
            if name:
                return p, owner or body
            known = [k for k in self.known if k in ctx.model.carriers(p)
                     and ctx.motion_key(p, k) == ctx.motion_key(p, body)]
            if known:                           # a point of a body found before (a weld to the ground)
                return p, known[0]
        for name, owner in written.values():
            if owner == body:
                return name, body
        still = self.still_joint(body)
        if still is not None:                   # rolling on a fixed body: its contact is at rest
            return ctx.contact(still[0]), body
        return None

    def at_rest(self, q: str, body: str) -> list:
        """The sentence that point q of `body` has no velocity, the first time an equation
        starts from it: an instant centre placed before the velocities, or the contact of a
        body rolling on a fixed one."""
        ctx = self.ctx
        label = ctx.point_label(q, body)
        if self.level != "v" or label in self.done:
            return []
        if ctx.centre_sites.get(q) == body:
            self.done.add(label)
            return [centre_site(ctx, q, body)]
        still = self.still_joint(body)
        if still is not None and q == ctx.contact(still[0]):
            self.done.add(label)
            self.used.add(still[0].id)
            return [still_contact(ctx, still[0], still[1], body)]
        return []

    def still_joint(self, body: str) -> Optional[tuple[Joint, str]]:
        """(joint, fixed body) of a rolling contact of `body` on a fixed body, at velocities:
        its contact point is at rest, the body's instant centre."""
        ctx = self.ctx
        if self.level != "v":
            return None
        for j in ctx.model.joints:
            if rolls(j) and ctx.sol.geometry(j.id).contact is not None:
                for fixed, b in ((j.a, j.b), (j.b, j.a)):
                    if b == body and fixed in self.known and ctx.fixed(fixed):
                        return j, fixed
        return None


def split_segment(seg: str) -> tuple[str, str]:
    """The two point names of a segment written by `segment` (AB, OA1; `context.split_pair`)."""
    return split_pair(seg)


def joint_rate_sym(ctx: Ctx, joint_id: str, level: str) -> Sym:
    """A driven pin's rate as the notes give it, by the bodies it joins: ω_{b rel a} (α), the
    second body relative to the first (ω_b alone on the frame), the symbol the composition
    ω_b = ω_a + ω_{b rel a} writes later (C5-2.1: the steering held, ω_{front wheel rel
    chassis} = 0) — not "the relative angular velocity at the pin F", a sentence the notes
    do not write."""
    j = ctx.model.joint(joint_id)
    rel = None if j.a == ctx.frame else j.a
    return (omega_sym if level == "v" else alpha_sym)(j.b, rel)


def held(ctx: Ctx, d, level: str) -> bool:
    """Whether a pin's driver holds it at this level: rate 0 (velocities), and rate and
    acceleration 0 (accelerations). A held pin is a condition of the joint (C5-2.1's steering,
    its angle given and not changing), not a motion given: it is said so, never as a datum."""
    given = [d.value] + ([d.accel] if level == "a" else [])
    return all(g is not None and ctx.is_zero(ctx.inst.value(g, d.where), "") for g in given)


def held_msg(ctx: Ctx, joint_id: str, level: str) -> Msg:
    """A held pin in words: it does not turn at this instant, ω_{b rel a} = 0 (α likewise)."""
    j = ctx.model.joint(joint_id)
    return msg("driver.held" if level == "v" else "driver.held_accel", point=point(j.at) if j.at else joint(j.id),
               a=body(j.a), b=body(j.b), sym=joint_rate_sym(ctx, joint_id, level))


def sensed(ctx: Ctx, value: Value) -> Value | Inline:
    """A planar rate given as data with its sense in words, as the answers give one:
    ω_O2E = −5 rad/s (clockwise), ω_M = 4 rad/s (counter-clockwise) (twenty-ninth round (a):
    the data said the sign only); a zero rate, or a formula whose sign its symbols do not fix,
    as it is."""
    sign = fixed_sign(ctx, value.value) if ctx.planar else 0
    if sign == 0:
        return value
    return Inline([value, " (", msg("sense.ccw" if sign > 0 else "sense.cw"), ")"])


def driver_msg(ctx: Ctx, d, level: str) -> Msg:
    """The known motion the model states, as values (never the model's own text)."""
    given = d.accel if level == "a" else d.value
    inst, where = ctx.inst, d.where
    if d.kind == "omega":
        spatial = isinstance(given, tuple)           # a spatial rate: a vector
        sym = (omega_sym if level == "v" else alpha_sym)(d.body, d.relative_to, vector=spatial)
        unit = "rate" if level == "v" else "rate2"
        value = inst.vector(given, where) if spatial else inst.value(given, where)
        shown = Value(ctx.clean(value, unit), unit)
        said = shown if spatial else sensed(ctx, shown)
        if level == "a" and not spatial and d.relative_to in (None, ctx.frame) and ctx.is_zero(value, unit):
            return msg("driver.omega_steady", sym=sym, body=body(d.body))    # the notes: ω constant
        if level == "a" and not spatial and d.relative_to in (None, ctx.frame):     # a body's own turning
            faster = speeding(ctx, inst.value(d.value, where), value)
            if faster is not None:
                return msg("driver.omega_sense", sym=sym, value=said, body=body(d.body),
                           w=omega_sym(d.body, d.relative_to), faster=int(faster))
        return msg("driver.omega", sym=sym, value=said)
    if d.kind == "joint":
        turning = turns(ctx.model.joint(d.joint))
        unit = ("rate" if turning else "speed") if level == "v" else ("rate2" if turning else "accel")
        value = Value(ctx.clean(inst.value(given, where), unit), unit)
        if turning and held(ctx, d, level):
            return held_msg(ctx, d.joint, level)
        if turning:                 # the pin's rate as the symbol the composition writes later
            return msg("driver.omega", sym=joint_rate_sym(ctx, d.joint, level), value=sensed(ctx, value))
        key = "driver.slide" if level == "v" else "driver.slide_accel"
        return msg(key, joint=joint(d.joint), value=value)
    unit = "speed" if level == "v" else "accel"
    sym = Sym("v" if level == "v" else "a", ctx.point_label(d.point.point, d.point.body))
    if d.along is not None:
        along = (Inline([point(d.along.start), point(d.along.end)]) if isinstance(d.along, PointPair)
                 else Value(ctx.clean(inst.vector(d.along, where), ""), ""))
        size = inst.value(given, where)
        if not whole_along(ctx, d, level):      # truly a component: the point also moves across
            return msg("driver.along", sym=sym, value=Value(ctx.clean(size, unit), unit), along=along)
        vector = tuple(size * c for c in inst.direction(d.along, where))      # the notes' v_U = (←v)
        if sign_of(ctx, size) < 0:
            along = (Inline([point(d.along.end), point(d.along.start)]) if isinstance(d.along, PointPair)
                     else Value(ctx.clean(tuple(-c for c in inst.vector(d.along, where)), ""), ""))
    else:
        vector = inst.vector(given, where)
        along = None
    value = Value(ctx.clean(vector, unit), unit)
    if level == "a" and all(ctx.is_zero(c, unit) for c in vector):      # the notes: constant velocity
        return msg("driver.steady", sym=sym, point=point(d.point.point))
    words = heading(ctx, vector, along)
    return msg("driver.velocity", sym=sym, value=value) if words is None else \
        msg("driver.whole", sym=sym, value=value, heading=words)


def condition_msg(j: Joint, level: str, frame: str = "") -> Msg:
    """A joint's condition in words (for groups solved together), named from its kind and
    the bodies it joins (`kinds.kind_key`)."""
    return msg(f"cond.{kind_key(j, frame)}", joint=joint(j.id), a=body(j.a), b=body(j.b), point=point(j.at or ""))




def gather_own(ctx: Ctx, written: list[tuple[Section, list[str]]]) -> None:
    """A step's title and its equations go together: a step that writes no equation (C5-1.4's
    ring, given ω and turning about O) takes the equations a later step wrote first for a
    point of its bodies from their own motion (v_{Q∈ring} = v_O + v_QO, written under planet
    1's step because planet 1 needs it) — each moved to the end of the step that names the
    body, in its order, so no step is left with a title and no equation."""
    for k, (sub, bodies) in enumerate(written):
        if any(isinstance(b, Equation) for b in sub.blocks):
            continue
        for later, _ in written[k + 1:]:
            moved = [b for b in later.blocks if isinstance(b, Equation) and _own(ctx, b, bodies)]
            later.blocks = [b for b in later.blocks if not any(b is m for m in moved)]
            sub.blocks += moved


def _own(ctx: Ctx, eq: Equation, bodies: list[str]) -> bool:
    """Whether `eq` writes a point of `bodies` from that body's own motion alone: one side,
    a known point of the body or of a fixed body, then the body's rotation terms."""
    if eq.point is None or eq.point.body not in bodies or len(eq.sides) != 1 or eq.relative_to:
        return False
    for t in eq.sides[0]:
        if t.unknown or t.kind not in ("point", "rotation", "normal", "tangential"):
            return False
        if t.kind == "point" and not _of(ctx, t.sym.sub, bodies):
            return False
    return True


def _of(ctx: Ctx, label: str, bodies: list[str]) -> bool:
    """Whether the point written `label` (B, or B∈body) is a point of `bodies` or of a fixed
    body (a pin's point, written without ∈, moves as each body it joins)."""
    name, _, owner = label.partition("∈")
    owners = [owner] if owner else [b for b, body in ctx.model.bodies.items() if name in body.points]
    return any(o in bodies or ctx.fixed(o) for o in owners)
