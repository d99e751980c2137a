"""Body shapes at an instant: where a body's circle, line, disc or plane is, evaluated (on
numbers or symbols) from the model's shapes (`model.model`), and its curves (a spline
through points, a cam's profile and pitch curve), placed, on numbers. Joints with a contact
find it between them (`joints.rolling_contact`, `joints.touching`); figures draw them."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np


@dataclass
class Circle:
    """A circle (planar): its centre and radius; `arc` (degrees, from → to counter-clockwise,
    turned with its body when the model is moved) when its body is only that part of the disc
    (figures only: contacts are found on the whole circle)."""

    center: tuple
    radius: Any
    center_point: Optional[str] = None
    arc: Optional[tuple[float, float]] = None


@dataclass
class Line:
    """A straight line (planar): a point on it and its unit direction."""

    through: tuple
    direction: tuple          # unit
    through_point: Optional[str] = None


@dataclass
class Disc:
    """A disc (3D): its centre, radius and unit axis."""

    center: tuple
    radius: Any
    axis: tuple               # unit
    center_point: Optional[str] = None


@dataclass
class Plane:
    """A plane (3D): a point on it and its unit normal."""

    through: tuple
    normal: tuple             # unit
    through_point: Optional[str] = None


@dataclass
class Curve:
    """A planar curve fixed in a body at this instant: `curve` (`kinematika.curves`) in its own
    coordinates, placed so that its own origin is at `origin` and its own x axis at `angle`
    (radians) from the model's. Every method answers in the model's axes:

        P(u) = origin + R(angle)·r(u),  t, n turned alike,  κ(u) unchanged by the placing.
    """

    curve: Any
    origin: tuple = (0.0, 0.0)
    angle: float = 0.0
    role: str = "curve"          # "curve", or a cam's "profile" or "pitch"

    def _r(self) -> np.ndarray:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.array([[c, -s], [s, c]])

    def point(self, u: Any) -> np.ndarray:
        """P(u) in the model's axes."""
        return np.asarray(self.origin, dtype=float) + self.curve.point(u) @ self._r().T

    def tangent(self, u: Any) -> np.ndarray:
        """The unit tangent t(u) in the model's axes (the curve's own, turned by `angle`)."""
        return self.curve.tangent(u) @ self._r().T

    def normal(self, u: Any) -> np.ndarray:
        """The unit normal: the tangent turned +90° (the curve's left)."""
        return self.curve.normal(u) @ self._r().T

    def curvature(self, u: Any) -> Any:
        """Signed curvature κ (positive when the curve turns towards its normal)."""
        return self.curve.curvature(u)

    def own(self, p: Any) -> np.ndarray:
        """A point of the model's axes in the curve's own coordinates."""
        return (np.asarray(p, dtype=float) - np.asarray(self.origin, dtype=float)) @ self._r()

    def nearest(self, p: Any, near: Optional[float] = None) -> float:
        """The parameter of the point nearest to p (followed from `near` when given)."""
        q = self.own(p)
        return float(self.curve.near(q, near) if near is not None else self.curve.nearest(q))

    def points(self, n: int = 400) -> np.ndarray:
        """Points along it for drawing, in the model's axes."""
        return np.asarray(self.origin, dtype=float) + self.curve.points(n) @ self._r().T


@dataclass
class Cam:
    """A cam at this instant: its design (`kinematika.cams`), its profile and the pitch curve
    (the path of a roller's centre or knife edge relative to the cam), placed (`Curve`s)."""

    design: Any                  # cams.profile.DiscCam (or PlateCam)
    profile: Curve
    pitch: Curve
    center: tuple
    angle: float                 # the cam angle at this instant (where the program is), radians
    layout: float                # the design frame's turn in the model's axes, radians
    turns: bool = True           # a disc cam (False: a plate cam, which slides)
