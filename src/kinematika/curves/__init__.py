"""Planar curves fixed in a body: lines, circles and arcs, splines through points, cam
profiles — one interface (`Curve`: point, d1, d2, tangent, normal, curvature, nearest,
length, closed, domain, points), numeric (numpy), each kind in its own module."""
from __future__ import annotations

from .base import Curve
from .cam_profile import CamProfile
from .circle import Arc, Circle
from .jet import Jet
from .line import Line
from .spline import Spline

__all__ = ["Arc", "CamProfile", "Circle", "Curve", "Jet", "Line", "Spline"]
