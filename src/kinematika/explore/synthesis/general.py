"""The general path: a task on any model the four-bar path does not take (six-bars, slider
mechanisms, gears …), scored on the batch sweep's rows.

Each design is swept as a study sweeps it (`evaluate.Evaluator`: the batch kernel where a
closed form exists, else one design at a time); each target's error is read off the rows —
a path's target: its distance to the polyline through the point's positions; a pose: its
distance to the nearest pose of the rows; a function's row: the rotation interpolated
linearly at its input — and weighted into the task's objective (sse or max). A design that
does not complete its cycle scores PENALTY; `--require transmission=DEG` reads the
`transmission` metric (four-bars and slider-cranks), `ordered` the rows at which the targets
are met. scipy's differential evolution minimises it, a generation per batch call.

`minimise_metric` minimises any single study metric (the Python API's older entry point).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from ...errors import KinematikaError
from ..cycle import Cycle
from ..designs import Vary
from ..evaluate import Evaluator, Sweep
from ..metrics import Metric, path_distances, pose_distances, rotation_errors
from ..study import evaluator, make_study

PENALTY = 1e9           # the objective of a design that does not complete its cycle


@dataclass
class MetricSynthesis:
    """The result of `minimise_metric`: the best designs (parameter values and objective, best
    first), how many designs were evaluated, and (seconds, best) per generation."""

    names: list[str]
    designs: list[dict[str, float]]
    errors: list[float]
    evaluated: int
    objective: str
    history: list[tuple[float, float]]


def synthesize_general(model: Any, varied: list[Vary], task: Any, population: int, generations: Optional[int],
                       seed: int, best: int, seconds: Optional[float], steps: Optional[int]) -> Any:
    """The task on a model the four-bar path does not take (see the module's docstring)."""
    from . import Synthesis

    if task.timing is not None:
        raise KinematikaError("usage", "timing-needs-four-bar", "--timing")
    names = [v.name for v in varied]
    ev = Evaluator(model, names, [], Sweep(steps=steps))
    metric = task_metric(ev, task)
    requirements = _requirements(ev, task)
    ev.metrics = [metric, *requirements]
    out = _minimise(ev, names, [(v.low, v.high) for v in varied], metric.name,
                    [(m.name, m.data) for m in requirements], population, generations or 200, seed, best, seconds)
    return Synthesis(out.names, out.designs, out.errors, out.evaluated, task.label, out.history,
                     [None] * len(out.designs), [None] * len(out.designs), path="general")


def task_metric(ev: Evaluator, task: Any) -> Metric:
    """The task's objective as a metric over the designs' cycles (NaN where a design stops),
    with, as its data, the rows at which each target is met (for `ordered`)."""
    model, sqrtw = ev.model, np.sqrt(task.weights)
    where = {"path": "--target", "motion": "--target-motion", "function": "--target-function"}[task.kind]
    if task.kind == "function":
        if task.body not in model.bodies:
            raise KinematikaError("usage", "unknown-body", "--output", body=task.body, bodies=list(model.bodies))
        table = np.column_stack([task.inputs, task.angle])
        low, high = sorted((ev.context.coordinate[0], ev.context.coordinate[-1]))
        if (task.inputs < low - 1e-9).any() or (task.inputs > high + 1e-9).any():
            raise KinematikaError("usage", "input-outside-sweep", where, low=float(low), high=float(high),
                                  unit=ev.context.unit)
        if task.output_zero is not None:
            raise KinematikaError("usage", "output-zero-needs-four-bar", "--output-zero")
        errors = lambda c: rotation_errors(c, task.body, table)
    else:
        try:
            ref = model.resolve_point(task.point, "--point")
        except KinematikaError as err:
            raise KinematikaError("usage", err.said, "--point") from None
        if task.kind == "motion":
            points = model.bodies[ref.body].points
            if len(points) < 2:
                raise KinematikaError("usage", "body-needs-two-points", where, body=ref.body)
            poses = np.column_stack([task.xy.real, task.xy.imag, task.angle])
            errors = lambda c: pose_distances(c, ref, points, poses)
        else:
            errors = lambda c: path_distances(c.motion(ref)[0], task.xy)

    def compute(c: Cycle) -> np.ndarray:
        r = sqrtw * errors(c)
        return (r ** 2).sum(axis=1) if task.objective == "sse" else r.max(axis=1)

    return Metric(task.label, compute)


def _requirements(ev: Evaluator, task: Any) -> list[Metric]:
    """The requirements as metrics, each with the bound it must meet as data."""
    from ..metrics import parse_metric

    out = []
    if task.requires.transmission is not None:
        try:
            metric = parse_metric("transmission", ev.context)
        except KinematikaError:
            raise KinematikaError("usage", "require-transmission-linkage", "--require") from None
        metric.name, metric.data = "·transmission", task.requires.transmission
        out.append(metric)
    if task.requires.ordered and task.kind == "path":
        ref = ev.model.resolve_point(task.point, "--point")

        def order(c: Cycle) -> np.ndarray:
            path = c.motion(ref)[0]
            rows = np.argmin(np.abs(path[:, None, :] - task.xy[None, :, None]), axis=2)    # (D, K)
            turn = np.mod(rows - rows[:, :1], path.shape[1] - 1)
            return np.maximum(turn[:, :-1] - turn[:, 1:], 0).sum(axis=1).astype(float)
        out.append(Metric("·order", order, data=0.0))
    return out


def _minimise(ev: Evaluator, names: list[str], bounds: list[tuple[float, float]], objective: str,
              limits: list[tuple[str, float]], population: int, generations: int, seed: int, best: int,
              seconds: Optional[float]) -> MetricSynthesis:
    """Differential evolution of `objective` over the box; a design breaking a limit (a
    transmission below its bound, targets out of order) or not completing its cycle scores
    PENALTY."""
    from scipy.optimize import differential_evolution

    archive_x: list[np.ndarray] = []
    archive_f: list[np.ndarray] = []
    history: list[tuple[float, float]] = []
    start = time.perf_counter()

    def cost(x: np.ndarray) -> np.ndarray:
        x = x.reshape(len(names), -1)
        columns = ev.evaluate({n: x[i] for i, n in enumerate(names)})
        f = np.asarray(columns[objective], dtype=float)
        ok = np.isfinite(f)
        for name, bound in limits:
            value = np.asarray(columns[name], dtype=float)
            ok &= (value >= bound) if name == "·transmission" else (value <= bound)
        f = np.where(ok, f, PENALTY)
        archive_x.append(x.T.copy())
        archive_f.append(f)
        return f

    def progress(intermediate_result: Any) -> bool:        # scipy passes the result by this name
        fun = float(intermediate_result.fun)
        elapsed = time.perf_counter() - start
        history.append((elapsed, fun))
        return seconds is not None and elapsed >= seconds

    size = max(5, math.ceil(population / len(names)))
    differential_evolution(cost, bounds, popsize=size, maxiter=generations, seed=seed, tol=0.0,
                           polish=False, vectorized=True, updating="deferred", init="sobol",
                           callback=progress)
    xs, fs = np.concatenate(archive_x), np.concatenate(archive_f)
    chosen = _distinct_best(xs, fs, bounds, best)
    if not chosen:
        raise KinematikaError("assembly", "synthesis-no-design", "--vary", requirements=len(limits))
    designs = [{n: float(xs[i, k]) for k, n in enumerate(names)} for i in chosen]
    return MetricSynthesis(names, designs, [float(fs[i]) for i in chosen], len(fs), objective, history)


def minimise_metric(model: Any, vary: list[Vary | str], objective: str, population: int = 40,
                    generations: int = 200, seed: int = 0, best: int = 3, sweep: Sweep = Sweep(),
                    files: Optional[dict[str, str]] = None, seconds: Optional[float] = None) -> MetricSynthesis:
    """Minimise the study metric `objective` (any of `explore`'s) over the varied parameters'
    intervals, the whole population of each generation swept at once; `files` gives target
    files' text by name (as `make_study`)."""
    study = make_study(model, vary, [objective], grid=1, sweep=sweep, files=files, what="synthesize")
    ev = evaluator(study)
    names = study.designs.names
    bounds = [(v.low, v.high) for v in study.designs.vary]
    return _minimise(ev, names, bounds, objective, [], population, generations, seed, best, seconds)


def _distinct_best(xs: np.ndarray, fs: np.ndarray, bounds: list[tuple], count: int) -> list[int]:
    """The best designs, each at least 2 % of the intervals away from the better ones."""
    span = np.array([max(hi - lo, 1e-300) for lo, hi in bounds])
    out: list[int] = []
    for i in np.argsort(fs, kind="stable"):
        if fs[i] >= PENALTY:
            break
        if all(np.max(np.abs(xs[i] - xs[j]) / span) > 0.02 for j in out):
            out.append(int(i))
        if len(out) == count:
            break
    return out


def function_targets(expression: str, over: tuple[float, float], points: int) -> str:
    """A target function f(x) (an expression in x: the input's increment, giving the output's
    rotation in degrees) at `points` Chebyshev precision points of `over`, as CSV text."""
    from ...algebra.arrays import Arrays
    from ...expressions import ExpressionError, evaluate, parse

    low, high = over
    k = np.arange(1, points + 1)
    x = 0.5 * (low + high) - 0.5 * (high - low) * np.cos((2 * k - 1) * np.pi / (2 * points))
    try:
        expr = parse(expression)
        unknown = expr.names() - {"x", "pi"}
        if unknown:
            raise ExpressionError("function-unknown-name", source=repr(expression), name=sorted(unknown)[0])
        with np.errstate(all="ignore"):
            y = np.broadcast_to(evaluate(expr, {"x": x}, Arrays({})), x.shape)
    except ExpressionError as err:
        raise KinematikaError("usage", err.said, "--target-function") from None
    if not np.isfinite(y).all():
        raise KinematikaError("usage", "function-not-finite", "--target-function", source=repr(expression),
                              low=float(low), high=float(high))
    return "".join(f"{a!r},{b!r}\n" for a, b in zip(x.tolist(), y.tolist()))
