"""The configuration curve followed by pseudo-arclength continuation, through limit positions.

Newton's path steps the driven coordinate q and corrects the poses x (`newton`). At a limit
position that fails: the curve Φ(x, q) = 0 turns back in q there, and no pose exists a step
further. Here q is an unknown like the others: with z = (x, q) scaled to be dimensionless
(rotations in radians, translations over the model's size), the curve's unit tangent t spans
the null space of J = [Φ_x | Φ_q] (Φ_x is the engine's velocity matrix, Φ_q the driver
row's dependence on q). From a point, the predictor goes a distance s along t; the corrector
(Newton's method on Φ = 0 together with tᵀ(z − z₀) = s, a square system even where Φ_x is
singular) brings it back onto the curve (Keller's pseudo-arclength). Where t's q component
changes sign between two points, the curve has passed a limit position: it is located where
that component vanishes (regula falsi on s), and the input runs back from there. A target
coordinate is reached by the same search on q(s), then Newton's method at that q.

Where the curve cannot be followed (the step falls below `MIN_STEP` without converging) the
reason is told apart by J's rank: J of rank < n is a point where branches of the motion
meet (`singular`); otherwise the mechanism cannot be assembled further (`assembly`).
Every loop is bounded by counts (`kinematika.limits.CONTINUATION_STEPS`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from .. import limits as bounds
from ..engine.levels import VelocityLevel
from ..engine.system import InstantSolver
from ..errors import KinematikaError, Said, said_of
from .assembler import Assembler
from .poses import moved_geometry, moved_instant


CORRECTIONS = 8          # Newton iterations of one corrector
SEARCH = 60              # regula-falsi iterations locating a limit position or a target
MIN_STEP = 1e-10         # the smallest continuation step (dimensionless arclength)
RANK = 1e-9              # J's n-th singular value over its largest: below, J has lost rank
RUNAWAY = 1e3            # a body this many model sizes away: the motion runs off to infinity
TOLERANCE = 1e-12        # a converged correction (dimensionless), as `assembler.TOLERANCE`


@dataclass
class Point:
    """An assembled point of the curve: poses, coordinate q (radians or length), the scaled
    Jacobian [Φ_x | Φ_q] (rows equilibrated) and the unit tangent t (scaled)."""

    poses: Any
    q: float
    jac: np.ndarray
    t: np.ndarray
    lost: float                   # J's n-th singular value over its largest (rank: > RANK)
    norms: np.ndarray             # the rows' scales (Φ is divided by them as J's rows are)

    @property
    def dq(self) -> float:
        """The tangent's q component (scaled)."""
        return float(self.t[-1])


class CannotFollow(Exception):
    """The curve cannot be followed from `q`: `kind` singular (branches meet) or assembly."""

    def __init__(self, q: float, kind: str, why: Said) -> None:
        super().__init__(str(why))
        self.q, self.kind, self.why = q, kind, why


class Curve:
    """The configuration curve of one Newton sweep: points, tangents and searches on it."""

    def __init__(self, asm: Assembler, turns: bool) -> None:
        self.asm = asm
        u = asm.unknowns
        size = asm.scale
        self.n = u.n
        self.weights = np.append(np.where(asm.translation, 1.0 / size, 1.0),
                                 1.0 if turns else 1.0 / size)      # z = weights · (x, q)

    # points ------------------------------------------------------------------------------
    def point(self, poses: Any, q: float, like: Optional[np.ndarray] = None) -> Point:
        """The curve's point at the assembled (poses, q), its tangent oriented along `like`."""
        jac, norms = self._jacobian(poses, q)
        _, sing, vt = np.linalg.svd(jac, full_matrices=True)
        t = vt[-1]
        if like is not None and float(t @ like) < 0:
            t = -t
        lost = float(sing[self.n - 1] / sing[0]) if len(sing) >= self.n and sing[0] > 0 else 0.0
        return Point(poses, q, jac, t, lost, norms)

    def _jacobian(self, poses: Any, q: float) -> tuple[np.ndarray, np.ndarray]:
        """[Φ_x | Φ_q] in scaled unknowns, its rows scaled to unit length (and their norms)."""
        asm = self.asm
        delta = 1e-6
        dphi = (asm.residual(poses, q + delta) - asm.residual(poses, q)) / delta   # linear in q
        jac = np.column_stack([_matrix(asm, poses), dphi]) / self.weights
        norms = np.linalg.norm(jac, axis=1)
        norms[norms == 0] = 1.0
        return jac / norms[:, None], norms

    def step(self, base: Point, s: float) -> Optional[Point]:
        """The point a distance s along `base`'s tangent, corrected onto the curve on the
        hyperplane tᵀ(z − z_base) = s by chord iterations with `base`'s matrix (the poses
        between are not assembled: the joints' geometry is not checked there); None if the
        corrector does not converge."""
        t = base.t
        rows = np.vstack([base.jac, t])
        poses, q = self._moved(base.poses, base.q, s * t)
        moved = s * t                              # z − z_base so far (to first order)
        first, last = None, math.inf
        for _ in range(CORRECTIONS):
            r = self.asm.residual(poses, q) / base.norms
            rhs = np.append(-r, s - float(t @ moved))
            dz = np.linalg.lstsq(rows, rhs, rcond=None)[0]
            size = float(np.abs(dz).max(initial=0.0))
            if not math.isfinite(size) or size > 2 * last + 1e-9:
                return None
            if first is None:
                first = size
            elif size > 0.5 * max(first, abs(s)) + 1e-9:
                return None
            poses, q = self._moved(poses, q, dz)
            moved = moved + dz
            if size < TOLERANCE or (size < 1e3 * TOLERANCE and size > 0.5 * last):
                self.asm.keep_aux(poses)
                try:
                    return self.point(poses, q, t)
                except CannotFollow:
                    return None
            last = size
        return None

    def _moved(self, poses: Any, q: float, dz: np.ndarray) -> tuple[Any, float]:
        dx = dz / self.weights
        return poses.stepped(dx[:-1], self.asm.unknowns), q + float(dx[-1])

    def at(self, near: Point, q: float) -> Any:
        """Chord iterations at the fixed coordinate q from the point `near` (least squares
        where Φ_x is nearly singular); the poses, or None."""
        poses, last = near.poses, math.inf
        matrix = near.jac[:, :-1]
        for _ in range(4 * CORRECTIONS):
            r = self.asm.residual(poses, q) / near.norms
            dz = np.linalg.lstsq(matrix, -r, rcond=None)[0]
            size = float(np.abs(dz).max(initial=0.0))
            if not math.isfinite(size) or size > 2 * last + 1e-9:
                return None
            poses = poses.stepped(dz / self.weights[:-1], self.asm.unknowns)
            if size < TOLERANCE or (size < 1e3 * TOLERANCE and size > 0.5 * last):
                self.asm.keep_aux(poses)
                return poses
            last = size
        return None

    # searches ----------------------------------------------------------------------------
    def search(self, base: Point, ends: tuple[tuple[float, Point], tuple[float, Point]],
               value: Callable[[Point], float]) -> tuple[Point, float]:
        """The point (and its s) between two points at s0 < s1 along `base`'s tangent where
        value(point) = 0, its values at the ends of opposite signs (regula falsi, Illinois)."""
        (lo, p_lo), (hi, p_hi) = ends
        f_lo, f_hi = value(p_lo), value(p_hi)
        best, at = (p_lo, lo) if abs(f_lo) <= abs(f_hi) else (p_hi, hi)
        side = 0
        for _ in range(SEARCH):
            if f_lo == 0 or f_hi == 0 or hi - lo <= 1e-16 * max(1.0, abs(hi)):
                break
            s = hi - f_hi * (hi - lo) / (f_hi - f_lo)
            if not lo < s < hi:
                s = 0.5 * (lo + hi)
            p = self.step(base, s)
            if p is None:
                raise CannotFollow(base.q, "assembly", Said("follow-not-corrected"))
            f = value(p)
            best, at = p, s
            if abs(f) < 1e-15:
                break
            if (f > 0) == (f_hi > 0):
                hi, f_hi = s, f
                if side == 1:
                    f_lo *= 0.5
                side = 1
            else:
                lo, f_lo = s, f
                if side == -1:
                    f_hi *= 0.5
                side = -1
        return best, at


@dataclass
class Passage:
    """Where a stretch of travel along the curve ends: poses at coordinate q, the direction
    d in which q runs there, and the limit positions passed [(q*, travel from the start)]."""

    poses: Any
    q: float
    d: float
    limits: list[tuple[float, float]]


def advance(asm: Assembler, poses: Any, q: float, d: float, travel: float, step: float,
            turns: bool) -> Passage:
    """From the assembled `poses` at q, follow the curve with q running in direction d
    (±1) until q has travelled `travel` (radians or length) in all, turning back at every
    limit position met. `step` is a row's travel (the largest continuation step, unscaled).
    Raises `CannotFollow` where the curve cannot be followed."""
    curve = Curve(asm, turns)
    here = curve.point(poses, q)
    if here.dq * d < 0:
        here.t = -here.t
    if abs(here.dq) < 1e-14:
        raise CannotFollow(q, "singular", Said("follow-starts-at-limit"))
    top = max(step * float(curve.weights[-1]), 1e-6)
    s = top / 4
    done = 0.0
    passed: list[tuple[float, float]] = []
    for _ in range(bounds.CONTINUATION_STEPS):
        new = curve.step(here, s)
        if new is None or float(new.t @ here.t) < 0.9:
            s /= 2
            if s < MIN_STEP:
                raise _stuck(here)
            continue
        start, end = (0.0, here), (s, new)
        if new.dq * here.dq < 0:                  # a limit position between here and there
            fold, at = curve.search(here, (start, end), lambda p: p.dq)
            if fold.lost < RANK:
                raise CannotFollow(fold.q, "singular", Said("follow-branches-meet"))
            piece = abs(fold.q - here.q)
            if done + piece >= travel:
                return _land(curve, here, start, (at, fold), here.q + d * (travel - done), d, passed)
            done += piece
            passed.append((fold.q, done))
            d = -d
            start = (at, fold)
        piece = abs(new.q - start[1].q)
        if done + piece >= travel:
            return _land(curve, here, start, end, start[1].q + d * (travel - done), d, passed)
        done += piece
        here = new
        far = _distance(asm, here.poses)
        if far > RUNAWAY:
            raise CannotFollow(here.q, "assembly", Said("follow-runs-off"))
        s = min(2 * s, top * max(1.0, 4 * far))     # far away, the curve is nearly straight
    raise CannotFollow(here.q, "assembly", Said("follow-too-many-steps",
                                                                 limit=bounds.CONTINUATION_STEPS))


def _land(curve: Curve, base: Point, start: tuple[float, Point], end: tuple[float, Point],
          target: float, d: float, passed: list[tuple[float, float]]) -> Passage:
    """The poses at coordinate `target`, which lies between two points of a stretch where q
    is monotone (at s0 < s1 along `base`'s tangent)."""
    f0, f1 = start[1].q - target, end[1].q - target
    if f0 * f1 >= 0:
        near = start[1] if abs(f0) <= abs(f1) else end[1]
    else:
        near, _ = curve.search(base, (start, end), lambda p: p.q - target)
    poses = curve.at(near, target)
    if poses is None:
        raise CannotFollow(target, "assembly", Said("follow-not-assembled"))
    return Passage(poses, target, d, passed)


def _distance(asm: Assembler, poses: Any) -> float:
    """How far the bodies have gone from the drawing, in model sizes (their reference
    point's displacement)."""
    ref = tuple(float(c) for c in asm.base.ref)
    far = max((math.dist(poses.point(b, ref), ref) for b in asm.unknowns.offset), default=0.0)
    return far / asm.scale


def _stuck(here: Point) -> CannotFollow:
    if here.lost < RANK:
        return CannotFollow(here.q, "singular", Said("follow-branches-meet"))
    return CannotFollow(here.q, "assembly", Said("follow-stuck"))


def _matrix(asm: Assembler, poses: Any) -> np.ndarray:
    """The engine's velocity matrix at `poses` (the constraints' Jacobian in pose
    coordinates), without its analysis (which refuses a dead point)."""
    inst = moved_instant(asm.base, poses, asm.owners)
    try:
        geos = {jid: moved_geometry(g, poses, inst) for jid, g in asm.base_geos.items()}
        solver = InstantSolver(inst, geos)
        rows = solver.rows(VelocityLevel(solver.unknowns, inst.ref))
    except KinematikaError as err:
        raise CannotFollow(math.nan, "assembly", said_of(err)) from None
    a, _ = solver.matrix(rows)
    return np.array([[inst.num(c) for c in row] for row in a], dtype=float).reshape(len(a), solver.unknowns.n)
