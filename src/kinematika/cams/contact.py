"""Where a follower rests on a cam of any shape: the contact search behind measured cams.

Given a cam's outline as a `Curve` (its own frame) turned by σθ, the follower is pushed onto
it from outside, so its position is the extreme one among the positions that touch a point
Q of the outline (ground frame, cam centre O at the origin):

- translating roller of radius R_f on the axis x = e: its centre's height
  y* = max over Q with |Q_x − e| ≤ R_f of  Q_y + √(R_f² − (Q_x − e)²);
- translating knife edge: the highest crossing of the outline with the axis x = e;
- translating flat face: y* = max Q_y (the face rests on the outline's highest point);
- oscillating roller (pivot A = (a, 0), arm ℓ, trace point B(ψ) = A + ℓ(−cos ψ, sin ψ)): with
  Q − A = ρ(cos γ, sin γ), the roller covers Q for π − γ − δ ≤ ψ ≤ π − γ + δ,
  cos δ = (ℓ² + ρ² − R_f²)/(2ℓρ), so ψ* = max over Q of π − γ + δ;
- oscillating knife edge: the largest ψ of the outline's crossings with the circle |Q − A| = ℓ;
- oscillating flat face n(ψ)·X = a sin ψ − f: Q is on it when
  (a − Q_x) sin ψ − Q_y cos ψ = f, i.e. ψ = β + arcsin(f/R) with R = |(a − Q_x, Q_y)|,
  β = atan2(Q_y, a − Q_x); ψ* = max over Q.

Each maximum is found on a dense sampling of the outline and refined by a bounded scalar
search in the parameter (crossings by Brent's root finder).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..curves import Curve
from .follower import Flat, Follower, Translating
from ..errors import Said

SAMPLES = 2048


def _turned(curve: Curve, theta: float, sense: int, u: np.ndarray) -> np.ndarray:
    """The outline's points at parameters u, in the ground frame with the cam turned by σθ."""
    a = sense * theta
    c, s = math.cos(a), math.sin(a)
    p = curve.point(u)
    return np.stack([c * p[..., 0] - s * p[..., 1], s * p[..., 0] + c * p[..., 1]], axis=-1)


def _touch(follower: Follower, q: np.ndarray) -> np.ndarray:
    """For each ground point Q (…, 2): the follower's coordinate (y, or ψ) at which it just
    touches Q from outside, −inf where it cannot (module docstring)."""
    contact = follower.contact
    if isinstance(follower, Translating):
        if contact.touches_with_face:
            return q[..., 1]
        dx = q[..., 0] - follower.offset
        room = contact.radius**2 - dx**2
        return np.where(room >= 0, q[..., 1] + np.sqrt(np.maximum(room, 0.0)), -np.inf)
    a, arm = follower.pivot, follower.arm
    if isinstance(contact, Flat):
        r = np.hypot(a - q[..., 0], q[..., 1])
        return np.arctan2(q[..., 1], a - q[..., 0]) + np.arcsin(np.clip(contact.face / r, -1, 1))
    d = q - np.array([a, 0.0])
    rho, gamma = np.hypot(d[..., 0], d[..., 1]), np.arctan2(d[..., 1], d[..., 0])
    k = (arm**2 + rho**2 - contact.radius**2) / (2 * arm * rho)
    psi = np.mod(math.pi - gamma + np.arccos(np.clip(k, -1, 1)), 2 * math.pi)
    return np.where((np.abs(k) <= 1) & (psi < math.pi), psi, -np.inf)


def _path_gap(follower: Follower, q: np.ndarray) -> np.ndarray:
    """For a knife edge: the signed gap between Q and the trace point's path (the axis, or the
    circle of radius ℓ about the pivot)."""
    if isinstance(follower, Translating):
        return q[..., 0] - follower.offset
    return np.hypot(q[..., 0] - follower.pivot, q[..., 1]) - follower.arm


def _knife_coordinate(follower: Follower, q: np.ndarray) -> np.ndarray:
    if isinstance(follower, Translating):
        return q[..., 1]
    return np.arctan2(q[..., 1], -(q[..., 0] - follower.pivot))


def position(curve: Curve, follower: Follower, theta: float, sense: int = 1) -> float:
    """The follower's coordinate (trace point's height y, or arm angle ψ in radians; a flat
    translating face: its height) resting on `curve` turned by σθ."""
    a, b = curve.domain
    u = np.linspace(a, b, SAMPLES, endpoint=not curve.closed)
    step = u[1] - u[0]
    q = _turned(curve, theta, sense, u)
    contact = follower.contact
    if not contact.touches_with_face and contact.radius == 0:
        return _knife(curve, follower, theta, sense, u, q)
    value = _touch(follower, q)
    i = int(np.argmax(value))
    if not np.isfinite(value[i]):
        raise ValueError(Said("cam-follower-misses"))

    def minus(x: float) -> float:
        return -float(_touch(follower, _turned(curve, theta, sense, np.array(x))))

    found = minimize_scalar(minus, bounds=(u[i] - step, u[i] + step), method="bounded",
                            options={"xatol": 1e-12 * max(1.0, b - a)})
    return max(float(value[i]), -float(found.fun))


def _knife(curve: Curve, follower: Follower, theta: float, sense: int, u: np.ndarray, q: np.ndarray) -> float:
    gap = _path_gap(follower, q)
    ends = np.roll(gap, -1) if curve.closed else np.append(gap[1:], gap[-1])
    best = -np.inf
    nxt = np.roll(u, -1) if curve.closed else np.append(u[1:], u[-1])
    if curve.closed:
        nxt[-1] += curve.domain[1] - curve.domain[0]
    for i in np.flatnonzero(gap * ends <= 0):
        lo, hi = float(u[i]), float(nxt[i])
        if lo == hi:
            continue

        def g(x: float) -> float:
            return float(_path_gap(follower, _turned(curve, theta, sense, np.array(x))))

        root = brentq(g, lo, hi, xtol=1e-14) if g(lo) * g(hi) < 0 else lo
        best = max(best, float(_knife_coordinate(follower, _turned(curve, theta, sense, np.array(root)))))
    if not np.isfinite(best):
        raise ValueError(Said("cam-knife-misses"))
    return best


def positions(curve: Curve, follower: Follower, thetas: np.ndarray, sense: int = 1) -> np.ndarray:
    """`position` at each cam angle."""
    return np.array([position(curve, follower, float(t), sense) for t in thetas])
