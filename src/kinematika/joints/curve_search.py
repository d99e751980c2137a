"""Where an outline touches a placed curve (`shapes.Curve`: a spline, a cam's profile or pitch
curve): the curve's parameter at the contact, for the higher pairs (`touching`) at an instant
and along a sweep (the previous contact's parameter `near`, followed by Newton's method).

- **A circle** of radius r about c touches the curve where the distance |P(u) − c| is
  stationary — g(u) = (P − c)·P′ = 0 — and equal to r: at its nearest point when the circle
  is outside the curve or in a hollow of it, at its farthest when the curve is inside the
  circle (a ring about a cam). Every stationary point of the sampled distance is refined
  (Newton's method kept inside its bracket, g changing sign there) and the one whose
  distance is nearest r is the contact (`circle_contact`). A point is the circle of radius 0.
- **A line** with unit normal m through q touches it at the curve's point lowest along m:
  (P − q)·m least, where P′·m = 0 (`support`).
- **Two curves** touch where the tangent of a is perpendicular to b's normal at a's point's
  nearest point on b: s(u) = t_a(u)·n_b(v(u)) = 0 with v(u) the nearest parameter on b
  (the distance of P_a(u) from b is then stationary in u); s has a simple root while the
  curvatures differ (a secant iteration), unlike the distance between the two parameters,
  whose Hessian is singular at a touch (`curves_contact`; along a sweep from the last
  contact's pair of parameters).
"""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

SAMPLES = 2048               # points of a global search along a curve
ITERATIONS = 60


def _jet(curve: Any, u: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """P, P′, P″ at u in the model's axes (the curve's own turned by its placing)."""
    c, s = math.cos(curve.angle), math.sin(curve.angle)
    turn = np.array([[c, s], [-s, c]])                     # row vectors times Rᵀ
    p, d1, d2 = curve.curve.derivatives(u)
    return np.asarray(curve.origin, dtype=float) + p @ turn, d1 @ turn, d2 @ turn


def _grid(curve: Any) -> np.ndarray:
    a, b = curve.curve.domain
    return np.linspace(a, b, SAMPLES, endpoint=not curve.curve.closed)


def circle_contact(curve: Any, c: np.ndarray, radius: float, near: Optional[float] = None) -> float:
    """The parameter where a circle of `radius` about c touches the curve (see the module):
    from `near` by Newton's method when it converges there, else the global search."""
    if near is not None:
        u = _newton_from(curve, c, float(near))
        if u is not None:
            return u
    grid = _grid(curve)
    dist = np.linalg.norm(curve.point(grid) - c, axis=-1)
    closed = curve.curve.closed
    before = np.roll(dist, 1) if closed else np.concatenate([[np.nan], dist[:-1]])
    after = np.roll(dist, -1) if closed else np.concatenate([dist[1:], [np.nan]])
    lows = (dist <= before) & (dist <= after)
    highs = (dist >= before) & (dist >= after)
    if not closed:                                  # an end is a candidate too
        lows[[0, -1]] = highs[[0, -1]] = True
    step = float(grid[1] - grid[0])
    best, best_miss = float(grid[int(np.argmin(np.abs(dist - radius)))]), np.inf
    for i in np.flatnonzero(lows | highs):
        u = _bracketed(curve, c, float(grid[i]) - step, float(grid[i]) + step)
        miss = abs(float(np.linalg.norm(curve.point(u) - c)) - radius)
        if miss < best_miss:
            best, best_miss = u, miss
    return float(curve.curve.wrap(best))


def _g(curve: Any, c: np.ndarray, u: float) -> tuple[float, float]:
    """g = (P − c)·P′ and g′ = |P′|² + (P − c)·P″."""
    p, d1, d2 = _jet(curve, u)
    return float((p - c) @ d1), float(d1 @ d1 + (p - c) @ d2)


def _newton_from(curve: Any, c: np.ndarray, u: float) -> Optional[float]:
    """Plain Newton on g from a hint (a sweep's previous contact); None if it wanders off
    (more than a quarter of the domain), does not settle, or settles on a stationary point of
    the other kind (a farthest point for a nearest one: g′ of the other sign there than at
    the hint, the sign read from the steps' own g′)."""
    a, b = curve.curve.domain
    width = (b - a) / 4 if np.isfinite(b - a) else max(1.0, abs(u))
    x, kind = u, None
    for _ in range(16):
        g, slope = _g(curve, c, x)
        if slope == 0:
            return None
        kind = slope > 0 if kind is None else kind
        step = g / slope
        x -= step
        if abs(x - u) > width:
            return None
        if abs(step) <= 1e-13 * max(1.0, abs(x)):
            return float(curve.curve.wrap(x)) if (slope > 0) == kind else None
    return None


def _bracketed(curve: Any, c: np.ndarray, lo: float, hi: float) -> float:
    """A root of g in [lo, hi] (open curves: within the domain), Newton's steps kept inside
    the bracket, else bisection; an end when g keeps its sign (the curve's end)."""
    a, b = curve.curve.domain
    if not curve.curve.closed:
        lo, hi = max(lo, a), min(hi, b)
    g_lo, g_hi = _g(curve, c, lo)[0], _g(curve, c, hi)[0]
    if g_lo * g_hi > 0:
        return lo if abs(g_lo) < abs(g_hi) else hi
    u = (lo + hi) / 2
    for _ in range(ITERATIONS):
        g, slope = _g(curve, c, u)
        if (g < 0) == (g_lo < 0):
            lo, g_lo = u, g
        else:
            hi = u
        nxt = u - g / slope if slope != 0 else None
        nxt = nxt if nxt is not None and lo < nxt < hi else (lo + hi) / 2
        if abs(nxt - u) <= 1e-15 * max(1.0, abs(u)) or hi - lo <= 1e-15 * max(1.0, abs(u)):
            return nxt
        u = nxt
    return u


def support(curve: Any, q: np.ndarray, m: np.ndarray, near: Optional[float] = None) -> tuple[float, float]:
    """The curve's point lowest along m from the line through q (a flat face touching a cam):
    (u, height); from `near`, else the lowest of the samples, then Newton on P′·m = 0."""
    if near is None:
        grid = _grid(curve)
        u = float(grid[int(np.argmin((curve.point(grid) - q) @ m))])
    else:
        u = float(near)
    for _ in range(ITERATIONS):
        _, d1, d2 = _jet(curve, u)
        g, dg = float(d1 @ m), float(d2 @ m)
        if dg <= 0:
            if near is not None:                 # not a lowest point there: search it all
                return support(curve, q, m)
            break
        step = g / dg
        u = float(curve.curve.wrap(u - step))
        if abs(step) < 1e-14 * max(1.0, abs(u)):
            break
    return u, float((curve.point(u) - q) @ m)


def curves_contact(ca: Any, cb: Any, near: Optional[tuple[float, float]] = None) -> tuple[float, float]:
    """(u, v): where curve a (at u) touches curve b (at v), see the module: from `near` (the
    previous contact's (u, v)) or from the closest of sampled pairs, then secant steps on s(u)."""
    if near is None:
        pb = cb.points(512)[::8]
        ua = np.array([ca.nearest(p) for p in pb])
        k = int(np.argmin(np.linalg.norm(ca.point(ua) - pb, axis=-1)))
        u = float(ua[k])
        v = float(cb.nearest(ca.point(u)))
    else:
        u, v = (float(x) for x in near)

    def s(x: float, hint: float) -> tuple[float, float]:
        w = cb.nearest(ca.point(x), hint)
        return float(ca.tangent(x) @ cb.normal(w)), w      # a closed curve wraps x itself

    f0, v = s(u, v)
    a, b = ca.curve.domain
    h = 1e-6 * ((b - a) if np.isfinite(b - a) else max(1.0, abs(u)))
    u1 = u + h
    f1, v1 = s(u1, v)
    for _ in range(ITERATIONS):
        if f1 == f0 or abs(f1) < 1e-15:
            break
        u2 = u1 - f1 * (u1 - u) / (f1 - f0)
        u, f0, v = u1, f1, v1
        u1 = float(u2 if ca.curve.closed else ca.curve.wrap(u2))
        f1, v1 = s(u1, v)
        if abs(u1 - u) <= 1e-14 * max(1.0, abs(u1)):
            break
    return float(ca.curve.wrap(u1)), v1
