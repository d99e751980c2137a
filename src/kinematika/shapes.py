"""Body shapes at an instant: where a body's circle, line, disc or plane is, evaluated (on
numbers or symbols) from the model's shapes (`model.model`). Rolling and gear joints find
their contact between them (`joints.contact`); figures draw them."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional


@dataclass
class Circle:
    """A circle (planar): its centre and radius."""

    center: tuple
    radius: Any
    center_point: Optional[str] = None


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
