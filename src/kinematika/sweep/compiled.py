"""The Newton path compiled once per mechanism, for spatial linkages of revolute and spherical
joints driven by a joint's rate (the RSSR, Hooke's joint, the spherical four-bar, robot arms).

The general path (`newton`) assembles one position after the other with the engine's
Python rows. Here the same conditions (`constraints`: points coincide, the relative
rotation stays about the revolute's axis, the driven joint's angle is the increment, no
idle spin of an S–S link) become numpy arrays over every position at once:

- the rows are made of vectors fixed in bodies (joint points, axes, perpendiculars), all of
  them one product per pose (`rigid.LinearVectors`); the velocity matrix is those vectors'
  coordinates scattered by fixed index arrays;
- coarse positions (about every 8°) are assembled five at a time by Newton's method from
  the tangent at the last one (one at a time where that fails), with the general path's
  safeguard against a jump to another branch (a correction larger than 0.3 of the step);
- then, level by level (eight times denser each time), every other position starts from
  the second-order tangent at its nearest solved one and all of them are corrected
  together by chord iterations with that one's inverse (stacked (N, n, n) arrays);
- velocities and accelerations are stacked solves: exact inverses at the positions that
  served as parents, and at the last level, refinement from the parent's inverse
  (`stacked.refined`) with a bound that certifies the condition number as an inverse would.

Anything it does not handle (other joints or drivers, a redundant or nearly singular
matrix at any position, Newton failing or jumping anywhere) returns None, and the general
path runs the whole sweep as before: that is where `--skip-bad`, dead points and the
mobility diagnosis live. Both paths give the same positions, velocities and accelerations
to round-off (tests compare them), except the idle spin angle of an S–S link, which has no
position form and so depends on the path taken (its ω and α are the same).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..engine.idle import idle_links
from ..joints.capabilities import Coordinate
from .plan import Plan
from .rigid import LinearVectors, perpendicular, rotation_vectors, stepped
from .stacked import Regular, Twists, cross, dot, norm1, refined, times
from .swept import Swept

COARSE_STEP = 0.15          # rad between coarse positions
AHEAD = 5                   # coarse positions solved at once from the last one
DENSER = 8                  # each level has this many times more rows than the last
ITERATIONS = 25
TOLERANCE = 1e-12           # as the general path: dimensionless step size
JUMP = 0.3                  # a correction above this fraction of the step is a jump
CONDITION = 1e10            # the engine's limit for a dead point (2-norm, dimensionless)
CHUNK = 8192                # positions whose stacked matrices are built at once (memory)
FROZEN = 1e-5               # Newton keeps its last matrix once the corrections are this small


@dataclass
class _Pairs:
    """Rows that compare two bodies (index −1: the frame), one per entry."""

    a: np.ndarray
    b: np.ndarray


class CompiledNewton:
    """The constraint pattern of one mechanism as arrays; `sweep` solves every position."""

    def __init__(self, sweeper: Swept, plan: Plan) -> None:
        inst, u = sweeper.inst, sweeper.solver.unknowns
        model = inst.model
        self.bodies = list(u.bodies)
        index = {b: i for i, b in enumerate(self.bodies)}
        at = lambda name: index.get(name, -1)
        self.c = np.asarray(inst.ref, dtype=float)
        self.scale = float(inst.scale)
        self.n = u.n
        geos = sweeper.solver.geos
        points, pa, pb = [], [], []                # coincident points (3 rows each)
        perps, ra, rb = [], [], []                 # turning rows: perpendicular fixed in a
        for j in model.joints:
            g = geos[j.id]
            points.append(np.asarray(g.at, dtype=float))
            pa.append(at(j.a))
            pb.append(at(j.b))
            if j.kind.pins and not j.kind.ball:          # a pin about an axis: its turning rows
                for p in g.perps:
                    perps.append(np.asarray(p, dtype=float))
                    ra.append(at(j.a))
                    rb.append(at(j.b))
        self.p0 = np.array(points).reshape(-1, 3)
        self.coincide = _Pairs(np.array(pa, dtype=int), np.array(pb, dtype=int))
        self.perp0 = np.array(perps).reshape(-1, 3)
        self.turn = _Pairs(np.array(ra, dtype=int), np.array(rb, dtype=int))
        # the revolutes' own axes (e fixed in b) for the position form of the turning rows
        self.axis_b0 = np.array([np.asarray(geos[j.id].axis, dtype=float)
                                 for j in model.joints if j.kind.pins and not j.kind.ball]).reshape(-1, 3)
        axes, da, db, rates, accels, swept = [], [], [], [], [], []
        for d in model.drivers:
            g = geos[d.driven_joint()]
            axes.append(np.asarray(g.axis, dtype=float))
            da.append(at(g.joint.a))
            db.append(at(g.joint.b))
            rates.append(float(inst.value(d.rate(), d.where)))
            accels.append(float(inst.value(d.rate(accel=True), d.where)))
            swept.append(d is plan.driver)
        self.drive_axis0 = np.array(axes).reshape(-1, 3)
        self.drive = _Pairs(np.array(da, dtype=int), np.array(db, dtype=int))
        self.rates, self.accels = np.array(rates), np.array(accels)
        self.swept = np.array(swept, dtype=bool)
        owners = {p: (model.carriers(p) or [model.frame])[0] for p in model.points}
        idle = idle_links(inst)
        self.idle_body = np.array([index[body] for body, _, _ in idle], dtype=int)
        self.idle_a = [(at(owners[a]), np.asarray(inst.points[a], dtype=float)) for _, a, _ in idle]
        self.idle_b = [(at(owners[b]), np.asarray(inst.points[b], dtype=float)) for _, _, b in idle]
        self.m_all = 3 * len(self.p0) + len(self.perp0) + len(self.drive_axis0) + len(idle)
        self.vectors = self._vectors(len(self.bodies))
        self.translation = np.tile(np.r_[np.zeros(3, bool), np.ones(3, bool)], len(self.bodies))
        self._column = np.where(self.translation, self.scale, 1.0)
        self.keep, self.m = np.arange(self.m_all), self.m_all
        self._scatter()
        self.keep = self._independent_rows()
        self.m = len(self.keep)
        self.usable = self._scatter()

    def _independent_rows(self) -> np.ndarray:
        """Rows independent at the drawn pose (a Hooke joint's closure repeats its point
        conditions): kept greedily in order, as long as they add a direction."""
        rot = np.broadcast_to(np.eye(3), (1, len(self.bodies), 3, 3))
        a = self.matrix(rot, np.zeros((1, len(self.bodies), 3)))[0] * self._column
        basis: list[np.ndarray] = []
        keep = []
        for i, row in enumerate(a):
            size = np.abs(row).max(initial=0.0)
            rest = row.copy()
            for q in basis:
                rest -= (rest @ q) * q
            if size > 0 and np.linalg.norm(rest) > 1e-8 * size:
                basis.append(rest / np.linalg.norm(rest))
                keep.append(i)
        return np.array(keep, dtype=int)

    # poses ------------------------------------------------------------------------------
    def _vectors(self, n_bodies: int) -> LinearVectors:
        """The vectors the rows are made of, each fixed in a body: the joints' points as
        carried by b and by a (from c), the revolutes' axes (in b) and perpendiculars (in
        a), the driven axes and a perpendicular to each (in a, and in b), idle links' AB."""
        out, c, k, tr, dr = LinearVectors(n_bodies), self.c, self.coincide, self.turn, self.drive
        out.add("pb", [[(b, p - c, True, 1.0)] for b, p in zip(k.b, self.p0)])
        out.add("pa", [[(a, p - c, True, 1.0)] for a, p in zip(k.a, self.p0)])
        out.add("axis", [[(b, e, False, 1.0)] for b, e in zip(tr.b[0::2], self.axis_b0)])
        out.add("perp", [[(a, p, False, 1.0)] for a, p in zip(tr.a, self.perp0)])
        out.add("drive", [[(a, e, False, 1.0)] for a, e in zip(dr.a, self.drive_axis0)])
        across = [perpendicular(e) for e in self.drive_axis0]
        out.add("ua", [[(a, u, False, 1.0)] for a, u in zip(dr.a, across)])
        out.add("ub", [[(b, u, False, 1.0)] for b, u in zip(dr.b, across)])
        out.add("idle", [[(bb, pb - c, True, 1.0), (ba, pa - c, True, -1.0)]
                         for (ba, pa), (bb, pb) in zip(self.idle_a, self.idle_b)])
        out.compile()
        return out

    def residual(self, rot, t, dq) -> np.ndarray:
        """Φ (M, m): the general path's position constraints, row for row (the drivers' as
        the angle turned about the axis, which the engine writes as log(exp(−q e) R_b R_aᵀ)·e:
        the same to first order, and zero at the same poses)."""
        v = self.vectors(rot, t)
        get = self.vectors.part
        parts = [(get(v, "pb") - get(v, "pa")).reshape(len(dq), -1)]
        if len(self.perp0):
            dots = dot(np.repeat(get(v, "axis"), 2, axis=1), get(v, "perp"))   # e·p1, e·p2 per revolute
            out = np.empty_like(dots)
            out[:, 0::2], out[:, 1::2] = -dots[:, 1::2], dots[:, 0::2]
            parts.append(out)
        if len(self.drive_axis0):
            ua, ub = get(v, "ua"), get(v, "ub")
            turned = np.arctan2(dot(cross(ua, ub), get(v, "drive")), dot(ua, ub))
            target = np.where(self.swept, 1.0, 0.0)[None, :] * dq[:, None]
            parts.append(np.remainder(turned - target + math.pi, 2 * math.pi) - math.pi)
        if len(self.idle_body):
            parts.append(np.zeros((len(dq), len(self.idle_body))))
        return np.concatenate(parts, axis=1)[:, self.keep]

    def matrix(self, rot, t) -> np.ndarray:
        """The engine's velocity matrix at these poses (M, m, n): the constraints' Jacobian."""
        return self._placed(self._values(rot, t, self._layout[2]))

    def scaled_matrix(self, rot, t) -> tuple[np.ndarray, np.ndarray]:
        """S = R A C (rows equilibrated, lengths in the model's scale) and R's diagonal."""
        values = self._values(rot, t, self._layout[3])
        norms = np.maximum.reduceat(np.abs(values), self._layout[4], axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            values /= norms[:, self._layout[5]]
            return self._placed(values), 1.0 / norms

    def _values(self, rot, t, sign: np.ndarray) -> np.ndarray:
        """The matrix's nonzero entries (M, E), row by row. Each is ±1 or ± a coordinate of a
        joint's lever arm, a turning row's perpendicular, a driven axis or an idle link's AB:
        those vectors are computed for every pose at once (`vectors`) and picked by
        `_scatter`'s fixed index arrays."""
        m = rot.shape[0]
        v = self.vectors(rot, t)
        features = np.concatenate([self.vectors.part(v, name).reshape(m, -1)
                                   for name in ("pb", "perp", "drive", "idle")] + [np.ones((m, 1))], axis=1)
        return features[:, self._layout[1]] * sign

    def _placed(self, values: np.ndarray) -> np.ndarray:
        a = np.zeros((len(values), self.m * self.n))
        a[:, self._layout[0]] = values
        return a.reshape(len(values), self.m, self.n)

    def _scatter(self) -> bool:
        """Where `matrix` puts each entry: (flat index, feature, sign) for the entries that
        are a coordinate of a computed vector, (flat index, value) for the ±1 ones; rows left
        out and the frame's columns dropped. Feature order: the joints' lever arms r (3 per
        joint), the turning rows' perpendiculars, the driven axes, the idle links' AB."""
        var: list[tuple[int, int, int, float]] = []     # (row, column, feature, sign)
        one: list[tuple[int, int, float]] = []
        k = self.coincide
        for q in range(len(k.a)):
            for sign, body in ((1.0, k.b[q]), (-1.0, k.a[q])):
                if body < 0:
                    continue
                c0 = 6 * body
                for i in range(3):
                    j, l = (i + 1) % 3, (i + 2) % 3
                    one.append((3 * q + i, c0 + 3 + i, sign))
                    var.append((3 * q + i, c0 + j, 3 * q + l, sign))
                    var.append((3 * q + i, c0 + l, 3 * q + j, -sign))
        row, feature = 3 * len(k.a), 3 * len(k.a)
        for pairs in (self.turn, self.drive):
            for q in range(len(pairs.a)):
                for sign, body in ((1.0, pairs.b[q]), (-1.0, pairs.a[q])):
                    if body >= 0:
                        var += [(row + q, 6 * body + i, feature + 3 * q + i, sign) for i in range(3)]
            row, feature = row + len(pairs.a), feature + 3 * len(pairs.a)
        for q, body in enumerate(self.idle_body):
            var += [(row + q, 6 * body + i, feature + 3 * q + i, 1.0) for i in range(3)]
        place = np.full(self.m_all, -1)
        place[self.keep] = np.arange(len(self.keep))
        unit = len(self.p0) * 3 + 3 * (len(self.perp0) + len(self.drive_axis0) + len(self.idle_body))
        entries = sorted((place[r] * self.n + c, f, s) for r, c, f, s in var + [(r, c, unit, s) for r, c, s in one]
                         if place[r] >= 0)
        at = np.array([e[0] for e in entries], dtype=int)
        signs = np.array([e[2] for e in entries])
        rows = at // self.n
        starts = np.searchsorted(rows, np.arange(self.m))
        self._layout = (at, np.array([e[1] for e in entries], dtype=int), signs,
                        signs * self._column[at % self.n], starts, rows)
        every_row = (np.diff(np.r_[starts, len(at)]) > 0).all()
        return len(np.unique(at)) == len(at) and bool(every_row)     # one writer each, no empty row

    def _drive_rows(self) -> np.ndarray:
        """The drivers' rows among all the rows."""
        return 3 * len(self.p0) + len(self.perp0) + np.arange(len(self.drive_axis0))

    def _driver_rows(self) -> np.ndarray:
        """The drivers' rows among the kept ones."""
        return np.searchsorted(self.keep, self._drive_rows())

    def _rates(self, n_rows: int) -> np.ndarray:
        """The velocity system's right side: the drivers' rates."""
        rhs = np.zeros((n_rows, self.m))
        rhs[:, self._driver_rows()] = self.rates
        return rhs

    # the sweep ---------------------------------------------------------------------------
    def sweep(self, increments: np.ndarray) -> Optional[dict]:
        """Every position's poses, twists and their rates; None where the general path must run.

        Coarse rows first (`_coarse`); then, level by level, the rows between them (eight
        times denser each time, twice where that fails) all at once, each from its nearest
        solved row: its tangent as predictor, then chord iterations with that row's inverse
        matrix; the twists of the last level from those inverses (`_near_twists`), the
        others' from their own.
        """
        if (not self.usable or self.m != self.n or len(self.bodies) == 0
                or not np.isin(self._drive_rows(), self.keep).all()):
            return None
        dq = np.asarray(increments, dtype=float)
        n_rows = len(dq)
        step = abs(dq[1] - dq[0]) if n_rows > 1 else 1.0
        stride = max(1, int(COARSE_STEP / step)) if step > 0 else 1
        coarse = np.unique(np.r_[np.arange(0, n_rows, stride), n_rows - 1])
        b = len(self.bodies)
        rots, ts = np.empty((n_rows, b, 3, 3)), np.empty((n_rows, b, 3))
        rots[0], ts[0] = np.eye(3), 0.0
        solved = self._coarse(rots, ts, dq, coarse)
        if solved is None:
            return None
        twists = Twists(n_rows, self.n)
        while stride > 1:
            for denser in (DENSER, 2):         # where a level fails, one twice as dense first
                level = np.setdiff1d(np.arange(0, n_rows, max(1, stride // denser)), solved)
                last = twists if stride // denser <= 1 else None
                if self._levels(rots, ts, dq, solved, level, last):
                    break
                twists.known[level] = False
            else:
                return None
            stride = max(1, stride // denser)
            solved = np.union1d(solved, level)
        if len(self.keep) < self.m_all and not self._consistent(rots, ts, dq):
            return None
        rest = np.flatnonzero(~twists.known)
        for part in range(0, len(rest), CHUNK):
            rows = rest[part:part + CHUNK]
            regular = self._regular(rots[rows], ts[rows])
            if regular is None:
                return None
            twists.x_v[rows], twists.x_a[rows] = self._twists(rots[rows], ts[rows], regular)
        return {"rot": rots, "t": ts, "x_v": twists.x_v, "x_a": twists.x_a}

    def _coarse(self, rots, ts, dq, coarse) -> Optional[np.ndarray]:
        """The coarse rows by Newton's method from the last one solved: the next AHEAD rows
        at once, each from its tangent there (one stacked Newton), kept if `_in_sequence`;
        where any of them fails, only the next one; where that fails too, a row halfway to
        it first (down to the sweep's own step, as the general path goes). The rows solved."""
        solved, pending = [int(coarse[0])], [int(k) for k in coarse[1:]]
        start = None                       # A⁻¹ and the tangents at solved[-1], when known
        while pending:
            k0 = np.array(solved[-1:])
            if start is None:
                inverse = self._inverse(rots[k0], ts[k0])
                if inverse is None:
                    return None
                start = (inverse, *self._predictor(rots[k0], ts[k0], inverse))
            inverse, slope, bend = start
            for targets in (np.array(pending[:AHEAD]), np.array(pending[:1])):
                from_ = np.repeat(k0, len(targets))
                done = self._chord(rots[from_], ts[from_], inverse[from_ * 0], (slope[from_ * 0], bend[from_ * 0]),
                                   dq[from_], dq[targets], newton=True)
                if done is not None and len(targets) > 1:
                    checked = self._in_sequence(done, dq[targets])
                    done = None if checked is None else done
                if done is not None:
                    break
            if done is None:
                if pending[0] - solved[-1] < 2:
                    return None
                pending.insert(0, (solved[-1] + pending[0]) // 2)
                continue
            start = checked if len(targets) > 1 else None
            rots[targets], ts[targets] = done
            solved += targets.tolist()
            del pending[:len(targets)]
        return np.array(solved)

    def _in_sequence(self, done: tuple, dq_rows: np.ndarray) -> Optional[tuple]:
        """Rows solved at once from one start are the rows that one after the other would
        give: each row's joints and turns (an idle link's spin aside: it has no position
        form) are where the tangent at the row before puts them, within the general path's
        jump guard (0.3 of the step the tangent takes). Far from the
        start, Newton's method can land on the other branch near a limit position; this
        finds it. A⁻¹ and the tangents at the last row (the next start), or None."""
        rot, t = done
        inverse = self._inverse(rot, t)
        if inverse is None:
            return None
        slope, bend = self._predictor(rot, t, inverse)
        h = (dq_rows[1:] - dq_rows[:-1])[:, None]
        guess = stepped(rot[:-1], t[:-1], slope[:-1] * h + 0.5 * bend[:-1] * h * h)
        joints = lambda r, tt: self.vectors(r, tt)[:, self.vectors.slices["pb"]]
        turning = np.setdiff1d(np.arange(len(self.bodies)), self.idle_body)         # not idle spins
        miss = np.maximum(np.abs(joints(rot[1:], t[1:]) - joints(*guess)).max(axis=(1, 2)) / self.scale,
                          np.abs(rot[1:, turning] - guess[0][:, turning]).max(axis=(1, 2, 3)))
        ok = (miss <= JUMP * self._size(slope[:-1] * h)).all()
        return (inverse[-1:], slope[-1:], bend[-1:]) if ok else None

    def _levels(self, rots, ts, dq, solved, level, twists: Optional[Twists]) -> bool:
        """The rows of `level`, each from its nearest solved row, a chunk at a time."""
        if not len(level):
            return True
        right = np.clip(np.searchsorted(solved, level), 1, len(solved) - 1)
        left = solved[right - 1]
        parent = np.where(level - left <= solved[right] - level, left, solved[right])
        for part in range(0, len(level), CHUNK):      # stacked matrices a chunk at a time
            if not self._level(rots, ts, dq, level[part:part + CHUNK], parent[part:part + CHUNK], twists):
                return False
        return True

    def _level(self, rots, ts, dq, rows, parents, twists: Optional[Twists]) -> bool:
        """Rows of one level from their parents (solved rows): the parents' matrices inverted
        and checked, the rows predicted and corrected with them; with `twists` (the last
        level), the rows' twists too, from the parents' inverses (`_near_twists`)."""
        heads, which = np.unique(parents, return_inverse=True)
        regular = self._regular(rots[heads], ts[heads])
        if regular is None:
            return False
        inverse = regular.inverse()
        slope, bend = self._predictor(rots[heads], ts[heads], inverse)
        done = self._chord(rots[parents], ts[parents], inverse[which], (slope[which], bend[which]),
                           dq[parents], dq[rows])
        if done is None:
            return False
        rots[rows], ts[rows] = done
        if twists is not None:
            twists.put(heads, *self._twists(rots[heads], ts[heads], regular))
            x_v, x_a, ok = self._near_twists(rots[rows], ts[rows], regular, which)
            twists.put(rows[ok], x_v[ok], x_a[ok])
        return True

    def _consistent(self, rots, ts, dq) -> bool:
        """The rows left out (repeated conditions) hold too at every position."""
        keep, self.keep = self.keep, np.arange(self.m_all)
        try:
            phi = self.residual(rots, ts, dq)
        finally:
            self.keep = keep
        return bool((np.abs(phi) / np.where(self._row_is_length(), self.scale, 1.0) < 1e-9).all())

    def _row_is_length(self) -> np.ndarray:
        return np.r_[np.ones(3 * len(self.p0), bool), np.zeros(self.m_all - 3 * len(self.p0), bool)]

    def _inverse(self, rot, t) -> Optional[np.ndarray]:
        try:
            return np.linalg.inv(self.matrix(rot, t))
        except np.linalg.LinAlgError:
            return None

    def _predictor(self, rot, t, inverse) -> tuple[np.ndarray, np.ndarray]:
        """dx/dq and d²x/dq² at assembled poses: the velocity system with a unit rate on the
        swept driver (a column of A⁻¹) and the acceleration system with those velocities and
        no driver acceleration. In the steps' coordinates (R ← exp(δθ) R, t ← exp(δθ) t + δ)
        x(q + h) = x + h x' + h²/2 x'' + O(h³), so a predicted position is off by O(h³)."""
        slope = inverse[:, :, self._driver_rows()[self.swept]].sum(axis=2)
        bend = times(inverse, self._accel_terms(rot, t, slope, driven=False))
        return slope, bend

    def _size(self, dx: np.ndarray) -> np.ndarray:
        return np.abs(np.where(self.translation, dx / self.scale, dx)).max(axis=-1)

    def _chord(self, rot, t, inverse, predictor, dq_from, dq_to, newton: bool = False) -> Optional[tuple]:
        """From assembled poses at dq_from: the second-order predictor to dq_to, then
        iterations x ← x − A⁻¹Φ(x) with the start's matrix (or, `newton`, the current one
        until the corrections are small), rows that have converged left alone; None if any
        row does not converge or jumps."""
        slope, bend = predictor
        h = (dq_to - dq_from)[:, None]
        predicted = self._size(slope * h)
        step = slope * h + 0.5 * bend * h * h
        rot, t = stepped(rot, t, step)
        r, tt, inv, dq, last, rows = rot, t, inverse, dq_to, np.full(len(dq_to), np.inf), np.arange(len(dq_to))
        for _ in range(ITERATIONS):             # r, tt, ... : the rows still iterating
            phi = self.residual(r, tt, dq)
            if newton and (last > FROZEN).any():
                inv = self._inverse(r, tt)
                if inv is None:
                    return None
            dx = -times(inv, phi)
            size = self._size(dx)
            if not np.isfinite(size).all() or (size > JUMP * predicted + 1e-9).any():
                return None
            r, tt = stepped(r, tt, dx)
            rate = np.where(np.isfinite(last), np.minimum(size / np.maximum(last, 1e-300), 0.5), 0.5)
            done = (size < TOLERANCE) | (size * rate < 0.1 * TOLERANCE) | \
                ((size < 1e3 * TOLERANCE) & (size > 0.5 * last))
            if done.all():
                rot[rows], t[rows] = r, tt
                return rot, t
            if done.any():
                rot[rows[done]], t[rows[done]] = r[done], tt[done]
                going = ~done
                r, tt, inv, dq, rows, predicted = r[going], tt[going], inv[going], dq[going], rows[going], predicted[going]
                size = size[going]
            last = size
        return None

    def _twists(self, rots, ts, regular: Regular) -> tuple[np.ndarray, np.ndarray]:
        """The twists and their rates at these poses, whose matrices are `regular`."""
        x_v = regular.solve(self._rates(len(rots)))
        return x_v, regular.solve(self._accel_terms(rots, ts, x_v))

    def _near_twists(self, rots, ts, near: Regular, which) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The twists and their rates at poses next to already inverted ones (`near`, row
        `which` for each), without inverting again. With P = S_near⁻¹ and E = I − P S,
        ‖E‖₁ ≤ ‖P‖₁ ‖S_near − S‖₁ = ρ; where ρ < ½, ‖S⁻¹‖₁ ≤ ‖P‖₁ / (1 − ρ) bounds the
        condition number as `_regular` checks it, and P₂ = P (2I − S P) (one Newton–Schulz
        step: I − P₂S = E²) solves S y = b by y ← y + P₂(b − S y), converging as ρ²ᵏ.
        Rows where that cannot be certified are flagged, for `_regular` to decide."""
        scaled, rows = self.scaled_matrix(rots, ts)
        p = near.s_inv[which]
        gap = near.scaled[which]
        np.subtract(scaled, gap, out=gap)
        rho = near.size_inv[which] * norm1(gap, in_place=True)
        cond = (near.size[which] + rho / near.size_inv[which]) * near.size_inv[which] / (1.0 - rho)
        ok = (rho < 0.5) & (cond * self.n < CONDITION)
        q = scaled @ p
        np.negative(q, out=q)
        q.reshape(len(q), -1)[:, ::self.n + 1] += 2.0
        p = p @ q                                        # P (2I − S P)
        y_v, ok_v = refined(scaled, p, rows * self._rates(len(rots)))
        x_v = self._column * y_v
        y_a, ok_a = refined(scaled, p, rows * self._accel_terms(rots, ts, x_v))
        return x_v, self._column * y_a, ok & ok_v & ok_a

    def _regular(self, rot, t) -> Optional[Regular]:
        """The dimensionless S = R A C at these poses inverted, when every S is certainly
        below the engine's condition limit (its exact 1-norm condition number times n bounds
        the 2-norm one), else None."""
        scaled, rows = self.scaled_matrix(rot, t)
        if not np.isfinite(rows).all():
            return None
        try:
            inverse = np.linalg.inv(scaled)
        except np.linalg.LinAlgError:
            return None
        size, size_inv = norm1(scaled), norm1(inverse)
        cond = size * size_inv
        if not (np.isfinite(cond).all() and (cond * self.n < CONDITION).all()):
            return None
        return Regular(scaled, inverse, self._column, rows, size, size_inv)

    def _accel_terms(self, rots, ts, x_v, driven: bool = True) -> np.ndarray:
        """The acceleration system's right side: minus the rows' terms in the velocities
        (with the drivers' accelerations, or none: `driven` False)."""
        n_rows = len(rots)
        v, get = self.vectors(rots, ts), self.vectors.part
        w = np.concatenate([x_v.reshape(n_rows, -1, 6)[:, :, :3], np.zeros((n_rows, 1, 3))], axis=1)
        k = self.coincide
        r = get(v, "pb")
        wb, wa = w[:, k.b], w[:, k.a]
        known = [(cross(wb, cross(wb, r)) - cross(wa, cross(wa, r))).reshape(n_rows, -1)]
        if len(self.perp0):
            tr = self.turn
            w_rel = w[:, tr.b] - w[:, tr.a]
            known.append(dot(w_rel, cross(w[:, tr.a], get(v, "perp"))))
        if len(self.drive_axis0):
            dr = self.drive
            w_rel = w[:, dr.b] - w[:, dr.a]
            known.append(dot(w_rel, cross(w[:, dr.a], get(v, "drive"))) - (self.accels if driven else 0.0))
        if len(self.idle_body):
            known.append(np.zeros((n_rows, len(self.idle_body))))
        return -np.concatenate(known, axis=1)[:, self.keep]


def supported(sweeper: Swept) -> bool:
    """A spatial mechanism of revolute and spherical joints, every driver a revolute's rate."""
    model = sweeper.model
    if model.dimension != 3 or not model.drivers:
        return False
    joints = {j.id: j for j in model.joints}
    return (all(j.kind.pins for j in model.joints)
            and all(d.kind == "joint" and joints[d.driven_joint()].kind.coordinate is Coordinate.ANGLE
                    for d in model.drivers))


def compiled_sweep(sweeper: Swept, plan: Plan):
    """The sweep's `SweepResult` by the compiled path, or None when the general one must run."""
    if not supported(sweeper) or plan.steps < 1:
        return None
    kernel = CompiledNewton(sweeper, plan)
    with np.errstate(all="ignore"):
        out = kernel.sweep(plan.increments)
    if out is None:
        return None
    n_rows = len(plan.increments)
    rots, ts = out["rot"], out["t"]
    x_v = out["x_v"].reshape(n_rows, -1, 6)
    x_a = out["x_a"].reshape(n_rows, -1, 6)
    if not (np.isfinite(x_v).all() and np.isfinite(x_a).all()):
        return None
    index = {b: i for i, b in enumerate(kernel.bodies)}
    zero = np.zeros((n_rows, 3))
    bodies = {}
    for name in sweeper.model.bodies:
        if name not in index:
            bodies[name] = {"angle": zero, "omega": zero, "alpha": zero}
            continue
        i = index[name]
        bodies[name] = {"angle": np.degrees(rotation_vectors(rots[:, i])),
                        "omega": x_v[:, i, :3], "alpha": x_a[:, i, :3]}
    c = kernel.c
    motions = {}
    for name, body, _ in sweeper.motions:
        p0 = np.asarray(sweeper.points[name], dtype=float)
        if body not in index:
            motions[name, body] = (np.broadcast_to(p0, (n_rows, 3)).copy(), zero, zero)
            continue
        i = index[body]
        r = np.einsum("mij,j->mi", rots[:, i], p0 - c) + ts[:, i]        # P − ref, now
        w, v0, al, a0 = x_v[:, i, :3], x_v[:, i, 3:], x_a[:, i, :3], x_a[:, i, 3:]
        motions[name, body] = (r + c, v0 + cross(w, r),
                               a0 + cross(al, r) + cross(w, cross(w, r)))
    ok = np.ones(n_rows, dtype=bool)
    return sweeper.result(plan, ok, bodies, motions, [])
