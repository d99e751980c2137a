"""Where the bodies are: each moving body's displacement from its drawn pose.

A body's pose is a rotation φ about the instant's reference point c and a translation t:
the material point drawn at P₀ is now at R(φ)(P₀ − c) + c + t. A small step of the
engine's unknowns (δθ, δ) — a rotation about c and a translation, the same layout as the
twists (ω, v₀ at c) — moves every point by δθ k × (P − c) + δ, so the engine's velocity
matrix is the Jacobian of the position constraints in these coordinates.
"""
from __future__ import annotations

import copy
import math
from typing import Any, Optional, Union

import numpy as np

from ..engine.instant import Instant
from ..shapes import Cam, Circle, Curve, Disc, Line, Plane
from ..joints import JointGeometry
from ..engine.levels import Unknowns


class Poses:
    """Planar poses of the moving bodies (the frame stays at its drawn pose)."""

    def __init__(self, ref: tuple, phi: dict[str, float], t: dict[str, tuple], aux: dict[str, float]):
        self.ref = ref
        self.phi = phi
        self.t = t
        self.aux = aux                      # continuous angles kept by rolling joints
        self._cs = {b: (math.cos(f), math.sin(f)) for b, f in phi.items()}

    @classmethod
    def drawn(cls, ref: tuple, bodies: list[str]) -> "Poses":
        """Every body at its drawn pose: no rotation, no translation."""
        return cls(ref, dict.fromkeys(bodies, 0.0), dict.fromkeys(bodies, (0.0, 0.0)), {})

    def angle(self, body: str) -> float:
        """`body`'s rotation φ from its drawn pose (radians; 0 for the frame)."""
        return self.phi.get(body, 0.0)

    def turn(self, body: str, vec: tuple) -> tuple:
        """A direction fixed in `body`, drawn as `vec`, now."""
        if body not in self._cs:
            return vec
        c, s = self._cs[body]
        return (c * vec[0] - s * vec[1], s * vec[0] + c * vec[1])

    def point(self, body: str, p0: tuple) -> tuple:
        """The material point of `body` drawn at `p0`, now."""
        if body not in self._cs:
            return p0
        c, s = self._cs[body]
        rx, ry = p0[0] - self.ref[0], p0[1] - self.ref[1]
        t = self.t[body]
        return (self.ref[0] + c * rx - s * ry + t[0], self.ref[1] + s * rx + c * ry + t[1])

    def stepped(self, dx: Any, unknowns: Unknowns) -> "Poses":
        """The poses after a step of the unknowns: a rotation δθ about c, then a translation δ."""
        phi, t = {}, {}
        for b, o in unknowns.offset.items():
            d_theta, dx_, dy_ = float(dx[o]), float(dx[o + 1]), float(dx[o + 2])
            c, s = math.cos(d_theta), math.sin(d_theta)
            tx, ty = self.t[b]
            phi[b] = self.phi[b] + d_theta
            t[b] = (c * tx - s * ty + dx_, s * tx + c * ty + dy_)
        return Poses(self.ref, phi, t, dict(self.aux))

    def rotation_error(self, a: Optional[str], b: str, target: float = 0.0) -> list:
        """b's rotation relative to a, minus `target` (radians)."""
        return [self.angle(b) - (self.angle(a) if a else 0.0) - target]

    def axis_angle_error(self, a: str, b: str, axis: Optional[tuple], target: float) -> float:
        """b's rotation relative to a minus `target` (radians); in the plane every axis is the
        normal, so `axis` is not needed."""
        return self.angle(b) - self.angle(a) - target


class SpatialPoses:
    """Poses of the moving bodies in 3D: a rotation matrix R about c and a translation t.

    `rotvec` keeps each body's rotation from its drawn pose as a rotation vector, continued
    from step to step (it may exceed a half turn: a crank's grows to 2π e after a turn).
    """

    def __init__(self, ref: tuple | np.ndarray, rot: dict, t: dict, rotvec: dict, aux: dict) -> None:
        self.ref = np.asarray(ref, dtype=float)
        self.rot, self.t, self.rotvec, self.aux = rot, t, rotvec, aux
        self._ref = tuple(float(c) for c in self.ref)
        self._rot: dict = {}       # each body's R as rows of floats, and its t, once read
        self._t: dict = {}

    @classmethod
    def drawn(cls, ref: tuple, bodies: list[str]) -> "SpatialPoses":
        """Every body at its drawn pose: identity rotations, zero translations and rotation
        vectors."""
        return cls(ref, {b: np.eye(3) for b in bodies}, {b: np.zeros(3) for b in bodies},
                   {b: np.zeros(3) for b in bodies}, {})

    def angle(self, body: str) -> np.ndarray:
        """`body`'s rotation from its drawn pose as a rotation vector, continued along the sweep
        (zero for the frame)."""
        return self.rotvec.get(body, np.zeros(3))

    def turn(self, body: str, vec: tuple) -> tuple:
        """A direction fixed in `body`, drawn as `vec`, now: R·vec."""
        rows = self._rows(body)
        if rows is None:
            return vec
        x, y, z = float(vec[0]), float(vec[1]), float(vec[2])
        return tuple(r0 * x + r1 * y + r2 * z for r0, r1, r2 in rows)

    def point(self, body: str, p0: tuple) -> tuple:
        """The material point of `body` drawn at `p0`, now: R(P₀ − c) + c + t."""
        rows = self._rows(body)
        if rows is None:
            return p0
        (cx, cy, cz), (tx, ty, tz) = self._ref, self._t[body]
        x, y, z = float(p0[0]) - cx, float(p0[1]) - cy, float(p0[2]) - cz
        return tuple(r0 * x + r1 * y + r2 * z + c + t for (r0, r1, r2), c, t
                     in zip(rows, (cx, cy, cz), (tx, ty, tz)))

    def _rows(self, body: str) -> Optional[list]:
        """R of `body` as three rows of floats, or None for a body that does not move (the
        frame). Kept: a pose's points and directions are read many times (a search's
        residual reads each body's a dozen times), and 3 × 3 products of Python floats are
        several times quicker than numpy's on arrays this small."""
        if body not in self._rot:
            moves = body in self.rot
            self._rot[body] = self.rot[body].tolist() if moves else None
            if moves:
                self._t[body] = tuple(float(c) for c in self.t[body])
        return self._rot[body]

    def stepped(self, dx: Any, unknowns: Unknowns) -> "SpatialPoses":
        """The poses after a step of the unknowns: the rotation exp(δθ) composed on the left of
        R (about c, the translation turned with it), then the translation δ; rotation vectors
        continued so that a turn keeps growing past π."""
        rot, t, rotvec = {}, {}, {}
        for b, o in unknowns.offset.items():
            step = exp_rotation(np.asarray(dx[o:o + 3], dtype=float))
            rot[b] = step @ self.rot[b]
            t[b] = step @ self.t[b] + np.asarray(dx[o + 3:o + 6], dtype=float)
            rotvec[b] = _continued(log_rotation(rot[b]), self.rotvec[b])
        return SpatialPoses(self.ref, rot, t, rotvec, dict(self.aux))

    def _relative(self, a: Optional[str], b: str) -> np.ndarray:
        rb = self.rot.get(b, np.eye(3))
        ra = self.rot.get(a, np.eye(3)) if a else np.eye(3)
        return rb @ ra.T

    def rotation_error(self, a: Optional[str], b: str, target: Optional[np.ndarray] = None) -> list:
        """log(R_b R_aᵀ Tᵀ): b's rotation relative to a, past the target rotation T."""
        rel = self._relative(a, b)
        if target is not None:
            rel = rel @ target.T
        return log_rotation(rel).tolist()

    def axis_angle_error(self, a: str, b: str, axis: Optional[tuple], target: float) -> float:
        """The relative rotation about the joint's axis (fixed in a, given in 3D), minus `target`."""
        assert axis is not None, "a turning joint in 3D has its axis"
        e = np.asarray(self.turn(a, axis))
        return float(log_rotation(exp_rotation(-target * e) @ self._relative(a, b)) @ e)


AnyPoses = Union[Poses, SpatialPoses]     # the poses of a planar or of a spatial sweep


def exp_rotation(w: np.ndarray) -> np.ndarray:
    """Rodrigues: the rotation by |w| about w."""
    x, y, z = float(w[0]), float(w[1]), float(w[2])
    angle = math.sqrt(x * x + y * y + z * z)
    if angle < 1e-12:
        return np.array([[1.0, -z, y], [z, 1.0, -x], [-y, x, 1.0]])
    x, y, z = x / angle, y / angle, z / angle      # the unit axis k: R = I + sin θ K + (1 − cos θ) K²,
    s, c = math.sin(angle), 1 - math.cos(angle)     # K² = k kᵀ − I, written out in floats (an array
    return np.array([[1 - c * (y * y + z * z), c * x * y - s * z, c * x * z + s * y],     # per call,
                     [c * x * y + s * z, 1 - c * (x * x + z * z), c * y * z - s * x],     # not six)
                     [c * x * z - s * y, c * y * z + s * x, 1 - c * (x * x + y * y)]])


def log_rotation(r: np.ndarray) -> np.ndarray:
    """The rotation vector of a rotation matrix (angle in [0, π])."""
    v = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]])
    angle = math.atan2(float(np.linalg.norm(v)) / 2, (np.trace(r) - 1) / 2)
    if angle < 1e-6:
        return v / 2
    if math.pi - angle > 1e-3:
        return v * (angle / (2 * math.sin(angle)))
    b = (r + np.eye(3)) / 2                       # near a half turn: b = a aᵀ (nearly)
    i = int(np.argmax(np.diag(b)))
    axis = b[:, i] / math.sqrt(b[i, i])
    return (axis if axis @ v >= 0 else -axis) * angle


def _continued(r: np.ndarray, previous: np.ndarray) -> np.ndarray:
    """Of the rotation vectors r + 2πk r̂ (the same rotation), the one nearest `previous`.

    Near no rotation (a crank back after a full turn) r̂ is round-off: the previous axis is
    taken instead, so that the crank ends at 2π about its axis rather than at 0.
    """
    angle = float(np.linalg.norm(r))
    size = float(np.linalg.norm(previous))
    if angle < 1e-6 and size > 0:
        axis = previous / size
    elif angle < 1e-12:
        return r
    else:
        axis = r / angle
    candidates = [r + 2 * math.pi * k * axis for k in range(-3, 4)]
    return min(candidates, key=lambda c: float(np.linalg.norm(c - previous)))


def moved_instant(base: Instant, poses: AnyPoses, owners: dict[str, str]) -> Instant:
    """The drawn instant with every point and shape carried by its body to the new poses."""
    inst = copy.copy(base)           # as dataclasses.replace(base): the same fields, shared
    inst.body_turn = poses.turn
    inst.points = {name: poses.point(owners[name], p) for name, p in base.points.items()}
    inst.shapes = {body: [_moved_shape(s, body, poses) for s in shapes]
                   for body, shapes in base.shapes.items()}
    return inst


def _moved_shape(s: Any, body: str, poses: AnyPoses) -> Any:
    if isinstance(s, Circle):
        return Circle(poses.point(body, s.center), s.radius, s.center_point)
    if isinstance(s, Line):
        return Line(poses.point(body, s.through), poses.turn(body, s.direction), s.through_point)
    if isinstance(s, Disc):
        return Disc(poses.point(body, s.center), s.radius, poses.turn(body, s.axis), s.center_point)
    if isinstance(s, Plane):
        return Plane(poses.point(body, s.through), poses.turn(body, s.normal), s.through_point)
    if isinstance(s, Curve):
        return _moved_curve(s, body, poses)
    if isinstance(s, Cam):
        turned = _turned_by(body, poses)
        theta = s.angle + s.design.sense * turned if s.turns else s.angle
        return Cam(s.design, _moved_curve(s.profile, body, poses), _moved_curve(s.pitch, body, poses),
                   tuple(poses.point(body, s.center)), theta, s.layout, s.turns)
    return s


def _turned_by(body: str, poses: AnyPoses) -> float:
    """How far a planar body has turned from the drawing."""
    e = poses.turn(body, (1.0, 0.0))
    return math.atan2(e[1], e[0])


def _moved_curve(s: Curve, body: str, poses: AnyPoses) -> Curve:
    """A placed curve carried by its body: its origin moved, its axis turned."""
    return Curve(s.curve, tuple(poses.point(body, s.origin)), s.angle + _turned_by(body, poses), s.role)


def moved_geometry(geo: JointGeometry, poses: AnyPoses, inst: Instant) -> JointGeometry:
    """A joint's drawn geometry carried by its bodies: `at` by the second body, directions by
    the body they are fixed in (the first; the second for a wheel)."""
    j = geo.joint
    owner = j.kind.along_body(j)
    out = JointGeometry(j)
    if geo.at is not None:
        out.at = poses.point(j.b, geo.at)
    if geo.along is not None:
        out.along = poses.turn(owner, geo.along)
    if geo.axis is not None:
        out.axis = poses.turn(j.a, geo.axis)
    out.perps = [poses.turn(owner, p) for p in geo.perps]
    found = j.kind.moved(out, inst, poses.aux.get(j.id))   # a contact found anew where it has moved
    return found if found is not None else out
