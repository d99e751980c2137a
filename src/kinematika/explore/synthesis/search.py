"""The global search: differential evolution over whole generations at once, restarted,
each run's best designs polished and kept.

scipy's `differential_evolution` proposes a generation; the closed-form four-bar scores it
in one call (`FourBarTask.evaluate`: thousands of designs a second). A design that breaks
a requirement scores PENALTY·(1 + violation), so any feasible design beats any infeasible
one and the less infeasible of two wins (Deb's rules as one number); the violation is
zero exactly on feasible designs. A run stops when its population has converged or its
best has not improved for STALL generations; its best distinct designs are polished
(`polish`) and kept, and a new run starts from a new Latin hypercube population (another seed),
until the budget — generations in all, or the user's `--seconds` — is spent.

Where the model states the four-bar by its pivots, lengths and coupler point (`linkage.
CarriedMap`) and the task is a path whose first target is free, the search runs over the
coupler curve's *shape* instead (`Shapes`): the four-bar with its crank 1 and its ground
along x from the origin — the other lengths' ratios, the coupler point, the targets'
crank angles — and places each shape on the targets by the similarity (translation,
rotation, scale: a complex a z + b) that fits them best, in closed form (weighted linear
least squares). Nine dimensions of the search become four exact ones; the placed design's
parameters are read back through the map and checked against their intervals.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable, Optional

import numpy as np

from ..fourbar import FourBar, crank_range, grashof_gaps, pose, transmission_gaps
from .linkage import CarriedMap
from .problem import TWO_PI, FourBarTask, Scores

PENALTY = 1e9
STALL = 40              # generations without improving the best by IMPROVED that end a run
IMPROVED = 1e-2
ALONG = 40              # a run's best designs are polished every ALONG generations
LONGEST = 150           # generations of a run at most (the polish finishes what a run finds)
SPREAD = 8              # designs per generation, per variable searched, at least
POLISHED = 8            # a run's designs polished together on the way
ENDED = 32              # … and when it ends
FINAL = 400             # residual evaluations of the best designs' last polish
FINISHED = 4            # the best designs polished last
RESERVE = 0.1           # the share of the user's seconds kept for the last polish (5 s at most)
DISTINCT = 0.02         # designs written are this fraction of the intervals apart


@dataclass
class Budget:
    """How long to search: `generations` in all (None: no limit but the time), `seconds` of
    wall time (None: no limit but the generations), `population` designs a generation."""

    generations: Optional[int]
    seconds: Optional[float]
    population: int
    started: float = field(default_factory=time.perf_counter)
    spent: int = 0                  # generations so far
    evaluated: int = 0              # designs scored

    def left(self) -> bool:
        """Whether the search may go on (the last polish's reserve of the seconds kept)."""
        if self.generations is not None and self.spent >= self.generations:
            return False
        if self.seconds is None or self.spent == 0:             # a time budget runs a generation at least
            return True
        return time.perf_counter() - self.started < self.seconds - min(RESERVE * self.seconds, 5.0)

    def remaining(self) -> int:
        """Generations the next run may take."""
        return (self.generations - self.spent) if self.generations is not None else 10 ** 9


@dataclass
class Found:
    """A design the search kept: its search vector, its score, whether that score is exact, and
    for free timing the crank angles the targets are met at."""

    z: np.ndarray
    objective: float
    exact: bool = False
    phi: Optional[np.ndarray] = None


class Archive:
    """The feasible designs found and polished, each with its score: exact (through the model's
    constructions, the nearest points converged) for the designs polished to the end."""

    def __init__(self, fbt: FourBarTask) -> None:
        self.fbt = fbt
        self.found: list[Found] = []
        self.history: list[tuple[float, float]] = []        # (seconds, best) as it improves
        self.exact = False                                  # an exactly scored design is kept

    def add(self, z: np.ndarray, started: float, phi: Optional[np.ndarray] = None, exact: bool = False) -> None:
        """Score designs z (K, dims) (free timing: near the crank angles `phi`, when given) and
        keep the feasible ones."""
        z = np.atleast_2d(z)
        s = self.fbt.evaluate(z, exact=exact, phi=None if phi is None else np.atleast_2d(phi))
        timed = not self.fbt.task.free_timing
        for i in np.flatnonzero((s.violation <= 0) & np.isfinite(s.objective)):
            value = float(s.objective[i])
            if value < self.best_value():
                self.history.append((time.perf_counter() - started, value))
            self.found.append(Found(np.array(z[i], dtype=float), value, exact, None if timed else s.phi[i].copy()))
            self.exact |= exact

    def best_value(self) -> float:
        """The best objective kept (inf before any)."""
        return min((f.objective for f in self.found), default=math.inf)

    def best(self, count: int, exact: bool = False) -> list[Found]:
        """The best designs (`exact`: of those scored exactly), each at least DISTINCT of the
        intervals from the better ones."""
        lo, hi = np.array(self.fbt.bounds()).T
        span = np.maximum(hi - lo, 1e-300)
        out: list[Found] = []
        for f in sorted(self.found, key=lambda f: f.objective):
            if exact and not f.exact:
                continue
            if all(np.max(np.abs(f.z - g.z) / span) > DISTINCT for g in out):
                out.append(f)
            if len(out) == count:
                break
        return out


def energy(s: Scores) -> np.ndarray:
    """One number per design for the evolution: the objective if feasible, else PENALTY·(1 +
    violation)."""
    return np.where(s.violation > 0, PENALTY * (1.0 + np.minimum(s.violation, 1e6)), s.objective)


class Space:
    """What a run searches: a box, and how its points become designs (search vectors) with
    their scores."""

    def bounds(self) -> list[tuple[float, float]]:
        """The box searched: (low, high) per variable."""
        raise NotImplementedError

    def score(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]:
        """Energies (D,) and designs (D, dims) of the points y (D, k), and for free timing the
        crank angles the targets are met at (None: the nearest points)."""
        raise NotImplementedError


class Parameters(Space):
    """The parameters themselves (and START when free)."""

    def __init__(self, fbt: FourBarTask) -> None:
        self.fbt = fbt

    def bounds(self) -> list[tuple[float, float]]:
        """The parameters' intervals (and a turn for START)."""
        return self.fbt.bounds()

    def score(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]:
        """The designs' energies; the points are the designs; the nearest points their timing."""
        return energy(self.fbt.evaluate(y)), y, None


def run(fbt: FourBarTask, budget: Budget, seed: int, starts: list[np.ndarray],
        progress: Optional[Callable[[float], None]] = None) -> Archive:
    """Search until the budget is spent; the archive of polished designs."""
    archive = Archive(fbt)
    spaces: list[Space] = [Parameters(fbt)]
    shapes = Shapes.of(fbt)
    if shapes is not None:
        spaces = [shapes, Parameters(fbt)]
    for z in starts:
        _finish(archive, fbt, Found(z, math.inf), budget)
    attempt = 0
    while budget.left():
        space = spaces[0] if attempt % 4 != 3 else spaces[-1]
        along = lambda z, phi: _polish_many(archive, fbt, z, phi, budget)
        run_seed = int(np.random.SeedSequence([seed, attempt]).generate_state(1)[0])   # runs of seeds never overlap
        best = _evolve(space, budget, run_seed, starts if attempt == 0 else [], along)
        if best is not None:
            _polish_many(archive, fbt, best[0], best[1], budget)
        if progress is not None:
            progress(archive.best_value())
        attempt += 1
    for found in archive.best(FINISHED):
        if budget.seconds is not None and time.perf_counter() - budget.started > budget.seconds and archive.exact:
            break
        _finish(archive, fbt, found, budget)
    return archive


def _polish_many(archive: Archive, fbt: FourBarTask, z: np.ndarray, phi: Optional[np.ndarray],
                 budget: Budget) -> None:
    """Designs z (K, dims) polished together (`polish.batch_lm`) and kept with them; `phi`
    the free timing's crank angles they were found with (None: the nearest points)."""
    from .polish import batch_lm

    z = np.atleast_2d(z)
    s = fbt.evaluate(z, phi=phi)
    keep = np.isfinite(s.objective) | (s.violation < 1e6)
    if not keep.any():
        return
    archive.add(z[keep], budget.started, None if phi is None else s.phi[keep])
    polished, angles = batch_lm(fbt, z[keep], _take(s, keep))
    archive.add(polished, budget.started, angles)


def _finish(archive: Archive, fbt: FourBarTask, found: Found, budget: Budget) -> None:
    """A design polished to the end (scipy's least squares) and scored exactly, as is the
    design it started from."""
    from .polish import polish

    archive.add(found.z, budget.started, found.phi, exact=True)
    s = fbt.evaluate(found.z[None, :], phi=None if found.phi is None else found.phi[None, :])
    if not np.isfinite(s.objective[0]) and s.violation[0] >= 1e6:
        return
    polished = polish(fbt, found.z, s, 0, FINAL)
    if polished is not None:
        archive.add(polished[0], budget.started, polished[1], exact=True)


def _take(s: Scores, index) -> Scores:
    return Scores(s.objective[index], s.violation[index], s.phi[index], s.zero[index], s.start[index])


def _evolve(space: Space, budget: Budget, seed: int, starts: list[np.ndarray],
            along: Callable) -> Optional[tuple[np.ndarray, Optional[np.ndarray]]]:
    """One run of differential evolution; its best distinct designs (search vectors, and the
    crank angles a shape search met the targets at). The run's best distinct designs are
    polished on the way (`along`), every ALONG generations."""
    from scipy.optimize import differential_evolution

    bounds = space.bounds()
    k = len(bounds)
    size = max(5, math.ceil(budget.population / k), SPREAD if isinstance(space, Shapes) else 0)
    record = {"best": math.inf, "since": 0, "age": 0}

    def cost(y: np.ndarray) -> np.ndarray:
        e, _, _ = space.score(y.T)
        budget.evaluated += len(e)
        return e

    def callback(intermediate_result) -> bool:          # scipy passes the result by this name
        budget.spent += 1
        record["age"] += 1
        fun = float(intermediate_result.fun)
        if record["age"] % ALONG == 0 and fun < PENALTY:
            chosen = _distinct(np.asarray(intermediate_result.population),
                               np.asarray(intermediate_result.population_energies), bounds)
            if chosen is not None:
                _, z, phi = space.score(chosen)
                along(z, phi)
        if fun < record["best"] * (1 - IMPROVED) - 1e-300:
            record["best"], record["since"] = fun, 0
        else:
            record["since"] += 1
        return record["since"] >= STALL or not budget.left()

    init = _initial(bounds, size * k, seed, starts, space)
    result = differential_evolution(cost, bounds, popsize=size, maxiter=max(1, min(budget.remaining(), LONGEST)), seed=seed,
                                    tol=1e-10, atol=0.0, polish=False, vectorized=True, updating="deferred",
                                    init=init, callback=callback, mutation=(0.5, 1.0), recombination=0.9)
    chosen = _distinct(np.asarray(result.population), np.asarray(result.population_energies), bounds, ENDED)
    if chosen is None:
        return None
    _, z, phi = space.score(chosen)
    return z, phi


def _distinct(population: np.ndarray, energies: np.ndarray, bounds: list[tuple[float, float]],
              count: int = 0) -> Optional[np.ndarray]:
    """The best feasible points of a population (POLISHED of them, or `count`), each 5 % of
    the box from the better ones."""
    order = np.argsort(energies, kind="stable")
    lo, hi = np.array(bounds).T
    span = np.maximum(hi - lo, 1e-300)
    chosen: list[int] = []
    for i in order:
        if energies[i] >= PENALTY:
            break
        if all(np.max(np.abs(population[i] - population[j]) / span) > 0.05 for j in chosen):
            chosen.append(int(i))
        if len(chosen) == (count or POLISHED):
            break
    return population[chosen] if chosen else None


def _initial(bounds: list[tuple[float, float]], count: int, seed: int, starts: list[np.ndarray],
             space: Space) -> np.ndarray:
    """A Latin hypercube population in the box (each variable's range cut in `count` equal
    slices, one design in each), the starts first (parameter space only)."""
    lo, hi = np.array(bounds).T
    count = max(count, 5)
    rng = np.random.default_rng(seed)
    slices = np.argsort(rng.random((count, len(bounds))), axis=0)
    points = (slices + rng.random((count, len(bounds)))) / count
    population = lo + points * (hi - lo)
    if isinstance(space, Parameters):
        for i, z in enumerate(starts[:count // 2]):
            population[i] = np.clip(z, lo, hi)
    return population


class Shapes(Space):
    """The coupler curve's shape, placed on the targets by the best similarity (see the
    module's docstring). The point y: log(r1/r2), log(r3/r2), log(r4/r2), log(|c|/r2), arg c,
    then the first target's crank angle and, for free timing, the targets' spacing."""

    SPAN = 1e3              # the largest ratio of two lengths searched

    def __init__(self, fbt: FourBarTask) -> None:
        assert isinstance(fbt.map, CarriedMap)
        self.fbt = fbt
        self.map: CarriedMap = fbt.map
        self.u_lo, self.u_hi = self.map.coordinate_bounds(fbt.low, fbt.high)
        self.ordered = fbt.task.requires.ordered and fbt.task.free_timing
        self.count = fbt.task.count

    @classmethod
    def of(cls, fbt: FourBarTask) -> Optional["Shapes"]:
        """The shape search, when the model's map is in closed form, carries all nine numbers
        of the four-bar, and the task is a path whose first target is free."""
        m = fbt.map
        if not isinstance(m, CarriedMap) or fbt.task.kind != "path":
            return None
        if not all(c.param is not None for c in m.coordinates[:9]):
            return None
        if fbt.task.timing is not None and fbt.task.timing.start is not None:
            return None
        return cls(fbt)

    def bounds(self) -> list[tuple[float, float]]:
        """Length ratios to the crank from 1/SPAN (1 for a crank-rocker) to what the intervals
        allow (SPAN at most), the coupler point's size likewise and its angle, the first
        target's crank angle, and the targets' spacing."""
        lo, hi = self.u_lo, self.u_hi
        small = 1.0 / self.SPAN
        crank = max(lo[4], hi[4] * small, 1e-300)
        floor = 0.0 if self.fbt.task.requires.crank_rocker else math.log(small)

        def top(length: float) -> float:
            return math.log(min(max(length / crank, 1.0), self.SPAN))

        ground = hi[2] if self.map.polar else math.hypot(max(abs(lo[2] - hi[0]), abs(hi[2] - lo[0])),
                                                         max(abs(lo[3] - hi[1]), abs(hi[3] - lo[1])))
        coupler_point = math.hypot(max(abs(lo[7]), abs(hi[7])), max(abs(lo[8]), abs(hi[8])))
        out = [(floor, top(ground)), (floor, top(hi[5])), (floor, top(hi[6])),
               (math.log(small), top(coupler_point)), (0.0, TWO_PI), (0.0, TWO_PI)]
        if self.fbt.task.free_timing:
            out += [(0.0, 1.0)] * self.count if self.ordered else [(0.0, TWO_PI)] * (self.count - 1)
        return [(a, b if b > a else a + 1e-9) for a, b in out]

    def angles(self, y: np.ndarray) -> np.ndarray:
        """The targets' crank angles in the shape's frame (D, n)."""
        first = y[:, 5:6]
        s = self.fbt.sign
        task = self.fbt.task
        if not task.free_timing:
            return first + s * self.fbt.x[None, :]
        if self.ordered:
            g = y[:, 6:] + 1e-12
            steps = TWO_PI * np.cumsum(g, axis=1) / g.sum(axis=1, keepdims=True)
            return first + s * np.concatenate([np.zeros((len(y), 1)), steps[:, :self.count - 1]], axis=1)
        return np.concatenate([first, y[:, 6:]], axis=1)

    def score(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]:
        """Each shape placed on the targets by its best similarity: its energy, the placed
        design's parameters, and the crank angles it meets the targets at."""
        fbt, task = self.fbt, self.fbt.task
        size = len(y)
        with np.errstate(all="ignore"):
            r1, r3, r4, cm = (np.exp(y[:, k:k + 1]) for k in range(4))
            c = cm * np.exp(1j * y[:, 4:5])
            shape = FourBar(np.zeros((size, 1), complex), r1 + 0j, np.ones((size, 1)), r3, r4, c,
                            self.map.sigma, np.zeros((size, 1)))
            phi = self.angles(y)
            p = pose(shape, phi)[0].p
            w = task.weights[None, :]
            pm = (w * p).sum(axis=1, keepdims=True) / w.sum()
            tm = (w * task.xy[None, :]).sum(axis=1, keepdims=True) / w.sum()
            pc, tc = p - pm, task.xy[None, :] - tm
            a = (w * np.conj(pc) * tc).sum(axis=1) / (w * np.abs(pc) ** 2).sum(axis=1)
            a = a / np.abs(a) * self._scale(np.abs(a), shape)      # the best scale the intervals allow
            b = tm[:, 0] - a * pm[:, 0]
            residual = fbt.sqrtw[None, :] * np.abs(a[:, None] * p + b[:, None] - task.xy[None, :])
            objective = (residual ** 2).sum(axis=1) if task.objective == "sse" else residual.max(axis=1)
            z, violation = self._design(y, shape, a, b, phi)
        objective = np.where(np.isfinite(objective), objective, np.inf)
        violation = np.where(np.isfinite(objective), violation, PENALTY)
        return np.where(violation > 0, PENALTY * (1.0 + np.minimum(violation, 1e6)), objective), z, \
            phi + np.angle(a)[:, None]

    def _scale(self, best: np.ndarray, shape: FourBar) -> np.ndarray:
        """The similarity's scale nearest the best fit's that keeps the placed lengths and
        coupler point in their intervals (the best fit's where none does)."""
        lo, hi = self.u_lo, self.u_hi
        ones = np.ones_like(best)
        pairs = [(4, ones), (5, shape.r3[:, 0]), (6, shape.r4[:, 0]), (7, shape.c[:, 0].real), (8, shape.c[:, 0].imag)]
        if self.map.polar:
            pairs.append((2, shape.r1[:, 0].real))
        low, high = np.zeros_like(best), np.full_like(best, np.inf)
        with np.errstate(divide="ignore", invalid="ignore"):
            for k, v in pairs:
                a, b = lo[k] / v, hi[k] / v
                low = np.maximum(low, np.where(v > 0, a, np.where(v < 0, b, 0.0)))
                high = np.minimum(high, np.where(v > 0, b, np.where(v < 0, a, np.inf)))
        return np.where(low <= high, np.clip(best, low, high), best)

    def _design(self, y, shape: FourBar, a, b, phi) -> tuple[np.ndarray, np.ndarray]:
        """The placed designs' search vectors, and their violations (intervals, requirements,
        targets beyond a limited crank's range)."""
        fbt, m = self.fbt, self.map
        size = len(y)
        scale, turn = np.abs(a), np.angle(a)
        o2, o4 = b, b + a * shape.r1[:, 0]
        u = np.zeros((size, 10))
        u[:, 0], u[:, 1] = o2.real, o2.imag
        if m.polar:
            u[:, 2] = np.abs(o4 - o2)
            u[:, 3] = self.u_lo[3] + np.mod(turn - self.u_lo[3], TWO_PI)       # the ground's angle in its turn
        else:
            u[:, 2], u[:, 3] = o4.real, o4.imag
        u[:, 4] = scale
        u[:, 5], u[:, 6] = scale * shape.r3[:, 0], scale * shape.r4[:, 0]
        u[:, 7], u[:, 8] = scale * shape.c[:, 0].real, scale * shape.c[:, 0].imag
        phi1 = phi[:, 0] + turn                                     # the first target's crank angle
        theta0 = turn
        crank0 = m.coordinates[9]
        drawn: np.ndarray
        if crank0.param is None:
            drawn = crank0.offset + (theta0 if m.relative else np.zeros(size))
            u[:, 9] = crank0.offset
        else:
            wanted = phi1 - (theta0 if m.relative else 0.0)
            lo9, hi9 = self.u_lo[9], self.u_hi[9]
            wanted = lo9 + np.mod(wanted - lo9, TWO_PI)
            u[:, 9] = np.clip(wanted, lo9, hi9)
            drawn = u[:, 9] + (theta0 if m.relative else 0.0)
        violation = self._outside(u)
        placed = FourBar(o2[:, None], o4[:, None], u[:, 4:5], u[:, 5:6], u[:, 6:7], (u[:, 7] + 1j * u[:, 8])[:, None],
                         m.sigma, (np.asarray(drawn, dtype=float) * np.ones(size))[:, None])
        violation += self._requirements(placed, phi + turn[:, None])
        params = m.parameters(u)
        params = np.where(np.isnan(params), 0.5 * (fbt.low + fbt.high), params)
        params = np.clip(params, fbt.low, fbt.high)
        if fbt.free_start:
            start = np.degrees(fbt.sign * (phi1 - placed.phi0[:, 0]))
            params = np.concatenate([params, np.mod(start, 360.0)[:, None]], axis=1)
        return params, violation

    def _outside(self, u: np.ndarray) -> np.ndarray:
        """How far the coordinates lie outside their intervals (relative to the intervals'
        size; the ground's angle on the circle)."""
        lo, hi = self.u_lo[:9], self.u_hi[:9]
        v = u[:, :9]
        scale = np.maximum(np.maximum(np.abs(lo), np.abs(hi)), 1e-12)
        over = np.maximum(lo - v, 0.0) + np.maximum(v - hi, 0.0)
        return (over / scale).sum(axis=1)

    def _requirements(self, fb: FourBar, phi: np.ndarray) -> np.ndarray:
        """Requirements, and the targets' crank angles on the drawn configuration's branch
        between a limited crank's limit positions."""
        req = self.fbt.task.requires
        out = np.zeros(len(phi))
        if req.crank_rocker:
            scale = np.max(fb.lengths(), axis=0)[:, 0]
            out += np.maximum(-grashof_gaps(fb)[:, :, 0], 0).sum(axis=0) / scale
        reach = crank_range(fb)
        full = reach.full[:, 0]
        if req.transmission is not None:
            scale = (2 * fb.r3 * fb.r4)[:, 0]
            out += np.maximum(-transmission_gaps(fb, req.transmission)[:, :, 0], 0).sum(axis=0) / scale
            out += np.where(full, 0.0, 1.0)
        low = reach.low
        inside = np.mod(phi - low, TWO_PI) <= (reach.high - low) + 1e-12
        limited = ~full & reach.drawn[:, 0]
        out += np.where(full, 0.0, np.where(limited, (~inside).sum(axis=1), 1.0))
        return out
