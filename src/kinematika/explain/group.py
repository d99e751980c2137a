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
from .context import Ctx, alpha_sym, magnitude, omega_sym, segment
from .document import (CENTRE_POINT_RE, Ann, Derived, Equation, Msg, Name, Sym, Term, Value, body as body_name, joint as joint_name, msg,
                       point as point_name)
from .order import jointed
from .contacts import geometric_blocks
from .drives import drive_blocks, pair_blocks
from .given import whole_along
from .kin import kin
from .kinds import (by_centre_path, meshes, roller, crossed_by_a_slot, guided, kind_key, knife_edge, on_fixed_line, pin_only, rolls,
                    same_rate, slider, welds)
from .terms import contact_term, guide, point_term, relative_name, rotation_terms, slide_terms

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

    def crossed(self) -> Joint:
        """The joint a "cross" piece crosses (every crossing is made with its joint)."""
        assert self.joint is not None, f"a {self.kind} piece crosses no joint"
        return self.joint


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
class Still:
    """`body` translates: its instant centre relative to the frame is at infinity (placed
    by the structure before the velocities), so its ω is zero."""

    body: str


@dataclass
class Glides:
    """`body` carries the centres p and q of two wheels rolling on fixed straight profiles,
    all along one line: both centres run on that line at every instant, so the body slides
    along it and does not turn (α = 0 at accelerations, C5-E.4's chassis)."""

    body: str
    p: str
    q: str
    one_line: bool = True       # both centres on one line (equal radii), else on parallel lines


@dataclass
class Tangent:
    """`body`, a line, rolls on two circles whose centres `centres` are known and move alike
    across it: it stays tangent to both, so it does not turn (C5-1.5's strands: "en no
    haver-hi moviment pendular")."""

    body: str
    circles: tuple
    centres: tuple


@dataclass
class Same:
    """ω (α) of `body` from `other`'s: a weld, a prismatic pair, a driven pin or ω driver."""

    body: str
    other: str
    joint: Optional[Joint] = None
    driver: Any = None
    sign: int = 1                                  # ω_body = ω_other + sign · rate

    def pair(self) -> Joint:
        """The weld or prismatic pair that gives the rate when no driver does (every such
        `Same` is made with its joint)."""
        assert self.joint is not None, f"ω of {self.body} from a driver, not a joint"
        return self.joint


class Planner:
    """The order of the equations that find a group's bodies at one level ('v' or 'a')."""

    def __init__(self, ctx: Ctx, group: list[str], known: set[str], level: str,
                 rates: Optional[set[str]] = None, centres: bool = False) -> None:
        self.ctx, self.level = ctx, level
        self.group = [b for b in group if b != ctx.frame]
        self.determined = set(known) | {ctx.frame}
        self.rates = set(self.determined) | set(rates or ())       # rates known (a drive's)
        self.composed = set(rates or ()) - set(known)       # a drive or a pair gave them: not turned about a centre
        self.full: set[str] = set()                 # labels of points whose motion is known
        self.partial: dict[str, dict] = {}          # label -> {"wheel": joint, "driver": driver}
        self.slides: set[str] = set()               # slots and guides whose relative speed is known
        self.events: list = []                      # Path and Same, in order
        self.used: list[str] = []                   # joints written, in order
        self.still: dict[str, tuple[Joint, str]] = {}   # label of a contact at rest -> (joint, fixed body)
        self.centred: dict[str, tuple[str, str]] = {}     # at accelerations: joint -> (wheel, its centre)
        self.centred_steps = centres                # planning a step's equations (not the order's groups)
        self.tangent: set[str] = set()              # lines found not to turn (`_tangents`)
        self._labels: dict[Site, str] = {}
        self.gliding: set[str] = set()              # bodies that translate: their turns add no term
        self.sites = {b: self._sites(b) for b in ctx.model.bodies}
        self.glide: dict[str, tuple[str, str, str]] = {}    # joint -> (line body, wheel, centre)
        self._glides_on_lines()
        for b in self.determined:
            self.full.update(self.label(s) for s in self.sites[b])
        if centres and level == "v":
            self._centres()
        if level == "a":
            self._centred()
        self._glides()
        self._given()
        self._propagate()
        # known before any equation (a driven bar about its centre placed first: C5-1.2's OQ),
        # so named first where the step's bodies are listed as found (`record_found`)
        self.at_once = [b for b in self.group if b in self.determined]

    def _centred(self) -> None:
        """At accelerations, a wheel rolling on a fixed body is reached through its centre C:
        C keeps its distance from the fixed profile, so it moves on a circle about the
        profile's centre (on a line along a straight one), and v_C = ω × JC at every instant —
        the notes' road to a_C (C5-1.7: "trajectòria circular de radi 3r"; C5-E.1, E.6)."""
        ctx, group = self.ctx, set(self.group)
        for j in ctx.model.joints:
            contact = ctx.sol.geometry(j.id).contact if rolls(j) and by_centre_path(j) else None
            if contact is None:
                continue
            for fixed, body in ((j.a, j.b), (j.b, j.a)):
                if body not in group or fixed not in self.determined or not ctx.fixed(fixed):
                    continue
                centre = path_centre(ctx, j, body)
                if centre is not None and Site(centre, body) in self.sites[body]:
                    self.centred[j.id] = (body, centre)

    def _glides_on_lines(self) -> None:
        """A wheel rolling on the straight edge of a moving body N (the slides' rolling pair,
        4.4): seen from N, its centre A keeps its distance from the edge, so it runs along a
        line parallel to it — the slides' axes at the wheel's centre turning with N. The point
        of N at A is a site, and crossing from it into the wheel adds the relative motion
        along that line (and Coriolis at accelerations), as across a guide: v_A = v_A∈N +
        v_A∈R/N. The wheel's own ω (α) then comes from the rolling conditions at the contact:
        equal velocities, equal tangential accelerations. Taken where accelerations are
        asked (at velocities the rolling conditions alone solve the pair; the accelerations
        need the two rates one at a time, and their Coriolis term the relative velocity
        written here), and for an edge that rolls on one wheel only: a strand or chain
        between two wheels goes as the notes take it (`_tangents`, C5-1.5, C5-E.6)."""
        from .needs import accelerations_asked

        ctx = self.ctx
        if not ctx.planar or not accelerations_asked(ctx):
            return
        contacts = [ctx.sol.geometry(j.id).contact for j in ctx.model.joints if rolls(j)]
        lines = [c.line_body for c in contacts if c is not None and c.kind == "circle-line"]
        for j in ctx.model.joints:
            contact = ctx.sol.geometry(j.id).contact if rolls(j) and by_centre_path(j) else None
            if contact is None or contact.kind != "circle-line":
                continue
            line = contact.line_body
            wheel = j.b if j.a == line else j.a
            if ctx.fixed(line) or ctx.fixed(wheel) or lines.count(line) > 1:
                continue
            centre = path_centre(ctx, j, wheel)
            if centre is None or self.apart(centre, ctx.contact(j)) is None:
                continue
            self.glide[j.id] = (line, wheel, centre)
            site = Site(centre, line)
            if site not in self.sites[line]:
                self.sites[line].append(site)

    def _glide_cross(self, seg: Seg) -> bool:
        """Whether `seg` crosses from a moving edge into a wheel at the wheel's centre
        (`_glides_on_lines`), not at the contact."""
        if seg.kind != "cross" or seg.joint is None or seg.joint.id not in self.glide:
            return False
        line, wheel, centre = self.glide[seg.joint.id]
        return seg.p == centre and seg.body == wheel

    def _glides(self) -> None:
        """A body pinned at the centres of two wheels that roll on fixed straight profiles
        that are parallel (one straight ground, wheels of any radii): each centre keeps its
        distance from its profile, so it runs on a line parallel to it, and two points of a
        rigid body moving on parallel straight lines (the segment between them not across
        the lines) keep their offset: the body translates at every instant, ω = 0 and α = 0
        — the notes' "el quadre només es trasllada respecte del terra" (C5-E.4, E.5, E.6),
        said before the velocity equations, never solved from a chained equation with two
        unknown rotations (v_A = v_J∈wheel2 + v_BJ + v_AB)."""
        ctx, group = self.ctx, set(self.group)
        straight = []
        for j in ctx.model.joints:      # every such wheel, in this group or not: the path is geometry
            contact = ctx.sol.geometry(j.id).contact if rolls(j) else None
            if contact is None or contact.kind != "circle-line":
                continue
            for fixed, wheel in ((j.a, j.b), (j.b, j.a)):
                if ctx.fixed(fixed) and not ctx.fixed(wheel) and path_origin(ctx, j, fixed) is None:
                    centre = path_centre(ctx, j, wheel)
                    if centre is not None:
                        straight.append((centre, ctx.num(tuple(contact.normal))))
        for body in self.group:
            if body in self.rates or body not in group:
                continue
            held = [(c, n) for c, n in straight if c in ctx.model.bodies[body].points]
            if len(held) < 2:
                continue
            (p, n1), (q, n2) = held[:2]
            a, b = ctx.num(ctx.pos(p)), ctx.num(ctx.pos(q))
            parallel = abs(n1[0] * n2[1] - n1[1] * n2[0]) <= 1e-9
            along = abs((b[0] - a[0]) * n1[1] - (b[1] - a[1]) * n1[0])     # PQ's part along the lines
            offset = abs((b[0] - a[0]) * n1[0] + (b[1] - a[1]) * n1[1])    # and across them
            still = ctx.is_zero(ctx.omega(body), "rate") and (self.level == "v" or ctx.is_zero(ctx.alpha(body), "rate2"))
            if parallel and along > 1e-9 * ctx.inst.scale and self.apart(p, q) is not None and still:
                self.rates.add(body)
                self.gliding.add(body)
                self.events.append(Glides(body, p, q, offset <= 1e-9 * ctx.inst.scale))

    def _centres(self) -> None:
        """The instant centres placed before the velocities (`centres.centre_sites`): each a
        point of its body with zero velocity, where routes may start (v_A = v_I14 + ω × I14-A,
        the notes' rotation about the centre); a body whose centre is at infinity translates.
        Not the centre of a body whose rate a drive or a pair gave (`composed`): its points
        follow from its pin, as at accelerations (C5-E.4's v_P = v_U + ω × UP, round 27b)."""
        group = set(self.group)
        for name, body in self.ctx.centre_sites.items():
            if body in group and body not in self.determined and body not in self.composed:
                site = Site(name, body)
                if site not in self.sites[body]:
                    self.sites[body].append(site)
                self.full.add(self.label(site))
        for body in self.ctx.translating:
            if body in group and body not in self.rates:
                self.rates.add(body)
                self.gliding.add(body)      # it translates: its points move alike, no ω × r is written
                self.events.append(Still(body))

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
            elif d.kind == "velocity" and d.driven_point().body not in self.determined:
                label = ctx.motion_key(d.driven_point().point, d.driven_point().body)
                if d.along is None or whole_along(ctx, d, self.level):     # a component that is the whole
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
            if rolls(j) and j.id in self.glide and s.point == self.glide[j.id][2]:
                ok = s.body == self.glide[j.id][0]              # from the edge into the wheel, at its centre
            elif rolls(j):
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
        j = seg.crossed()
        if self._glide_cross(seg):
            return [] if j.id in self.slides else [self._along_edge(j)]
        if self.level == "a" and rolls(j) and j.id in self.glide:
            n = self.ctx.num(tuple(self.ctx.sol.geometry(j.id).contact.normal))
            return [n]                  # equal tangential components: the normal difference unknown
        if guided(j) and not self._driven(j) and j.id not in self.slides:
            return [self._dir(j)]
        return []

    def _along_edge(self, j: Joint) -> tuple:
        """The direction of the edge a wheel rolls on (across the common normal)."""
        n = self.ctx.num(tuple(self.ctx.sol.geometry(j.id).contact.normal))
        return (-n[1], n[0])

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
            queue: list[tuple[Site, tuple[str, ...], tuple[Seg, ...], int, str]] = [(start, (start.body,), (), 0, "")]
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
                    if label == self.label(start) or (seg.kind == "cross" and label in self.still):
                        continue                # a contact at rest is known as it is, not crossed into
                    route = segs + (seg,)
                    into = seg.kind == "cross" and self.centred.get(seg.crossed().id, ("",))[0] == nxt.body
                    if not into:                # the wheel's contact point is no end: its centre is
                        out.setdefault(label, []).append(Route(start, route, t))
                    if self.state(nxt) == "none":
                        seen = visited + ((nxt.body,) if nxt.body not in visited else ())
                        queue.append((nxt, seen, route, t, self._went(segs, seg)))
        return out

    def _went(self, segs: tuple, seg: Seg) -> str:
        """How a route arrived where it is, for what may follow: "centre" after it crossed into
        a wheel on a fixed body and turned to its centre (`_centred`), where it may turn on
        with the wheel — the notes' a_S on its path, then a_Q = a_S + a_QS^n + a_QS^t (one
        body, one α: C5-1.3's support, from its centre to the bar's pin) — else the piece's
        kind (a turn is not followed by another turn with the same body)."""
        if seg.kind == "turn" and segs and segs[-1].kind == "cross" and segs[-1].joint is not None \
                and self.centred.get(segs[-1].joint.id) == (seg.body, seg.p):
            return "centre"
        return seg.kind

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
                    put(("w", seg.body) if seg.kind == "turn" else
                        ("slide" if not rolls(seg.joint) or self._glide_cross(seg) else "contact", seg.joint.id), b, c)
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
        def key(p: Path) -> tuple:      # a rotation about a point at rest finds ω alone, as the notes do
            rest = self._from_rest(p)
            return (self._across_tangent(p), self._unlike(p), not p.finds, len(p.routes), self._off_centre(p),
                    -self._via_centre(p), not rest, p.turns,
                    p.unknowns if rest else -p.unknowns, self._against(p), -self._end_rank(p), -self._witnessed(p),
                    order[id(p)])
        return min(found, key=key)

    def reads(self, p: Path) -> frozenset:
        """The known bodies the equation writes points of, other than those it finds: the
        frame for an instant centre at rest, the body of each known end or start, and the
        bodies pinned there (A1 of the carrier for A1 of the planet)."""
        out: set[str] = set()
        for s in [p.end] + [r.start for r in p.routes]:
            if p.known[s][0] == "none":
                continue
            if s.point in self.ctx.centre_sites:
                out.add(self.ctx.frame)
                continue
            label = self.label(s)
            out |= {b for b in self.determined if b == s.body or any(self.label(x) == label for x in self.sites[b])}
        return frozenset(out - set(p.finds))

    def _unlike(self, p: Path) -> int:
        """How many bodies the equation finds from other bodies than the equation that found
        one of their kind read (`kin.kin`, recorded by `step` in `Ctx.kin_reads`): bodies of
        one kind are found from the same bodies, by the same equation (issue 30, round 27b:
        C5-1.4's second planet was read off the sun, the first found from the carrier and the
        ring, as the notes find each planet)."""
        reads = self.reads(p)
        n = 0
        for b in p.finds:
            seen = [self.ctx.kin_reads.get((self.level, self.centred_steps, k)) for k in kin(self.ctx, b)]
            if any(r is not None and not reads <= r for r in seen) and not any(r is not None and reads <= r for r in seen):
                n += 1
        return n

    def _witnessed(self, p: Path) -> int:
        """How many of the equation's points placed the instant centre of a body it finds
        (C5-E.4: the upper wheel's centre on the perpendicular to v_M through M): the step
        reads ω from the point the centres section named, not from its mirror N."""
        points = {p.end.point} | {r.start.point for r in p.routes}
        return sum(len(points & self.ctx.witnessed.get(b, set())) for b in p.finds)

    def _across_tangent(self, p: Path) -> int:
        """How many times the equation turns with a line found not to turn (`_tangents`):
        the notes carry a velocity along the strand as it is (its points move alike) and
        write the pulley's rotation from there, one body at a time."""
        return sum(1 for r in p.routes for g in r.segs if g.kind == "turn" and g.body in self.tangent)

    def _via_centre(self, p: Path) -> int:
        """How many times the equation goes from a fixed body into a wheel and on to its
        centre — the notes' a_C = v_C²/OC + α × JC (`_centred`)."""
        n = 0
        for r in p.routes:
            for g, h in zip(r.segs, r.segs[1:]):
                found = self.centred.get(g.joint.id) if g.kind == "cross" and g.joint is not None else None
                if found is not None and found[0] == g.body and h.kind == "turn" and h.p == found[1]:
                    n += 1
        return n

    def _off_centre(self, p: Path) -> int:
        """How many times the equation enters a wheel on a fixed body and turns to another
        point than its centre (the notes go through the centre: `_centred`)."""
        if not self.centred:
            return 0
        ends = {(body, self.ctx.contact(self.ctx.model.joint(jid))): centre
                for jid, (body, centre) in self.centred.items()}
        n = 0
        for r in p.routes:
            for g in r.segs:
                if g.kind != "turn":
                    continue
                for a, b in ((g.q, g.p), (g.p, g.q)):     # the wheel turned between its contact and another point
                    centre = ends.get((g.body, a))
                    if centre is not None and b != centre:
                        n += 1
        return n

    def _against(self, p: Path) -> int:
        """How many guides the equation crosses from the slider into the guide's body: the
        notes say the slider slides on the guide (v_Q = v_Q∈support + v_Q∈bar/support), so
        that way round reads first."""
        return sum(1 for r in p.routes for g in r.segs
                   if g.kind == "cross" and g.joint is not None and guided(g.joint) and g.frm == g.joint.b)

    def _from_rest(self, p: Path) -> bool:
        """Whether the equation starts at a point at rest: an instant centre placed before
        (v_O = v_I17 + ω_7 × I17-O), or a contact on a fixed body — the notes' way, a
        velocity as a rotation about the centre."""
        return any(self.label(r.start) in self.still or r.start.point in self.ctx.centre_sites for r in p.routes)

    def _end_rank(self, p: Path) -> float:
        """Which end reads best as the equation's left side: a point partly known, then a
        point of a known body (0 of the ground, a contact of a known wheel)."""
        label = self.label(p.end)
        if label in self.still or p.end.point in self.ctx.centre_sites:
            return -1                   # a point at rest starts an equation, it does not end one
        own = 0.5 if p.end.point in self.ctx.model.bodies[p.end.body].points else 0.0     # Q of the bar, not S
        if p.known[p.end][0] == "partial":
            return 2 + own
        return (1 if p.end.body in self.determined else 0) + own

    # writing an equation -------------------------------------------------------------------
    def run(self) -> bool:
        """Plan until the group is known; False when no equation can go on. At velocities,
        then the relative velocity of each slide found by no equation (the bar's in its
        sleeve, once the bar's ω came from its instant centre): the composition v_Q∈b =
        v_Q∈a + v_Q∈b/a, which the accelerations' Coriolis term needs."""
        while not self.complete():
            if self.step() is None:
                return False
        while self.level == "v" and self._open_slides():
            if self.step() is None:
                break
        return True

    def _open_slides(self) -> bool:
        """Whether a guide that turns, inside the group, has its relative speed still
        unwritten while accelerations are explained (its Coriolis term needs it)."""
        from .needs import accelerations_asked

        ctx, group = self.ctx, set(self.group)
        if not accelerations_asked(ctx):
            return False
        return any(guided(j) and {j.a, j.b} & group and {j.a, j.b} <= (group | self.determined)
                   and not ctx.fixed(j.a) and not self._driven(j) and j.id not in self.slides
                   for j in ctx.model.joints)

    def step(self) -> Optional[Path]:
        """Write the best equation, mark what it finds and what follows; None when stuck."""
        path = self._best()
        if path is None:
            return None
        self.events.append(path)
        for b in path.finds:        # what its kind's next one is found from (`_unlike`)
            self.ctx.kin_reads.setdefault((self.level, self.centred_steps, b), self.reads(path))
        self.full.add(self.label(path.end))
        for r in path.routes:
            self.full.add(self.label(r.start))
            self.full.update(self.label(Site(g.p, g.body)) for g in r.segs)
        self.rates.update(path.finds)
        self.slides.update(g.joint.id for r in path.routes for g in r.segs
                           if g.joint is not None and (guided(g.joint) or self._glide_cross(g)))
        self._use([g.joint.id for r in path.routes for g in r.segs if g.joint is not None] +
                  [spec["wheel"].id for _, spec in path.known.values() if spec.get("wheel") is not None])
        self._propagate()
        return path

    def _use(self, joints: list[str]) -> None:
        self.used += [j for j in joints if j not in self.used]

    def _still_contacts(self) -> None:
        """A body rolling without slipping on a fixed one (the ground, a track): its point at
        the contact has no velocity — it is the body's instant centre, as the notes take it
        (C5-1.7: "ja que J és el CIR"). Velocities only: the point's acceleration is not zero."""
        if self.level != "v":
            return
        ctx, group = self.ctx, set(self.group)
        for j in ctx.model.joints:
            if not rolls(j) or ctx.sol.geometry(j.id).contact is None:
                continue
            for fixed, body in ((j.a, j.b), (j.b, j.a)):
                if body in group and fixed in self.determined and ctx.fixed(fixed):
                    label = self.label(Site(ctx.contact(j), body))
                    if label not in self.full:
                        self.full.add(label)
                        self.still[label] = (j, fixed)
                        self._use([j.id])

    def _tangents(self) -> None:
        """A line rolling on two circles (a strand of cable between two pulleys) keeps its
        distance r from both centres C_a, C_b: the components of v_Ca and v_Cb across the line
        differ by ω_line times the distance between its two contacts. With both centres known
        and moving alike across it (the pulleys' axles fixed, or hanging in the cable), the
        line does not turn: it translates, as the notes take each strand (C5-1.5). Said at
        velocities, in the steps (the order of solution is the block-triangular one)."""
        if self.level != "v" or not self.centred_steps:
            return
        ctx = self.ctx
        for body in self.group:
            if body in self.rates:
                continue
            held = []
            for j in ctx.model.joints:
                contact = ctx.sol.geometry(j.id).contact if rolls(j) else None
                if contact is None or contact.kind != "circle-line" or contact.line_body != body:
                    continue
                (circle, c), = contact.centres
                from .contacts import centre_name

                name = centre_name(ctx, circle, c)
                if name in ctx.model.bodies[circle].points and self.label(Site(name, circle)) in self.full:
                    held.append((circle, name, contact))
            if len(held) < 2 or not ctx.is_zero(ctx.omega(body), "rate"):
                continue
            (a, ca, first), (b, cb, second) = held[:2]
            n = first.normal
            across = sum(x * (u - w) for x, u, w in zip(n, ctx.vel(a, ca), ctx.vel(b, cb)))
            if ctx.is_zero(across, "speed") and self.apart(ctx.contact(first.joint), ctx.contact(second.joint)):
                self.rates.add(body)
                self.tangent.add(body)
                self.events.append(Tangent(body, (a, b), (ca, cb)))

    def _propagate(self) -> None:
        """What follows at once: shared rates, bodies with a known point and ω, and the
        contact points at rest of bodies rolling on fixed ones."""
        self._still_contacts()
        self._tangents()
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
                j = ctx.model.joint(d.driven_joint())
                if pin_only(j):
                    out += [Same(j.b, j.a, j, d, 1), Same(j.a, j.b, j, d, -1)]
            elif d.kind == "omega" and d.relative_to is not None and d.relative_to != ctx.frame:
                out.append(Same(d.driven_body(), d.relative_to, None, d, 1))
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
        out += _recut(ctx, run, known, found_rank(ctx, out))
        known.update(b for s in run for b in s.bodies)
    return out


def found_rank(ctx: Ctx, steps: list) -> dict[str, int]:
    """Each body's place in the order its motion was found: the frame first, then the bodies
    of `steps` as they list them (a step lists first the body its equation finds: C5-1.2's
    bar OQ, before the wheels it carries). A point shared by several known bodies (a pin) is
    credited to the first of them (`_reads`)."""
    rank = {ctx.frame: 0}
    for s in steps:
        for b in s.bodies:
            rank.setdefault(b, len(rank))
    return rank


def _recut(ctx: Ctx, run: list, known: set[str], rank: dict[str, int]) -> list:
    from .order import Step

    pool = [b for s in run for b in s.bodies]
    done = set(known)
    out: list = []
    while any(b not in done for b in pool):
        plan = Planner(ctx, [b for b in pool if b not in done], done, "v")
        mark = seen = 0
        while True:
            new = [b for b in pool if b in plan.determined and b not in done]
            if new:
                out.append(Step("other", new, _joining(ctx, new, done, plan.used[mark:]),
                                _sources(ctx, plan.events[seen:], done, rank) or jointed(ctx.model, new, done),
                                source=run[0].source))
                mark, seen = len(plan.used), len(plan.events)
                done |= set(new)
                for b in new:
                    rank.setdefault(b, len(rank))
            if plan.complete() or plan.step() is None:
                break
        if plan.complete():
            break
        stuck = next(s for s in run if any(b not in done for b in s.bodies))
        bodies = [b for b in stuck.bodies if b not in done]
        out.append(Step(stuck.kind, bodies, stuck.joints, stuck.known, stuck.letters, stuck.source))
        done |= set(bodies)
        for b in bodies:
            rank.setdefault(b, len(rank))
    return out


def _sources(ctx: Ctx, events: list, done: set[str], rank: dict[str, int], ordered: bool = False) -> list[str]:
    """The known bodies a step's equations read (`_reads`, event by event), in the model's
    order — or, `ordered`, in the order the written equations read them (`record_found`,
    round 20f: C5-1.5's strand 2 "from pulley 1 and the ceiling", T1 of pulley 1 first).
    The order of solution says these, the same source the step's equation reads (round
    16a: 001's lever N was said "from the ground" while its equation reads the slider's A);
    empty when the step writes no equation of known points (the caller then names the
    jointed bodies)."""
    read = list(dict.fromkeys(b for ev in events for b in _reads(ctx, ev, done, rank)))
    return read if ordered else [b for b in ctx.model.bodies if b in read]


def _reads(ctx: Ctx, ev: Any, done: set[str], rank: dict[str, int]) -> list[str]:
    """The known bodies one event reads, in its order: for an equation (`Path`) the bodies of
    the known points it writes, in the order the step writes them: an instant centre the
    equation starts from first (at rest, the frame's point: "I_OJ … has no velocity" is said
    before v_O = v_{I_OJ} + ω × I_{OJ}O), then the point it ends at when that is a contact on
    a known body (none of the body's own points), whose motion is written first (001's v_{F∈N} = v_B + …, before v_{F∈R} = v_A
    + …), then the routes' starts (an equation goes from its start: 001's v_A = v_B + v_AB +
    … reads the lever's fixed pivot B), then the others — a point of a body still unknown but pinned to known ones
    read from the frame if it is one of them, else from the body whose motion was found
    first (`rank`: C5-1.2's O, on the wheel and on the bar OQ, is the bar's, whose equation
    found v_O) — for a line tangent to two circles (`Tangent`) the circles' bodies whose
    centres it reads, and for a rate carried (`Same`) the body it is carried from."""
    found: list[str] = []
    if isinstance(ev, Path):
        first = [s for s in ev.known if s.point in ctx.centre_points]    # said at rest before the equation
        end = ev.end           # a known body's contact point: its motion is carried there first
        first += [end] if end.body in done and end.point not in ctx.model.bodies[end.body].points else []
        first += [r.start for r in ev.routes]
        for site in dict.fromkeys(s for s in first + list(ev.known) if s in ev.known):
            state = ev.known[site][0]
            if site.point in ctx.centre_points:     # I_b, at rest: a point of the frame (v_{I_OJ} = 0)
                found.append(ctx.frame)
            elif site.body in done:
                found.append(site.body)
            elif state == "full":
                key = ctx.motion_key(site.point, site.body)
                pinned = [b for b in ctx.model.carriers(site.point)
                          if b in done and ctx.motion_key(site.point, b) == key]
                pinned.sort(key=lambda b: rank.get(b, len(rank)))
                found += [ctx.frame] if ctx.frame in pinned else pinned[:1]   # one source a point
            found += _touched(ctx, site, done)
    elif isinstance(ev, Tangent):
        for circle, centre in zip(ev.circles, ev.centres):
            found += _reads(ctx, Path([], Site(centre, circle), 0, [], {Site(centre, circle): ("full", {})}),
                            done, rank)
    elif isinstance(ev, Same) and ev.other in done:
        found.append(ev.other)
    return found


def _touched(ctx: Ctx, site: Site, done: set[str]) -> list[str]:
    """The known bodies a rolling contact at `site` touches: a wheel's contact point on the
    ground is read from the ground (v_J = 0 there), so the ground is a source of the step."""
    return [other for j in ctx.model.joints if rolls(j) and site.body in (j.a, j.b)
            for other in [j.b if site.body == j.a else j.a] if other in done and ctx.contact(j) == site.point]


def _joining(ctx: Ctx, new: list[str], done: set[str], used: list[str]) -> list[str]:
    """The joints a step's bodies are found through: those the planner used for it that
    touch one of them; for a body found by carrying (a translating chassis' wheel, whose
    joints an earlier equation already used), the joints between it and the bodies known
    or found with it — never none (C5-E.4's right wheel: its contact and its pin)."""
    mine = [j for j in used if {ctx.model.joint(j).a, ctx.model.joint(j).b} & set(new)]
    if mine:
        return mine
    reach = set(new) | set(done)
    return [j.id for j in ctx.model.joints if {j.a, j.b} & set(new) and {j.a, j.b} <= reach] or list(used)


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
            if isinstance(ev, Tangent):
                out.append(self.tangent(ev))
                continue
            if isinstance(ev, Glides):
                out.append(self.glides(ev))
                continue
            out += self.path(ev) if isinstance(ev, Path) else [self.still(ev)] if isinstance(ev, Still) \
                else [self.same(ev)]
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
        contacts: list[str] = []
        for r in p.routes:
            for i, seg in enumerate(r.segs):
                if seg.joint is not None:
                    if self._centred(r, i):
                        out += self.path_said(seg.joint, seg.body, r.segs[i + 1].p)
                        contacts.append(ctx.contact(seg.joint))     # the sentence goes with the equation
                        continue
                    if self.plan._glide_cross(seg):
                        out += self.glide_said(seg.joint)
                        continue
                    out += self.condition(seg.joint, Site(seg.p, seg.body))
                    if rolls(seg.joint):
                        contacts.append(ctx.contact(seg.joint))
                    if lv == "a" and rolls(seg.joint) and seg.joint.id not in self.plan.glide:
                        out += geometric_blocks(ctx, seg.joint, ps.geometric, (seg.body, seg.frm))
        owned = list(out)
        # the end point written from its own body first (C5-E.3: v_B from the rod, after v_A),
        # then what the routes start from (the right wheel's contact at rest), each sentence
        # next to the equation that uses it, never between one body's equations
        for s in [p.end] + [r.start for r in p.routes]:
            out += self.known_first(s, p)
        sides: list[list[Term]] = []
        reads: dict[str, tuple[Seg, Term]] = {}
        moved = self.one_body(p)
        for k, r in enumerate(p.routes):
            terms = self.site_terms(r.start, p)
            if k in moved["starts"]:
                terms = [self.carried(terms[0], r.start, r.segs[0], moved)]
            skip = -1
            for i, seg in enumerate(r.segs):
                if i == skip:
                    continue
                if self._centred(r, i):         # J∈fixed, the contact, ω²·JC: the centre's path normal
                    turn = r.segs[i + 1]
                    made = self.seg_terms(turn, p)
                    normal = self.path_terms(seg.joint, turn.body, turn.p, terms + self.seg_terms(seg, p) + made[:-1])
                    if not normal:              # a straight path: the term is a_C whole
                        label = ctx.point_label(turn.p, turn.body)
                        # the centre alone: a_C = a_C^t (magnitude α·JC, ⊥ JC), as C5-1.7 writes
                        # a_C = a_C^t + a_C^n — term by term, never a product α × JC as a term
                        # (issue 30, round 29 c), nor a_C = a_CJ^t, which reads as if the
                        # contact had no acceleration
                        alone = p.end == Site(turn.p, turn.body)
                        made[-1].sym = Sym(lv, label, "t" if alone else "")
                        ps.done.add(label)
                    terms = self.path_tangential(made[-1], turn.body, turn.p, normal) + normal
                    skip = i + 1
                    if turn.body in p.finds:
                        reads.setdefault(turn.body, (turn, made[-1]))
                    continue
                made = self.seg_terms(seg, p)
                terms += made
                if seg.kind == "turn" and seg.body in p.finds and made:
                    reads.setdefault(seg.body, (seg, made[-1]))
            sides.append(terms)
        end = self.site_terms(p.end, p)
        if moved["end"] and len(end) == 1:
            end = [self.carried(end[0], p.end, p.routes[0].segs[-1], moved)]
        if len(end) == 1:
            target = end[0]
        else:
            target = Term(Sym(lv, self.label(p.end)), _total(end), Ann("?"), Ann("?"), unknown=True, kind="point")
            sides.insert(0, end)
        position = None if p.end.point in ctx.inst.points else ctx.pos(p.end.point)
        crossing = _crossing_only(p)
        if lv == "v" and crossing is not None and len(sides) == 1 and len(sides[0]) == 1 and not p.finds:
            ps.done.add(self.label(p.end))       # no slip says it: v_J10∈9 = v_J10∈8, in its sentence
            out = [b for b in out if not (isinstance(b, Msg) and b.key == "rolling.noslip"
                                          and b.args["joint"].text == crossing.id)]
            rolling, on = roller(ctx.model, crossing)
            out.append(msg("rolling.same", joint=joint_name(crossing.id), a=body_name(on), gear=meshes(crossing),
                           b=body_name(rolling), point=point_name(p.end.point), sym=target.sym,
                           other=sides[0][0].sym))
            return out
        out = self.said_equal(out, owned, moved)
        out.append(Equation(target, sides, lv, ctx.ref(p.end.point, p.end.body), position=position,
                            owned=owned if contacts else [], contacts=contacts))
        ps.done.add(self.label(p.end))
        ps.done.update(moved.get("labels", ()))
        ps.done.update(t.sym.sub for side in sides for t in side if t.kind == "point" and not t.sym.sup)
        for body in p.finds:
            seg, term = reads[body]
            out.append(ps.read(body, term, seg.q, seg.p))
        return out + self.anchors(p)

    def one_body(self, p: Path) -> dict:
        """The rolling contacts an equation's velocities cross with no term of their own
        (no slip: v_J∈b = v_J∈a), at a route's start or at its end: there the point is
        written as a point of the body the route turns with, so that each side is one rigid
        body's relation (v_Q∈planet2 = v_K∈planet2 + ω_planet2 × KQ), as the notes write
        v_F∈R = v_F∈N at the contact and then each point from its own body — never
        v_Q∈ring = v_K∈sun + v_QK, whose terms belong to three bodies. The equality at the
        contact is said in the contact's sentence (`said_equal`). Keys: "starts", the indices
        of the routes whose start is carried; "end", whether the end is; "pairs", (carried
        label, crossed label, joint); "labels", the carried labels."""
        out: dict = {"starts": set(), "end": False, "pairs": [], "labels": set()}
        if self.level != "v":
            return out

        def plain(seg: Seg) -> bool:
            j = seg.joint
            return seg.kind == "cross" and j is not None and rolls(j) and not self.plan._glide_cross(seg)

        for k, r in enumerate(p.routes):
            state, spec = p.known.get(r.start, ("full", {}))
            if len(r.segs) > 1 and plain(r.segs[0]) and r.segs[1].kind == "turn" and not spec:
                out["starts"].add(k)
        lasts = [r.segs[-1] for r in p.routes if r.segs]
        state, spec = p.known.get(p.end, ("full", {}))
        if (len(p.routes) == 1 and len(lasts) == 1 and len(p.routes[0].segs) > 1 and plain(lasts[0])
                and p.routes[0].segs[-2].kind == "turn" and not spec):
            out["end"] = True
        return out

    def carried(self, term: Term, s: Site, seg: Seg, moved: dict) -> Term:
        """`term`, the velocity of site `s`, written as the point of the body on the other
        side of the rolling contact `seg` crosses (the same velocity: no slip)."""
        ctx = self.ctx
        other = seg.body if seg.body != s.body else seg.frm
        label, before = ctx.point_label(s.point, other), term.sym.sub
        if label == before or term.kind != "point" or term.sym.sup:
            return term
        moved["pairs"].append((label, before, seg.crossed()))
        moved["labels"].add(label)
        return Term(Sym(term.sym.base, label), term.value, term.mag, term.dir, term.how, term.unknown,
                    term.kind, term.spelt)

    def said_equal(self, out: list, owned: list, moved: dict) -> list:
        """The contact's sentence of each rolling contact an equation's point was carried
        across (`one_body`) says the equality it uses, v_K∈planet2 = v_K∈sun, just before the
        equation (after the crossed point's own equation, which it carries on); said alone
        ("no slip at K: …") when the sentence was written before. `owned` follows."""
        for label, before, j in moved.get("pairs", ()):
            said = next((b for b in out if isinstance(b, Msg) and b.key == "rolling.noslip"
                         and b.args["joint"].text == j.id), None)
            if said is not None:            # said where it is used: after the crossed point's equation
                out.remove(said)
                same = msg("rolling.same", **said.args, sym=Sym("v", label), other=Sym("v", before))
                owned[:] = [same if b is said else b for b in owned]
                out.append(same)
            else:
                out.append(msg("rolling.equal", point=point_name(self.ctx.contact(j)), sym=Sym("v", label),
                               other=Sym("v", before)))
        return out

    def _centred(self, r: Route, i: int) -> bool:
        """Whether piece i of the route crosses into a wheel on a fixed body that the route
        then turns to its centre (at accelerations: `Planner._centred`)."""
        seg = r.segs[i]
        if self.level != "a" or seg.kind != "cross" or seg.joint is None or i + 1 >= len(r.segs):
            return False
        found = self.plan.centred.get(seg.joint.id)
        nxt = r.segs[i + 1]
        return found is not None and found[0] == seg.body and nxt.kind == "turn" and nxt.p == found[1]

    def glide_said(self, j: Joint) -> list:
        """The sentence of a wheel's centre running along a moving edge (once per joint and
        level): the slides' axes at the wheel's centre, turning with the edge's body."""
        ps, ctx = self.ps, self.ctx
        key = f"{j.id}:centre"
        if key in ps.used:
            return []
        ps.used.add(key)
        line, wheel, centre = self.plan.glide[j.id]
        return [msg("rolling.glide", a=body_name(line), b=body_name(wheel),
                    centre=point_name(centre), point=point_name(ctx.contact(j)))]

    def path_said(self, j: Joint, body: str, centre: str) -> list:
        """The sentence of a wheel's centre on its path (once per joint and level); when an
        earlier step found the centre's acceleration (C5-E.1: C on the arm OC), the sentence
        refers to it and only says how it splits, never "C keeps its distance …" again."""
        ps, ctx = self.ps, self.ctx
        if j.id in ps.used:
            return []
        ps.used.add(j.id)
        fixed = j.a if j.b == body else j.b
        name, o = ctx.contact(j), path_origin(ctx, j, fixed)
        args = dict(joint=joint_name(j.id), a=body_name(fixed), b=body_name(body), centre=point_name(centre),
                    point=point_name(name), vc=Sym("v", ctx.point_label(centre, body)), ac=Sym("a", centre),
                    vs=Sym("v", ctx.point_label(centre, body), vector=False),
                    w=omega_sym(body), al=alpha_sym(body), arm=point_name(str(segment(name, centre))))
        if o is None:           # its acceleration is tangential alone: a_C = a_C^t = α × JC
            return [msg("path.line", at=Sym("a", ctx.point_label(centre, body), "t"), **args)]
        step = getattr(ps, "found_in", {}).get(ctx.point_label(centre, body))
        if step is not None:                 # a_C found before (C5-E.1: on the arm OC, Step 1): referred to
            return [msg("path.found", o=point_name(o), radius=point_name(str(segment(o, centre))), step=step, **args)]
        return [msg("path.circle", o=point_name(o), radius=point_name(str(segment(o, centre))), **args)]

    def path_tangential(self, term: Term, body: str, centre: str, normal: list[Term]) -> list[Term]:
        """The centre's tangential acceleration on its path, α × JC, named and placed as the
        notes write the intrinsic components (C5-1.7: a_C = (→ r ω̇) + (↓ r ω²/3), a_C^t then
        a_C^n), the way the curvature section writes them too: one style for a_C on a page.
        On a straight path (no normal term) the term is the whole acceleration: left as it is."""
        if not normal:
            return [term]
        term.sym = Sym("a", self.ctx.point_label(centre, body), "t")
        return [term]

    def path_terms(self, j: Joint, body: str, centre: str, replaced: list[Term]) -> list[Term]:
        """The centre's normal acceleration on its path, v_C² / OC towards O: the sum of the
        terms it stands for (a_J∈fixed, the contact's term, ω²·JC), none on a straight path."""
        ctx = self.ctx
        fixed = j.a if j.b == body else j.b
        o = path_origin(ctx, j, fixed)
        if o is None:
            return []
        value = _total(replaced)
        oc = segment(o, centre)
        v = Sym("v", ctx.point_label(centre, body), vector=False)
        return [Term(Sym("a", ctx.point_label(centre, body), "n"), ctx.clean(value, "accel"),
                     Ann("M", [v, f"²/{oc}"]), Ann("para", segment(centre, o)), [v, f"² / {oc}"], False, "path")]

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
        if label in self.plan.still:             # a contact at rest: the body's instant centre
            ps.done.add(label)
            j, fixed = self.plan.still[label]
            ps.used.add(j.id)
            return [still_contact(ctx, j, fixed, s.body)]
        rest = ps.at_rest(s.point, s.body)       # an instant centre placed in the centres section
        if rest:
            return rest
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
            said = ps.at_rest(q, owner)
            side = [point_term(ctx, lv, q, owner, True)] + rotation_terms(ctx, lv, body, q, s.point, False)
            eq = ps.equation(point_term(ctx, lv, s.point, body, True), [side], s.point, body)
            eq.position = None if s.point in ctx.inst.points else ctx.pos(s.point)
            return said + [eq]
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
            for i, g in enumerate(route.segs):
                if g.kind == "turn" and g.body == body:
                    if self.plan.apart(g.q, x) is not None:
                        made = rotation_terms(ctx, lv, body, g.q, x, False)
                        if i > 0 and self._centred(route, i - 1) and x == g.p:     # the wheel's centre on its path
                            j = route.segs[i - 1].joint
                            normal = self.path_terms(j, body, x, terms + made[:-1])
                            terms = self.path_tangential(made[-1], body, x, normal) + normal
                        else:
                            terms += made
                    break
                if self._centred(route, i):
                    continue            # its contact term goes into the centre's path normal
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
            rolling, on = roller(self.ctx.model, j)
            return [msg(key, joint=joint_name(j.id), a=body_name(on), b=body_name(rolling), gear=meshes(j),
                        point=point_name(self.ctx.contact(j)),
                        vrel=Sym("v", relative_name(self.ctx.contact(j), *((s.body, j.a if s.body == j.b else j.b)
                                                                           if s.body in (j.a, j.b) else (j.b, j.a)))))]
        if knife_edge(j):
            return [msg("group.wheel_v" if lv == "v" else "group.wheel_a", joint=joint_name(j.id),
                        point=point_name(j.point_at()), body=body_name(j.b), w=omega_sym(j.b), v=Sym("v", self.label(s)))]
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
                         Ann("M", magnitude(ctx, w, ctx.omega(wheel.b)) + ["·", Sym("v", label, vector=False)]), Ann("perp", plane),
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
            if self.plan.apart(seg.q, seg.p) is None or seg.body in self.plan.gliding:
                return []               # a body that slides along a line moves its points alike
            return rotation_terms(ctx, lv, seg.body, seg.q, seg.p, not known and seg.body not in p.rates)
        j = seg.crossed()
        if self.plan._glide_cross(seg):
            unknown = not known and j.id not in p.slides
            tangent = msg("dir.tangent", point=point_name(ctx.contact(j)))
            return slide_terms(ctx, lv, seg.frm, seg.body, seg.p, tangent, j.id, unknown)
        if rolls(j) and j.id in self.plan.glide:    # equal tangential components, the normal unknown
            return [contact_term(ctx, seg.p, seg.body, seg.frm, unknown=not known)] if lv == "a" else []
        if rolls(j):
            return [contact_term(ctx, seg.p, seg.body, seg.frm)] if lv == "a" else []
        if guided(j):
            unknown = not known and not self.plan._driven(j) and j.id not in p.slides
            line = (Value(ctx.clean(ctx.sol.geometry(j.id).along, ""), "") if on_fixed_line(j, ctx.frame)
                    else guide(j))       # a fixed line: its direction
            return slide_terms(ctx, lv, seg.frm, seg.body, seg.p, line, j.id,
                               unknown)
        return []

    def still(self, s: Still) -> Derived:
        """ω = 0 of a body whose instant centre is at infinity: it translates."""
        ctx = self.ctx
        centre = Sym("I", f"{ctx.frame},{s.body}", vector=False)
        return Derived(omega_sym(s.body), [], ctx.value(ctx.omega(s.body), "rate"), s.body, "omega", False,
                       remark=msg("how.centre_infinity", centre=centre))

    def glides(self, g: Glides) -> Derived:
        """ω = 0 (α = 0 at accelerations) of a body whose two wheels' centres run on one line,
        or on parallel lines. The reason is said once: where the velocities gave it, α = 0
        refers to it (it translates at every instant), not repeating it (sixteenth round: C5-E.5 said it twice)."""
        ctx = self.ctx
        if self.level != "v" and g.body in ctx.glides_said:
            remark = msg("how.translates_always")
        elif g.one_line:
            remark = msg("how.glides", p=point_name(g.p), q=point_name(g.q), line=point_name(str(segment(g.p, g.q))))
        else:
            remark = msg("how.parallel_paths", p=point_name(g.p), q=point_name(g.q))
        if self.level == "v":
            ctx.glides_said.add(g.body)
            return Derived(omega_sym(g.body), [], ctx.value(ctx.omega(g.body), "rate"), g.body, "omega", False,
                           remark=remark)
        return Derived(alpha_sym(g.body), [], ctx.value(ctx.alpha(g.body), "rate2"), g.body, "alpha", False,
                       remark=remark)

    def tangent(self, t: Tangent) -> Derived:
        """ω = 0 of a line tangent to two circles whose centres move alike across it, said as
        the notes say it: the strand stays vertical (horizontal, parallel to itself), tangent
        to both, so it translates and all its points have the same velocity (twenty-ninth
        round (b): "C1 and C2 have the same velocity component across it: no swinging" was
        opaque)."""
        ctx = self.ctx
        return Derived(omega_sym(t.body), [], ctx.value(ctx.omega(t.body), "rate"), t.body, "omega", False,
                       remark=msg("how.tangent", a=body_name(t.circles[0]), b=body_name(t.circles[1]),
                                  way=_line_way(ctx, t.body)))

    def same(self, s: Same) -> Derived:
        """ω (α) shared across a weld or a prismatic pair, or through a driven joint."""
        ctx, lv = self.ctx, self.level
        sym_of = omega_sym if lv == "v" else alpha_sym
        unit = "rate" if lv == "v" else "rate2"
        value = ctx.omega(s.body) if lv == "v" else ctx.alpha(s.body)
        if s.driver is None:
            key = "how.weld" if welds(s.pair()) else "how.prismatic"
            how = [sym_of(s.other), " ", msg(key, joint=joint_name(s.pair().id))]
        else:
            rel = sym_of(s.body, s.other) if s.sign > 0 else sym_of(s.other, s.body)
            given = s.driver.accel if lv == "a" else s.driver.value
            rate = Value(ctx.clean(ctx.inst.value(given, s.driver.where), unit), unit)
            sign = " + " if s.sign > 0 else " − "
            how = [sym_of(s.other), sign, rel, " = ", sym_of(s.other), sign, rate]
        return Derived(sym_of(s.body), how, ctx.value(value, unit), s.body,
                       "omega" if lv == "v" else "alpha", not ctx.symbolic)


def path_centre(ctx: Ctx, j: Joint, body: str) -> Optional[str]:
    """The named centre of `body`'s circle in rolling joint j (a point of the body), or None."""
    from .contacts import centre_name

    contact = ctx.sol.geometry(j.id).contact
    for b, c in getattr(contact, "centres", []):
        if b == body:
            name = centre_name(ctx, b, c)
            return name if name in ctx.model.bodies[body].points else None
    return None


def path_origin(ctx: Ctx, j: Joint, fixed: str) -> Optional[str]:
    """The centre of the fixed circle a wheel rolls on (its centre's path is a circle about
    it), or None on a straight profile."""
    from .contacts import centre_name

    contact = ctx.sol.geometry(j.id).contact
    for b, c in getattr(contact, "centres", []):
        if b == fixed:
            return centre_name(ctx, b, c)
    return None


def _crossing_only(p: Path) -> Optional[Joint]:
    """The rolling joint of an equation that only crosses one contact (no turn): the
    material points there have one velocity."""
    if len(p.routes) != 1 or len(p.routes[0].segs) != 1:
        return None
    seg = p.routes[0].segs[0]
    return seg.joint if seg.kind == "cross" and seg.joint is not None and rolls(seg.joint) else None


def still_contact(ctx: Ctx, j: Joint, fixed: str, body: str):
    """The sentence that a body rolling on a fixed one has its contact point at rest: its
    instant centre (v_J∈b = 0)."""
    from .centres import placed_at_contact

    name = ctx.contact(j)
    if placed_at_contact(ctx, body, j.id):      # the centres section placed it: refer to it
        return centre_site(ctx, name, body)
    return msg("rolling.centre", joint=joint_name(j.id), a=body_name(fixed), b=body_name(body), point=point_name(name), gear=meshes(j),
               sym=Sym("v", ctx.point_label(name, body)))


def centre_site(ctx: Ctx, name: str, body: str):
    """The sentence that the instant centre placed before (a point of the body there, or
    I_pulley) has no velocity."""
    # a centre at no point of the model is named by its symbol (I_pulley), so it is said once:
    # "I_pulley, found above, has no velocity", never "I_pulley … is the point I" (round 15a)
    key = "centre.site_s" if CENTRE_POINT_RE.fullmatch(name) else "centre.site"
    return msg(key, point=point_name(name), body=body_name(body),
               frame=Name(ctx.frame, "body", reference=True),
               centre=Sym("I", f"{ctx.frame},{body}", vector=False), sym=Sym("v", ctx.point_label(name, body)))


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
    geared, more = pair_blocks(ps.ctx, [b for b in step.bodies if b not in rates], set(ps.known), ps.level)
    given, rates = given + geared, rates | more
    plan = Planner(ps.ctx, step.bodies, set(ps.known), ps.level, rates, centres=True)
    if not plan.run():
        return None
    ps.ctx.worked.update(f"drive:{b}" for b in rates)
    if ps.level == "v":         # a drive's sentence reads its own sources first: the order of the known kept
        record_found(ps.ctx, step, plan, set(ps.known), found_rank(ps.ctx, ps.steps), bool(given))
    return given + Writer(ps, plan).blocks()


def record_found(ctx: Ctx, step, plan: Planner, known: set[str], rank: dict[str, int], given: bool) -> None:
    """Records the order in which the plan's events find the step's bodies (a line's tangency,
    a rate carried, an equation's ω) and read its sources (`_reads`), for the order of
    solution and the step's title (`order.as_found`): a body known before any equation comes
    first (`Planner.at_once`: C5-1.2's driven bar OQ, before the wheels found from its
    points' velocities, round 27b); a body or source no event names keeps its place after
    those that are named — the order changes, never the lists. A step whose
    rates a drive or a gear pair gave first (`given`: the drive's sentence reads the carrier
    and the known wheel in its own order) keeps its sources' order."""
    found: list[str] = []
    for ev in plan.events:
        if isinstance(ev, (Tangent, Still, Glides, Same)):
            found.append(ev.body)
        elif isinstance(ev, Path):
            found += ev.finds
    bodies = [b for b in dict.fromkeys(plan.at_once + found) if b in step.bodies]
    bodies += [b for b in step.bodies if b not in bodies]
    read = [] if given else [b for b in _sources(ctx, plan.events, known, rank, True) if b in step.known]
    ctx.found_order[frozenset(step.bodies)] = (bodies, read + [b for b in step.known if b not in read])


def _line_way(ctx: Ctx, body: str) -> str:
    """How a straight body lies at this instant, as a teacher says it: "vertical" or
    "horizontal" when its line is so (to 1e-9 of its unit direction), else "other"."""
    line = next((sh for sh in ctx.inst.shapes.get(body, []) if type(sh).__name__ == "Line"), None)
    if line is None:
        return "other"
    try:
        dx, dy = (float(c) for c in line.direction[:2])
    except TypeError:
        return "other"
    return "vertical" if abs(dx) < 1e-9 else "horizontal" if abs(dy) < 1e-9 else "other"
