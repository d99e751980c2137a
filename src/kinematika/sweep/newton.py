"""The general path: assemble each position by Newton's method, continuing from the last one.

From an assembled position, the next increment of the swept coordinate is reached by
iterating x ← x − A⁺ Φ(x) with A the engine's velocity matrix at the last position (the
Jacobian of the constraints Φ in pose coordinates, see `poses`): its first iterate is the
tangent predictor, the next ones correct. If that does not converge, or the correction is
large next to the prediction (the sign of a jump to another branch), the increment is
split in halves, down to 1/1024 of it; failing that the position cannot be assembled.
Each assembled position is then solved by the engine (velocities and accelerations), and
that solution's matrix is the Jacobian for the next increment.
"""
from __future__ import annotations

import math
from typing import Any, Callable, Optional

import numpy as np

from ..engine.motion import Motion
from ..engine.system import InstantSolver
from ..errors import KinematikaError
from .assembler import Assembler, NotAssembled
from .compiled import compiled_sweep
from .continuation import CannotFollow, advance
from .limit_positions import Zigzag, not_followed, with_rows
from .plan import Plan, bad_row
from .poses import AnyPoses
from .progress import reporter
from .result import SweepResult, dead_points
from .swept import Swept

def newton_sweep(sweeper: Swept, plan: Plan, skip_bad: bool,
                 progress: bool | Callable[[int, int], None], through: bool = True) -> SweepResult:
    """Every row of the plan by continuation, solved by the engine; NaN rows if skipped. At
    a limit position (a row that cannot be reached by stepping the coordinate) the curve is
    followed by arclength (`continuation`) and the input runs back, unless not `through`."""

    fast = compiled_sweep(sweeper, plan)       # spatial R/S linkages: all positions as arrays
    if fast is not None:
        return fast
    rows = _Rows(sweeper, plan)
    asm = Assembler(sweeper, plan)
    zig = rows.zig
    scale = math.pi / 180 if plan.turns else 1.0
    poses = asm.poses_class.drawn(sweeper.inst.ref, list(asm.unknowns.offset))
    solver, motion = sweeper.solver, sweeper.drawn
    good = (poses, solver, 0.0)                   # the last assembled row: poses, solver, q (user)
    report = reporter(progress, rows.n, "sweeping")
    follow = through
    q = 0.0
    for k in range(rows.n):
        if k > 0:
            q = float(zig.coordinate(zig.travel(k))) if zig.limits else float(plan.coordinate[k])
            met = len(zig.limits)
            try:
                if rows.ok[k - 1]:
                    poses, solver, q = _reach(asm, good, q, zig, k, scale, follow)
                else:           # after skipped rows: assemble afresh near the last good poses
                    poses, solver = asm.assemble(good[0], q * scale)
            except _CannotFollow as err:
                report(None)
                if not skip_bad:
                    raise err.error(plan, zig, rows.partial(k)) from None
                follow = False                        # the rest as before: rows that assemble
                rows.singular[k] = err.kind == "singular"
                rows.coordinate[k] = q
                report(k + 1)
                continue
            except (NotAssembled, KinematikaError) as err:
                kind = err.kind if isinstance(err, KinematikaError) else "assembly"
                kind = "assembly" if kind not in ("singular", "assembly") else kind
                if not skip_bad:
                    report(None)
                    raise bad_row(plan, k, kind, at=q) from None
                rows.singular[k] = kind == "singular"
                rows.coordinate[k] = q
                report(k + 1)
                continue
            try:
                motion = solver.solve()
            except KinematikaError:     # assembled, but the drivers' values contradict the joints
                report(None)
                raise bad_row(plan, k, "mobility", at=q) from None
            home = _home(sweeper, asm, zig, good, (poses, solver, q), scale, len(zig.limits) > met) \
                if zig.limits else None
            if home is not None:                  # back at the drawing: the cycle is complete
                poses, solver, q = home
                motion = solver.solve()
                rows.close(k, q)
        rows.coordinate[k] = q
        _store(sweeper, poses, motion, k, rows.bodies, rows.motions)
        rows.ok[k] = True
        good = (poses, solver, q)
        report(k + 1)
        if rows.closed:
            break
    report(None)
    return rows.result()


class _CannotFollow(Exception):
    """The curve could not be followed to a row (see `continuation.CannotFollow`)."""

    def __init__(self, q: float, travel: float, kind: str, why: Any) -> None:
        super().__init__(str(why))
        self.q, self.travel, self.kind, self.why = q, travel, kind, why

    def error(self, plan: Plan, zig: Any, partial: SweepResult) -> KinematikaError:

        return with_rows(not_followed(plan, self.q, self.travel, self.why, self.kind), partial)


def _reach(asm: Assembler, good: tuple, q: float, zig: Any, k: int, scale: float,
           through: bool) -> tuple[Any, InstantSolver, float]:
    """Row k from the last assembled row: by stepping the coordinate to q, else (`through`)
    by following the curve through the limit positions between (the coordinate reached)."""
    poses, solver, q_good = good
    try:
        found, found_solver = asm.step(poses, solver, q_good * scale, q * scale)
        return found, found_solver, q
    except NotAssembled:
        if not through:
            raise

    travel = zig.travel(k) - (zig.travel0 + abs(q_good - zig.start))
    try:
        way = advance(asm, poses, q_good * scale, zig.d, travel * scale, zig.h * scale, zig.plan.turns)
    except CannotFollow as err:
        at = q_good if math.isnan(err.q) else err.q / scale
        raise _CannotFollow(at, zig.travel0 + abs(at - zig.start), err.kind, err.why) from None
    for limit, _ in way.limits:
        zig.turn(limit / scale)
    return way.poses, asm.solver_at(way.poses), way.q / scale


def _home(sweeper: Swept, asm: Assembler, zig: Any, before: tuple, after: tuple,
          scale: float, turned: bool) -> Optional[tuple]:
    """After a limit position: the drawn configuration, if the run from the row `before` (or
    from the limit position, if it `turned` on the way) to the row `after` passes it (the
    input at a multiple of its period, every body as drawn)."""
    start = zig.start if turned else before[2]
    home = zig.drawn_between(start, after[2])
    if home is None:
        return None
    poses, solver, q = after
    try:
        found, found_solver = asm.step(poses, solver, q * scale, home * scale)
    except (NotAssembled, KinematikaError):
        return None
    size = asm.scale
    for name, body, _ in sweeper.motions:
        drawn = sweeper.points[name]
        if max(abs(a - b) for a, b in zip(found.point(body, drawn), drawn)) > 1e-6 * size:
            return None
    return found, found_solver, home


class _Rows:
    """The arrays of a Newton sweep's rows, filled one by one (and cut where the cycle closes)."""

    def __init__(self, sweeper: Swept, plan: Plan) -> None:

        self.sweeper, self.plan = sweeper, plan
        self.zig = Zigzag(plan)
        model, n, dim = sweeper.model, plan.steps + 1, sweeper.model.dimension
        shape = (n,) if dim == 2 else (n, 3)
        self.n = n
        self.bodies = {b: {q: np.full(shape, np.nan) for q in ("angle", "omega", "alpha")}
                       for b in model.bodies}
        self.motions = {(name, body): tuple(np.full((n, dim), np.nan) for _ in range(3))
                        for name, body, _ in sweeper.motions}
        self.ok = np.zeros(n, dtype=bool)
        self.singular = np.zeros(n, dtype=bool)
        self.coordinate = np.array(plan.coordinate, dtype=float)
        self.closed = False
        self.end = n

    def close(self, k: int, q: float) -> None:
        """Row k is the drawn configuration again: the last row."""
        self.closed, self.end = True, k + 1
        self.closing_travel = self.zig.travel0 + abs(q - self.zig.start)

    def partial(self, k: int) -> SweepResult:
        """The rows before row k."""
        self.end = k
        return self.result()

    def result(self) -> SweepResult:

        end = self.end
        cut = slice(0, end)
        ok, singular = self.ok[cut], self.singular[cut]
        coordinate = self.coordinate[cut]
        bodies = {b: {q: v[cut] for q, v in values.items()} for b, values in self.bodies.items()}
        motions = {key: tuple(v[cut] for v in values) for key, values in self.motions.items()}
        travel = self.zig.travel(np.arange(end)).astype(float)
        if self.closed:
            travel[-1] = self.closing_travel
        return self.sweeper.result(self.plan, ok, bodies, motions, dead_points(coordinate, ok, singular),
                                   coordinate=coordinate, travel=travel, limits=self.zig,
                                   closed=self.closed)


def _store(sweeper: Swept, poses: AnyPoses, motion: Motion, k: int, bodies: dict, motions: dict) -> None:
    for b, values in bodies.items():
        s = motion.states[b]
        values["angle"][k] = np.degrees(poses.angle(b))
        values["omega"][k] = s.omega
        values["alpha"][k] = s.alpha
    for (name, body), (pos, vel, acc) in motions.items():
        p = poses.point(body, sweeper.points[name])
        state = motion.states[body]
        pos[k] = p
        vel[k] = motion.velocity(state, p)
        acc[k] = motion.acceleration(state, p)
