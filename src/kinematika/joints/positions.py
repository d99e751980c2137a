"""The position forms of joint conditions, for sweeps: each kind's `residual` is the
integral of its rows, so that the engine's velocity matrix is their Jacobian in the pose
coordinates of `sweep.poses`. They work on a pose `q` (duck-typed: `q.point(body, P)` the
drawn point P carried by body, `q.turn(body, e)` a drawn direction turned with it,
`q.angle(body)`, `q.rotation_error(a, b)`, `q.aux` a sweep's remembered values)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Callable

if TYPE_CHECKING:
    from .seam import Pose


Residual = Callable[["Pose", float], list]     # (poses, increment) -> residual rows


def differences(p: Any, r: Any) -> list:
    """p − r, component by component."""
    return [x - y for x, y in zip(p, r)]


def dot(p: Any, r: Any) -> float:
    """p · r = Σ pᵢrᵢ, for the residuals (duck-typed: floats, arrays over designs or compiled
    terms)."""
    return sum(x * y for x, y in zip(p, r))


def coincide(q: Pose, a: str, b: str, p0: tuple) -> list:
    """The material points of a and b drawn at p0, apart by this much (pins, welds)."""
    return differences(q.point(b, p0), q.point(a, p0))


def across(q: Pose, a: str, b: str, p0: tuple, perps: list) -> list:
    """The offset of b's point from a's across each direction fixed in a (sliding pairs)."""
    gap = differences(q.point(b, p0), q.point(a, p0))
    return [dot(gap, q.turn(a, n)) for n in perps]


def axis_kept(q: Pose, a: str, b: str, axis: tuple, perps: list) -> list:
    """3D: b's axis stays along a's: e_b·p₂ and e_b·p₁ (p₁, p₂ ⊥ e fixed in a), signed so that
    their rates are the engine's rows (ω_b − ω_a)·p₁ and (ω_b − ω_a)·p₂."""
    e = q.turn(b, axis)
    return [-dot(e, q.turn(a, perps[1])), dot(e, q.turn(a, perps[0]))]


def wrap(x: float) -> float:
    """An angle in [−π, π)."""
    return (x + math.pi) % (2 * math.pi) - math.pi


def continued(q: Pose, key: str, psi0: float, d: Any) -> float:
    """The angle of d, continued from the value remembered under `key` (no jump of 2π)."""
    psi = q.aux.get(key, psi0)
    return psi + wrap(math.atan2(d[1], d[0]) - psi)
