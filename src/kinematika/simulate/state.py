"""The moving bodies' poses as one vector, for the ODE solver, and its rate from the twists.

A body's pose is the sweep's (`sweep.poses`): the material point drawn at P₀ is now at
R (P₀ − c) + c + t, c the instant's reference point. In the plane a body holds (φ, tx, ty);
in space (q, t) with q = (w, x, y, z) a unit quaternion (R's), seven numbers. The engine
gives each body's twist at c, (ω, v₀) with v₀ the velocity of the material point now at c;
the point drawn at c is now at c + t, so

    φ̇ = ω,   ṫ = v₀ + ω × t,   q̇ = ½ (0, ω) ⊗ q   (ω in the ground's axes).
"""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from ..engine.levels import Unknowns
from ..sweep.poses import Poses, SpatialPoses, _continued, log_rotation


class PoseState:
    """The layout of the state vector: each moving body's numbers, in the unknowns' order."""

    def __init__(self, unknowns: Unknowns, ref: tuple, dim: int) -> None:
        self.unknowns = unknowns
        self.bodies = list(unknowns.offset)
        self.ref = tuple(float(c) for c in ref)
        self.dim = dim
        self.width = 3 if dim == 2 else 7

    @property
    def size(self) -> int:
        """The length of the state vector."""
        return self.width * len(self.bodies)

    def drawn(self) -> np.ndarray:
        """Every body at its drawn pose: no rotation (the unit quaternion), no translation."""
        y = np.zeros(self.size)
        if self.dim == 3:
            y[0::7] = 1.0
        return y

    def tolerances(self, scale: float, rtol: float) -> np.ndarray:
        """Absolute tolerances per component: `rtol` in rotations, `rtol`·scale in lengths."""
        atol = np.full(self.size, rtol)
        start = 1 if self.dim == 2 else 4
        for k in range(len(self.bodies)):
            atol[k * self.width + start:(k + 1) * self.width] = rtol * scale
        return atol

    def poses(self, y: np.ndarray, aux: Optional[dict] = None, before: Optional[Any] = None) -> Any:
        """The poses of state `y` (`Poses`, or `SpatialPoses` whose rotation vectors are
        continued from `before`'s, the previous row's)."""
        w = self.width
        aux = dict(aux or {})
        if self.dim == 2:
            phi = {b: float(y[k * w]) for k, b in enumerate(self.bodies)}
            shift = {b: (float(y[k * w + 1]), float(y[k * w + 2])) for k, b in enumerate(self.bodies)}
            return Poses(self.ref, phi, shift, aux)
        rot: dict[str, np.ndarray] = {}
        t: dict[str, np.ndarray] = {}
        rotvec: dict[str, np.ndarray] = {}
        for k, b in enumerate(self.bodies):
            q = y[k * w:k * w + 4]
            rot[b] = rotation(q)
            t[b] = np.array(y[k * w + 4:k * w + 7], dtype=float)
            previous = before.rotvec[b] if before is not None else np.zeros(3)
            rotvec[b] = _continued(log_rotation(rot[b]), previous)
        return SpatialPoses(self.ref, rot, t, rotvec, aux)

    def vector(self, poses: Any, like: np.ndarray) -> np.ndarray:
        """The state of `poses` (quaternions on the side of those of `like`)."""
        w = self.width
        y = np.empty(self.size)
        for k, b in enumerate(self.bodies):
            if self.dim == 2:
                y[k * w] = poses.phi[b]
                y[k * w + 1:k * w + 3] = poses.t[b]
                continue
            q = quaternion(poses.rot[b])
            y[k * w:k * w + 4] = q if float(q @ like[k * w:k * w + 4]) >= 0 else -q
            y[k * w + 4:k * w + 7] = poses.t[b]
        return y

    def rates(self, y: np.ndarray, twists: Any) -> np.ndarray:
        """ẏ from the engine's solution `twists` ((ω, v₀) of every body at their offsets)."""
        x = np.asarray(twists, dtype=float)
        w, u = self.width, self.unknowns
        out = np.empty(self.size)
        for k, b in enumerate(self.bodies):
            o = u.offset[b]
            if self.dim == 2:
                omega, v0 = x[o], x[o + 1:o + 3]
                tx, ty = y[k * w + 1], y[k * w + 2]
                out[k * w] = omega
                out[k * w + 1] = v0[0] - omega * ty
                out[k * w + 2] = v0[1] + omega * tx
                continue
            omega, v0 = x[o:o + 3], x[o + 3:o + 6]
            q = y[k * w:k * w + 4]
            qw, qv = q[0], q[1:]
            out[k * w] = -0.5 * float(omega @ qv)
            out[k * w + 1:k * w + 4] = 0.5 * (qw * omega + np.cross(omega, qv))
            out[k * w + 4:k * w + 7] = v0 + np.cross(omega, y[k * w + 4:k * w + 7])
        return out


def rotation(q: np.ndarray) -> np.ndarray:
    """The rotation matrix of the quaternion q = (w, x, y, z), normalised."""
    w, x, y, z = np.asarray(q, dtype=float) / math.sqrt(float(np.dot(q, q)))
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def quaternion(r: np.ndarray) -> np.ndarray:
    """The unit quaternion (w, x, y, z) of a rotation matrix (scipy's, reordered)."""
    from scipy.spatial.transform import Rotation

    x, y, z, w = Rotation.from_matrix(r).as_quat()
    return np.array([w, x, y, z])
