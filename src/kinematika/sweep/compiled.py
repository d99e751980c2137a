"""The Newton path compiled once per mechanism, for spatial linkages of revolute and spherical
joints driven by a joint's rate (the RSSR, Hooke's joint, the spherical four-bar, robot arms).

The general path (`newton`) assembles one position after the other with the engine's
Python rows. Here the same conditions (`constraints`: points coincide, the relative
rotation stays about the revolute's axis, the driven joint's angle is the increment, no
idle spin of an S–S link) become numpy arrays over every position at once:

- a few coarse positions (about every 8°) are assembled one after the other by Newton's
  method from the tangent at the last one, with the general path's safeguard against a
  jump to another branch (a correction larger than 0.3 of the step taken);
- every other position starts from the tangent at its nearest coarse position and all of
  them are corrected together: stacked (N, n, n) Jacobians and solves;
- velocities and accelerations are then two more stacked solves with the same matrices, the
  acceleration's known terms (centripetal and Coriolis) written as arrays.

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
from typing import TYPE_CHECKING, Optional

import numpy as np

from ..engine.idle import idle_links
from .plan import Plan

if TYPE_CHECKING:
    from .run import Sweeper

COARSE_STEP = 0.15          # rad between coarse positions
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

    def __init__(self, sweeper: "Sweeper", plan: Plan) -> None:
        inst, u = sweeper.inst, sweeper.solver.unknowns
        model = inst.model
        self.bodies = list(u.bodies)
        index = {b: i for i, b in enumerate(self.bodies)}
        at = lambda name: index.get(name, -1)  # noqa: E731  (the frame and fixed bodies: −1)
        self.c = np.asarray(inst.ref, dtype=float)
        self.scale = float(inst.scale)
        self.n = u.n
        geos = sweeper.solver.geos
        points, pa, pb = [], [], []                # coincident points (3 rows each)
        perps, ra, rb = [], [], []                 # turning rows: perpendicular fixed in a
        for j in model.joints:
            g = geos[j.id]
            points.append(np.asarray(g.at, dtype=float))
            pa.append(at(j.a)), pb.append(at(j.b))
            if j.type == "revolute":
                for p in g.perps:
                    perps.append(np.asarray(p, dtype=float))
                    ra.append(at(j.a)), rb.append(at(j.b))
        self.p0 = np.array(points).reshape(-1, 3)
        self.coincide = _Pairs(np.array(pa, dtype=int), np.array(pb, dtype=int))
        self.perp0 = np.array(perps).reshape(-1, 3)
        self.turn = _Pairs(np.array(ra, dtype=int), np.array(rb, dtype=int))
        # the revolutes' own axes (e fixed in b) for the position form of the turning rows
        self.axis_b0 = np.array([np.asarray(geos[j.id].axis, dtype=float)
                                 for j in model.joints if j.type == "revolute"]).reshape(-1, 3)
        axes, da, db, rates, accels, swept = [], [], [], [], [], []
        for d in model.drivers:
            g = geos[d.joint]
            axes.append(np.asarray(g.axis, dtype=float))
            da.append(at(g.joint.a)), db.append(at(g.joint.b))
            rates.append(float(inst.value(d.value, d.where)))
            accels.append(float(inst.value(d.accel, d.where)))
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
        self.translation = np.tile(np.r_[np.zeros(3, bool), np.ones(3, bool)], len(self.bodies))
        self.keep = np.arange(self.m_all)
        self.keep = self._independent_rows()
        self.m = len(self.keep)

    def _independent_rows(self) -> np.ndarray:
        """Rows independent at the drawn pose (a Hooke joint's closure repeats its point
        conditions): kept greedily in order, as long as they add a direction."""
        rot = np.broadcast_to(np.eye(3), (1, len(self.bodies), 3, 3))
        a = self.matrix(rot, np.zeros((1, len(self.bodies), 3)))[0]
        a = a * np.where(self.translation, self.scale, 1.0)
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
    def _full(self, rot: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rotations and translations with the frame appended last (index −1)."""
        m = rot.shape[0]
        rot = np.concatenate([rot, np.broadcast_to(np.eye(3), (m, 1, 3, 3))], axis=1)
        t = np.concatenate([t, np.zeros((m, 1, 3))], axis=1)
        return rot, t

    def _point(self, rot, t, body: np.ndarray, p0: np.ndarray) -> np.ndarray:
        """Where the material points drawn at p0 (K, 3) of `body` (K,) are: (M, K, 3)."""
        return _turned(rot[:, body], p0 - self.c) + self.c + t[:, body]

    def residual(self, rot, t, dq) -> np.ndarray:
        """Φ (M, m): the general path's position constraints, row for row."""
        rot, t = self._full(rot, t)
        k = self.coincide
        gap = self._point(rot, t, k.b, self.p0) - self._point(rot, t, k.a, self.p0)
        parts = [gap.reshape(len(dq), -1)]
        if len(self.perp0):
            tr = self.turn
            e = _turned(rot[:, tr.b], _pair_axes(self.axis_b0))
            p = _turned(rot[:, tr.a], self.perp0)
            dots = _dot(e, p)          # e_b·p1, e_b·p2, ... per revolute
            out = np.empty_like(dots)
            out[:, 0::2], out[:, 1::2] = -dots[:, 1::2], dots[:, 0::2]
            parts.append(out)
        if len(self.drive_axis0):
            dr = self.drive
            e = _turned(rot[:, dr.a], self.drive_axis0)
            rel = rot[:, dr.b] @ rot[:, dr.a].swapaxes(-1, -2)      # R_b R_aᵀ
            target = np.where(self.swept, 1.0, 0.0)[None, :] * dq[:, None]
            back = _exp(-target[..., None] * e)
            parts.append(_dot(_log(back @ rel), e))
        if len(self.idle_body):
            parts.append(np.zeros((len(dq), len(self.idle_body))))
        return np.concatenate(parts, axis=1)[:, self.keep]

    def matrix(self, rot, t) -> np.ndarray:
        """The engine's velocity matrix at these poses (M, m, n): the constraints' Jacobian."""
        m = rot.shape[0]
        rot_f, t_f = self._full(rot, t)
        a = np.zeros((m, self.m_all, self.n + 6))      # the frame's columns, dropped at the end
        col = lambda body: np.where(body < 0, self.n, 6 * body)  # noqa: E731
        k = self.coincide
        p = self._point(rot_f, t_f, k.b, self.p0)      # the joint point, carried by b
        r = p - self.c
        rows = 3 * np.arange(len(k.a))
        for sign, body in ((1.0, k.b), (-1.0, k.a)):
            c0 = col(body)
            for i in range(3):
                # v_P = v0 + ω × r: d/dω of (ω × r)_i, and the identity on v0
                a[:, rows + i, c0 + 3 + i] += sign
                j, l = (i + 1) % 3, (i + 2) % 3
                a[:, rows + i, c0 + j] += sign * r[:, :, l]
                a[:, rows + i, c0 + l] -= sign * r[:, :, j]
        base = 3 * len(k.a)
        if len(self.perp0):
            tr = self.turn
            p = _turned(rot_f[:, tr.a], self.perp0)
            base = _relative_rotation_rows(a, base, tr, p, col)
        if len(self.drive_axis0):
            dr = self.drive
            e = _turned(rot_f[:, dr.a], self.drive_axis0)
            base = _relative_rotation_rows(a, base, dr, e, col)
        for k_, body in enumerate(self.idle_body):
            ab = self._idle_ab(rot_f, t_f, k_)
            for i in range(3):
                a[:, base + k_, 6 * body + i] = ab[:, i]
        return a[:, self.keep, :self.n]

    def _idle_ab(self, rot_f, t_f, k: int) -> np.ndarray:
        (ba, pa), (bb, pb) = self.idle_a[k], self.idle_b[k]
        one = lambda body, p: self._point(rot_f, t_f, np.array([body]), p[None, :])[:, 0]  # noqa: E731
        return one(bb, pb) - one(ba, pa)

    def _driver_rows(self) -> np.ndarray:
        """The drivers' rows among the kept ones."""
        rows = 3 * len(self.p0) + len(self.perp0) + np.arange(len(self.drive_axis0))
        return np.searchsorted(self.keep, rows)

    # the sweep ---------------------------------------------------------------------------
    def sweep(self, increments: np.ndarray) -> Optional[dict]:
        """Every position's poses, twists and their rates; None where the general path must run.

        Coarse rows first, one after the other; then, level by level, the rows between them
        (eight times denser each time) all at once, each from its nearest solved row: its
        tangent as predictor, then chord iterations with that row's inverse matrix.
        """
        drivers = 3 * len(self.p0) + len(self.perp0) + np.arange(len(self.drive_axis0))
        if self.m != self.n or len(self.bodies) == 0 or not np.isin(drivers, self.keep).all():
            return None
        dq = np.asarray(increments, dtype=float)
        n_rows = len(dq)
        step = abs(dq[1] - dq[0]) if n_rows > 1 else 1.0
        stride = max(1, int(COARSE_STEP / step)) if step > 0 else 1
        coarse = np.unique(np.r_[np.arange(0, n_rows, stride), n_rows - 1])
        b = len(self.bodies)
        rots, ts = np.empty((n_rows, b, 3, 3)), np.empty((n_rows, b, 3))
        rots[0], ts[0] = np.eye(3), 0.0
        for k0, k1 in zip(coarse[:-1], coarse[1:]):
            inverse = self._inverse(rots[[k0]], ts[[k0]])
            if inverse is None:
                return None
            done = self._chord(rots[[k0]], ts[[k0]], inverse, self._predictor(rots[[k0]], ts[[k0]], inverse),
                               dq[[k0]], dq[[k1]], newton=True)
            if done is None:
                return None
            rots[k1], ts[k1] = done[0][0], done[1][0]
        solved = coarse
        while stride > 1:
            stride = max(1, stride // 8)
            level = np.setdiff1d(np.arange(0, n_rows, stride), solved)
            if not len(level):
                continue
            right = np.clip(np.searchsorted(solved, level), 1, len(solved) - 1)
            left = solved[right - 1]
            parent = np.where(level - left <= solved[right] - level, left, solved[right])
            for part in range(0, len(level), CHUNK):      # stacked matrices a chunk at a time
                rows, parents = level[part:part + CHUNK], parent[part:part + CHUNK]
                heads, which = np.unique(parents, return_inverse=True)
                inverse = self._inverse(rots[heads], ts[heads])
                if inverse is None:
                    return None
                slope, bend = self._predictor(rots[heads], ts[heads], inverse)
                done = self._chord(rots[parents], ts[parents], inverse[which], (slope[which], bend[which]),
                                   dq[parents], dq[rows])
                if done is None:
                    return None
                rots[rows], ts[rows] = done
            solved = np.union1d(solved, level)
        if len(self.keep) < self.m_all and not self._consistent(rots, ts, dq):
            return None
        return self._motion(rots, ts)

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
        bend = _times(inverse, self._accel_terms(rot, t, slope, driven=False))
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
        rot, t = _stepped(rot, t, step)
        last = np.full(len(dq_to), np.inf)
        active = np.arange(len(dq_to))
        for _ in range(ITERATIONS):
            r, tt = rot[active], t[active]
            phi = self.residual(r, tt, dq_to[active])
            if newton and (last[active] > FROZEN).any():
                current = self._inverse(r, tt)
                if current is None:
                    return None
                inverse = inverse.copy()
                inverse[active] = current
            dx = -_times(inverse[active], phi)
            size = self._size(dx)
            if not np.isfinite(size).all() or (size > JUMP * predicted[active] + 1e-9).any():
                return None
            r, tt = _stepped(r, tt, dx)
            rot[active], t[active] = r, tt
            done = (size < TOLERANCE) | ((size < 1e3 * TOLERANCE) & (size > 0.5 * last[active]))
            last[active] = size
            active = active[~done]
            if not len(active):
                return rot, t
        return None

    def _motion(self, rots, ts) -> Optional[dict]:
        """Twists and their rates at every position, checked as the engine checks a dead
        point: any doubt returns None (the general path decides). A chunk of positions at a
        time, so that the stacked matrices stay small whatever the sweep's length."""
        parts = [self._motion_of(rots[k:k + CHUNK], ts[k:k + CHUNK]) for k in range(0, len(rots), CHUNK)]
        if any(part is None for part in parts):
            return None
        return {"rot": rots, "t": ts, "x_v": np.concatenate([x_v for x_v, _ in parts]),
                "x_a": np.concatenate([x_a for _, x_a in parts])}

    def _motion_of(self, rots, ts) -> Optional[tuple[np.ndarray, np.ndarray]]:
        """The twists and their rates of some positions (see `_motion`)."""
        n_rows = len(rots)
        a = self.matrix(rots, ts)
        regular = self._regular(a)
        if regular is None:
            return None
        inverse, column, rows = regular          # A⁻¹ = C S⁻¹ R
        rhs = np.zeros((n_rows, self.m))
        rhs[:, self._driver_rows()] = self.rates
        x_v = column * _times(inverse, rows * rhs)
        x_a = column * _times(inverse, rows * self._accel_terms(rots, ts, x_v))
        return x_v, x_a

    def _regular(self, a: np.ndarray) -> Optional[tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """The dimensionless S = R A C (rows equilibrated, lengths in the model's scale) of
        every matrix inverted, with C and R's diagonals, when every S is certainly below the
        engine's condition limit (its exact 1-norm condition number times n bounds the 2-norm
        one), else None. A⁻¹ = C S⁻¹ R is applied to vectors, never formed."""
        column = np.where(self.translation, self.scale, 1.0)
        scaled = a * column
        norms = np.abs(scaled).max(axis=2, keepdims=True)
        if (norms == 0).any():
            return None
        scaled /= norms
        try:
            inverse = np.linalg.inv(scaled)
        except np.linalg.LinAlgError:
            return None
        cond = np.abs(scaled).sum(axis=1).max(axis=1) * np.abs(inverse).sum(axis=1).max(axis=1)
        if not (np.isfinite(cond).all() and (cond * self.n < CONDITION).all()):
            return None
        return inverse, column, 1.0 / norms[..., 0]

    def _accel_terms(self, rots, ts, x_v, driven: bool = True) -> np.ndarray:
        """The acceleration system's right side: minus the rows' terms in the velocities
        (with the drivers' accelerations, or none: `driven` False)."""
        n_rows = len(rots)
        rot_f, t_f = self._full(rots, ts)
        w = np.concatenate([x_v.reshape(n_rows, -1, 6)[:, :, :3], np.zeros((n_rows, 1, 3))], axis=1)
        k = self.coincide
        r = self._point(rot_f, t_f, k.b, self.p0) - self.c
        wb, wa = w[:, k.b], w[:, k.a]
        known = [(np.cross(wb, np.cross(wb, r)) - np.cross(wa, np.cross(wa, r))).reshape(n_rows, -1)]
        if len(self.perp0):
            tr = self.turn
            p = _turned(rot_f[:, tr.a], self.perp0)
            w_rel = w[:, tr.b] - w[:, tr.a]
            known.append(_dot(w_rel, np.cross(w[:, tr.a], p)))
        if len(self.drive_axis0):
            dr = self.drive
            e = _turned(rot_f[:, dr.a], self.drive_axis0)
            w_rel = w[:, dr.b] - w[:, dr.a]
            known.append(_dot(w_rel, np.cross(w[:, dr.a], e)) - (self.accels if driven else 0.0))
        if len(self.idle_body):
            known.append(np.zeros((n_rows, len(self.idle_body))))
        return -np.concatenate(known, axis=1)[:, self.keep]


def _relative_rotation_rows(a: np.ndarray, base: int, pairs: _Pairs, e: np.ndarray, col) -> int:
    """Rows (ω_b − ω_a)·e from row `base` on (e: (M, K, 3)); the next free row."""
    rows = base + np.arange(len(pairs.a))
    for sign, body in ((1.0, pairs.b), (-1.0, pairs.a)):
        for i in range(3):
            a[:, rows, col(body) + i] += sign * e[:, :, i]
    return base + len(pairs.a)


def _pair_axes(axes: np.ndarray) -> np.ndarray:
    """Each revolute's axis twice (its two turning rows)."""
    return np.repeat(axes, 2, axis=0)


def _turned(rot: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotations (M, K, 3, 3) applied to fixed vectors (K, 3): (M, K, 3) (matmul, which
    numpy runs several times faster than the same einsum on small matrices)."""
    return (rot @ v[:, :, None])[..., 0]


def _times(a: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Stacked matrix-vector products: (…, i, j) · (…, j) → (…, i)."""
    return (a @ x[..., None])[..., 0]


def _dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return (u * v).sum(axis=-1)


def _exp(w: np.ndarray) -> np.ndarray:
    """Rodrigues on stacked rotation vectors (…, 3) → (…, 3, 3), as `poses.exp_rotation`:
    R = I + (sin θ/θ) W + ((1 − cos θ)/θ²) W², with W² = w wᵀ − θ² I; I + W below 1e-12."""
    sq = (w * w).sum(axis=-1)
    angle = np.sqrt(sq)
    small = angle < 1e-12
    safe = np.where(small, 1.0, angle)
    s = np.where(small, 1.0, np.sin(safe) / safe)
    c = np.where(small, 0.0, (1.0 - np.cos(safe)) / (safe * safe))
    out = (c[..., None, None] * w[..., :, None]) * w[..., None, :]
    diagonal = 1.0 - c * sq
    sw = s[..., None] * w
    for i in range(3):
        j, k = (i + 1) % 3, (i + 2) % 3
        out[..., i, i] += diagonal
        out[..., j, i] += sw[..., k]
        out[..., i, j] -= sw[..., k]
    return out


def _log(r: np.ndarray) -> np.ndarray:
    """Stacked rotation vectors of rotations within a small angle of the identity (the
    driven joint's error): as `poses.log_rotation` there."""
    v = np.stack([r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0], r[..., 1, 0] - r[..., 0, 1]], -1)
    angle = np.arctan2(np.linalg.norm(v, axis=-1) / 2, (np.trace(r, axis1=-2, axis2=-1) - 1) / 2)
    factor = np.where(angle < 1e-6, 0.5, angle / (2 * np.sin(np.where(angle < 1e-6, 1.0, angle))))
    return v * factor[..., None]


def _stepped(rot, t, dx) -> tuple[np.ndarray, np.ndarray]:
    """Poses after a step of the unknowns, as `SpatialPoses.stepped`: R ← exp(δθ) R,
    t ← exp(δθ) t + δ."""
    d = dx.reshape(dx.shape[0], -1, 6)
    step = _exp(d[..., :3])
    return step @ rot, _times(step, t) + d[..., 3:]


def rotation_vectors(rots: np.ndarray) -> np.ndarray:
    """Each row's rotation vector (N, 3), continued from row to row from 0 at row 0, as the
    general path's `_continued` does: the axis kept on one side, the angle unwrapped (a crank
    ends a turn at 2π about its axis, not at 0)."""
    v = np.stack([rots[:, 2, 1] - rots[:, 1, 2], rots[:, 0, 2] - rots[:, 2, 0],
                  rots[:, 1, 0] - rots[:, 0, 1]], -1)
    angle = np.arctan2(np.linalg.norm(v, axis=-1) / 2, (np.trace(rots, axis1=1, axis2=2) - 1) / 2)
    axis = np.zeros_like(v)
    regular = (angle > 1e-6) & (math.pi - angle > 1e-3)
    axis[regular] = v[regular] / np.linalg.norm(v[regular], axis=-1, keepdims=True)
    half = math.pi - angle <= 1e-3
    for i in np.flatnonzero(half):                   # near a half turn (rare): as log_rotation
        bm = (rots[i] + np.eye(3)) / 2
        j = int(np.argmax(np.diag(bm)))
        a = bm[:, j] / math.sqrt(bm[j, j])
        axis[i] = a if a @ v[i] >= 0 else -a
    known = regular | half
    if not known.any():
        return v / 2
    # rows at (nearly) no rotation take the axis of the nearest earlier row (or the first)
    fill = np.maximum.accumulate(np.where(known, np.arange(len(v)), -1))
    axis = axis[np.where(fill < 0, int(np.argmax(known)), fill)]
    flips = np.sign(np.einsum("ki,ki->k", axis[1:], axis[:-1]))
    flips[flips == 0] = 1.0
    sign = np.r_[1.0, np.cumprod(flips)]
    return np.unwrap(sign * angle)[:, None] * (axis * sign[:, None])


def supported(sweeper: "Sweeper") -> bool:
    """A spatial mechanism of revolute and spherical joints, every driver a revolute's rate."""
    model = sweeper.model
    if model.dimension != 3 or not model.drivers:
        return False
    joints = {j.id: j for j in model.joints}
    return (all(j.type in ("revolute", "spherical") for j in model.joints)
            and all(d.kind == "joint" and joints[d.joint].type == "revolute" for d in model.drivers))


def compiled_sweep(sweeper: "Sweeper", plan: Plan):
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
        motions[name, body] = (r + c, v0 + np.cross(w, r),
                               a0 + np.cross(al, r) + np.cross(w, np.cross(w, r)))
    ok = np.ones(n_rows, dtype=bool)
    return sweeper.result(plan, ok, bodies, motions, [])
