"""Independent derivations for the spatial tests, with sympy.physics.vector.

Every expected value in tests/spatial comes from here or from a closed form written in the
test: reference frames oriented by their rotations (``orient_axis``, Euler angles),
angular velocities and accelerations from ``ang_vel_in``/``ang_acc_in``, point motion from
the two-point (and one-point) theorems, and the generalised coordinates, their rates and
accelerations replaced by numbers only at the end. Nothing here calls kinematika.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Iterable, Mapping

import pytest
import sympy as sp
from sympy.physics.mechanics import msubs
from sympy.physics.vector import Point, ReferenceFrame, Vector, dynamicsymbols

t = dynamicsymbols._t
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def coordinates(names: str) -> tuple:
    """Generalised coordinates q(t), as sympy.physics.vector dynamic symbols."""
    out = dynamicsymbols(names)
    return tuple(out) if isinstance(out, (list, tuple)) else (out,)


def instant(values: Mapping[Any, tuple]) -> dict:
    """{q: (q, q', q'')} as the substitution q'' → ., q' → ., q → . (derivatives first)."""
    subs: dict = {}
    for q, (q0, q1, q2) in values.items():
        subs[q.diff(t, 2)] = sp.nsimplify(q2)
        subs[q.diff(t)] = sp.nsimplify(q1)
        subs[q] = sp.nsimplify(q0)
    return subs


def fixed_point(name: str, frame: ReferenceFrame) -> Point:
    """A point at rest in `frame`."""
    point = Point(name)
    point.set_vel(frame, 0)
    return point


def carried(origin: Point, name: str, offset: Vector, fixed: ReferenceFrame,
            body: ReferenceFrame) -> Point:
    """The point of `body` at `offset` from `origin` (also of `body`): its velocity and
    acceleration in `fixed` by the two-point theorems."""
    point = origin.locatenew(name, offset)
    point.v2pt_theory(origin, fixed, body)
    point.a2pt_theory(origin, fixed, body)
    return point


def components(vec: Vector | Iterable, frame: ReferenceFrame, subs: Mapping | None = None) -> tuple:
    """A vector's components in `frame` (exact sympy numbers when `subs` fixes every symbol)."""
    items = vec.to_matrix(frame) if isinstance(vec, Vector) else vec
    return tuple(sp.simplify(msubs(c, subs) if subs else c) for c in items)


def floats(values: Iterable) -> list[float]:
    return [float(v) for v in values]


def assert_close(actual: Iterable, expected: Iterable, tol: float = 1e-9) -> None:
    """Component-wise equality, relative to the vector's size."""
    a, e = floats(actual), floats(expected)
    size = max([abs(x) for x in e] + [1.0])
    assert a == pytest.approx(e, abs=tol * size), f"{a} != {e}"


def cross(a: Iterable, b: Iterable) -> tuple:
    (a1, a2, a3), (b1, b2, b3) = a, b
    return (a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1)


def dot(a: Iterable, b: Iterable) -> Any:
    return sum(x * y for x, y in zip(a, b))


def plus(*vectors: Iterable) -> tuple:
    return tuple(sum(c) for c in zip(*vectors))


def minus(a: Iterable, b: Iterable) -> tuple:
    return tuple(x - y for x, y in zip(a, b))


def times(k: Any, a: Iterable) -> tuple:
    return tuple(k * x for x in a)
