"""Vectors as tuples, and the planar and spatial products the kinematics is written with.

Components may be floats, sympy expressions or the engine's linear forms: only ``+ - *``
are used. In a planar space an angular quantity is a scalar (its z component) and
``cross(w, r)`` is ``w k × r``; in space it is a 3-vector. Joints and questions are
written once against this interface.
"""
from __future__ import annotations

import operator
from typing import Any, Sequence

Vec = tuple


def add(a: Sequence, b: Sequence) -> Vec:
    """a + b, component by component."""
    return tuple(map(operator.add, a, b))      # x + y, pairwise (map: no generator per call)


def sub(a: Sequence, b: Sequence) -> Vec:
    """a − b, component by component."""
    return tuple(map(operator.sub, a, b))


def scale(k: Any, a: Sequence) -> Vec:
    """k·a: each component times the scalar k."""
    return tuple(k * x for x in a)


def dot(a: Sequence, b: Sequence) -> Any:
    """a · b = Σ aᵢbᵢ (started from the integer 0, so that exact and linear components stay
    exact)."""
    total: Any = 0
    for x, y in zip(a, b):
        total = total + x * y
    return total


def cross3(a: Sequence, b: Sequence) -> Vec:
    """a × b of two 3-vectors: (a_y b_z − a_z b_y, a_z b_x − a_x b_z, a_x b_y − a_y b_x)."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


class Space:
    """The products of a planar (dim 2) or spatial (dim 3) model."""

    def __init__(self, dim: int) -> None:
        self.dim = dim
        self.rot = 1 if dim == 2 else 3   # components of an angular velocity

    def cross(self, w: Any, r: Sequence) -> Vec:
        """Angular quantity × vector (ω × r)."""
        if self.dim == 2:
            return (-w * r[1], w * r[0])
        return cross3(w, r)

    def cross_ww(self, w1: Any, w2: Any) -> Any:
        """Angular × angular (ω1 × ω2): zero in the plane."""
        if self.dim == 2:
            return 0
        return cross3(w1, w2)

    def cross_vv(self, a: Sequence, b: Sequence) -> Any:
        """Vector × vector: a scalar (z component) in the plane, a vector in space."""
        if self.dim == 2:
            return a[0] * b[1] - a[1] * b[0]
        return cross3(a, b)

    def rot_components(self, w: Any) -> tuple:
        """An angular quantity as a tuple of components (1 in the plane, 3 in space)."""
        return (w,) if self.dim == 2 else tuple(w)

    def rot_zero(self) -> Any:
        """A zero angular quantity: 0 in the plane, (0, 0, 0) in space."""
        return 0 if self.dim == 2 else (0, 0, 0)

    def rot_sub(self, a: Any, b: Any) -> Any:
        """ω₁ − ω₂ of two angular quantities (scalars in the plane, 3-vectors in space)."""
        return a - b if self.dim == 2 else sub(a, b)

    def rot_dot(self, a: Any, b: Any) -> Any:
        """ω₁ · ω₂ of two angular quantities (a plain product in the plane)."""
        return a * b if self.dim == 2 else dot(a, b)

    def zero(self) -> Vec:
        """The zero vector of the space's dimension."""
        return (0,) * self.dim

    def perpendiculars(self, u: Sequence, sqrt: Any) -> list[Vec]:
        """Unit vectors perpendicular to the unit vector `u` (1 in the plane, 2 in space)."""
        if self.dim == 2:
            return [(-u[1], u[0])]
        # pick the coordinate axis least aligned with u, then Gram-Schmidt
        ax = min(range(3), key=lambda i: _magnitude_hint(u[i]))
        e = tuple(1 if i == ax else 0 for i in range(3))
        p1 = sub(e, scale(dot(e, u), u))
        p1 = scale(1 / sqrt(dot(p1, p1)), p1)
        return [p1, cross3(u, p1)]


def _magnitude_hint(x: Any) -> float:
    try:
        return abs(float(x))
    except (TypeError, ValueError):
        return 1.0 if x != 0 else 0.0
