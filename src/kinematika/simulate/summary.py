"""A readable summary of a simulation: what was followed and how, the drift, each body's and
point's ranges, and where the motion stopped if it did."""
from __future__ import annotations

import numpy as np

from ..sweep.summary import peak_lines
from .result import SimulationResult


def summary_lines(result: SimulationResult) -> list[str]:
    """The summary printed by `kinematika simulate MODEL` (plain text, one line each)."""
    n = done = len(result)
    if result.stopped is not None and n:
        lines = [f"{result.name}: followed in time for {result.time[-1] - result.time[0]:g} s of the "
                 f"{result.duration:g} s asked, {n} rows ({result.method}, {result.evaluations} velocity "
                 "solutions); then it stopped"]
    else:
        lines = [f"{result.name}: followed in time over {result.duration:g} s in {n - 1} steps "
                 f"({result.method}, {result.evaluations} velocity solutions)"]
    lines += result.notes
    if done == 0:
        return lines
    rows = slice(0, done)
    drift = float(np.nanmax(result.drift[rows]))
    lines.append(f"drift: at most {drift:.2g} of the model's size before projection (the joints' "
                 "position conditions are kept by projecting each row back onto them)")
    scales = result.scales()
    rot = "angle (deg)" if result.dimension == 2 else "rotation (deg)"
    lines += ["", f"{'body':<14}{rot:>24}{'omega (rad/s)':>26}{'alpha (rad/s²)':>26}"]
    for name, values in result.bodies.items():
        if name == result.frame:
            continue
        cells = []
        for q, width in (("angle", 24), ("omega", 26), ("alpha", 26)):
            v = values[q][rows]
            v = np.linalg.norm(v, axis=1) if v.ndim == 2 else v
            cells.append(f"{_span(v, scales.get(q, 0.0)):>{width}}")
        lines.append(f"{name:<14}" + "".join(cells))
    lines += ["", f"{'point':<14}{'max speed':>14}{'at (s)':>12}{'max acceleration':>20}{'at (s)':>12}"]
    lines += peak_lines(result.points, result.frame, scales, result.time[rows], rows, steady="-")
    return lines


def _span(values: np.ndarray, scale: float) -> str:
    """`min .. max`, or the one value; round-off (below 1e-9 of the quantity's scale) as 0."""
    tol = 1e-9 * scale
    low, high = (0.0 if abs(x) <= tol else float(x) for x in (np.nanmin(values), np.nanmax(values)))
    return f" {low:.5g} .. {high:.5g}" if high - low > tol else f" {0.5 * (low + high):.5g}"
