"""Sweep plots: a mechanism's motion over its swept coordinate, as a student reads it.

The horizontal axis is the driving coordinate: the absolute angle θ of a crank driven from
the frame (the angle of the line from its pivot to its next point, from the x axis), else
the driven joint's increment. The panels, each only when it has something to show:

- the absolute angles θ of the bodies that swing (degrees, each body's line from the x axis,
  as the summary of `kinematika sweep` gives them: `sweep.angles`); bodies that turn fully have a
  panel of their own, so that a 0–360° turn does not flatten a ±30° rocker;
- ω and α of the moving bodies (signed, counter-clockwise positive);
- for points running on a straight line (a ram, a piston): their position along the line,
  and their velocity and acceleration along it, signed, so that the slow and the fast
  strokes show; with the stroke and, when a crank turns once at a steady rate, the time
  ratio of the two strokes (a quick-return's);
- for the other points (the asked ones, else every moving one, at most `MAX_POINTS`):
  their speed and their tangential acceleration (signed: speeding up or slowing down).

Lengths are in the model's unit, times in seconds. Dead points are dashed red vertical
lines across every panel; rows the sweep could not assemble leave gaps. A motion through
the input's limit positions runs back along the axis there (a rocker's cycle is a loop):
those positions are dotted vertical lines. The frame and
points at rest are left out; points moving alike (a pin of two bodies) appear once, under
their bare name.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ..errors import KinematikaError
from ..questions import QUESTIONS
from ..sweep.angles import angles_of, input_axis
from .style import BODY_COLOURS, INK

MAX_POINTS = 6
DEAD = "#c62828"
PANEL = 1.75          # inches per panel
TURNING = 180.0       # degrees: a body whose angle spans more turns fully (own panel)


@dataclass
class Series:
    """One curve of a panel: its name (a body or a point) and its values over the sweep's rows."""

    name: str
    values: np.ndarray


@dataclass
class Panel:
    """One panel of the sweep plot: the quantity (its lines' gid prefix), the vertical axis'
    label, the curves and an optional note above it (a stroke, a time ratio)."""

    quantity: str                 # the gid prefix of its lines
    ylabel: str
    series: list[Series]
    note: str = ""


@dataclass
class Reading:
    """The sweep read as the plots show it."""

    x: np.ndarray
    xlabel: str
    panels: list[Panel] = field(default_factory=list)


def plot_sweep(result: Any, path: Optional[Path | str] = None, model: Any = None) -> Figure:
    """The sweep plots of `result` (a `SweepResult`), written to `path` when given (its
    suffix names the format, PNG without one). With the `model`, the curved-path points
    shown are the ones it asks about."""
    fmt = _format(Path(path)) if path is not None else None
    reading = read_sweep(result, model)
    n = len(reading.panels)
    fig = Figure(figsize=(8.5, 1.2 + PANEL * n))
    FigureCanvasAgg(fig)
    axes = np.atleast_1d(fig.subplots(n, 1, sharex=True))
    for ax, panel in zip(axes, reading.panels):
        for i, s in enumerate(panel.series):
            ax.plot(reading.x, s.values, lw=1.6, color=_colour(i), label=s.name,
                    gid=f"{panel.quantity}:{s.name}")
        ax.set_ylabel(panel.ylabel, fontsize=9.5)
        ax.grid(True, lw=0.4, alpha=0.5)
        if panel.quantity not in ("angle", "position"):          # rates: where the sign changes
            ax.axhline(0, color="#9e9e9e", lw=0.6, zorder=0)
        for d in getattr(result, "dead_points", []) or []:
            x = _dead_x(reading, result, float(d))
            ax.axvline(x, color=DEAD, lw=1.0, ls="--", gid=f"dead:{float(d):g}")
        for d in getattr(result, "limits", []) or []:
            x = _dead_x(reading, result, float(d))
            ax.axvline(x, color=INK, lw=0.9, ls=":", gid=f"limit:{float(d):g}")
        if panel.series:
            ax.legend(fontsize=8, ncol=min(len(panel.series), 6), loc="best", framealpha=0.85)
        if panel.note:
            ax.set_title(panel.note, fontsize=9, color=INK, loc="left", gid=f"note:{panel.quantity}")
    axes[-1].set_xlabel(reading.xlabel, fontsize=10)
    if "(deg)" in reading.xlabel and np.nanmax(reading.x) - np.nanmin(reading.x) >= 90:
        axes[-1].xaxis.set_major_locator(_degrees_locator())
    title = getattr(result, "name", "Sweep")
    if getattr(result, "dead_points", None):
        title += "  (dashed red: dead points)"
    if getattr(result, "limits", None):
        title += "  (dotted: limit positions, where the input runs back)"
    fig.suptitle(title.replace("$", r"\$"), fontsize=12, weight="bold", color=INK)
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    if path is not None:
        from .lock import MATPLOTLIB

        with MATPLOTLIB:
            fig.savefig(path, dpi=100, format=fmt, facecolor="white")
    return fig


def read_sweep(result: Any, model: Any = None) -> Reading:
    """The horizontal axis and the panels of `result`."""
    bodies = _moving_bodies(result)
    angles = angles_of(result, list(bodies))
    axis = input_axis(result, angles)
    x, driver = axis.x, axis.driver
    reading = Reading(x, axis.label)
    swinging = {n: a for n, a in angles.items() if n != driver and _span(a) <= TURNING}
    turning = {n: a for n, a in angles.items() if n != driver and _span(a) > TURNING}
    for group, label in ((swinging, "angle θ (deg)"), (turning, "angle θ, turning bodies (deg)")):
        if group:
            reading.panels.append(Panel("angle", label, [Series(n, a) for n, a in group.items()]))
    reading.panels.append(Panel("omega", "ω (rad/s)",
                                [Series(n, _scalar(d["omega"])) for n, d in bodies.items()]))
    reading.panels.append(Panel("alpha", "α (rad/s²)",
                                [Series(n, _scalar(d["alpha"])) for n, d in bodies.items()]))
    points = _moving_points(result)
    straight = {n: u for n, d in points.items() if (u := line_direction(d["position"])) is not None}
    if straight:
        reading.panels += _slider_panels(result, points, straight, x, driver, bodies)
    pivots = _fixed_points(result)
    free = {n: d for n, d in points.items() if n not in straight and not _on_circle(d, pivots)}
    curved = _asked(free, model)[:MAX_POINTS]
    if curved:
        reading.panels += _curved_panels(points, curved)
    for panel in reading.panels:
        _clean(panel)
    return reading


def _clean(panel: Panel) -> None:
    """Round-off (below 1e-9 of the panel's largest value) shown as 0."""
    scale = max((float(np.nanmax(np.abs(s.values), initial=0.0)) for s in panel.series),
                default=0.0)
    for s in panel.series:
        s.values = np.where(np.abs(s.values) <= 1e-9 * scale, 0.0, s.values)


# bodies ---------------------------------------------------------------------------------
def _moving_bodies(result: Any) -> dict[str, dict]:
    """Every body that moves (the frame and bodies at rest left out)."""
    out = {}
    frame = getattr(result, "frame", "ground")
    for name, data in result.bodies.items():
        omega = _scalar(data["omega"])
        angle = _scalar(data.get("angle", np.zeros_like(omega)))
        if name != frame and (np.nanmax(np.abs(omega), initial=0.0) > 0 or
                              np.nanmax(np.abs(angle), initial=0.0) > 0):
            out[name] = data
    return out


def _span(a: np.ndarray) -> float:
    return float(np.nanmax(a) - np.nanmin(a)) if np.isfinite(a).any() else 0.0


# points ---------------------------------------------------------------------------------
def _moving_points(result: Any) -> dict[str, dict]:
    """Moving points, each motion once (named bare when shared)."""
    kept: dict[str, dict] = {}
    for key, data in result.points.items():
        v = np.asarray(data["velocity"], dtype=float)
        if not np.nanmax(np.abs(v), initial=0.0) > 0:
            continue
        if not any(_alike(d, data) for d in kept.values()):
            kept[key] = data
    out = {}
    for key, data in kept.items():
        name = key.partition("@")[0]
        bare = sum(k.partition("@")[0] == name for k in kept) == 1
        out[name if bare else key] = data
    return out


def _alike(a: dict, b: dict) -> bool:
    return all(np.allclose(np.asarray(a[q], dtype=float), np.asarray(b[q], dtype=float),
                           rtol=1e-9, atol=1e-12, equal_nan=True)
               for q in ("position", "velocity", "acceleration"))


def _fixed_points(result: Any) -> list[np.ndarray]:
    out = []
    for data in result.points.values():
        p = np.asarray(data["position"], dtype=float)[:, :2]
        if np.all(np.isfinite(p)) and np.abs(p - p[0]).max() <= 1e-9 * (1 + np.abs(p).max()):
            out.append(p[0])
    return out


def _on_circle(data: dict, pivots: list[np.ndarray]) -> bool:
    """Whether the point runs on a circle about a fixed point (a crank's or a rocker's
    point: its body's ω and α tell its motion)."""
    p = np.asarray(data["position"], dtype=float)[:, :2]
    p = p[np.all(np.isfinite(p), axis=1)]
    for c in pivots:
        r = np.linalg.norm(p - c, axis=1)
        if len(r) and float(np.ptp(r)) <= 1e-7 * (1 + float(r.max())):
            return True
    return False


def line_direction(position: Any) -> Optional[np.ndarray]:
    """The unit direction of a path that is a straight line (pointing right, else up), or
    None for a curved path or a point that does not move."""
    p = np.asarray(position, dtype=float)
    p = p[np.all(np.isfinite(p), axis=1)]
    if len(p) < 3 or p.shape[1] != 2:
        return None
    centred = p - p.mean(axis=0)
    spread = float(np.abs(centred).max())
    if spread <= 1e-12 * (1 + float(np.abs(p).max())):
        return None
    _, sv, vt = np.linalg.svd(centred, full_matrices=False)
    if sv[1] > 1e-7 * sv[0]:
        return None
    u = vt[0]
    return -u if (u[0] < -1e-12 or (abs(u[0]) <= 1e-12 and u[1] < 0)) else u


def _asked(points: dict[str, dict], model: Any) -> list[str]:
    """The points to plot on curved paths: those the model asks about, else all."""
    if model is None or getattr(model, "default_questions", True):
        return list(points)
    asked = [q.target for q in model.questions if QUESTIONS[q.kind].about == "point"]
    names = [n for n in points if any(n == str(t) or n == t.point for t in asked)]
    return names or list(points)


def _slider_panels(result: Any, points: dict, straight: dict, x: np.ndarray,
                   driver: Optional[str], bodies: dict) -> list[Panel]:
    pos, vel, acc = [], [], []
    for name, u in straight.items():
        d = points[name]
        pos.append(Series(name, np.asarray(d["position"], dtype=float)[:, :2] @ u))
        vel.append(Series(name, np.asarray(d["velocity"], dtype=float)[:, :2] @ u))
        acc.append(Series(name, np.asarray(d["acceleration"], dtype=float)[:, :2] @ u))
    crank = driver if driver is not None and _steady(bodies[driver]) else None
    notes = [strokes(s.name, s.values, v.values, x, crank) for s, v in zip(pos, vel)]
    return [Panel("position", "position along\nits line (length)", pos,
                  "\n".join(n for n in notes if n)),
            Panel("velocity", "velocity along\nits line (length/s)", vel),
            Panel("acceleration", "acceleration along\nits line (length/s²)", acc)]


def _steady(driver: dict) -> bool:
    w = _scalar(driver["omega"])
    w = w[np.isfinite(w)]
    return bool(len(w)) and float(np.ptp(w)) <= 1e-9 * float(np.abs(w).max()) and w[0] != 0


def strokes(name: str, s: np.ndarray, v: np.ndarray, x: np.ndarray,
            crank: Optional[str] = None) -> str:
    """`C: stroke 0.42; the strokes take 220° and 140° of crank: time ratio 1.57` — the
    travel between the limit positions (where the velocity changes sign) and, when a
    `crank` turning at a steady rate is swept once round, the ratio of the slow stroke's
    time to the quick one's."""
    ok = np.isfinite(s) & np.isfinite(v) & np.isfinite(x)
    if ok.sum() < 3:
        return ""
    text = f"{name}: stroke {np.nanmax(s[ok]) - np.nanmin(s[ok]):.4g}"
    xs, vs = x[ok], v[ok]
    if crank is None or not ok.all() or abs(abs(xs[-1] - xs[0]) - 360) > 1e-6:
        return text
    limits = limit_angles(xs[:-1], vs[:-1])          # the last row is the first once round
    if len(limits) != 2:
        return text
    one = abs(limits[1] - limits[0])
    slow, quick = max(one, 360 - one), min(one, 360 - one)
    return (f"{text}; the strokes take {slow:.4g}° and {quick:.4g}° of {crank}: "
            f"time ratio {slow / quick:.4g}")


def limit_angles(x: np.ndarray, v: np.ndarray) -> list[float]:
    """Where v changes sign over one turn of x (read round the turn), by linear
    interpolation between rows."""
    out = []
    n = len(x)
    sign = np.sign(v)
    for k in range(n):
        j = (k + 1) % n
        xj = x[j] + (360.0 if j == 0 else 0.0) * np.sign(x[-1] - x[0])
        if sign[k] == 0:
            out.append(float(x[k]))
        elif sign[j] != 0 and sign[k] != sign[j]:
            out.append(float(x[k] + v[k] * (x[k] - xj) / (v[j] - v[k])))
    return out


def _curved_panels(points: dict, names: list[str]) -> list[Panel]:
    speed, tangential = [], []
    for name in names:
        v = np.asarray(points[name]["velocity"], dtype=float)
        a = np.asarray(points[name]["acceleration"], dtype=float)
        sense = path_sense(v)
        size = np.linalg.norm(v, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            at = np.where(size > 0, np.einsum("ij,ij->i", a, v) / size, np.nan)
        speed.append(Series(name, sense * size))
        tangential.append(Series(name, sense * at))
    return [Panel("speed", "velocity along\nits path (length/s)", speed),
            Panel("tangential", "tangential acc.\n(length/s²)", tangential)]


def path_sense(v: np.ndarray) -> np.ndarray:
    """+1 or −1 per row: the sense along the path, taken positive at the first row and
    reversed where the point stops and comes back (the velocity turns round), so that
    speeds read signed — a rocker pin's swing forth and back."""
    out = np.ones(len(v))
    sign = 1.0
    for k in range(1, len(v)):
        if np.all(np.isfinite(v[k])) and np.all(np.isfinite(v[k - 1])) and \
                float(v[k] @ v[k - 1]) < 0:
            sign = -sign
        out[k] = sign
    return out


# helpers --------------------------------------------------------------------------------
def _dead_x(reading: Reading, result: Any, coordinate: float) -> float:
    """Where a dead point (given in the sweep's coordinate) lies on the plots' axis."""
    xs = np.asarray(result.coordinate, dtype=float)
    ok = np.isfinite(reading.x) & np.isfinite(xs)
    if ok.sum() < 2 or np.array_equal(reading.x[ok], xs[ok]) or np.ptp(xs[ok]) == 0:
        return coordinate
    slope, offset = np.polyfit(xs[ok], reading.x[ok], 1)    # the driver's angle: θ0 ± coordinate
    return float(offset + slope * coordinate)


def _degrees_locator() -> Any:
    from matplotlib.ticker import MultipleLocator

    return MultipleLocator(45)


def _format(path: Path) -> str:
    """The format of `path` by its suffix; one matplotlib cannot write is refused up front."""
    fmt = path.suffix.lower().lstrip(".") or "png"
    if fmt not in FigureCanvasAgg.get_supported_filetypes():
        raise KinematikaError("usage", "plot-format", str(path), name=path.name)
    return fmt


def _colour(i: int) -> str:
    palette = ("#1565c0", "#c62828", "#2e7d32", "#6a1b9a", "#ef6c00", "#00838f", "#5d4037",
               "#ad1457", "#9e9d24", "#455a64")
    return palette[i % len(palette)] if i < len(palette) else BODY_COLOURS[i % len(BODY_COLOURS)]


def _scalar(values: Any) -> np.ndarray:
    """A planar scalar as is; a vector (N, dim) by its magnitude."""
    arr = np.asarray(values, dtype=float)
    return np.linalg.norm(arr, axis=1) if arr.ndim == 2 else arr
