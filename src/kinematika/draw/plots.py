"""Sweep plots: how the bodies and points move over the swept coordinate.

Five panels sharing the horizontal axis (the driven joint's increment): body angles,
angular velocities, angular accelerations, point speeds |v| and accelerations |a|. Dead
points are marked by a dashed vertical line across every panel; rows the sweep could not
assemble (NaN) leave gaps. Points moving alike (a pin shared by two bodies) are plotted
once, under their bare name; points at rest throughout and the frame are left out.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ..errors import KinematikaError
from .style import BODY_COLOURS, INK

MAX_POINTS = 10
PANELS = (("angle", "angle (deg)"), ("omega", "ω (rad/s)"), ("alpha", "α (rad/s²)"),
          ("velocity", "speed |v|"), ("acceleration", "|a|"))
DEAD = "#c62828"


def plot_sweep(result: Any, path: Optional[Path | str] = None) -> Figure:
    """The sweep plots of `result` (a `SweepResult`), written to `path` when given (its
    suffix names the format, PNG without one)."""
    fmt = _format(Path(path)) if path is not None else None
    x = np.asarray(result.coordinate, dtype=float)
    fig = Figure(figsize=(8.0, 11.0))
    FigureCanvasAgg(fig)
    axes = fig.subplots(len(PANELS), 1, sharex=True)
    bodies = _bodies(result)
    points = _points(result)
    for ax, (quantity, ylabel) in zip(axes, PANELS):
        series = bodies if quantity in ("angle", "omega", "alpha") else points
        for i, (name, data) in enumerate(series.items()):
            ax.plot(x, _scalar(data[quantity]), lw=1.5, color=_colour(i), label=name,
                    gid=f"{quantity}:{name}")
        ax.set_ylabel(ylabel)
        ax.grid(True, lw=0.4, alpha=0.5)
        for d in getattr(result, "dead_points", []) or []:
            ax.axvline(float(d), color=DEAD, lw=1.0, ls="--", gid=f"dead:{float(d):g}")
        if series:
            ax.legend(fontsize=7.5, ncol=min(len(series), 5), loc="best", framealpha=0.8)
    unit = getattr(result, "unit", "deg")
    axes[-1].set_xlabel(f"{getattr(result, 'joint', 'joint')} increment "
                        f"({'deg' if unit == 'deg' else unit})")
    title = getattr(result, "name", "Sweep")
    if getattr(result, "dead_points", None):
        title += "  (dashed red: dead points)"
    fig.suptitle(title.replace("$", r"\$"), fontsize=12, weight="bold", color=INK)
    fig.tight_layout(rect=(0, 0, 1, 0.98))
    if path is not None:
        fig.savefig(path, dpi=100, format=fmt, facecolor="white")
    return fig


def _format(path: Path) -> str:
    """The format of `path` by its suffix; one matplotlib cannot write is refused up front."""
    fmt = path.suffix.lower().lstrip(".") or "png"
    if fmt not in FigureCanvasAgg.get_supported_filetypes():
        raise KinematikaError("schema", f"cannot plot to {path.name!r}: give a .png, .svg or .pdf file",
                              str(path))
    return fmt


def _colour(i: int) -> str:
    palette = ("#1565c0", "#c62828", "#2e7d32", "#6a1b9a", "#ef6c00", "#00838f", "#5d4037",
               "#ad1457", "#9e9d24", "#455a64")
    return palette[i % len(palette)] if i < len(palette) else BODY_COLOURS[i % len(BODY_COLOURS)]


def _scalar(values: Any) -> np.ndarray:
    """A planar scalar as is; a vector (N, dim) by its magnitude."""
    arr = np.asarray(values, dtype=float)
    return np.linalg.norm(arr, axis=1) if arr.ndim == 2 else arr


def _bodies(result: Any) -> dict[str, dict]:
    """Every body that moves (the frame and bodies at rest left out)."""
    out = {}
    for name, data in result.bodies.items():
        omega = _scalar(data["omega"])
        angle = _scalar(data.get("angle", np.zeros_like(omega)))
        if np.nanmax(np.abs(omega), initial=0.0) > 0 or np.nanmax(np.abs(angle), initial=0.0) > 0:
            out[name] = data
    return out


def _points(result: Any) -> dict[str, dict]:
    """Moving points, each motion once (named bare when shared), at most MAX_POINTS."""
    groups: dict[str, list[str]] = {}
    kept: dict[str, dict] = {}
    for key, data in result.points.items():
        v = np.asarray(data["velocity"], dtype=float)
        if not np.nanmax(np.abs(v), initial=0.0) > 0:
            continue
        same = next((k for k, d in kept.items() if _alike(d, data)), None)
        if same is None:
            kept[key] = data
            groups[key] = [key]
        else:
            groups[same].append(key)
    out = {}
    for key, data in list(kept.items())[:MAX_POINTS]:
        name = key.partition("@")[0]
        bare = sum(k.partition("@")[0] == name for k in kept) == 1
        out[name if bare else key] = data
    return out


def _alike(a: dict, b: dict) -> bool:
    return all(np.allclose(np.asarray(a[q], dtype=float), np.asarray(b[q], dtype=float),
                           rtol=1e-9, atol=1e-12, equal_nan=True)
               for q in ("position", "velocity", "acceleration"))
