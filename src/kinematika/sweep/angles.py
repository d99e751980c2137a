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


def body_angle(result: Any, body: str) -> Optional[np.ndarray]:
    """The absolute angle (degrees, continuous) of the body's line: from its fixed pivot (or
    its first point) to its next point elsewhere; None for a body with one point (planar)."""
    keys = [k for k in result.points if k.partition("@")[2] == body]
    pos = {k: np.asarray(result.points[k]["position"], dtype=float)[:, :2] for k in keys}
    if not pos or getattr(result, "dimension", 2) != 2:
        return None
    scale = max(float(np.nanmax(np.abs(p))) for p in pos.values()) or 1.0
    fixed = [k for k, p in pos.items() if np.nanmax(np.abs(p - p[0]), initial=0.0) <= 1e-9 * scale]
    origin = fixed[0] if fixed else keys[0]
    other = next((k for k in keys if np.linalg.norm(pos[k][0] - pos[origin][0]) > 1e-9 * scale),
                 None)
    if other is None:
        return None
    d = pos[other] - pos[origin]
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
