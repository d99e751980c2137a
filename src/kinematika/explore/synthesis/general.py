"""Synthesis: the designs whose metric is least — path, function and motion generation.

The objective is one of the study's metrics: `path_error:POINT=FILE` (path generation: the
point passes near the targets), `structural_error:BODY=FILE` (function generation: the
body's rotation follows a function of the input's), `motion_error:POINT=FILE` (motion
generation: the body passes through target poses), or any other metric to minimise. The
optimiser is scipy's differential evolution, its whole population evaluated at once by
the batch kernel (`vectorized=True`): a generation is one call over (population ×
positions) arrays. A design that cannot be assembled over its whole cycle scores a
penalty. The best distinct designs are returned and written as model files, ready for
`solve`, `draw`, `animate`.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from ...errors import KinematikaError
from ..designs import Vary
from ..evaluate import Sweep
from ..study import evaluator, make_study

PENALTY = 1e9           # the objective of a design that does not complete its cycle


@dataclass
class MetricSynthesis:
    """The result: the best designs (parameter values and objective, best first), and how
    many designs were evaluated."""

    names: list[str]
    designs: list[dict[str, float]]
    errors: list[float]
    evaluated: int
    objective: str
    history: list[tuple[float, float]]   # (seconds from the start, best objective) per generation


def minimise_metric(model: Any, vary: list[Vary | str], objective: str, population: int = 40,
               generations: int = 200, seed: int = 0, best: int = 3, sweep: Sweep = Sweep(),
               tol: float = 0.0, target: Optional[float] = None,
               files: Optional[dict[str, str]] = None, seconds: Optional[float] = None) -> MetricSynthesis:
    """Minimise the metric `objective` over the varied parameters' intervals.

    `population` designs per generation (scipy's popsize is per parameter: it is derived),
    at most `generations` generations; stop early once the objective is below `target`, or
    after `seconds`.
    `files` gives target files' text by name (as `make_study`).
    """
    from scipy.optimize import differential_evolution

    study = make_study(model, vary, [objective], grid=1, sweep=sweep, files=files, what="synthesize")
    ev = evaluator(study)
    names = study.designs.names
    bounds = [(v.low, v.high) for v in study.designs.vary]
    archive_x: list[np.ndarray] = []
    archive_f: list[np.ndarray] = []
    history: list[tuple[float, float]] = []           # (seconds, best objective) per generation
    start = time.perf_counter()

    def cost(x: np.ndarray) -> np.ndarray:
        x = x.reshape(len(names), -1)                          # (parameters, designs)
        columns = ev.evaluate({n: x[i] for i, n in enumerate(names)})
        f = np.asarray(columns[objective], dtype=float)
        f = np.where(np.isfinite(f), f, PENALTY)
        archive_x.append(x.T.copy())
        archive_f.append(f)
        return f

    def progress(intermediate_result: Any) -> bool:        # scipy passes the result by this name
        fun = float(intermediate_result.fun)
        elapsed = time.perf_counter() - start
        history.append((elapsed, fun))
        return (target is not None and fun <= target) or (seconds is not None and elapsed >= seconds)

    size = max(5, math.ceil(population / len(names)))
    differential_evolution(cost, bounds, popsize=size, maxiter=generations, seed=seed, tol=tol,
                           polish=False, vectorized=True, updating="deferred", init="sobol",
                           callback=progress)
    xs, fs = np.concatenate(archive_x), np.concatenate(archive_f)
    chosen = _distinct_best(xs, fs, bounds, best)
    designs = [{n: float(xs[i, k]) for k, n in enumerate(names)} for i in chosen]
    return MetricSynthesis(names, designs, [float(fs[i]) for i in chosen], len(fs), objective, history)


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
            raise ExpressionError(f"in {expression!r}: unknown name {sorted(unknown)[0]!r} (the function "
                                  "is of x, the input's increment)")
        with np.errstate(all="ignore"):
            y = np.broadcast_to(evaluate(expr, {"x": x}, Arrays({})), x.shape)
    except ExpressionError as err:
        raise KinematikaError("usage", str(err), "--target-function") from None
    if not np.isfinite(y).all():
        raise KinematikaError("usage", f"{expression!r} is not finite over {low:g} to {high:g}",
                              "--target-function")
    return "".join(f"{a!r},{b!r}\n" for a, b in zip(x.tolist(), y.tolist()))


def synthesize_general(model: Any, varied: list[Vary], task: Any, population: int, generations: Optional[int],
                       seed: int, best: int, seconds: Optional[float], steps: Optional[int]) -> Any:
    """A task on a model the four-bar path does not take, by the study's metrics over the
    batch sweep's rows (path_error, structural_error, motion_error)."""
    from . import Synthesis

    if task.timing is not None or task.objective != "max" or task.requires or not np.all(task.weights == 1.0):
        raise KinematikaError("usage", "--timing, --objective sse, --require and weights need a four-bar "
                              "driven at its crank (the task's point on its coupler)", "--timing")
    if task.kind == "function":
        rows = "".join(f"{x!r},{y!r}\n" for x, y in zip(task.inputs.tolist(), task.angle.tolist()))
        objective = f"structural_error:{task.body}=targets.csv"
    elif task.kind == "motion":
        rows = "".join(f"{p.real!r},{p.imag!r},{a!r}\n" for p, a in zip(task.xy.tolist(), task.angle.tolist()))
        objective = f"motion_error:{task.point}=targets.csv"
    else:
        rows = "".join(f"{p.real!r},{p.imag!r}\n" for p in task.xy.tolist())
        objective = f"path_error:{task.point}=targets.csv"
    out = minimise_metric(model, list(varied), objective, population, generations or 200, seed, best,
                          Sweep(steps=steps), files={"targets.csv": rows}, seconds=seconds)
    return Synthesis(out.names, out.designs, out.errors, out.evaluated, "max", out.history,
                     [None] * len(out.designs), [None] * len(out.designs), path="general")
