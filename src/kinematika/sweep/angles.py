"""A sweep's angles as a textbook gives them: each body's angle θ, its line's from the x axis
(counter-clockwise, degrees), and the input on the same footing — the angle θ of the crank
the sweep turns from the frame, else the driven joint's coordinate from the drawn position.

The sweep's plot (`draw.plots`) and its text summary (`summary`) read both here, so that
the two say the same numbers under the same names.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import numpy as np


@dataclass
class ReferenceLine:
    """A body's line as a textbook measures its angle θ: from point `start` to point `end`,
    `grounded` when `start` is its fixed pivot."""

    start: str
    end: str
    grounded: bool

    def angle(self, xy: dict[str, Any]) -> float:
        """Its angle from the x axis, counter-clockwise, degrees in (−180°, 180°], with the
        points at `xy` (name -> page position)."""
        d = np.asarray(xy[self.end], dtype=float) - np.asarray(xy[self.start], dtype=float)
        return float(np.degrees(np.arctan2(d[1], d[0])))


def reference_line(points: dict[str, Any], frame: dict[str, Any]) -> Optional[ReferenceLine]:
    """A body's reference line (its points `points`, name -> position, in the body's order;
    the frame's `frame`): from its fixed pivot — its first point the frame carries at the same
    place — else its first point, to its first other point drawn elsewhere; None for a body
    with one place. The one rule of the sweep's angles (`body_angle`), the figure's scene and
    the page's table and plot."""
    xy = {name: np.asarray(p, dtype=float)[:2] for name, p in points.items()}
    if len(xy) < 2 or any(len(np.asarray(p)) != 2 for p in points.values()):
        return None
    first = next(iter(xy.values()))
    scale = max(float(np.linalg.norm(p - first)) for p in xy.values()) or 1.0
    pinned = [name for name, p in xy.items() if name in frame and
              np.linalg.norm(np.asarray(frame[name], dtype=float)[:2] - p) <= 1e-9 * scale]
    start = pinned[0] if pinned else next(iter(xy))
    end = next((name for name, p in xy.items() if np.linalg.norm(p - xy[start]) > 1e-9 * scale), None)
    return None if end is None else ReferenceLine(start, end, bool(pinned))


def body_angle(result: Any, body: str) -> Optional[np.ndarray]:
    """The absolute angle (degrees, continuous) of the body's line (`reference_line`, at the
    first assembled row, the frame's points where the rows give them, else the body's points
    that stay put) over the rows; None for a body with one point (planar)."""
    if getattr(result, "dimension", 2) != 2:
        return None
    frame = getattr(result, "frame", "ground")
    pos = {k.partition("@")[0]: np.asarray(v["position"], dtype=float)[:, :2]
           for k, v in result.points.items() if k.partition("@")[2] == body}
    fixed = {k.partition("@")[0]: np.asarray(v["position"], dtype=float)[:, :2]
             for k, v in result.points.items() if k.partition("@")[2] == frame}
    if not pos:
        return None
    if not fixed:                 # rows without the frame's points: where it carries them is
        scale = max(float(np.nanmax(np.abs(p))) for p in pos.values()) or 1.0    # where they stay
        fixed = {n: p for n, p in pos.items() if np.nanmax(np.abs(p - p[0]), initial=0.0) <= 1e-9 * scale}
    ok = np.flatnonzero(np.all(np.isfinite(np.hstack(list(pos.values()))), axis=1))
    row = int(ok[0]) if len(ok) else 0
    line = reference_line({n: p[row] for n, p in pos.items()}, {n: p[row] for n, p in fixed.items()})
    if line is None:
        return None
    d = pos[line.end] - pos[line.start]
    return unwrap_degrees(np.arctan2(d[:, 1], d[:, 0]))


def unwrap_degrees(rad: np.ndarray) -> np.ndarray:
    """Continuous angles in degrees; NaN rows (not assembled) stay NaN."""
    out = np.full(len(rad), np.nan)
    ok = np.isfinite(rad)
    out[ok] = np.degrees(np.unwrap(rad[ok]))
    return out


def driving_body(result: Any, angles: dict[str, np.ndarray]) -> Optional[str]:
    """The body the sweep turns from the frame: its angle advances with the coordinate."""
    if getattr(result, "unit", "deg") != "deg":
        return None
    x = np.asarray(result.coordinate, dtype=float)
    for name, a in angles.items():
        ok = np.isfinite(a) & np.isfinite(x)
        if ok.sum() >= 2 and np.allclose(a[ok] - a[ok][0], x[ok] - x[ok][0], atol=1e-6):
            return name
    return None


@dataclass
class InputAxis:
    """The input as the plot's horizontal axis gives it: its values at every row, what they
    are (`label`), the crank whose angle they are (None: the joint's coordinate), and
    `shift`, what turns a coordinate into such a value (value = coordinate + shift)."""

    x: np.ndarray
    label: str
    driver: Optional[str]
    shift: float

    def at(self, coordinate: float) -> float:
        """A coordinate of the sweep (a dead point's) as a value of this axis."""
        return float(coordinate) + self.shift


def angles_of(result: Any, bodies: Optional[list[str]] = None) -> dict[str, np.ndarray]:
    """The angle θ of every body (or of `bodies`) that has a line (planar)."""
    names = bodies if bodies is not None else [b for b in result.bodies if b != getattr(result, "frame", "ground")]
    return {name: a for name in names if (a := body_angle(result, name)) is not None}


def input_axis(result: Any, angles: Optional[dict[str, np.ndarray]] = None) -> InputAxis:
    """The crank's angle θ when the sweep turns a crank from the frame, else the driven
    joint's coordinate from the drawn position."""
    angles = angles_of(result) if angles is None else angles
    driver = driving_body(result, angles)
    coordinate = np.asarray(result.coordinate, dtype=float)
    if driver is not None:
        a = angles[driver]
        ok = np.isfinite(a) & np.isfinite(coordinate)
        return InputAxis(a, f"{driver} angle θ (deg)", driver, float(a[ok][0] - coordinate[ok][0]))
    unit = getattr(result, "unit", "deg")
    if unit == "s":                                   # a simulation's rows: against time
        return InputAxis(coordinate, "time t (s)", None, 0.0)
    return InputAxis(coordinate, f"{getattr(result, 'joint', 'joint')} from the drawn position "
                                 f"({'deg' if unit == 'deg' else 'length'})", None, 0.0)
