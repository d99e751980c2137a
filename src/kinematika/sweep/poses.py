"""Where the bodies are: each moving body's displacement from its drawn pose (planar).

A body's pose is a rotation φ about the instant's reference point c and a translation t:
the material point drawn at P₀ is now at R(φ)(P₀ − c) + c + t. A small step of the
engine's unknowns (δθ, δ) — a rotation about c and a translation, the same layout as the
twists (ω, v₀ at c) — moves every point by δθ k × (P − c) + δ, so the engine's velocity
matrix is the Jacobian of the position constraints in these coordinates.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from ..engine.contact import find_contact
from ..engine.instant import Circle, Instant, Line
from ..engine.joints import JointGeometry
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
        return cls(ref, {b: 0.0 for b in bodies}, {b: (0.0, 0.0) for b in bodies}, {})

    def angle(self, body: str) -> float:
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


def moved_instant(base: Instant, poses: Poses, owners: dict[str, str]) -> Instant:
    """The drawn instant with every point and shape carried by its body to the new poses."""
    inst = replace(base)
    inst.points = {name: poses.point(owners[name], p) for name, p in base.points.items()}
    inst.shapes = {body: [_moved_shape(s, body, poses) for s in shapes]
                   for body, shapes in base.shapes.items()}
    return inst


def _moved_shape(s: Any, body: str, poses: Poses) -> Any:
    if isinstance(s, Circle):
        return Circle(poses.point(body, s.center), s.radius, s.center_point)
    if isinstance(s, Line):
        return Line(poses.point(body, s.through), poses.turn(body, s.direction), s.through_point)
    return s


def moved_geometry(geo: JointGeometry, poses: Poses, inst: Instant) -> JointGeometry:
    """A joint's drawn geometry carried by its bodies: `at` by the second body, directions by
    the body they are fixed in (the first; the second for a wheel)."""
    j = geo.joint
    owner = j.b if j.type == "wheel" else j.a
    out = JointGeometry(j)
    if geo.at is not None:
        out.at = poses.point(j.b, geo.at)
    if geo.along is not None:
        out.along = poses.turn(owner, geo.along)
    if geo.axis is not None:
        out.axis = poses.turn(j.a, geo.axis)
    out.perps = [poses.turn(owner, p) for p in geo.perps]
    if geo.contact is not None:
        out.contact = find_contact(inst, replace(j, at=None))
    return out
