"""The fast path: a crank or slider followed by dyads, solved in closed form over all rows.

Each dyad (RRR, RRP, RPR, PRP; see `structure.assur`) is solved at every position at once
with numpy: the position from a circle–circle, circle–line or line–line intersection, on
the branch of the drawn configuration (the sign of a cross product fixed at row 0), then
the velocity and acceleration equations of the dyad, two scalar equations in two unknowns
(Cramer's rule). A body's motion is kept as the motion of one of its points (its *origin*)
and its rotation; every material point follows from those.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..engine.motion import Motion
from ..errors import KinematikaError
from ..model.model import Driver, Joint, Model
from ..structure.assur import Group

DYADS = ("RRR", "RRP", "RPR", "PRP")
SINGULAR = 1e-10        # |sin| of the angle between a dyad's two unknown directions

XY = tuple  # (x array, y array)


class Track:
    """A body's motion over the rows: rotation θ from the drawn pose, its origin's motion.

    Material points are computed once and kept (`point`), so a point a dyad already solved
    (a joint point) is not computed again for the answers.
    """

    __slots__ = ("origin0", "theta", "o", "v", "a", "omega", "alpha", "_cs", "known")

    def __init__(self, origin0: tuple, theta: np.ndarray, o: XY, v: XY, a: XY, omega: np.ndarray,
                 alpha: np.ndarray, cs: Optional[XY] = None) -> None:
        self.origin0, self.theta, self.o, self.v, self.a = origin0, theta, o, v, a
        self.omega, self.alpha = omega, alpha
        self._cs = cs
        self.known: dict[tuple, tuple[XY, XY, XY]] = {}

    @property
    def cs(self) -> XY:
        """cos θ, sin θ."""
        if self._cs is None:
            self._cs = (np.cos(self.theta), np.sin(self.theta))
        return self._cs

    def point(self, p0: tuple) -> tuple[XY, XY, XY]:
        """Position, velocity and acceleration of the material point drawn at `p0`, (2, N) each."""
        if p0 in self.known:
            return self.known[p0]
        rx0, ry0 = p0[0] - self.origin0[0], p0[1] - self.origin0[1]
        if rx0 == 0 and ry0 == 0:
            out = (self.o, self.v, self.a)
        else:
            c, s = self.cs
            rx = c * rx0
            rx -= s * ry0
            ry = s * rx0
            ry += c * ry0
            w, al = self.omega, self.alpha
            buf = np.empty((3, 2, len(rx)))
            np.add(self.o[0], rx, out=buf[0, 0])
            np.add(self.o[1], ry, out=buf[0, 1])
            np.subtract(self.v[0], w * ry, out=buf[1, 0])
            np.add(self.v[1], w * rx, out=buf[1, 1])
            w2 = w * w
            t = al * ry
            t += w2 * rx
            np.subtract(self.a[0], t, out=buf[2, 0])
            t = al * rx
            t -= w2 * ry
            np.add(self.a[1], t, out=buf[2, 1])
            out = (buf[0], buf[1], buf[2])
        self.known[p0] = out
        return out


def fixed_track(origin: tuple, n: int) -> Track:
    """The frame: at rest; its arrays are constants (no memory per row)."""
    zero = _const(0.0, n)
    zeros = _const((0.0, 0.0), n)
    return Track(origin, zero, _const(origin, n), zeros, zeros, zero, zero, (_const(1.0, n), zero))


def _fixed_point(track: Track, p0: tuple) -> tuple[XY, XY, XY]:
    return _const(p0, track.theta.shape[0]), track.v, track.a


@dataclass
class Outcome:
    """Tracks of every body and, per row, whether it was assembled and how singular it is."""

    tracks: dict[str, Track]
    assembled: np.ndarray          # bool (N,)
    margin: np.ndarray             # smallest |sin| over the dyads (N,); < SINGULAR: singular
    worst: list[str]               # per row with a failure: the group's bodies (for messages)


def applicable(model: Model, groups: Optional[list[Group]], joint: Joint, driver: Driver) -> bool:
    """The closed form applies to one driver at the swept joint followed by dyads only."""
    if groups is None or len(model.drivers) != 1 or model.dimension != 2:
        return False
    if any(g.kind not in ("input",) + DYADS for g in groups):
        return False
    if driver.kind == "velocity" and joint.type != "prismatic":
        return False          # a point's speed on a crank: the crank's ω varies over the turn
    return groups[0].kind == "input" and groups[0].joints == [joint.id]


class ClosedForm:
    """A crank/slider-and-dyads mechanism prepared for closed-form sweeps of its input."""

    def __init__(self, model: Model, points: dict[str, tuple], directions: dict[str, tuple],
                 groups: list[Group], joint: Joint, drawn: Motion) -> None:
        for b in model.bodies:
            if b != model.frame and not any(b in g.bodies for g in groups):
                raise KinematikaError("schema", f"body {b!r} is not part of the mechanism", "bodies")
        self.model, self.points, self.joint = model, points, joint
        self.input = groups[0].bodies[0]
        self.chains = [(g, _SOLVERS[g.kind], _Chain(model, g, points, directions)) for g in groups[1:]]
        self.input_origin, self.input_motion = _input_motion(model, points, directions, self.input,
                                                              joint, drawn)

    def solve(self, q: np.ndarray) -> Outcome:
        """Every body's track at the increments `q` (radians or length) of the input joint."""
        n = len(q)
        frame = fixed_track(next(iter(self.points.values())), n)
        for p in self.model.bodies[self.model.frame].points:
            frame.known[self.points[p]] = _fixed_point(frame, self.points[p])
        tracks = {self.model.frame: frame}
        tracks[self.input] = self._input(q)
        margin = np.full(n, np.inf)
        assembled = np.ones(n, dtype=bool)
        worst = [""] * n
        for g, solver, chain in self.chains:
            sing = solver(chain, tracks)
            ok = np.isfinite(tracks[g.bodies[0]].theta)
            failed = ~ok | (sing < SINGULAR)
            if failed.any():
                for k in np.flatnonzero(failed):
                    worst[k] = worst[k] or " and ".join(g.bodies)
                assembled &= ok
                margin = np.fmin(margin, np.where(ok, sing, np.inf))
            else:
                margin = np.fmin(margin, sing)
        return Outcome(tracks, assembled, margin, worst)

    def _input(self, q: np.ndarray) -> Track:
        """A crank turning by the increments about its pivot, or a slider moving along its guide."""
        j, n = self.joint, len(q)
        sign = 1.0 if j.a == self.model.frame else -1.0      # the coordinate is j.b relative to j.a
        w, al, v, a, e = self.input_motion
        o0 = self.input_origin
        if j.type == "revolute":
            return Track(o0, sign * q, _const(o0, n), _const(v, n), _const(a, n), _const(w, n),
                         _const(al, n))
        o = np.empty((2, n))
        np.multiply(q, sign * e[0], out=o[0])
        np.multiply(q, sign * e[1], out=o[1])
        o += np.asarray(o0, dtype=float)[:, None]
        zero = _const(0.0, n)
        return Track(o0, zero, o, _const(v, n), _const(a, n), zero, zero, (_const(1.0, n), zero))


def _input_motion(model: Model, points: dict, directions: dict, body: str, j: Joint,
                  drawn: Motion) -> tuple[tuple, tuple]:
    """The input's origin and its (ω, α, v, a, guide) from the drawn instant: constant."""
    state = drawn.states[body]
    if j.type == "revolute":
        o0, e = points[j.at], (0.0, 0.0)
    else:
        o0 = points[model.bodies[body].points[0]] if model.bodies[body].points else drawn.ref
        e = directions[j.id]
    v, a = drawn.velocity(state, o0), drawn.acceleration(state, o0)
    return o0, (float(state.omega), float(state.alpha), v, a, e)


def _const(value, n: int) -> np.ndarray:
    """A constant over the rows: a read-only view with stride 0, (N,) or (2, N)."""
    arr = np.array(value, dtype=float, ndmin=1)
    if len(arr) == 1:
        out = np.ndarray((n,), float, arr, strides=(0,))
    else:
        out = np.ndarray((2, n), float, arr, strides=(8, 0))
    out.flags.writeable = False
    return out


# the dyads --------------------------------------------------------------------------------
class _Chain:
    """A dyad read as k1 –J1– b1 –J2– b2 –J3– k2 (b2 None for a one-body dyad with a slot)."""

    def __init__(self, model: Model, g: Group, points: dict, directions: dict) -> None:
        self.model, self.points, self.directions = model, points, directions
        self.k1, self.k2 = g.known[0], g.known[-1]
        self.b1 = g.bodies[0]
        self.b2 = g.bodies[1] if len(g.bodies) == 2 else None
        joints = [model.joint(jid) for jid in g.joints]
        self.j1, self.j3 = joints[0], joints[-1]
        self.j2 = joints[1] if len(joints) == 3 else joints[-1]   # a slot is the middle pair too

    def at(self, j: Joint) -> tuple:
        return self.points[j.at]

    def along(self, j: Joint) -> tuple:
        return self.directions[j.id]


def _rrr(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Circle–circle: B at L1 from A (on k1) and L2 from C (on k2)."""
    a0, b0, c0 = c.at(c.j1), c.at(c.j2), c.at(c.j3)
    (A, vA, aA), (C, vC, aC) = tr[c.k1].point(a0), tr[c.k2].point(c0)
    l1, l2 = _dist2(a0, b0), _dist2(c0, b0)
    sigma = _sign(_cross(_sub(c0, a0), _sub(b0, a0)))
    dx, dy = C[0] - A[0], C[1] - A[1]
    d2 = dx * dx
    d2 += dy * dy
    f = d2 + (l1 - l2)
    f /= 2 * d2
    h2 = l1 / d2
    h2 -= f * f
    h = _root(h2)
    h *= sigma
    buf = np.empty((3, 2, len(h)))
    B, vB, aB = buf
    np.subtract(A[0] + f * dx, h * dy, out=B[0])
    np.add(A[1] + f * dy, h * dx, out=B[1])
    r1, r2 = _sub(B, A), _sub(B, C)
    k1, k2 = _perp(r1), _perp(r2)
    (w1, w2), sing = _solve2(k1, _neg(k2), _sub(vC, vA), (l1 * l2) ** 0.5)
    w1s, w2s = w1 * w1, w2 * w2
    rhs = (aC[0] - aA[0] + w1s * r1[0] - w2s * r2[0], aC[1] - aA[1] + w1s * r1[1] - w2s * r2[1])
    (al1, al2), _ = _solve2(k1, _neg(k2), rhs, False)
    np.add(vA[0], w1 * k1[0], out=vB[0])
    np.add(vA[1], w1 * k1[1], out=vB[1])
    np.subtract(aA[0] + al1 * k1[0], w1s * r1[0], out=aB[0])
    np.subtract(aA[1] + al1 * k1[1], w1s * r1[1], out=aB[1])
    tr[c.b1] = _turning(a0, _sub(b0, a0), l1, r1, A, vA, aA, w1, al1)
    tr[c.b2] = _turning(c0, _sub(b0, c0), l2, r2, C, vC, aC, w2, al2)
    for b in (c.b1, c.b2):
        tr[b].known[b0] = (B, vB, aB)
    return sing


def _turning(o0: tuple, r0: tuple, length2: float, r: XY, o: XY, v: XY, a: XY, w: np.ndarray,
             al: np.ndarray) -> Track:
    """A body whose drawn vector r0 (of squared length `length2`) is now r."""
    cos, sin = _dot(r0, r) / length2, _cross(r0, r) / length2
    return Track(o0, unwrap(np.arctan2(sin, cos)), o, v, a, w, al, (cos, sin))


def _rrp(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Circle–line: B at L1 from A (on k1) and on the line through B fixed in k2."""
    a0, b0 = c.at(c.j1), c.at(c.j2)
    u0 = c.along(c.j3)
    (A, vA, aA), (Q, vQ, aQ) = tr[c.k1].point(a0), tr[c.k2].point(b0)
    g = tr[c.k2]
    u = _rotate(u0, g.theta)
    l1 = _dist2(a0, b0)
    sigma = _sign(_dot(_sub(b0, a0), u0))
    w = _sub(Q, A)
    wu = _dot(w, u)
    s = -wu + sigma * _root(wu * wu - _dot(w, w) + l1)
    B = (Q[0] + s * u[0], Q[1] + s * u[1])
    r1 = _sub(B, A)
    k1 = _perp(r1)
    # k2's material point now at B, and the slider's motion along the guide
    vG = _guide_vel(vQ, g, s, u)
    (w1, sd), sing = _solve2(k1, _neg(u), _sub(vG, vA))
    gw2 = g.omega * g.omega
    aG = (aQ[0] - g.alpha * s * u[1] - gw2 * s * u[0], aQ[1] + g.alpha * s * u[0] - gw2 * s * u[1])
    cor = 2 * g.omega * sd
    rhs = (aG[0] - cor * u[1] - aA[0] + w1 * w1 * r1[0], aG[1] + cor * u[0] - aA[1] + w1 * w1 * r1[1])
    (al1, sdd), _ = _solve2(k1, _neg(u), rhs, False)
    vB = (vA[0] - w1 * r1[1], vA[1] + w1 * r1[0])
    aB = (aA[0] - al1 * r1[1] - w1 * w1 * r1[0], aA[1] + al1 * r1[0] - w1 * w1 * r1[1])
    tr[c.b1] = _turning(a0, _sub(b0, a0), l1, r1, A, vA, aA, w1, al1)
    tr[c.b1].known[b0] = (B, vB, aB)
    if c.b2 is not None:
        tr[c.b2] = Track(b0, g.theta, B, vB, aB, g.omega, g.alpha, g.cs)
    return sing


def _rpr(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """C (on k2) stays on the line through C fixed in b1, which turns about A (on k1)."""
    a0, c0 = c.at(c.j1), c.at(c.j3)
    u0 = c.along(c.j2)
    (A, vA, aA), (C, vC, aC) = tr[c.k1].point(a0), tr[c.k2].point(c0)
    n0 = (-u0[1], u0[0])
    d0 = _dot(_sub(c0, a0), n0)          # offset of the line from A, fixed in b1
    sigma = _sign(_dot(_sub(c0, a0), u0))
    w = _sub(C, A)
    d2 = _dot(w, w)
    t = sigma * _root(d2 - d0 * d0)
    u = ((t * w[0] + d0 * w[1]) / d2, (t * w[1] - d0 * w[0]) / d2)
    kw = _perp(w)
    (om, td), sing = _solve2(kw, u, _sub(vC, vA))
    cor = 2 * om * td
    rhs = (aC[0] - aA[0] + om * om * w[0] + cor * u[1], aC[1] - aA[1] + om * om * w[1] - cor * u[0])
    (al, _), _ = _solve2(kw, u, rhs, False)
    tr[c.b1] = _turning(a0, u0, 1.0, u, A, vA, aA, om, al)
    if c.b2 is not None:
        tr[c.b2] = Track(c0, tr[c.b1].theta, C, vC, aC, om, al, tr[c.b1].cs)
    return sing


def _prp(c: _Chain, tr: dict[str, Track]) -> np.ndarray:
    """Line–line: B on a line fixed in k1 and on a line fixed in k2."""
    b0 = c.at(c.j2)
    g1, g2 = tr[c.k1], tr[c.k2]
    u1, u2 = _rotate(c.along(c.j1), g1.theta), _rotate(c.along(c.j3), g2.theta)
    (Q1, v1, a1), (Q2, v2, a2) = g1.point(b0), g2.point(b0)
    (s1, s2), sing = _solve2(u1, _neg(u2), _sub(Q2, Q1))
    B = (Q1[0] + s1 * u1[0], Q1[1] + s1 * u1[1])
    # each guide's material point now at B
    vg1, vg2 = _guide_vel(v1, g1, s1, u1), _guide_vel(v2, g2, s2, u2)
    (sd1, sd2), _ = _solve2(u1, _neg(u2), _sub(vg2, vg1), False)
    ag1 = _guide_accel(a1, g1, s1, u1, sd1)
    ag2 = _guide_accel(a2, g2, s2, u2, sd2)
    (sdd1, sdd2), _ = _solve2(u1, _neg(u2), _sub(ag2, ag1), False)
    vB = (vg1[0] + sd1 * u1[0], vg1[1] + sd1 * u1[1])
    aB = (ag1[0] + sdd1 * u1[0], ag1[1] + sdd1 * u1[1])
    theta = np.where(np.isfinite(B[0]), g1.theta, np.nan)      # parallel guides: no B
    tr[c.b1] = Track(b0, theta, B, vB, aB, g1.omega, g1.alpha, g1.cs)
    if c.b2 is not None:
        tr[c.b2] = Track(b0, g2.theta, B, vB, aB, g2.omega, g2.alpha, g2.cs)
    return sing


def _guide_vel(v_q: XY, g: Track, s: np.ndarray, u: XY) -> XY:
    """Velocity of the guide's material point at Q + s u."""
    return v_q[0] - g.omega * s * u[1], v_q[1] + g.omega * s * u[0]


def _guide_accel(a_q: XY, g: Track, s: np.ndarray, u: XY, sd: np.ndarray) -> XY:
    """Acceleration of the guide's point at Q + s u, plus the Coriolis term 2 ω ṡ k×u."""
    w2 = g.omega * g.omega
    cor = 2 * g.omega * sd
    return (a_q[0] - g.alpha * s * u[1] - w2 * s * u[0] - cor * u[1],
            a_q[1] + g.alpha * s * u[0] - w2 * s * u[1] + cor * u[0])


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp}


# small vector helpers on (x, y) pairs of arrays or floats -----------------------------------
def _sub(p: XY, q: XY) -> XY:
    return p[0] - q[0], p[1] - q[1]


def _neg(p: XY) -> XY:
    return -p[0], -p[1]


def _dot(p: XY, q: XY):
    return p[0] * q[0] + p[1] * q[1]


def _cross(p: XY, q: XY):
    return p[0] * q[1] - p[1] * q[0]


def _perp(p: XY) -> XY:
    """k × p."""
    return -p[1], p[0]


def _dist2(p: tuple, q: tuple) -> float:
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def _sign(x: float) -> float:
    return -1.0 if x < 0 else 1.0


def _root(x: np.ndarray) -> np.ndarray:
    """√x, with round-off below zero taken as 0 and a real gap as NaN (cannot assemble)."""
    out = np.sqrt(np.maximum(x, 0.0))
    gap = x < -1e-12
    if gap.any():
        out[gap] = np.nan
    return out


def _rotate(u0: tuple, theta: np.ndarray) -> XY:
    c, s = np.cos(theta), np.sin(theta)
    return c * u0[0] - s * u0[1], s * u0[0] + c * u0[1]


def unwrap(angle: np.ndarray) -> np.ndarray:
    """Remove the 2π jumps between rows (as np.unwrap), over the rows that have a value."""
    good = np.isfinite(angle)
    if not good.all():
        out = angle.copy()
        out[good] = unwrap(angle[good])
        return out
    if np.abs(angle).max(initial=0.0) < np.pi / 2:
        return angle                      # no two rows can be a turn apart
    step = np.diff(angle)
    turns = np.concatenate(([0.0], np.cumsum(np.round(step / (2 * np.pi)))))
    return angle - 2 * np.pi * turns


def _solve2(c1: XY, c2: XY, rhs: XY, margin: bool | float = True) -> tuple[tuple, Optional[np.ndarray]]:
    """x c1 + y c2 = rhs by Cramer's rule; with `margin`, also |sin| of the angle c1, c2.

    `margin` may be the known product of the lengths of c1 and c2.
    """
    det = c1[0] * c2[1] - c1[1] * c2[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        x = (rhs[0] * c2[1] - rhs[1] * c2[0]) * inv
        y = (c1[0] * rhs[1] - c1[1] * rhs[0]) * inv
        if margin is False:
            sing = None
        elif margin is True:
            sing = np.abs(det) / np.sqrt(_dot(c1, c1) * _dot(c2, c2))
        else:
            sing = np.abs(det) * (1.0 / margin)
    return (x, y), sing
