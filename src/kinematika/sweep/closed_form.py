"""The fast path: a crank or slider followed by dyads, solved in closed form over all rows.

Each dyad (RRR, RRP, RPR, PRP; see `structure.assur`) is solved at every position at once
with numpy: the position from a circle–circle, circle–line or line–line intersection, on
the branch of the drawn configuration (the sign of a cross product fixed at row 0), then
the velocity and acceleration equations of the dyad, two scalar equations in two unknowns
(Cramer's rule). A body's motion is kept as the motion of one of its points (its *origin*)
and its rotation; every material point follows from those.

Planar vectors are complex numbers here (x + iy): k × r is i r, a rotation by θ is a
product by e^{iθ}, and an array of them is, as floats, the (N, 2) rows of the answers.

The batch axis: the drawn points, directions and input rates may be arrays of designs
(shape (D, 1)) and the increments a row (1, N); every formula broadcasts, so one call
solves D designs over N positions, each design on its own drawn branch (`sweep.batch`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal, Optional, Union, overload

import numpy as np

from ..engine.motion import Motion
from ..errors import Names
from ..joints.capabilities import Coordinate
from ..model.model import Driver, Joint, Model
from ..structure.assur import Group

DYADS = ("RRR", "RRP", "RPR", "PRP")
SINGULAR = 1e-10        # |sin| of the angle between a dyad's two unknown directions

Over = Union[np.ndarray, complex]     # a value over the rows: an array, or one number for all (a float too)


class Track:
    """A body's motion over the rows: rotation θ from the drawn pose and its origin's motion.

    `o`, `v`, `a` (complex) are the origin's position, velocity and acceleration, `rot` is
    e^{iθ}; `origin0` names the origin's drawn point in `drawn` (name → drawn location).
    A quantity that does not change over the rows (the frame's, a crank's ω) is a plain
    number rather than an array. Material points are computed once and kept (`point`), so
    a joint point a dyad has solved is not computed again for the answers.
    """

    __slots__ = ("a", "alpha", "drawn", "known", "o", "omega", "origin0", "rot", "theta", "v")

    def __init__(self, drawn: dict, origin0: str, theta: Over, o: Over, v: Over,
                 a: Over, omega: Over, alpha: Over, rot: Over) -> None:
        self.drawn, self.origin0, self.theta, self.o, self.v, self.a = drawn, origin0, theta, o, v, a
        self.omega, self.alpha, self.rot = omega, alpha, rot
        self.known: dict[str, tuple] = {}

    def point(self, name: str) -> tuple[Over, Over, Over]:
        """Position, velocity and acceleration of the body's material point `name`."""
        if name in self.known:
            return self.known[name]
        if name == self.origin0:
            out = (self.o, self.v, self.a)
        else:
            r = self.rot * (self.drawn[name] - self.drawn[self.origin0])
            out = (self.o + r, self.v + r * (1j * self.omega), self.a + r * _turning(self.omega, self.alpha))
        self.known[name] = out
        return out

    def moved(self, origin0: str, o: Over, v: Over, a: Over) -> "Track":
        """A body turning with this one whose origin `origin0` has the motion o, v, a."""
        return Track(self.drawn, origin0, self.theta, o, v, a, self.omega, self.alpha, self.rot)


def _turning(w: Over, al: Over) -> Over:
    """iα − ω²: a rigid body's acceleration of r is (iα − ω²) r."""
    return 1j * al - w * w


@dataclass
class Outcome:
    """Tracks of every body and, per row, whether it was assembled and how singular it is.

    The masks have the rows' shape: (N,) for one design, (D, N) for a batch of designs.
    """

    tracks: dict[str, Track]
    assembled: np.ndarray          # bool: the row could be assembled
    singular: np.ndarray           # bool: a dyad's directions parallel (|sin| < SINGULAR)
    failed: np.ndarray             # int: the first group (index in `groups`) that failed, or -1
    groups: list[Group]
    margins: dict[int, np.ndarray] = field(default_factory=dict)   # per group: |sin| between its
                                                                   # two unknown directions

    def worst(self, k) -> "Names | str":
        """The bodies of the group that failed first at row `k` (for messages), or ''."""
        index = int(self.failed[k])
        return Names(self.groups[index].bodies, joined="and") if index >= 0 else ""


class InputRates:
    """The input body's origin (drawn, by name) and its ω, α, v, a: constant over the rows
    (numbers, or arrays of designs)."""

    __slots__ = ("a", "alpha", "omega", "origin", "v")

    def __init__(self, origin: str, omega, alpha, v, a) -> None:
        self.origin, self.omega, self.alpha, self.v, self.a = origin, omega, alpha, v, a


def applicable(model: Model, groups: Optional[list[Group]], joint: Joint, driver: Driver) -> bool:
    """The closed form applies to one driver at the swept joint followed by dyads only."""
    if groups is None or len(model.drivers) != 1 or model.dimension != 2:
        return False
    if any(g.kind not in ("input",) + DYADS for g in groups):
        return False
    if driver.kind == "velocity" and joint.kind.coordinate is not Coordinate.LENGTH:
        return False          # a point's speed on a crank: the crank's ω varies over the turn
    return groups[0].kind == "input" and groups[0].joints == [joint.id]


class ClosedForm:
    """A crank/slider-and-dyads mechanism prepared for closed-form sweeps of its input.

    `points` (name → complex) and `directions` (joint id → unit complex) are the drawn
    configuration, `rates` the input's motion; each may hold arrays of designs (D, 1).
    """

    def __init__(self, model: Model, points: dict[str, Over], directions: dict[str, Over],
                 groups: list[Group], joint: Joint, rates: InputRates,
                 flips: Optional[dict[int, float]] = None) -> None:
        self.model, self.joint, self.groups = model, joint, groups
        self.points = points
        self.input = groups[0].bodies[0]
        self.guide = directions[joint.id] if joint.kind.coordinate is Coordinate.LENGTH else 0j
        flips = flips or {}
        self.chains = [(g, _SOLVERS[g.kind], _Chain(model, g, self.points, directions, flips.get(i, 1.0)))
                       for i, g in enumerate(groups[1:], start=1)]
        self.rates = rates

    @classmethod
    def at_drawn(cls, model: Model, points: dict[str, tuple], directions: dict[str, tuple],
                 groups: list[Group], joint: Joint, drawn: Motion,
                 flips: Optional[dict[int, float]] = None) -> "ClosedForm":
        """One design, its input's rates read from the engine's solution of the drawn instant;
        `flips` (group index → −1) close those dyads the other way than drawn (assemblies)."""
        cpoints: dict[str, Over] = {k: complex(*p) for k, p in points.items()}
        cdirections: dict[str, Over] = {k: complex(*u) for k, u in directions.items()}
        rates = drawn_rates(model, joint, groups[0].bodies[0], cpoints, drawn)
        return cls(model, cpoints, cdirections, groups, joint, rates, flips)

    def branches(self) -> list[tuple[int, Group, float]]:
        """The dyads that close in two ways: (index among the groups, group, drawn side ±1)."""
        return [(i, g, float(SIDES[g.kind](chain))) for i, (g, _, chain) in enumerate(self.chains, start=1)
                if g.kind in SIDES]

    def solve(self, q: np.ndarray) -> Outcome:
        """Every body's track at the increments `q` (radians or length) of the input joint:
        (N,) rows, or a (1, N) row of increments for a batch of designs."""
        frame_points = self.model.bodies[self.model.frame].points
        o0 = frame_points[0] if frame_points else next(iter(self.points))
        frame = Track(self.points, o0, 0.0, self.points[o0], 0j, 0j, 0.0, 0.0, 1 + 0j)   # at rest
        for p in frame_points:
            frame.known[p] = (self.points[p], 0j, 0j)
        tracks = {self.model.frame: frame, self.input: self._input(q)}
        failures = _Failures()
        margins = {}
        for index, (g, solver, chain) in enumerate(self.chains, start=1):
            sing = margins[index] = solver(chain, tracks)
            theta = tracks[g.bodies[0]].theta
            if np.isnan(np.sum(theta)) or sing.min() < SINGULAR:      # rare: find the rows
                failures.add(index, ~np.isnan(theta), sing < SINGULAR)
        shape = np.broadcast_shapes(np.shape(q), np.shape(self.rates.omega),
                                    *(np.shape(p) for p in self.points.values()))
        return Outcome(tracks, *failures.masks(shape), self.groups, margins)

    def _input(self, q: np.ndarray) -> Track:
        """A crank turning by the increments about its pivot, or a slider moving along its guide."""
        j = self.joint
        sign = 1.0 if j.a == self.model.frame else -1.0      # the coordinate is j.b relative to j.a
        r = self.rates
        o0 = self.points[r.origin]
        if j.kind.coordinate is Coordinate.ANGLE:
            theta = sign * q
            return Track(self.points, r.origin, theta, o0, r.v, r.a, r.omega, r.alpha, np.exp(1j * theta))
        return Track(self.points, r.origin, 0.0, o0 + (sign * self.guide) * q, r.v, r.a, 0.0, 0.0, 1 + 0j)


REF = "·ref"             # the drawn reference point, origin of an input slider that carries no point


def drawn_rates(model: Model, joint: Joint, body: str, points: dict[str, Over], drawn: Motion) -> InputRates:
    """The input's origin and its ω, α, v, a read from the engine's drawn instant."""
    state = drawn.states[body]
    if joint.kind.coordinate is Coordinate.ANGLE:
        origin = joint.point_at()
    else:
        names = model.bodies[body].points
        origin = names[0] if names else REF
        if not names:
            points[REF] = complex(*drawn.ref)
    here = (points[origin].real, points[origin].imag)
    v, a = drawn.velocity(state, here), drawn.acceleration(state, here)
    return InputRates(origin, float(state.omega), float(state.alpha), complex(*v), complex(*a))


class _Failures:
    """Which rows failed, in which group first, and which were singular (built lazily: rare)."""

    def __init__(self) -> None:
        self.found: list[tuple[int, np.ndarray, np.ndarray]] = []

    def add(self, index: int, ok: np.ndarray, singular: np.ndarray) -> None:
        self.found.append((index, ok, singular))

    def masks(self, shape: tuple) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        assembled = np.ones(shape, dtype=bool)
        singular = np.zeros(shape, dtype=bool)
        failed = np.full(shape, -1, dtype=np.int16)
        for index, ok, sing in self.found:
            first = (failed < 0) & (~ok | sing) & assembled & ~singular
            failed[first] = index
            singular |= ok & sing
            assembled &= ok
        return assembled, singular & assembled, failed


def const(value: complex | float, n: int) -> np.ndarray:
    """A constant over the rows: a read-only view with stride 0."""
    arr = np.array([value])
    out = np.ndarray((n,), arr.dtype, arr, strides=(0,))
    out.flags.writeable = False
    return out


def series(values: Any, n: int) -> np.ndarray:
    """Values over the rows: an array as it is, a constant as a read-only stride-0 view."""
    if isinstance(values, np.ndarray) and values.shape == (n,):
        return values
    return const(float(values), n)


# the dyads --------------------------------------------------------------------------------
class _Chain:
    """A dyad read as k1 –J1– b1 –J2– b2 –J3– k2 (b2 None for a one-body dyad with a slot).

    `flip` is −1 to close the dyad on the other branch than the drawn one (an assembly)."""

    def __init__(self, model: Model, g: Group, points: dict, directions: dict, flip: float = 1.0) -> None:
        self.points, self.directions, self.flip = points, directions, flip
        self.k1, self.k2 = g.known[0], g.known[-1]
        self.b1 = g.bodies[0]
        self.b2 = g.bodies[1] if len(g.bodies) == 2 else None
        joints = [model.joint(jid) for jid in g.joints]
        self.j1, self.j3 = joints[0], joints[-1]
        self.j2 = joints[1] if len(joints) == 3 else joints[-1]   # a slot is the middle pair too

    def at(self, j: Joint) -> str:
        """The name of the joint's point (a track's `point` takes names)."""
        return j.point_at()

    def drawn(self, j: Joint) -> complex:
        return self.points[j.point_at()]

    def second(self) -> str:
        """The dyad's second body (every dyad but a one-body one with a slot has one)."""
        assert self.b2 is not None, "a one-body dyad"
        return self.b2

    def along(self, j: Joint) -> complex:
        return self.directions[j.id]


def _rrr(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Circle–circle: B at L1 from A (on k1) and at L2 from C (on k2)."""
    a, b, c_ = c.at(c.j1), c.at(c.j2), c.at(c.j3)
    a0, b0, c0 = c.drawn(c.j1), c.drawn(c.j2), c.drawn(c.j3)
    (A, vA, aA), (C, vC, aC) = tr[c.k1].point(a), tr[c.k2].point(c_)
    r10, r20 = b0 - a0, b0 - c0
    l1, l2 = _abs2(r10), _abs2(r20)
    sigma = c.flip * _rrr_side(c)
    d = C - A
    d2 = d.real * d.real + d.imag * d.imag
    f = (d2 + (l1 - l2)) / (2 * d2)
    h = _root(l1 / d2 - f * f)
    r1 = d * (f + 1j * (sigma * h))              # B − A
    B = A + r1
    r2 = B - C
    m2 = -r2
    (w1, w2), sing = _solve2(r1, m2, (vA - vC) * 1j, (l1 * l2) ** 0.5)
    w1s = w1 * w1
    (al1, al2), _ = _solve2(r1, m2, (aA - aC - w1s * r1 + (w2 * w2) * r2) * 1j)
    vB = vA + r1 * (1j * w1)
    aB = aA + r1 * (1j * al1 - w1s)
    tr[c.b1] = _body(c.points, a, r10, l1, r1, A, vA, aA, w1, al1)
    b2 = c.second()
    tr[b2] = _body(c.points, c_, r20, l2, r2, C, vC, aC, w2, al2)
    tr[c.b1].known[b] = tr[b2].known[b] = (B, vB, aB)
    return sing


def _rrp(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Circle–line: B at L1 from A (on k1) and on the line through B fixed in k2."""
    a, b = c.at(c.j1), c.at(c.j2)
    a0, b0 = c.drawn(c.j1), c.drawn(c.j2)
    g = tr[c.k2]
    u = c.along(c.j3) * g.rot
    (A, vA, aA), (Q, vQ, aQ) = tr[c.k1].point(a), g.point(b)
    r10 = b0 - a0
    l1 = _abs2(r10)
    sigma = c.flip * _rrp_side(c)
    w = Q - A
    wu = w.real * u.real + w.imag * u.imag
    s = sigma * _root(wu * wu - (w.real * w.real + w.imag * w.imag) + l1) - wu
    su = s * u
    B = Q + su
    r1 = B - A
    vG = vQ + su * (1j * g.omega)                 # k2's material point now at B
    (w1, sd), sing = _solve2(1j * r1, -u, vG - vA, True)
    aG = aQ + su * _turning(g.omega, g.alpha) + u * (2j * g.omega * sd)   # with Coriolis
    (al1, _), _ = _solve2(1j * r1, -u, aG - aA + (w1 * w1) * r1)
    vB = vA + r1 * (1j * w1)
    aB = aA + r1 * _turning(w1, al1)
    tr[c.b1] = _body(c.points, a, r10, l1, r1, A, vA, aA, w1, al1)
    tr[c.b1].known[b] = (B, vB, aB)
    if c.b2 is not None:
        tr[c.b2] = g.moved(b, B, vB, aB)
    return sing


def _rpr(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """C (on k2) stays on the line through C fixed in b1, which turns about A (on k1)."""
    a, c_ = c.at(c.j1), c.at(c.j3)
    a0, c0 = c.drawn(c.j1), c.drawn(c.j3)
    u0 = c.along(c.j2)
    (A, vA, aA), (C, vC, aC) = tr[c.k1].point(a), tr[c.k2].point(c_)
    d0 = _dot(c0 - a0, 1j * u0)                   # offset of the line from A, fixed in b1
    sigma = c.flip * _rpr_side(c)
    w = C - A
    t = sigma * _root(w.real * w.real + w.imag * w.imag - d0 * d0)
    u = w / (t + 1j * d0)                          # w = t u + d0 i u
    iw = 1j * w
    (om, td), sing = _solve2(iw, u, vC - vA, True)
    (al, _), _ = _solve2(iw, u, aC - aA + (om * om) * w - u * (2j * om * td))
    tr[c.b1] = _body(c.points, a, u0, 1.0, u, A, vA, aA, om, al)
    if c.b2 is not None:
        tr[c.b2] = tr[c.b1].moved(c_, C, vC, aC)
    return sing


def _prp(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Line–line: B on a line fixed in k1 and on a line fixed in k2."""
    b = c.at(c.j2)
    g1, g2 = tr[c.k1], tr[c.k2]
    u1, u2 = c.along(c.j1) * g1.rot, c.along(c.j3) * g2.rot
    (Q1, v1, a1), (Q2, v2, a2) = g1.point(b), g2.point(b)
    (s1, s2), sing = _solve2(u1, -u2, Q2 - Q1, True)
    B = Q1 + s1 * u1
    vg1, vg2 = v1 + (s1 * u1) * (1j * g1.omega), v2 + (s2 * u2) * (1j * g2.omega)
    (sd1, sd2), _ = _solve2(u1, -u2, vg2 - vg1)
    ag1 = a1 + (s1 * u1) * _turning(g1.omega, g1.alpha) + u1 * (2j * g1.omega * sd1)
    ag2 = a2 + (s2 * u2) * _turning(g2.omega, g2.alpha) + u2 * (2j * g2.omega * sd2)
    (sdd1, _), _ = _solve2(u1, -u2, ag2 - ag1)
    vB, aB = vg1 + sd1 * u1, ag1 + sdd1 * u1
    theta = np.where(np.isnan(B), np.nan, g1.theta)          # parallel guides: no B
    tr[c.b1] = Track(c.points, b, theta, B, vB, aB, g1.omega, g1.alpha, g1.rot)
    if c.b2 is not None:
        tr[c.b2] = g2.moved(b, B, vB, aB)
    return sing


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp}


def _body(drawn: dict, origin: str, r0: complex, length2: float, r: np.ndarray, o: Over,
          v: Over, a: Over, w: np.ndarray, al: np.ndarray) -> Track:
    """A body whose drawn vector r0 (of squared length `length2`) is now r; its origin is the
    point named `origin`."""
    rot = r * (np.conjugate(r0) / length2)
    return Track(drawn, origin, unwrap(np.angle(rot)), o, v, a, w, al, rot)


def _abs2(z):
    """|z|² of a complex number or array."""
    return z.real * z.real + z.imag * z.imag


# which of a dyad's two closures is drawn: +1 or -1 (per design for arrays of designs) --------
def _rrr_side(c: _Chain):
    """+1 when the middle pin B is left of the line from A (on k1) to C (on k2)."""
    a0, b0, c0 = c.drawn(c.j1), c.drawn(c.j2), c.drawn(c.j3)
    return _sign(_cross(c0 - a0, b0 - a0))


def _rrp_side(c: _Chain):
    """+1 when the pin B is ahead of A along the guide it slides on."""
    a0, b0 = c.drawn(c.j1), c.drawn(c.j2)
    return _sign(_dot(b0 - a0, c.along(c.j3)))


def _rpr_side(c: _Chain):
    """+1 when the pin C is ahead of the pivot A along the slot that turns about A."""
    a0, c0 = c.drawn(c.j1), c.drawn(c.j3)
    return _sign(_dot(c0 - a0, c.along(c.j2)))


SIDES = {"RRR": _rrr_side, "RRP": _rrp_side, "RPR": _rpr_side}     # PRP closes one way only


def _sign(x):
    """-1 where x < 0, else 1: a number, or per design for an array of designs."""
    if isinstance(x, np.ndarray):
        return np.where(x < 0, -1.0, 1.0)
    return -1.0 if x < 0 else 1.0


def _dot(p: complex, q: complex) -> float:
    return p.real * q.real + p.imag * q.imag


def _cross(p, q):
    """p × q (z component): Im(p̄ q)."""
    return p.real * q.imag - p.imag * q.real


def _root(x: np.ndarray | float) -> np.ndarray:
    """√x, with round-off below zero taken as 0 and a real gap as NaN (cannot assemble)."""
    out = np.sqrt(np.maximum(x, 0.0))
    gap = np.asarray(x) < -1e-12
    if gap.any():
        out[gap] = np.nan
    return out


def unwrap(angle: np.ndarray) -> np.ndarray:
    """Remove the 2π jumps between rows (as np.unwrap) along the last axis, over the rows that
    have a value (a gap is bridged: the rows either side are compared)."""
    good = ~np.isnan(angle)
    if not good.all():
        if angle.ndim == 1:
            out = angle.copy()
            out[good] = unwrap(angle[good])
            return out
        return np.where(good, unwrap(_bridged(angle, good)), np.nan)
    if np.abs(angle).max(initial=0.0) < np.pi / 2:
        return angle                      # no two rows can be a turn apart
    step = np.diff(angle, axis=-1)
    turns = np.cumsum(np.round(step / (2 * np.pi)), axis=-1)
    out = angle.copy()
    out[..., 1:] -= 2 * np.pi * turns
    return out


def _bridged(angle: np.ndarray, good: np.ndarray) -> np.ndarray:
    """Each missing value replaced by the last one before it (the first good one at the start;
    0 in a design with none)."""
    n = angle.shape[-1]
    index = np.where(good, np.arange(n), -1)
    last = np.maximum.accumulate(index, axis=-1)
    first = np.argmax(good, axis=-1)[..., None]
    last = np.where(last < 0, first, last)
    return np.nan_to_num(np.take_along_axis(angle, last, axis=-1), nan=0.0)


@overload
def _solve2(c1: Over, c2: Over, rhs: Over, margin: Literal[False] = False) -> tuple[tuple, None]:
    ...


@overload
def _solve2(c1: Over, c2: Over, rhs: Over, margin: Literal[True] | float) -> tuple[tuple, np.ndarray]:
    ...


def _solve2(c1: Over, c2: Over, rhs: Over,
            margin: bool | float = False) -> tuple[tuple, Optional[np.ndarray]]:
    """Real x, y with x c1 + y c2 = rhs (complex): Cramer's rule with cross products.

    With `margin`, also |sin| of the angle between c1 and c2 (`margin` may be the known
    product of their lengths).
    """
    det = _cross(c1, c2)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        x = _cross(rhs, c2) * inv
        y = _cross(c1, rhs) * inv
        if margin is False:
            return (x, y), None
        size = margin if margin is not True else np.abs(c1) * np.abs(c2)
        return (x, y), np.abs(det) / size
