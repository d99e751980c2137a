"""Bodies solved together, explained one vector equation at a time (seed 001's method).

Each equation writes the motion of one material point along a route through the group's
bodies, from a point already known: the route turns with a body (`v_P = v_Q + ω × QP`)
and crosses a pin, a rolling contact without slip (at accelerations, plus the contact's
term along the normal), a slot or a prismatic guide (plus the relative slide and, at
accelerations, Coriolis), and ends at another point whose motion is known or partly
known — or two routes meet at one point, as a dyad closes. The bicycle's frame and front
wheel together, for example:

    v_J6∈ground = v_H + v_FH + v_J6-F          (two unknowns: ω_frame and ω_front)

Knife-edge wheels on the ground give part of a point's motion: its velocity lies in the
wheel's plane and, since the plane turns with the body, its acceleration across the plane
is the normal acceleration ω × v. A driver's component along a direction is the other
partial knowledge.

The `Planner` picks, step by step, an equation whose unknown scalars it fixes (checked by
the rank of the unknowns' directions), preferring equations that find an angular velocity,
one route, short routes; marks what it finds; then carries what follows at once (a body
with a known point and a known ω is known; bodies welded, joined by a prismatic pair or by
a driven pin share ω up to the given rate), until every body of the group is known.
Nothing is solved here: every value shown is the solver's; the planner only orders the
equations a student would write.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from ..algebra.vectors import dot, scale, sub
from ..model.model import Joint
from .context import Ctx, alpha_sym, omega_sym
from .document import (Ann, Derived, Equation, Sym, Term, Value, body as body_name, joint as joint_name, msg,
                       point as point_name)
from .order import jointed
from .contacts import geometric_blocks
from .drives import drive_blocks
from .kinds import (crossed_by_a_slot, guided, kind_key, knife_edge, on_fixed_line, pin_only, rolls, same_rate,
                    slider, welds)
from .terms import contact_term, point_term, rotation_terms, slide_terms

MAX_TURNS = 3           # rotations along one route at most
TOL = 1e-9              # relative: zero lengths


@dataclass(frozen=True)
class Site:
    """A material point: a point (or a named contact) of a body."""

    point: str
    body: str


@dataclass(frozen=True)
class Seg:
    """One piece of a route: `body` turning from q to p, or crossing `joint` at p from
    body `frm` into `body`."""

    kind: str                  # turn, cross
    body: str
    q: str = ""
    p: str = ""
    joint: Optional[Joint] = None
    frm: str = ""


@dataclass(frozen=True)
class Route:
    """The motion of a point written from `start` along `segs`."""

    start: Site
    segs: tuple
    turns: int


@dataclass
class Path:
    """An equation: the motion of `end` = that along each route (one, or two that meet)."""

    routes: list[Route]
    end: Site
    unknowns: int
    finds: list[str]                              # bodies whose ω (α) the equation finds
    known: dict = field(default_factory=dict)     # site -> its knowledge when written
    rates: frozenset = frozenset()                # bodies whose ω (α) was known
    slides: frozenset = frozenset()               # slides whose relative speed was known

    @property
    def turns(self) -> int:
        """The rotations written along the equation's routes in all (fewer read more easily)."""
        return sum(r.turns for r in self.routes)


@dataclass
class Same:
    """ω (α) of `body` from `other`'s: a weld, a prismatic pair, a driven pin or ω driver."""

    body: str
    other: str
    joint: Optional[Joint] = None
    driver: Any = None
    sign: int = 1                                  # ω_body = ω_other + sign · rate


class Planner:
    """The order of the equations that find a group's bodies at one level ('v' or 'a')."""

    def __init__(self, ctx: Ctx, group: list[str], known: set[str], level: str,
                 rates: Optional[set[str]] = None) -> None:
        self.ctx, self.level = ctx, level
        self.group = [b for b in group if b != ctx.frame]
        self.determined = set(known) | {ctx.frame}
        self.rates = set(self.determined) | set(rates or ())       # rates known (a drive's)
        self.full: set[str] = set()                 # labels of points whose motion is known
        self.partial: dict[str, dict] = {}          # label -> {"wheel": joint, "driver": driver}
        self.slides: set[str] = set()               # slots and guides whose relative speed is known
        self.events: list = []                      # Path and Same, in order
        self.used: list[str] = []                   # joints written, in order
        self._labels: dict[Site, str] = {}
        self.sites = {b: self._sites(b) for b in ctx.model.bodies}
        for b in self.determined:
            self.full.update(self.label(s) for s in self.sites[b])
        self._given()
        self._propagate()

    # what is known -------------------------------------------------------------------------
    def label(self, s: Site) -> str:
        """What the planner knows a point by: its motion (pinned points are one)."""
        if s not in self._labels:
            self._labels[s] = self.ctx.motion_key(s.point, s.body)
        return self._labels[s]

    def state(self, s: Site) -> str:
        """What is known of material point `s`'s motion: "full", "partial" (a knife-edge wheel's
        plane or a driver's component) or "none"."""
        label = self.label(s)
        if label in self.full:
            return "full"
        return "partial" if label in self.partial else "none"

    def complete(self) -> bool:
        """Whether every body of the group is known."""
        return all(b in self.determined for b in self.group)

    def _given(self) -> None:
        """Drivers and knife-edge wheels: rates given, points partly known (a point shared
        with a body outside the group too)."""
        ctx, group = self.ctx, set(self.group)
        for d in ctx.model.drivers:
            if d.kind == "omega" and d.body in group and d.relative_to in (None, ctx.frame):
                self.rates.add(d.body)
            elif d.kind == "velocity" and d.point.body not in self.determined:
                label = ctx.motion_key(d.point.point, d.point.body)
                if d.along is None:
                    self.full.add(label)
                else:
                    self.partial.setdefault(label, {})["driver"] = d
        for j in ctx.model.joints:
            if knife_edge(j) and j.a == ctx.frame and j.b not in self.determined and j.at:
                self.partial.setdefault(ctx.motion_key(j.at, j.b), {})["wheel"] = j
        for label, spec in list(self.partial.items()):
            if not self._open(spec):
                self.full.add(label)

    def _open(self, spec: dict) -> list[tuple]:
        """The unknown directions of a partly known point (none when fully fixed)."""
        wheel, driver = spec.get("wheel"), spec.get("driver")
        if wheel is not None and driver is not None:
            return []
        if wheel is not None:
            return [self._dir(wheel)]
        if driver is not None:
            d = self.ctx.num(self.ctx.inst.direction(driver.along, driver.where))
            return [(-d[1], d[0])]
        return []

    def _dir(self, j: Joint) -> tuple:
        return self.ctx.num(self.ctx.sol.geometry(j.id).along)

    def _driven(self, j: Joint) -> bool:
        return any(d.kind == "joint" and d.joint == j.id for d in self.ctx.model.drivers)

    # the sites of a body ---------------------------------------------------------------------
    def _sites(self, b: str) -> list[Site]:
        """The body's points, its rolling contacts, and where a pin or a slider of another
        body slides in it."""
        ctx, model = self.ctx, self.ctx.model
        out = [Site(p, b) for p in model.bodies[b].points]
        for j in model.joints:
            if b not in (j.a, j.b):
                continue
            if rolls(j) and ctx.sol.geometry(j.id).contact is not None:
                out.append(Site(ctx.contact(j), b))
            elif crossed_by_a_slot(j) and j.a == b and j.at:
                out.append(Site(j.at, b))
            elif slider(j):
                other = j.b if j.a == b else j.a
                out += [Site(p, b) for p in ([j.at] if j.at else model.bodies[other].points)]
        return list(dict.fromkeys(out))

    def apart(self, q: str, p: str) -> Optional[tuple]:
        """QP as floats, None when the two points coincide."""
        a, b = self.ctx.num(self.ctx.pos(q)), self.ctx.num(self.ctx.pos(p))
        r = (b[0] - a[0], b[1] - a[1])
        return None if (r[0] ** 2 + r[1] ** 2) ** 0.5 <= TOL * self.ctx.inst.scale else r

    # routes --------------------------------------------------------------------------------
    def _crossings(self, s: Site, visited: tuple) -> list[tuple[Seg, Site]]:
        """The joints at `s` leading into a body not yet on the route."""
        out = []
        for j in self.ctx.model.joints:
            if s.body not in (j.a, j.b):
                continue
            other = j.b if j.a == s.body else j.a
            if other in visited:
                continue
            if rolls(j):
                ok = self.ctx.sol.geometry(j.id).contact is not None and self.ctx.contact(j) == s.point
            elif crossed_by_a_slot(j):
                ok = j.at == s.point and j.a == s.body            # from the slotted body to the pin
            elif pin_only(j) or welds(j):
                ok = (welds(j) or j.at == s.point) and Site(s.point, other) in self.sites[other]
            elif slider(j):
                ok = Site(s.point, other) in self.sites[other]
            else:
                ok = False
            if ok:
                out.append((Seg("cross", other, p=s.point, joint=j, frm=s.body), Site(s.point, other)))
        return out

    def _cols(self, seg: Seg) -> list[tuple]:
        """The directions of the unknowns a piece of route adds."""
        if seg.kind == "turn":
            r = self.apart(seg.q, seg.p)
            return [] if r is None or seg.body in self.rates else [(-r[1], r[0])]
        j = seg.joint
        if guided(j) and not self._driven(j) and j.id not in self.slides:
            return [self._dir(j)]
        return []

    def _site_cols(self, s: Site) -> list[tuple]:
        st = self.state(s)
        if st == "full":
            return []
        return self._open(self.partial[self.label(s)]) if st == "partial" else [(1.0, 0.0), (0.0, 1.0)]

    def _touches(self, b: str) -> bool:
        """Whether a known body is jointed to the group (its points can start a route)."""
        group = set(self.group)
        return any({j.a, j.b} & group and b in (j.a, j.b) for j in self.ctx.model.joints)

    def routes(self) -> dict[str, list[Route]]:
        """Every route from a point known (or partly known) to the sites it reaches, by the
        label reached; a route stops at a point with any knowledge."""
        out: dict[str, list[Route]] = {}
        group = set(self.group)
        starts = [s for b in self.ctx.model.bodies for s in self.sites[b] if self.state(s) != "none"
                  and (b in group or self._touches(b))]
        for start in starts:
            queue = [(start, (start.body,), (), 0, "")]
            while queue:
                site, visited, segs, turns, last = queue.pop(0)
                moves = []
                if last != "turn" and site.body in group and site.body not in self.determined \
                        and turns < MAX_TURNS:
                    for nxt in self.sites[site.body]:
                        if nxt.point != site.point and self.apart(site.point, nxt.point) is not None:
                            moves.append((Seg("turn", site.body, q=site.point, p=nxt.point), nxt, turns + 1))
                moves += [(seg, nxt, turns) for seg, nxt in self._crossings(site, visited)]
                for seg, nxt, t in moves:
                    label = self.label(nxt)
                    if label == self.label(start):
                        continue
                    route = segs + (seg,)
                    out.setdefault(label, []).append(Route(start, route, t))
                    if self.state(nxt) == "none":
                        seen = visited + ((nxt.body,) if nxt.body not in visited else ())
                        queue.append((nxt, seen, route, t, seg.kind))
        return out

    def paths(self) -> list[Path]:
        """The equations that can be written now: one route to a point, or two routes that
        meet at it, with as many unknown scalars as they fix (one to four)."""
        out = []
        for found in self.routes().values():
            last = found[0].segs[-1]
            end = Site(last.p, last.body)
            for r in found:
                made = self._path([r], end)
                if made is not None:
                    out.append(made)
            pairs = [r for r in found if r.turns <= 2]
            for i, r1 in enumerate(pairs):
                for r2 in pairs[i + 1:]:
                    if _bodies(r1) != _bodies(r2):
                        made = self._path([r1, r2], end)
                        if made is not None:
                            out.append(made)
        return out

    def _path(self, routes: list[Route], end: Site) -> Optional[Path]:
        """The equation of `routes` meeting at `end`, when it fixes its unknowns."""
        blocks = len(routes)
        cols: dict = {}                 # unknown -> its direction in each block (two rows each)

        def put(key, block, vec):
            row = list(cols.setdefault(key, [(0.0, 0.0)] * blocks))
            row[block] = (row[block][0] + vec[0], row[block][1] + vec[1])
            cols[key] = row

        for k, c in enumerate(self._site_cols(end)):
            for b in range(blocks):
                put(("end", k), b, (-c[0], -c[1]))
        finds: list[str] = []
        for b, r in enumerate(routes):
            for k, c in enumerate(self._site_cols(r.start)):
                put(("start", self.label(r.start), k), b, c)
            for seg in r.segs:
                for c in self._cols(seg):
                    put(("w", seg.body) if seg.kind == "turn" else ("slide", seg.joint.id), b, c)
                    if seg.kind == "turn" and seg.body not in finds:
                        finds.append(seg.body)
        n = len(cols)
        if not 1 <= n <= 2 * blocks or not _full_rank(list(cols.values()), n):
            return None
        if blocks == 2 and all(self._path([r], end) is not None for r in routes):
            return None                 # each route alone would do
        sites = [end] + [r.start for r in routes]
        known = {x: (self.state(x), dict(self.partial.get(self.label(x), {}))) for x in sites}
        return Path(routes, end, n, finds, known, frozenset(self.rates), frozenset(self.slides))

    def _best(self) -> Optional[Path]:
        found = self.paths()
        if not found:
            return None
        order = {id(p): i for i, p in enumerate(found)}
        return min(found, key=lambda p: (not p.finds, len(p.routes), p.turns, -p.unknowns,
                                         -self._end_rank(p), order[id(p)]))

    def _end_rank(self, p: Path) -> int:
        """Which end reads best as the equation's left side: a point partly known, then a
        point of a known body (0 of the ground, a contact of a known wheel)."""
        if p.known[p.end][0] == "partial":
            return 2
        return 1 if p.end.body in self.determined else 0

    # writing an equation -------------------------------------------------------------------
    def run(self) -> bool:
        """Plan until the group is known; False when no equation can go on."""
        while not self.complete():
            if self.step() is None:
                return False
        return True

    def step(self) -> Optional[Path]:
        """Write the best equation, mark what it finds and what follows; None when stuck."""
        path = self._best()
        if path is None:
            return None
        self.events.append(path)
        self.full.add(self.label(path.end))
        for r in path.routes:
            self.full.add(self.label(r.start))
            self.full.update(self.label(Site(g.p, g.body)) for g in r.segs)
        self.rates.update(path.finds)
        self.slides.update(g.joint.id for r in path.routes for g in r.segs
                           if g.joint is not None and guided(g.joint))
        self._use([g.joint.id for r in path.routes for g in r.segs if g.joint is not None] +
                  [spec["wheel"].id for _, spec in path.known.values() if spec.get("wheel") is not None])
        self._propagate()
        return path

    def _use(self, joints: list[str]) -> None:
        self.used += [j for j in joints if j not in self.used]

    def _propagate(self) -> None:
        """What follows at once: shared rates, and bodies with a known point and ω."""
        changed = True
        while changed:
            changed = False
            for same in self._sames():
                if same.body not in self.rates and same.other in self.rates:
                    self.rates.add(same.body)
                    self.events.append(same)
                    if same.joint is not None:
                        self._use([same.joint.id])
                    changed = True
            for b in self.group:
                if b not in self.determined and b in self.rates and \
                        any(self.label(s) in self.full for s in self.sites[b]):
                    self.determined.add(b)
                    self.full.update(self.label(s) for s in self.sites[b])
                    changed = True

    def _sames(self) -> list[Same]:
        ctx, out = self.ctx, []
        for j in ctx.model.joints:
            if same_rate(j):
                out += [Same(j.b, j.a, j), Same(j.a, j.b, j)]
        for d in ctx.model.drivers:
            if d.kind == "joint":
                j = ctx.model.joint(d.joint)
                if pin_only(j):
                    out += [Same(j.b, j.a, j, d, 1), Same(j.a, j.b, j, d, -1)]
            elif d.kind == "omega" and d.relative_to not in (None, ctx.frame):
                out.append(Same(d.body, d.relative_to, None, d, 1))
        group = set(self.group)
        return [s for s in out if s.body in group]


def _bodies(r: Route) -> tuple:
    return tuple(s.body for s in r.segs)


def _full_rank(cols: list[list[tuple]], n: int) -> bool:
    """Whether the unknowns' columns (a direction per block of two rows) are independent."""
    m = np.array([[x for vec in col for x in vec] for col in cols], dtype=float).T
    norms = np.linalg.norm(m, axis=0)
    if np.any(norms <= 0):
        return False
    s = np.linalg.svd(m / norms, compute_uv=False)
    return len(s) >= n and s[n - 1] > 1e-6 * s[0]


# the order of solution ------------------------------------------------------------------------
def refine(ctx: Ctx, steps: list) -> list:
    """Runs of groups solved together, re-cut into the planner's steps: each step the bodies
    one or more equations find. A group the planner cannot go through (a triad, solved by
    its own method) is kept as it was, in its place."""
    out: list = []
    known = {ctx.frame}
    i = 0
    while i < len(steps):
        if steps[i].kind != "other":
            out.append(steps[i])
            known.update(steps[i].bodies)
            i += 1
            continue
        run = []
        while i < len(steps) and steps[i].kind == "other":
            run.append(steps[i])
            i += 1
        out += _recut(ctx, run, known)
        known.update(b for s in run for b in s.bodies)
    return out


def _recut(ctx: Ctx, run: list, known: set[str]) -> list:
    from .order import Step

    pool = [b for s in run for b in s.bodies]
    done = set(known)
    out: list = []
    while any(b not in done for b in pool):
        plan = Planner(ctx, [b for b in pool if b not in done], done, "v")
        mark = 0
        while True:
            new = [b for b in pool if b in plan.determined and b not in done]
            if new:
                out.append(Step("other", new, plan.used[mark:], jointed(ctx.model, new, done), source=run[0].source))
                mark = len(plan.used)
                done |= set(new)
            if plan.complete() or plan.step() is None:
                break
        if plan.complete():
            break
        stuck = next(s for s in run if any(b not in done for b in s.bodies))
        bodies = [b for b in stuck.bodies if b not in done]
        out.append(Step(stuck.kind, bodies, stuck.joints, stuck.known, stuck.letters, stuck.source))
        done |= set(bodies)
    return out


# the blocks of a planned group ------------------------------------------------------------------
class Writer:
    """Turns a plan into the document's blocks for one step of `PlanarSteps`."""

    def __init__(self, ps, plan: Planner) -> None:
        self.ps, self.plan, self.ctx, self.level = ps, plan, ps.ctx, plan.level

    def blocks(self) -> list:
        """The document's blocks of the plan, in its order: each equation with the values it
        reads (ω or α), and each rate carried from another body."""
        out: list = []
        for ev in self.plan.events:
            out += self.path(ev) if isinstance(ev, Path) else [self.same(ev)]
        return out

    def label(self, s: Site) -> str:
        """How the document writes material point `s`: `B`, or `B∈body` when bodies move apart
        there."""
        return self.ctx.point_label(s.point, s.body)

    def path(self, p: Path) -> list:
        """One equation of the plan: the conditions it uses (a knife edge's, a joint's), the
        motion of the end point along each route (v_P = v_Q + ω × QP at each turn, the contact
        or slide terms at each crossing), the ω or α it finds read off their terms, and an
        anchor point for a body found without one."""
        ctx, lv, ps = self.ctx, self.level, self.ps
        out: list = []
        for s in [p.end] + [r.start for r in p.routes]:
            wheel = p.known[s][1].get("wheel")
            if wheel is not None:
                out += self.condition(wheel, s)
        for r in p.routes:
            for seg in r.segs:
                if seg.joint is not None:
                    out += self.condition(seg.joint, Site(seg.p, seg.body))
                    if lv == "a" and rolls(seg.joint):
                        out += geometric_blocks(ctx, seg.joint, ps.geometric, (seg.body, seg.frm))
        for s in [r.start for r in p.routes] + [p.end]:
            out += self.known_first(s, p)
        sides, reads = [], {}
        for r in p.routes:
            terms = self.site_terms(r.start, p)
            for seg in r.segs:
                made = self.seg_terms(seg, p)
                terms += made
                if seg.kind == "turn" and seg.body in p.finds and made:
                    reads.setdefault(seg.body, (seg, made[-1]))
            sides.append(terms)
        end = self.site_terms(p.end, p)
        if len(end) == 1:
            target = end[0]
        else:
            target = Term(Sym(lv, self.label(p.end)), _total(end), Ann("?"), Ann("?"), unknown=True, kind="point")
            sides.insert(0, end)
        position = None if p.end.point in ctx.inst.points else ctx.pos(p.end.point)
        out.append(Equation(target, sides, lv, ctx.ref(p.end.point, p.end.body), position=position))
        ps.done.add(self.label(p.end))
        ps.done.update(t.sym.sub for side in sides for t in side if t.kind == "point" and not t.sym.sup)
        for body in p.finds:
            seg, term = reads[body]
            out.append(ps.read(body, term, seg.q, seg.p))
        return out + self.anchors(p)

    def known_first(self, s: Site, p: Path) -> list:
        """A point of a body found earlier (in an earlier step, or by an earlier equation of
        this one) is known, but may not be written yet — the pinion's J7 where the chain
        touches it, the articulated chassis' O once α of the front chassis is found: it is
        written first, from a written point of its body, so that every known term of the
        equation can be checked (v_J7∈4 = v_H + ω_4 × H-J7). Points of the frame and points
        a driver gives need no equation."""
        ctx, lv, ps = self.ctx, self.level, self.ps
        label = ctx.point_label(s.point, s.body)
        state, spec = p.known.get(s, ("full", {}))
        if s.body == ctx.frame or label in ps.done or state != "full" or spec or self._given(s):
            return []
        if ctx.fixed(s.body):              # a point of a body welded to the frame: it does not move
            ps.done.add(label)
            return [msg("contact.fixed", point=point_name(s.point), body=body_name(s.body), sym=Sym(lv, label))]
        key = ctx.motion_key(s.point, s.body)
        for body in [s.body] + [b for b in ctx.model.carriers(s.point) if b != s.body]:
            if body == ctx.frame:
                return []
            if body in p.finds or ctx.motion_key(s.point, body) != key:
                continue        # a body this equation finds, or one the point is not pinned to
            start = ps.anchor(body)
            if start is None or ctx.motion_key(*start) == key:
                continue
            q, owner = start
            side = [point_term(ctx, lv, q, owner, True)] + rotation_terms(ctx, lv, body, q, s.point, False)
            eq = ps.equation(point_term(ctx, lv, s.point, body, True), [side], s.point, body)
            eq.position = None if s.point in ctx.inst.points else ctx.pos(s.point)
            return [eq]
        return []

    def _given(self, s: Site) -> bool:
        """Whether a driver gives the point's motion."""
        key = self.ctx.motion_key(s.point, s.body)
        return any(d.kind == "velocity" and self.ctx.motion_key(d.point.point, d.point.body) == key
                   for d in self.ctx.model.drivers)

    def anchors(self, p: Path) -> list:
        """For a body the equation finds with none of its points written yet: one point,
        along the route (so that its other points can follow)."""
        ctx, lv, ps = self.ctx, self.level, self.ps
        out = []
        for body in p.finds:
            points = ctx.model.bodies[body].points
            if not points or ps.anchor(body) is not None:
                continue
            route = next(r for r in p.routes if any(g.kind == "turn" and g.body == body for g in r.segs))
            x = points[0]
            terms = self.site_terms(route.start, p, known=True)
            for g in route.segs:
                if g.kind == "turn" and g.body == body:
                    if self.plan.apart(g.q, x) is not None:
                        terms += rotation_terms(ctx, lv, body, g.q, x, False)
                    break
                terms += self.seg_terms(g, p, known=True)
            out.append(ps.equation(point_term(ctx, lv, x, body, True), [terms], x, body))
        return out

    def condition(self, j: Joint, s: Site) -> list:
        """The words of a joint's condition, once per level (pins and welds go unsaid)."""
        ps = self.ps
        if j.id in ps.used or pin_only(j) or welds(j):
            ps.used.add(j.id)
            return []
        ps.used.add(j.id)
        lv = self.level
        if rolls(j):
            key = "rolling.noslip" if lv == "v" else "rolling.kept"
            return [msg(key, joint=joint_name(j.id), a=body_name(j.a), b=body_name(j.b),
                        point=point_name(self.ctx.contact(j)))]
        if knife_edge(j):
            return [msg("group.wheel_v" if lv == "v" else "group.wheel_a", joint=joint_name(j.id),
                        point=point_name(j.at), body=body_name(j.b), w=omega_sym(j.b), v=Sym("v", self.label(s)))]
        return [msg(f"cond.{kind_key(j, self.ctx.frame)}", joint=joint_name(j.id), a=body_name(j.a), b=body_name(j.b),
                    point=point_name(j.at or ""))]

    def site_terms(self, s: Site, p: Path, known: bool = False) -> list[Term]:
        """A point's motion as known when the equation is written: whole (M, D), or in
        parts (along a wheel's plane, along a driver's direction); `known`: after it."""
        ctx, lv = self.ctx, self.level
        state, spec = p.known.get(s, ("full", {}))
        if known or state == "full":          # known whole: a driver's component says no more
            return [point_term(ctx, lv, s.point, s.body, True)]
        if state == "none":
            return [point_term(ctx, lv, s.point, s.body, False)]
        wheel, driver = spec.get("wheel"), spec.get("driver")
        label = self.label(s)
        whole = ctx.vel(s.body, s.point) if lv == "v" else ctx.acc(s.body, s.point)
        unit = "speed" if lv == "v" else "accel"
        if wheel is not None:
            e = ctx.sol.geometry(wheel.id).along
            plane = msg("dir.wheel", joint=joint_name(wheel.id))
            given = driver is not None
            if lv == "v":
                return [Term(Sym("v", label), ctx.clean(whole, unit), Ann("M" if given else "?"), Ann("para", plane),
                             [], not given, "point")]
            along = scale(dot(whole, e), e)
            w = omega_sym(wheel.b)
            return [Term(Sym("a", label, "t"), ctx.clean(along, unit), Ann("M" if given else "?"),
                         Ann("para", plane), [], not given, "point"),
                    Term(Sym("a", label, "n"), ctx.clean(sub(whole, along), unit),
                         Ann("M", [w, "·", Sym("v", label, vector=False)]), Ann("perp", plane),
                         [w, " × ", Sym("v", label)], False, "wheel")]
        d = ctx.inst.direction(driver.along, driver.where)
        along = scale(dot(whole, d), d)
        ref = Value(ctx.clean(d, ""), "")
        return [Term(Sym(lv, label, "∥"), ctx.clean(along, unit), Ann("M"), Ann("para", ref), [], False, "point"),
                Term(Sym(lv, label, "⊥"), ctx.clean(sub(whole, along), unit), Ann("?"), Ann("perp", ref), [],
                     True, "point")]

    def seg_terms(self, seg: Seg, p: Path, known: bool = False) -> list[Term]:
        """The terms one piece of a route adds: turning with a body ω × QP (at accelerations
        α × QP and ω × (ω × QP)); at a rolling contact, the contact's normal term at
        accelerations; across a slot or guide, the relative slide (and Coriolis at
        accelerations); a pin adds nothing."""
        ctx, lv = self.ctx, self.level
        if seg.kind == "turn":
            if self.plan.apart(seg.q, seg.p) is None:
                return []
            return rotation_terms(ctx, lv, seg.body, seg.q, seg.p, not known and seg.body not in p.rates)
        j = seg.joint
        if rolls(j):
            return [contact_term(ctx, seg.p, seg.body, seg.frm)] if lv == "a" else []
        if guided(j):
            unknown = not known and not self.plan._driven(j) and j.id not in p.slides
            line = (Value(ctx.clean(ctx.sol.geometry(j.id).along, ""), "") if on_fixed_line(j, ctx.frame)
                    else msg("dir.guide", joint=joint_name(j.id)))       # a fixed line: its direction
            return slide_terms(ctx, lv, seg.frm, seg.body, seg.p, line, j.id,
                               unknown)
        return []

    def same(self, s: Same) -> Derived:
        """ω (α) shared across a weld or a prismatic pair, or through a driven joint."""
        ctx, lv = self.ctx, self.level
        sym_of = omega_sym if lv == "v" else alpha_sym
        unit = "rate" if lv == "v" else "rate2"
        value = ctx.omega(s.body) if lv == "v" else ctx.alpha(s.body)
        if s.driver is None:
            key = "how.weld" if welds(s.joint) else "how.prismatic"
            how = [sym_of(s.other), " ", msg(key, joint=joint_name(s.joint.id))]
        else:
            rel = sym_of(s.body, s.other) if s.sign > 0 else sym_of(s.other, s.body)
            given = s.driver.accel if lv == "a" else s.driver.value
            rate = Value(ctx.clean(ctx.inst.value(given, s.driver.where), unit), unit)
            sign = " + " if s.sign > 0 else " − "
            how = [sym_of(s.other), sign, rel, " = ", sym_of(s.other), sign, rate]
        return Derived(sym_of(s.body), how, ctx.value(value, unit), s.body,
                       "omega" if lv == "v" else "alpha", not ctx.symbolic)


def _total(terms: list[Term]) -> tuple:
    out = terms[0].value
    for t in terms[1:]:
        out = tuple(a + b for a, b in zip(out, t.value))
    return out


def group_blocks(ps, step) -> Optional[list]:
    """The blocks of an `other` step by the planner, or None when it cannot go through. A
    belt or chain drive whose carrier and one wheel are known gives the other wheel's rate
    first, as the notes find it (`drives`); the planner then knows those rates."""
    given, rates = drive_blocks(ps.ctx, step.bodies, set(ps.known), ps.level)
    plan = Planner(ps.ctx, step.bodies, set(ps.known), ps.level, rates)
    if not plan.run():
        return None
    ps.ctx.worked.update(f"drive:{b}" for b in rates)
    return given + Writer(ps, plan).blocks()
