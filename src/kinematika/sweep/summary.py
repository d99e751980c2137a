"""A readable summary of a sweep: ranges, extremes, dead points, and the linkage's classics."""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

from .angles import InputAxis, angles_of, input_axis
from .result import SweepResult


def summary_lines(result: SweepResult, linkage: Any = None, groups: Optional[list] = None) -> list[str]:
    """The summary printed by `kinematika sweep MODEL` (plain text, one line each).

    Angles are those of the sweep's plot (`angles`): a planar body's angle θ is its line's
    from the x axis, counter-clockwise, and every place along the motion (`at`, dead points,
    limit positions) is the crank's angle θ when the sweep turns a crank from the frame,
    else the driven joint's coordinate from the drawn position; a line above the tables says
    which."""
    unit = "deg" if result.unit == "deg" else ""
    n, good = len(result), int(result.ok.sum())
    by = result.coordinate[-1] if n else 0.0
    if result.limits and result.travel is not None:
        lines = [f"{result.name}: sweep of {result.joint}, {result.travel[-1]:g} {unit} of travel in "
                 f"{n - 1} steps through {len(result.limits)} limit "
                 f"position{'s' if len(result.limits) > 1 else ''} ({result.method})".replace("  ", " ")]
    else:
        lines = [f"{result.name}: sweep of {result.joint} by {by:g} {unit} in {n - 1} steps "
                 f"({result.method})".replace("  ", " ")]
    if groups:
        lines.append("structure: " + ", then ".join(_group(g) for g in groups))
    if result.limits:
        lines += _limit_lines(result, unit)
    lines.append(f"assembled: {good} of {n} positions" +
                 ("" if good == n else f" (skipped: {_ranges(result.coordinate[~result.ok])})"))
    if good == 0:
        return lines
    planar = result.dimension == 2
    angles = angles_of(result) if planar else {}
    axis = input_axis(result, angles)
    at = axis.x
    lines.append(_conventions(axis, planar))
    # in 3D, the magnitudes: the rotation from the drawn pose, |ω| and |α|
    moving = {b: {q: np.linalg.norm(x, axis=1) if x.ndim == 2 else x for q, x in v.items()}
              for b, v in result.bodies.items() if b != result.frame}
    tops = {q: max((float(np.nanmax(np.abs(v[q]), initial=0.0)) for v in moving.values()), default=0.0)
            for q in ("angle", "omega", "alpha")}
    tops["alpha"] = max(tops["alpha"], tops["omega"] ** 2)     # the scale of α: α itself or ω²
    heads = (("angle θ (deg)", "omega (rad/s)", "alpha (rad/s²)") if planar else
             ("rotation (deg)", "|omega| (rad/s)", "|alpha| (rad/s²)"))
    lines += ["", f"{'body':<14}{heads[0]:>24}{heads[1]:>26}{heads[2]:>26}"]
    for name, values in moving.items():
        angle = _span(values["angle"], tops["angle"])
        if planar and name in angles:                  # θ, as the plot draws it
            angle = _span(angles[name], max(tops["angle"], 360.0))
        elif planar:                                   # one point: no line, how far it turns
            angle = " does not turn" if angle.strip() == "0" else f" turns{angle}"
        lines.append(f"{name:<14}{angle:>24}" + "".join(f"{_span(values[q], tops[q]):>26}" for q in ("omega", "alpha")))
    lines += ["", f"{'point':<14}{'max speed':>14}{'at':>12}{'max acceleration':>20}{'at':>12}"]
    lines += peak_lines(result.points, result.frame, result.scales(), at)
    lines += ["", "dead points: " + (", ".join(f"{axis.at(x):g} {unit}".strip() for x in result.dead_points)
                                     or "none in the range swept")]
    if linkage is not None:
        from ..structure.linkages import transmission_angle

        lines += [""] + linkage.summary(_drawn_angles(linkage, angles, axis))
        mu = transmission_angle(linkage, result)
        if np.isfinite(mu).any():
            k = int(np.nanargmin(np.minimum(mu, 180.0 - mu)))
            lines.append(f"  transmission angle: {np.nanmin(mu):.4g} to {np.nanmax(mu):.4g} deg; "
                         f"worst {mu[k]:.4g} deg at {at[k]:g} {unit}".rstrip())
    return lines


def _limit_lines(result: SweepResult, unit: str) -> list[str]:
    """Where the input ran back, its range, and whether the motion came back to the drawing."""
    shown = ", ".join(f"{x:.6g}" for x in result.limits)
    low = min(*result.limits, float(np.nanmin(result.coordinate)))
    high = max(*result.limits, float(np.nanmax(result.coordinate)))
    lines = [f"limit positions of {result.joint}: {shown} {unit} (the input runs back there)".replace("  ", " "),
             f"range of {result.joint}: {low:.6g} .. {high:.6g} {unit}".rstrip()]
    if result.closed and result.travel is not None:
        lines.append(f"back at the drawn configuration after {result.travel[-1]:.6g} {unit} of "
                     "travel: the whole cycle".replace("  ", " "))
    return lines


def _conventions(axis: InputAxis, planar: bool) -> str:
    """The line that says what the angles and the places along the motion are."""
    where = (f"the {axis.driver} angle θ (deg)" if axis.driver is not None else
             axis.label.replace(" (deg)", ", deg").replace(" (length)", ", length"))
    angles = ("angle θ: a body's line from the x axis, counter-clockwise (as --plot draws it); "
              if planar else "rotation: from the drawn pose; ")
    return f"{angles}at: {where}; constant: the same all along"


def _drawn_angles(linkage: Any, angles: dict[str, np.ndarray], axis: InputAxis) -> Optional[dict[str, float]]:
    """The drawn angle θ of the linkage's crank and rocker, for its limit positions to be
    written as angles θ too (None when the sweep does not turn the crank)."""
    crank = linkage.bodies.get("crank")
    if axis.driver is None or crank != axis.driver:
        return None
    out = {"crank": float(axis.x[0])}
    rocker = linkage.bodies.get("output")                 # a four-bar's rocker (a slider-crank's slider has no θ)
    if rocker in angles and np.isfinite(angles[rocker][0]):
        out["rocker"] = float(angles[rocker][0])
    return out


def _quiet(values: np.ndarray, scale: float) -> np.ndarray:
    """Round-off (below 1e-9 of the quantity's scale) as 0."""
    return np.where(np.abs(values) <= 1e-9 * scale, 0.0, values)


def peak_lines(points: dict[str, dict[str, np.ndarray]], frame: str, scales: dict[str, float],
               at: np.ndarray, rows: slice = slice(None), steady: str = "constant") -> list[str]:
    """A line per moving point: its largest speed and acceleration and where (`at`, over
    `rows`) each is reached — `steady` when it does not vary. A material point listed under
    several bodies' names is given once (the same largest values)."""
    lines: list[str] = []
    seen = set()
    for name, values in points.items():
        point, _, body = name.partition("@")
        if body == frame:
            continue
        speed = _quiet(np.linalg.norm(values["velocity"][rows], axis=1), scales["velocity"])
        accel = _quiet(np.linalg.norm(values["acceleration"][rows], axis=1), scales["acceleration"])
        key = (round(float(np.nanmax(speed)), 9), round(float(np.nanmax(accel)), 9), point)
        if key in seen:
            continue          # the same material motion under another body's name
        seen.add(key)
        ks, ka = int(np.nanargmax(speed)), int(np.nanargmax(accel))
        lines.append(f"{name:<14}{speed[ks]:>14.6g}{_where(speed, at, ks, steady):>12}"
                     f"{accel[ka]:>20.6g}{_where(accel, at, ka, steady):>12}")
    return lines


def _where(values: np.ndarray, at: np.ndarray, k: int, steady: str) -> str:
    """Where the largest value is reached; `steady` ("constant") when the value does not vary
    (a steady crank pin): it is reached all along."""
    if np.nanmax(values) - np.nanmin(values) <= 1e-9 * max(float(np.nanmax(values)), 1e-300):
        return steady
    return f"{at[k]:.6g}"


def _group(g: Any) -> str:
    bodies = " + ".join(g.bodies)
    return f"{g.kind} {bodies}" if g.kind != "input" else f"input {bodies}"


def _span(values: np.ndarray, top: float) -> str:
    """`min .. max`; round-off (below 1e-9 of the quantity's scale) is not shown."""
    if not np.isfinite(values).any():
        return "-"
    tol = 1e-9 * top
    low, high = (0.0 if abs(x) <= tol else float(x) for x in (np.nanmin(values), np.nanmax(values)))
    return f" {low:.5g} .. {high:.5g}" if high - low > tol else f" {0.5 * (low + high):.5g}"


def _ranges(values: np.ndarray) -> str:
    if len(values) <= 4:
        return ", ".join(f"{x:g}" for x in values)
    return f"{len(values)} positions from {values.min():g} to {values.max():g}"
