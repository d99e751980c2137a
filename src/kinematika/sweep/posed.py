"""A model at another configuration: one row of a motion written back as a model.

`move` and `--assembly` analyse the mechanism somewhere other than where it is drawn. The
position analysis (a sweep's row) gives every body's rotation and every material point's
place; this module writes that configuration as an ordinary `Model` with numeric
coordinates, so that every command and view works on it unchanged.

A point name listed by bodies that move differently there (a pin in a slot, a drawn
contact) names one place at the new instant (`Model.place_owner`: the pin's material
point, else the first moving carrier's); the others' points of that name are the points
of those bodies that coincide with it, as in the sweep's rows. Directions fixed in a body
turn with it; a direction given by two points stays so when both points belong to that
body there. Rolling joints find their new contact themselves.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any, Optional

import numpy as np

from ..engine.instant import instantiate
from ..errors import KinematikaError
from ..expressions import Expr, ExprVector, parse
from ..model.body_shapes import CamShape, Circle, CurveShape, Disc, Line, Plane
from ..model.model import Body, Direction, Joint, Model
from ..point_pair import PointPair
from ..model.constructions import Construction
from .result import SweepResult


def posed_model(model: Model, result: SweepResult, row: int = -1) -> Model:
    """`model` at row `row` of `result` (a sweep of it, or its assembly search)."""
    pose = _Pose(model, result, row)
    points: dict[str, ExprVector | Construction] = {name: _numbers(pose.location(name)) for name in model.points}
    posed = dataclasses.replace(
        model, points=points, move={},
        bodies={name: _moved_body(pose, b) for name, b in model.bodies.items()},
        joints=[_moved_joint(pose, j) for j in model.joints],
        drivers=[_moved_driver(pose, d) for d in model.drivers])
    return _contacts_placed(posed, pose)


class _Pose:
    """Rotations and material-point places of every body at one row."""

    def __init__(self, model: Model, result: SweepResult, row: int) -> None:
        self.model, self.result, self.row = model, result, row
        self.inst = instantiate(model, False)          # the drawn instant: directions, shapes
        self.rot = {b: _rotation(result.bodies[b]["angle"][row], model.dimension) for b in model.bodies}
        self.owner = {name: model.place_owner(name) for name in model.points}

    def material(self, point: str, body: str) -> np.ndarray:
        return np.asarray(self.result.points[f"{point}@{body}"]["position"][self.row], dtype=float)

    def location(self, point: str) -> np.ndarray:
        return self.material(point, self.owner[point])

    def carried(self, body: str, drawn: tuple) -> np.ndarray:
        """Where the material point of `body` drawn at `drawn` is now."""
        at = np.asarray([float(c) for c in drawn])
        if body == self.model.frame:
            return at
        names = self.model.bodies[body].points
        if not names:
            raise KinematikaError("schema", "body-no-point", f"bodies.{body}", body=body)
        ref = names[0]
        return self.material(ref, body) + self.rot[body] @ (at - np.asarray(
            [float(c) for c in self.inst.points[ref]]))

    def turned(self, body: str, d: Direction, where: str) -> Direction:
        """A direction fixed in `body`, now; two points stay two points when both are the
        body's own material points there."""
        if isinstance(d, PointPair) and all(self._belongs(p, body) for p in (d.start, d.end)):
            return d
        if body == self.model.frame and not isinstance(d, PointPair):
            return d
        drawn = np.asarray([float(c) for c in self.inst.direction(d, where)])
        return _numbers(self.rot[body] @ drawn)

    def own(self, point: str, body: str) -> bool:
        """Whether the point's name stands, at this row, for `body`'s material point."""
        return point in self.model.bodies[body].points and self._belongs(point, body)

    def _belongs(self, point: str, body: str) -> bool:
        classes = self.model.motion_classes(point, self.model.carriers(point))
        return any(body in c and self.owner[point] in c for c in classes)


def _moved_body(pose: _Pose, body: Body) -> Body:
    """The body's shapes carried by it: centres and points moved, directions turned, a
    disc cam's angle advanced by the body's turn (its program goes on as it turns: θ + σΔ,
    as `sweep.poses` moves it), a curve through the body's own points kept through them."""
    where = f"bodies.{body.name}"
    return dataclasses.replace(body, points=list(body.points),
                               shapes=[_moved_shape(pose, body.name, s, where) for s in body.shapes])


def _moved_shape(pose: _Pose, name: str, s: Any, where: str) -> Any:
    def place(coords: tuple, point: Optional[str]) -> tuple:
        return () if point else _numbers(pose.carried(name, pose.inst.vector(coords, where)))

    if isinstance(s, Circle):
        return dataclasses.replace(s, center=place(s.center, s.center_point))
    if isinstance(s, Disc):
        return dataclasses.replace(s, center=place(s.center, s.center_point),
                                   axis=pose.turned(name, s.axis, f"{where}.disc.axis"))
    if isinstance(s, Line):
        return dataclasses.replace(s, through=place(s.through, s.through_point),
                                   direction=pose.turned(name, s.direction, f"{where}.line.direction"))
    if isinstance(s, Plane):
        return dataclasses.replace(s, through=place(s.through, s.through_point),
                                   normal=pose.turned(name, s.normal, f"{where}.plane.normal"))
    if isinstance(s, CurveShape):
        through = tuple(p if isinstance(p, str) and pose.own(p, name) else
                        _numbers(pose.carried(name, pose.inst.points[p] if isinstance(p, str) else
                                              pose.inst.vector(p, f"{where}.curve")))
                        for p in s.through)
        return dataclasses.replace(s, through=through)
    assert isinstance(s, CamShape)
    angle = s.angle
    if not _translates(s.design.cam):
        turned = math.radians(float(pose.result.bodies[name]["angle"][pose.row]))
        drawn = float(pose.inst.value(s.angle, f"{where}.cam.angle"))
        angle = parse(drawn + s.design.cam.sense * turned)
    return dataclasses.replace(s, center=place(s.center, s.center_point), angle=angle)


def _translates(design: Any) -> bool:
    """A plate (translating) cam: it slides, and its program's place is its centre's."""
    from ..cams.profile import PlateCam

    return isinstance(design, PlateCam)


def _moved_joint(pose: _Pose, j: Joint) -> Joint:
    fixed_in = j.kind.along_body(j)
    along = pose.turned(fixed_in, j.along, f"{j.where}.along") if j.along is not None else None
    axis = pose.turned(j.a, j.axis, f"{j.where}.axis") if j.axis is not None else None
    return dataclasses.replace(j, along=along, axis=axis)


def _moved_driver(pose: _Pose, d: Any) -> Any:
    """A driver now: a velocity's direction is fixed in its frame of reference; a 3D ω along
    the axis of the revolute joining its bodies (that joint's rate, `joint_rates`) turns with
    that axis."""
    if d.kind == "omega" and isinstance(d.value, tuple):
        from .joint_rates import as_joint_rate

        if as_joint_rate(pose.model, pose.inst, d) is None:
            return dataclasses.replace(d)
        turn = pose.rot[d.relative_to or pose.model.frame]
        value = _numbers(turn @ np.array([float(c) for c in pose.inst.vector(d.value, d.where)]))
        accel = d.accel
        if isinstance(accel, tuple):
            accel = _numbers(turn @ np.array([float(c) for c in pose.inst.vector(accel, d.where)]))
        return dataclasses.replace(d, value=value, accel=accel)
    if d.kind != "velocity" or d.along is None or d.relative_to is None:
        return dataclasses.replace(d)
    return dataclasses.replace(d, along=pose.turned(d.relative_to, d.along, f"{d.where}.along"))


def _contacts_placed(model: Model, pose: _Pose) -> Model:
    """Rolling joints find their new contact themselves: the point that named the drawn
    contact (`at`) is now a material point that has rolled away."""
    joints = [dataclasses.replace(j, at=None) if j.kind.rolls else j for j in model.joints]
    return dataclasses.replace(model, joints=joints)


def _rotation(angle: Any, dim: int) -> np.ndarray:
    """The rotation by `angle` (degrees; a rotation vector in 3D)."""
    if dim == 2:
        t = math.radians(float(angle))
        return np.array([[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]])
    from .poses import exp_rotation

    return exp_rotation(np.radians(np.asarray(angle, dtype=float)))


def _numbers(values: Any) -> tuple[Expr, ...]:
    """Coordinates as the model's expressions (exact float literals)."""
    out = []
    for v in values:
        v = float(v)
        if not math.isfinite(v):
            raise KinematikaError("assembly", "cannot-assemble-there")
        out.append(parse(v + 0.0))
    return tuple(out)
