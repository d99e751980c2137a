"""Rigid-body poses of many positions at once: rotations from rotation vectors, steps of
the Newton unknowns, rotation vectors continued along a sweep, and vectors fixed in bodies
computed for every pose by one product."""
from __future__ import annotations

import math

import numpy as np

from .stacked import cross, times


class LinearVectors:
    """Vectors fixed in bodies (directions, or points measured from c that move with the
    body's translation too), sums of them allowed, for many poses at once: each is linear in
    the poses, so all of them are one matrix product X W + w₀, X a pose's rotations and
    translations flattened (the frame's vectors, index −1, are the constant w₀)."""

    def __init__(self, n_bodies: int) -> None:
        self.n_bodies = n_bodies
        self.terms: list[list[tuple[int, np.ndarray, bool, float]]] = []
        self.slices: dict[str, slice] = {}

    def add(self, name: str, terms: list[list[tuple[int, np.ndarray, bool, float]]]) -> None:
        """Vectors named `name`: each a list of (body, vector, moves with t, sign)."""
        self.slices[name] = slice(len(self.terms), len(self.terms) + len(terms))
        self.terms += terms

    def compile(self) -> None:
        """Build W and w₀ from the terms added, so that a pose's vectors are X W + w₀ (X: the
        bodies' rotation matrices, then their translations, flattened); call it once after the
        last `add`."""
        b, k = self.n_bodies, len(self.terms)
        self.w, self.w0 = np.zeros((12 * b, 3 * k)), np.zeros(3 * k)
        for q, term in enumerate(self.terms):
            for body, v, moves, sign in term:
                v = sign * np.asarray(v, dtype=float)
                if body < 0:
                    self.w0[3 * q:3 * q + 3] += v
                    continue
                for i in range(3):              # (R v)_i = Σ_j R_ij v_j, R_ij at 9 body + 3 i + j
                    self.w[9 * body + 3 * i:9 * body + 3 * i + 3, 3 * q + i] += v
                    if moves:
                        self.w[9 * b + 3 * body + i, 3 * q + i] += sign

    def __call__(self, rot: np.ndarray, t: np.ndarray) -> np.ndarray:
        """Every vector at poses rot (M, B, 3, 3), t (M, B, 3): (M, K, 3). A product per
        pose (stacked): one large product would run on BLAS threads that cost more than
        they give on matrices this small."""
        m = rot.shape[0]
        x = np.concatenate([rot.reshape(m, -1), t.reshape(m, -1)], axis=1)
        return ((x[:, None, :] @ self.w)[:, 0] + self.w0).reshape(m, -1, 3)

    def part(self, v: np.ndarray, name: str) -> np.ndarray:
        """The vectors named `name` (`add`) of every pose, from the result of a call."""
        return v[:, self.slices[name]]


def perpendicular(e: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to the unit vector e."""
    u = cross(e, np.eye(3)[int(np.argmin(np.abs(e)))])
    return u / np.linalg.norm(u)


def exp_rotations(w: np.ndarray) -> np.ndarray:
    """Rodrigues on stacked rotation vectors (…, 3) → (…, 3, 3), as `poses.exp_rotation`:
    R = I + (sin θ/θ) W + ((1 − cos θ)/θ²) W², with W² = w wᵀ − θ² I; I + W below 1e-12.
    Written entry by entry (fewer passes over the arrays than the matrix form)."""
    x, y, z = w[..., 0], w[..., 1], w[..., 2]
    sq = x * x + y * y + z * z
    angle = np.sqrt(sq)
    small = angle < 1e-12
    safe = np.where(small, 1.0, angle)
    s = np.where(small, 1.0, np.sin(safe) / safe)
    c = np.where(small, 0.0, (1.0 - np.cos(safe)) / (safe * safe))
    cx, cy, cz, sx, sy, sz = c * x, c * y, c * z, s * x, s * y, s * z
    cxy, cxz, cyz = cx * y, cx * z, cy * z
    out = np.empty(w.shape[:-1] + (3, 3))
    out[..., 0, 0], out[..., 0, 1], out[..., 0, 2] = 1.0 - cy * y - cz * z, cxy - sz, cxz + sy
    out[..., 1, 0], out[..., 1, 1], out[..., 1, 2] = cxy + sz, 1.0 - cx * x - cz * z, cyz - sx
    out[..., 2, 0], out[..., 2, 1], out[..., 2, 2] = cxz - sy, cyz + sx, 1.0 - cx * x - cy * y
    return out


def stepped(rot, t, dx) -> tuple[np.ndarray, np.ndarray]:
    """Poses after a step of the unknowns, as `SpatialPoses.stepped`: R ← exp(δθ) R,
    t ← exp(δθ) t + δ."""
    d = dx.reshape(dx.shape[0], -1, 6)
    step = exp_rotations(d[..., :3])
    return step @ rot, times(step, t) + d[..., 3:]


def rotation_vectors(rots: np.ndarray) -> np.ndarray:
    """Each row's rotation vector (N, 3), continued from row to row from 0 at row 0, as the
    general path's `_continued` does: the axis kept on one side, the angle unwrapped (a crank
    ends a turn at 2π about its axis, not at 0)."""
    v = np.stack([rots[:, 2, 1] - rots[:, 1, 2], rots[:, 0, 2] - rots[:, 2, 0],
                  rots[:, 1, 0] - rots[:, 0, 1]], -1)
    angle = np.arctan2(np.linalg.norm(v, axis=-1) / 2, (np.trace(rots, axis1=1, axis2=2) - 1) / 2)
    axis = np.zeros_like(v)
    regular = (angle > 1e-6) & (math.pi - angle > 1e-3)
    axis[regular] = v[regular] / np.linalg.norm(v[regular], axis=-1, keepdims=True)
    half = math.pi - angle <= 1e-3
    for i in np.flatnonzero(half):                   # near a half turn (rare): as log_rotation
        bm = (rots[i] + np.eye(3)) / 2
        j = int(np.argmax(np.diag(bm)))
        a = bm[:, j] / math.sqrt(bm[j, j])
        axis[i] = a if a @ v[i] >= 0 else -a
    known = regular | half
    if not known.any():
        return v / 2
    # rows at (nearly) no rotation take the axis of the nearest earlier row (or the first)
    fill = np.maximum.accumulate(np.where(known, np.arange(len(v)), -1))
    axis = axis[np.where(fill < 0, int(np.argmax(known)), fill)]
    flips = np.sign(np.einsum("ki,ki->k", axis[1:], axis[:-1]))
    flips[flips == 0] = 1.0
    sign = np.r_[1.0, np.cumprod(flips)]
    return np.unwrap(sign * angle)[:, None] * (axis * sign[:, None])
