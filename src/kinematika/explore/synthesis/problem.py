"""The fast path: a task on a four-bar model, scored in closed form over many designs at once.

A design is the varied parameters' values, plus, when the task leaves it free, where the
first target is met (`--timing JOINT`: START, degrees). Its numbers (`linkage`) give the
closed-form four-bar (`explore.fourbar`), which is asked at the crank angles the targets are
met at: for a timed task φ_i = φ0 + s (START + x_i) (s the joint's sense, x_i the row's
input, degrees → radians); for free timing, the nearest point of the continuous motion to
each target (a grid over the crank's reachable range, then Gauss–Newton steps on the
closed form). Feasibility is exact: the drawn configuration assembles, every timed target
lies in the crank's reachable range (closed-form limit positions), and the requirements
(Grashof's inequalities, the transmission angle's two extremes, the order of the targets'
crank angles along the motion) hold.

`evaluate` scores designs for the search: the objective, and a violation that is zero
exactly when the design is feasible. `residuals` gives one design's weighted residuals and
their analytic Jacobian (the four-bar's derivatives times dW/dp, timing variables
included) with the requirements as penalty rows that vanish on feasible designs, for the
local polish.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ...errors import KinematikaError
from ...model.model import Model
from ..fourbar import CrankRange, FourBar, Pose, crank_range, grashof_gaps, pose, transmission_gaps
from .linkage import Canon, CarriedMap, ModelMap, Roles, carried_map
from .task import Task

TWO_PI = 2 * np.pi
GRID = 96               # samples of the crank's range for the nearest points (search)
FINE = 1440             # … for a design's exact score
STEPS = 3               # Gauss–Newton steps on each nearest point (search)
FINE_STEPS = 30
BIG = 1e6               # violation of a design that cannot be drawn
RHO = 1e4               # weight of a penalty row (per unit of relative violation)
MARGIN = 1e-9           # relative margin the penalties keep from a requirement's boundary


def wrap(x: np.ndarray) -> np.ndarray:
    """An angle difference into (−π, π]."""
    return np.angle(np.exp(1j * x))


@dataclass
class Scores:
    """The search's view of D designs: objective, violation (0: feasible), the crank angles the
    targets are met at (absolute, radians), the output's zero (function: the absolute angle of
    its line, radians) and the timing's START (degrees)."""

    objective: np.ndarray
    violation: np.ndarray
    phi: np.ndarray
    zero: np.ndarray
    start: np.ndarray


class FourBarTask:
    """A task on a four-bar model whose varied parameters are `names` within [low, high]."""

    def __init__(self, model: Model, task: Task, roles: Roles, names: list[str], low: np.ndarray,
                 high: np.ndarray, point: Optional[str]) -> None:
        self.model, self.task, self.roles = model, task, roles
        self.names = list(names)
        self.low, self.high = np.asarray(low, float), np.asarray(high, float)
        self.n = len(self.names)
        self.exact_map = ModelMap(model, roles, self.names, point)
        self.map: ModelMap | CarriedMap = self.exact_map
        if task.kind != "motion":                   # a motion's weight ρ needs every point of the body
            self.map = carried_map(self.exact_map, self.low, self.high) or self.exact_map
        self.sign = roles.sign
        self.sqrtw = np.sqrt(task.weights)
        self.free_start = task.timing is not None and task.timing.start is None
        self.free_zero = task.kind == "function" and task.output_zero == "free"
        self.line = self._line_body()
        self.timed = task.inputs is not None
        self.x = np.radians(task.inputs) if task.inputs is not None else np.zeros(0)    # the inputs, radians

    def _line_body(self) -> str:
        """Function generation: which of the four-bar's angles the output's line follows."""
        if self.task.kind == "motion":
            return "coupler"
        if self.task.kind != "function":
            return ""
        if self.task.body == self.roles.rocker:
            return "rocker"
        if self.task.body == self.roles.coupler:
            return "coupler"
        raise KinematikaError("usage", "output-not-rocker-or-coupler", "--output", output=self.task.body,
                              rocker=self.roles.rocker, coupler=self.roles.coupler)

    # the search's variables ---------------------------------------------------------------
    @property
    def dims(self) -> int:
        """Parameters, and START when free."""
        return self.n + (1 if self.free_start else 0)

    def bounds(self) -> list[tuple[float, float]]:
        """The search box: the parameters' intervals, and a turn for START."""
        out = list(zip(self.low.tolist(), self.high.tolist()))
        return out + [(0.0, 360.0)] if self.free_start else out

    def start_of(self, z: np.ndarray) -> np.ndarray:
        """START (degrees) of designs z (D, dims): free, given, or 0 (no timing)."""
        if self.free_start:
            return z[:, self.n]
        timing = self.task.timing
        value = timing.start if timing is not None and timing.start is not None else 0.0
        return np.full(len(z), float(value))

    # scoring ------------------------------------------------------------------------------
    def evaluate(self, z: np.ndarray, exact: bool = False, phi: Optional[np.ndarray] = None) -> Scores:
        """Score designs z (D, dims); `exact`: through the model's own constructions, the
        nearest points converged (a design's final score). For free timing, `phi` (D, n) are
        crank angles the targets were met at (a polish's, kept in order): each is moved to
        the nearest point of the motion near it instead of the nearest of the whole turn."""
        z = np.atleast_2d(np.asarray(z, dtype=float))
        size = len(z)
        canon = (self.exact_map if exact else self.map).canon(z[:, :self.n])
        with np.errstate(all="ignore"):
            return self._score(z, canon, size, exact, phi)

    def _score(self, z: np.ndarray, canon: Canon, size: int, exact: bool, given: Optional[np.ndarray]) -> Scores:
        fb = four_bar(canon)
        reach = crank_range(fb)
        drawn = np.isfinite(canon.w).all(axis=1) & reach.drawn[:, 0]
        violation = np.where(drawn, 0.0, BIG)
        start = self.start_of(z)
        if self.timed:
            phi = fb.phi0 + self.sign * (np.radians(start)[:, None] + self.x[None, :])
            violation += self._unreachable(reach, phi)
        else:
            phi = self.nearest(fb, canon, reach, exact) if given is None else self.settle(fb, canon, reach, given, exact)
        p, lines = self._at(fb, canon, phi)
        error, zero = self._errors(fb, canon, p, lines)
        violation += self.requirement_violation(fb, reach, phi)
        residual = self.sqrtw * error
        objective = (residual ** 2).sum(axis=1) if self.task.objective == "sse" else np.abs(residual).max(axis=1)
        bad = ~np.isfinite(objective)
        objective = np.where(bad, np.inf, objective)
        violation = np.where(bad & (violation == 0), BIG, violation)
        return Scores(objective, violation, phi, zero, start)

    def _at(self, fb: FourBar, canon: Canon, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The point and the line the task follows at the crank angles `phi`."""
        at, _ = pose(fb, phi)
        return at.p, self._line(at, fb, canon)

    def _line(self, at: Pose, fb: FourBar, canon: Canon) -> np.ndarray:
        if self.line == "rocker":
            return at.theta4(fb.o4) + canon.kappa4[:, None]
        if self.line == "coupler":
            return at.theta3 + canon.kappa3[:, None]
        return np.zeros_like(at.p.real)

    def _errors(self, fb: FourBar, canon: Canon, p: np.ndarray, lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each target's error (length, or degrees for a function) and the output's zero."""
        task = self.task
        size = len(p)
        zero = np.full(size, np.nan)
        if task.kind == "path":
            return np.abs(p - task.xy[None, :]), zero
        if task.kind == "motion":
            turn = wrap(lines - np.radians(task.angle)[None, :])
            return np.hypot(np.abs(p - task.xy[None, :]), canon.rho[:, None] * turn), zero
        y = np.radians(task.angle)[None, :]
        if isinstance(task.output_zero, float):
            zero = np.full(size, np.radians(task.output_zero))
            return np.degrees(np.abs(wrap(lines - zero[:, None] - y))), zero
        at0, _ = pose(fb, fb.phi0)
        drawn = self._line(at0, fb, canon)[:, 0]
        d = wrap(lines - drawn[:, None] - y)
        if task.output_zero == "free":
            d = d[:, :1] + wrap(d - d[:, :1])
            offset = best_offset(d, self.sqrtw, task.objective)
            return np.degrees(np.abs(d - offset[:, None])), drawn + offset
        return np.degrees(np.abs(d)), drawn

    def _unreachable(self, reach: CrankRange, phi: np.ndarray) -> np.ndarray:
        """How many timed targets lie beyond the crank's limit positions."""
        inside = (phi >= reach.low - 1e-12) & (phi <= reach.high + 1e-12)
        return np.where(reach.full[:, 0], 0.0, (~inside).sum(axis=1))

    def requirement_violation(self, fb: FourBar, reach: CrankRange, phi: np.ndarray) -> np.ndarray:
        """The requirements' violations, relative, summed (0 when all hold)."""
        req = self.task.requires
        size = len(phi)
        out = np.zeros(size)
        if req.crank_rocker:
            scale = np.max(fb.lengths(), axis=0)[:, 0]
            out += np.maximum(-grashof_gaps(fb)[:, :, 0], 0).sum(axis=0) / scale
        if req.transmission is not None:
            scale = (2 * fb.r3 * fb.r4)[:, 0]
            out += np.maximum(-transmission_gaps(fb, req.transmission)[:, :, 0], 0).sum(axis=0) / scale
            out += np.where(reach.full[:, 0], 0.0, 1.0)
        if req.ordered and self.task.free_timing:
            out += order_violation(self.sign * phi, reach.full[:, 0]) / TWO_PI
        return out

    # nearest points of the continuous motion -----------------------------------------------
    def nearest(self, fb: FourBar, canon: Canon, reach: CrankRange, exact: bool) -> np.ndarray:
        """For each design and target, the crank angle where the motion passes nearest
        (path: the point; motion: the pose, by the task's distance), on the drawn branch
        within the crank's reachable range."""
        count = FINE if exact else GRID
        full = reach.full[:, 0]
        low = np.where(full, fb.phi0[:, 0], reach.low[:, 0])
        high = np.where(full, fb.phi0[:, 0] + TWO_PI, reach.high[:, 0])
        t = np.linspace(0.0, 1.0, count + 1)[None, :]
        grid = low[:, None] + (high - low)[:, None] * t                   # (D, M)
        p, lines = self._at(fb, canon, grid)
        dist = self._distance2(p[:, None, :], lines[:, None, :], canon)     # (D, n, M)
        dist = np.where(np.isfinite(dist), dist, np.inf)
        k = np.argmin(dist, axis=2)
        phi = np.take_along_axis(np.broadcast_to(grid[:, None, :], dist.shape), k[..., None], 2)[..., 0]
        step = ((high - low) / count)[:, None]
        phi = self._parabola(dist, k, phi, step, count, full)
        return self._converge(fb, canon, phi, low, high, full, exact)

    def settle(self, fb: FourBar, canon: Canon, reach: CrankRange, phi: np.ndarray, exact: bool) -> np.ndarray:
        """Given crank angles moved to the nearest point of the motion near each."""
        full = reach.full[:, 0]
        low = np.where(full, fb.phi0[:, 0], reach.low[:, 0])
        high = np.where(full, fb.phi0[:, 0] + TWO_PI, reach.high[:, 0])
        return self._converge(fb, canon, np.asarray(phi, dtype=float), low, high, full, exact)

    def _converge(self, fb: FourBar, canon: Canon, phi: np.ndarray, low: np.ndarray, high: np.ndarray,
                  full: np.ndarray, exact: bool) -> np.ndarray:
        """Gauss–Newton steps on each nearest point until they settle (or STEPS, in the search)."""
        for _ in range(FINE_STEPS if exact else STEPS):
            new = self._gauss_newton(fb, canon, phi, low, high, full)
            settled = np.all(np.abs(new - phi) <= 1e-15 * (1 + np.abs(phi)))
            phi = new
            if settled:
                break
        return phi

    def _distance2(self, p: np.ndarray, lines: np.ndarray, canon: Canon) -> np.ndarray:
        d = np.abs(p - self.task.xy[None, :, None]) ** 2
        if self.task.kind == "motion":
            turn = wrap(lines - np.radians(self.task.angle)[None, :, None])
            d = d + (canon.rho[:, None, None] * turn) ** 2
        return d

    @staticmethod
    def _parabola(dist: np.ndarray, k: np.ndarray, phi: np.ndarray, step: np.ndarray, count: int,
                  full: np.ndarray) -> np.ndarray:
        """The vertex of the parabola through the nearest sample and its neighbours."""
        m = dist.shape[2]
        km = np.where(full[:, None], (k - 1) % count, np.maximum(k - 1, 0))
        kp = np.where(full[:, None], (k + 1) % count, np.minimum(k + 1, m - 1))
        f0 = np.take_along_axis(dist, k[..., None], 2)[..., 0]
        fm = np.take_along_axis(dist, km[..., None], 2)[..., 0]
        fp = np.take_along_axis(dist, kp[..., None], 2)[..., 0]
        den = fm - 2 * f0 + fp
        off = np.where((den > 0) & np.isfinite(den), 0.5 * (fm - fp) / den, 0.0)
        return phi + np.clip(off, -1.0, 1.0) * step

    def _gauss_newton(self, fb: FourBar, canon: Canon, phi: np.ndarray, low: np.ndarray, high: np.ndarray,
                      full: np.ndarray) -> np.ndarray:
        """One Gauss–Newton step of each nearest point, kept within a limited crank's range."""
        at, tangent = pose(fb, phi, True, only_phi=True)
        assert tangent is not None
        r = at.p - self.task.xy[None, :]
        dp = tangent.p[..., 0]
        num = (np.conj(dp) * r).real
        den = np.abs(dp) ** 2
        if self.task.kind == "motion":
            u = at.b - at.a
            dline = (tangent.b[..., 0] - tangent.a[..., 0]) / u
            turn = wrap(self._line(at, fb, canon) - np.radians(self.task.angle)[None, :])
            rho2 = (canon.rho ** 2)[:, None]
            num = num + rho2 * turn * dline.imag
            den = den + rho2 * dline.imag ** 2
        new = phi - np.clip(np.where(den > 0, num / den, 0.0), -0.05, 0.05)
        new = np.where(full[:, None], new, np.clip(new, low[:, None], high[:, None]))
        better = self._distance2(*self._at_pair(fb, canon, new), canon)[..., 0] <= \
            self._distance2(*self._at_pair(fb, canon, phi), canon)[..., 0]
        return np.where(better & np.isfinite(new), new, phi)

    def _at_pair(self, fb: FourBar, canon: Canon, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        p, lines = self._at(fb, canon, phi)
        return p[..., None], lines[..., None]


def four_bar(canon: Canon) -> FourBar:
    """The closed-form four-bars of the designs' numbers, as (D, 1) columns."""
    w = canon.w
    col = lambda i: w[:, i:i + 1]
    return FourBar(col(0) + 1j * col(1), col(2) + 1j * col(3), col(4), col(5), col(6), col(7) + 1j * col(8),
                   canon.sigma[:, None], col(9))


def order_violation(u: np.ndarray, full: np.ndarray) -> np.ndarray:
    """How far the angles u (D, n), taken along the motion, are from coming in order: for a
    crank that turns, each target's angle from the first's, in [0, 2π) (a later target at the
    first's place counts as 2π: a closed path's last point), must not decrease; for a crank
    with limit positions, the angles themselves (one branch, between the limits)."""
    turn = np.mod(u - u[:, :1], TWO_PI)
    turn[:, 1:] = np.where(turn[:, 1:] < 1e-9, TWO_PI, turn[:, 1:])
    along = np.where(full[:, None], turn, u - u[:, :1])
    return np.maximum(along[:, :-1] - along[:, 1:], 0.0).sum(axis=1)


def best_offset(d: np.ndarray, sqrtw: np.ndarray, objective: str) -> np.ndarray:
    """The constant c minimising Σ w (d − c)² (the weighted mean) or max √w |d − c| (the
    weighted midpoint of the worst pair: c = (√wi di + √wj dj) / (√wi + √wj))."""
    w = sqrtw ** 2
    if objective == "sse":
        return (d * w).sum(axis=1) / w.sum()
    a = sqrtw[:, None]
    b = sqrtw[None, :]
    di, dj = d[:, :, None], d[:, None, :]
    value = np.where(di >= dj, a * b * (di - dj) / (a + b), -np.inf)
    flat = value.reshape(len(d), -1).argmax(axis=1)
    i, j = np.unravel_index(flat, value.shape[1:])
    return (sqrtw[i] * d[np.arange(len(d)), i] + sqrtw[j] * d[np.arange(len(d)), j]) / (sqrtw[i] + sqrtw[j])


