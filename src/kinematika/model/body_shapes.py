"""A body's shapes as the model holds them (circles, lines, discs, planes, curves, a cam's
profile), parsed but not evaluated: `engine.instant` places them at an instant
(`kinematika.shapes`). Apart from `model.model` so that a model whose bodies have no shapes
(most linkages) never builds these classes: this module is imported with the first body
that has a shape (start-up, docs/architecture.md).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Union

from ..expressions import Direction, Expr, ExprVector


@dataclass(frozen=True)
class Circle:
    """A body's circle (a wheel, a pitch circle, a slot's arc): its centre (coordinates, or the
    named point `center_point`) and radius; `arc` (degrees, from → to counter-clockwise, in
    the model's axes at the drawing) when the body is only that part of the disc, which only
    the figures read (a semicylinder is drawn as a half-disc; its contact is on the circle)."""

    center: ExprVector               # empty when `center_point` names the point
    radius: Expr
    center_point: Optional[str] = None
    arc: Optional[tuple[float, float]] = None


@dataclass(frozen=True)
class Line:
    """A body's straight line (a road, a rack, a flat face): a point it passes through
    (coordinates, or the named point `through_point`) and its direction."""

    through: ExprVector              # empty when `through_point` names the point
    direction: "Direction"
    through_point: Optional[str] = None


@dataclass(frozen=True)
class Disc:
    """A 3D body's disc (a wheel rolling on a plane): centre (or the point `center_point`),
    radius and the axis it turns about."""

    center: ExprVector
    radius: Expr
    axis: "Direction"
    center_point: Optional[str] = None


@dataclass(frozen=True)
class Plane:
    """A 3D body's plane (the ground a disc rolls on): a point it passes through (or the point
    `through_point`) and its normal."""

    through: ExprVector
    normal: "Direction"
    through_point: Optional[str] = None


@dataclass(frozen=True)
class CurveShape:
    """A smooth curve through points (names or coordinates at the drawing), closed or not."""

    through: tuple                   # each a point's name (str) or coordinates (ExprVector)
    closed: bool = False


@dataclass(frozen=True)
class CamShape:
    """A cam's profile, from its design (`kinematika.cams`), placed at its centre, turned by
    its cam angle `angle` within the design frame, itself turned by `layout` (radians)."""

    center: ExprVector
    angle: Expr
    layout: Expr
    design: Any                      # the checked cam design (`cams.spec.CamDesign`)
    center_point: Optional[str] = None


Shape = Union[Circle, Line, Disc, Plane, CurveShape, CamShape]
