"""Exact starting designs, where closed forms give them.

- **Function generation, Freudenstein's equation.** With the crank at φ and the rocker at ψ
  (both from the ground line), ground d, crank a, coupler b, rocker c, the loop closes when

      K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ),   K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac),

  linear in K1, K2, K3: three precision points (φj, ψj) give them exactly (more points: in
  the least-squares sense), and a = d/K1, c = d/K2, b² = a² + c² + d² − 2ac K3. The zeros
  the task leaves free are tried on a grid.
- **Motion generation, Burmester.** A point z of the moving body (in the first pose's frame:
  origin the task's point, x along its line) is at pj(z) = Pj + e^{iαj} z in pose j. Three
  poses put any z on a circle (its centre, the circumcentre, is a fixed pivot); four put z
  on a circle only on the circle-point curve, Im of the cross-ratio
  (p1 − p3)(p2 − p4) / ((p1 − p4)(p2 − p3)) = 0, found along lines of the plane by its sign
  changes and bisection; five only at the Burmester points, where the curves of poses
  1234 and 1235 cross (Newton from a grid). Two such points and their centres are a
  four-bar through the poses.

Each candidate is a four-bar's numbers; it becomes a design through the model's map
(`linkage`: in closed form, or by least squares on the model's constructions), must keep the
model's branch, and is scored like any design: the search starts from the best.
"""
from __future__ import annotations

import itertools
from typing import Optional

import numpy as np

from ..fourbar import FourBar, pose
from .linkage import Canon, CarriedMap
from .problem import FourBarTask, wrap

GRID = 12               # free zeros tried per turn
MOST = 24               # candidates kept


def starts(fbt: FourBarTask) -> list[np.ndarray]:
    """Designs (search vectors) that meet the targets exactly or nearly, best first."""
    task = fbt.task
    if task.kind == "function" and fbt.line == "rocker":
        candidates = _freudenstein(fbt)
    elif task.kind == "motion" and task.free_timing and task.count in (3, 4, 5):
        candidates = _burmester(fbt)
    else:
        return []
    if not candidates:
        return []
    z = np.array(candidates)
    s = fbt.evaluate(z)
    order = np.lexsort((s.objective, s.violation > 0))
    return [z[i] for i in order[:MOST] if np.isfinite(s.objective[i])][:4]


# designs from numbers -----------------------------------------------------------------------
def _reference(fbt: FourBarTask) -> tuple[np.ndarray, Canon]:
    """The middle of the box and its numbers (the values a start does not choose)."""
    mid = 0.5 * (fbt.low + fbt.high)
    return mid, fbt.exact_map.canon(mid[None, :])


def design_of(fbt: FourBarTask, w: np.ndarray, kappa3: Optional[float], start: Optional[float],
              mid: np.ndarray) -> Optional[np.ndarray]:
    """The search vector whose four-bar numbers are w (and coupler line κ3), or None when the
    varied parameters cannot reach them."""
    m = fbt.map
    if isinstance(m, CarriedMap) and kappa3 is None:
        u = _coordinates(m, w)
        params = m.parameters(u[None, :])[0]
        params = np.where(np.isnan(params), mid, params)
        if not ((params >= fbt.low - 1e-9) & (params <= fbt.high + 1e-9)).all():
            return None
    else:
        params = _solve(fbt, w, kappa3, mid)
        if params is None:
            return None
    params = np.clip(params, fbt.low, fbt.high)
    got = fbt.exact_map.canon(params[None, :])
    if not np.allclose(got.w[0, :9], w[:9], rtol=1e-7, atol=1e-7 * max(1.0, np.abs(w[:9]).max())):
        return None
    z = list(params)
    if fbt.free_start:
        z.append(0.0 if start is None else float(np.mod(start, 360.0)))
    return np.array(z)


def _coordinates(m: CarriedMap, w: np.ndarray) -> np.ndarray:
    """A carried map's coordinates of the numbers w."""
    u = w.copy()
    o2, o4 = w[0] + 1j * w[1], w[2] + 1j * w[3]
    if m.polar:
        u[2], u[3] = abs(o4 - o2), np.angle(o4 - o2)
    if m.relative:
        u[9] = wrap(w[9] - np.angle(o4 - o2))
    return u


def _solve(fbt: FourBarTask, w: np.ndarray, kappa3: Optional[float], mid: np.ndarray) -> Optional[np.ndarray]:
    """Parameters whose numbers are w, by least squares on the model's constructions."""
    from scipy.optimize import least_squares

    scale = max(1.0, float(np.abs(w[:9]).max()))

    def rows(p):
        c, jw, je = fbt.exact_map.jacobian(p[None, :])
        r = (c.w[0] - w) / scale
        r[9] = wrap(c.w[0, 9] - w[9])
        j = jw[0] / scale
        j[9] = jw[0, 9]
        if kappa3 is not None:
            r = np.append(r, wrap(c.kappa3[0] - kappa3))
            j = np.vstack([j, je[0, :1]])
        bad = ~np.isfinite(r)
        return np.where(bad, 1e3, r), np.where(np.isfinite(j), j, 0.0)

    try:
        sol = least_squares(lambda p: rows(p)[0], mid, jac=lambda p: rows(p)[1], bounds=(fbt.low, fbt.high + 1e-12),
                            method="trf", max_nfev=100, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    except (ValueError, np.linalg.LinAlgError):
        return None
    return sol.x if np.max(np.abs(rows(sol.x)[0])) < 1e-8 else None


# function generation: Freudenstein --------------------------------------------------------
def _freudenstein(fbt: FourBarTask) -> list[np.ndarray]:
    """Designs from Freudenstein's equation at the targets, for each choice of the free
    zeros; the ground and the crank's drawn angle stay as in the middle of the box."""
    task = fbt.task
    mid, ref = _reference(fbt)
    if not np.isfinite(ref.w).all():
        return []
    w0 = ref.w[0]
    o2, o4 = w0[0] + 1j * w0[1], w0[2] + 1j * w0[3]
    d, theta0 = abs(o4 - o2), np.angle(o4 - o2)
    kappa = ref.kappa4[0]
    turn = np.linspace(0.0, 360.0, GRID, endpoint=False)
    if fbt.free_start:
        starts_ = turn
    else:
        starts_ = np.array([fbt.start_of(mid[None, :])[0]])
    if isinstance(task.output_zero, float):
        zeros = np.array([np.radians(task.output_zero)])
    elif task.output_zero == "free":
        zeros = np.radians(turn)
    else:
        return []                               # the drawn zero moves with the design
    x, y = fbt.x, np.radians(task.angle)
    out = []
    for start, zero in itertools.product(starts_, zeros):
        phi = w0[9] - theta0 + fbt.sign * (np.radians(start) + x)
        psi = zero + y - kappa - theta0
        lengths = _from_k(phi, psi, d, task.weights)
        if lengths is None:
            continue
        w = w0.copy()
        w[4:7] = lengths
        if not _same_branch(fbt, w, ref.sigma[0], phi + theta0, psi + theta0):
            continue
        z = design_of(fbt, w, None, start if fbt.free_start else None, mid)
        if z is not None:
            out.append(z)
    return out


def _from_k(phi: np.ndarray, psi: np.ndarray, d: float, weights: np.ndarray) -> Optional[np.ndarray]:
    """Crank, coupler, rocker from Freudenstein's K1, K2, K3 fitted to the points."""
    a_ = np.stack([np.cos(psi), -np.cos(phi), np.ones_like(phi)], axis=1)
    rhs = np.cos(phi - psi)
    sw = np.sqrt(weights)[:, None]
    k, *_ = np.linalg.lstsq(a_ * sw, rhs * sw[:, 0], rcond=None)
    if k[0] <= 0 or k[1] <= 0:
        return None
    a, c = d / k[0], d / k[1]
    b2 = a * a + c * c + d * d - 2 * a * c * k[2]
    if not b2 > 0:
        return None
    return np.array([a, np.sqrt(b2), c])


def _same_branch(fbt: FourBarTask, w: np.ndarray, sigma: float, phi: np.ndarray, psi: np.ndarray) -> bool:
    """Whether the model's branch puts the rocker at ψ (absolute) at the first target."""
    fb = FourBar(w[0] + 1j * w[1], w[2] + 1j * w[3], w[4], w[5], w[6], w[7] + 1j * w[8], sigma, w[9])
    with np.errstate(all="ignore"):
        at, _ = pose(fb, phi[:1])
    got = at.theta4(fb.o4)
    return bool(np.isfinite(got).all() and abs(wrap(got[0] - psi[0])) < 1e-6)


# motion generation: Burmester --------------------------------------------------------------
def _burmester(fbt: FourBarTask) -> list[np.ndarray]:
    """Four-bars whose coupler passes through the poses exactly, from pairs of circle points:
    those on the model's branch at every pose, reaching them without a limit position, and
    meeting the requirements, best transmission first; the few best become designs."""
    task = fbt.task
    mid, ref = _reference(fbt)
    if not np.isfinite(ref.w).all():
        return []
    p, alpha = task.xy, np.radians(task.angle)
    size = max(np.abs(p - p[0]).max(), 1e-9)
    points = circle_points(p, alpha, size)
    ranked: list[tuple[float, np.ndarray, float]] = []
    for za, zb in itertools.permutations(points, 2):
        w, kappa3, sigma = four_bar_of(p, alpha, za, zb)
        if w is None or sigma != ref.sigma[0]:
            continue
        quality = _through_poses(fbt, w, sigma, p + np.exp(1j * alpha) * za, p + np.exp(1j * alpha) * zb)
        if quality is not None:
            ranked.append((quality, w, kappa3))
    ranked.sort(key=lambda item: -item[0])
    out = []
    for _, w, kappa3 in ranked[:6]:
        z = design_of(fbt, w, kappa3, None, mid)
        if z is not None:
            out.append(z)
    return out


def _through_poses(fbt: FourBarTask, w: np.ndarray, sigma: float, qa: np.ndarray, qb: np.ndarray) -> Optional[float]:
    """The least transmission angle of a four-bar that passes through the poses on its drawn
    branch, without a limit position between them, meeting the requirements; else None."""
    from ..fourbar import crank_range, crank_rocker, least_transmission

    fb = FourBar(*(np.array([[v]]) for v in (w[0] + 1j * w[1], w[2] + 1j * w[3], w[4], w[5], w[6], w[7] + 1j * w[8],
                                             sigma, w[9])))
    phi = np.angle(qa - (w[0] + 1j * w[1]))
    with np.errstate(all="ignore"):
        at, _ = pose(fb, phi[None, :])
    if not np.allclose(at.b[0], qb, atol=1e-7 * max(1.0, np.abs(qb).max())):
        return None
    reach = crank_range(fb)
    if not reach.full[0, 0]:
        low, high = reach.low[0, 0], reach.high[0, 0]
        if (np.mod(phi - low, 2 * np.pi) > high - low + 1e-12).any():
            return None
    req = fbt.task.requires
    least = float(least_transmission(fb)[0, 0])
    if req.crank_rocker and not crank_rocker(fb)[0, 0]:
        return None
    if req.transmission is not None and least < req.transmission:
        return None
    return least + (90.0 if reach.full[0, 0] else 0.0)


def circumcentre(a: complex, b: complex, c: complex) -> complex:
    """The centre of the circle through three points."""
    d = 2 * (a.real * (b.imag - c.imag) + b.real * (c.imag - a.imag) + c.real * (a.imag - b.imag))
    if abs(d) < 1e-300:
        return complex(np.nan, np.nan)
    a2, b2, c2 = abs(a) ** 2, abs(b) ** 2, abs(c) ** 2
    return complex((a2 * (b.imag - c.imag) + b2 * (c.imag - a.imag) + c2 * (a.imag - b.imag)) / d,
                   (a2 * (c.real - b.real) + b2 * (a.real - c.real) + c2 * (b.real - a.real)) / d)


def cross_ratio_im(p: np.ndarray, alpha: np.ndarray, z: np.ndarray, which: tuple[int, int, int, int]) -> np.ndarray:
    """Im of the cross-ratio of the four positions `which` of the body points z (zero on the
    circle-point curve of those poses)."""
    q = [p[k] + np.exp(1j * alpha[k]) * z for k in which]
    return ((q[0] - q[2]) * (q[1] - q[3]) / ((q[0] - q[3]) * (q[1] - q[2]))).imag


def circle_points(p: np.ndarray, alpha: np.ndarray, size: float) -> list[complex]:
    """Body points (in the world frame at e^{iα} z about each pose's point: z in the body's
    own frame) whose positions in every pose lie on one circle."""
    n = len(p)
    grid = size * np.linspace(-2.0, 2.0, 9)
    if n == 3:
        return [complex(x, y) for x in grid[::2] for y in grid[::2] if abs(complex(x, y)) > 1e-9 * size]
    if n == 4:
        return _on_curve(p, alpha, size, (0, 1, 2, 3))
    return _burmester_points(p, alpha, size)


def _on_curve(p, alpha, size, which) -> list[complex]:
    """Points of the circle-point curve of four poses, along vertical lines of the plane."""
    out: list[complex] = []
    ys = size * np.linspace(-3.0, 3.0, 601)
    for x in size * np.linspace(-2.5, 2.5, 11):
        f = cross_ratio_im(p, alpha, x + 1j * ys, which)
        flips = np.flatnonzero(np.isfinite(f[:-1]) & np.isfinite(f[1:]) & (np.sign(f[:-1]) != np.sign(f[1:])))
        for k in flips:
            lo, hi = ys[k], ys[k + 1]
            flo = f[k]
            for _ in range(80):
                m = 0.5 * (lo + hi)
                fm = cross_ratio_im(p, alpha, np.array([x + 1j * m]), which)[0]
                if np.sign(fm) == np.sign(flo):
                    lo, flo = m, fm
                else:
                    hi = m
            z = complex(x, 0.5 * (lo + hi))
            if _concyclic(p, alpha, z, size):
                out.append(z)
    return out


def _burmester_points(p, alpha, size) -> list[complex]:
    """Where the circle-point curves of poses 1234 and 1235 cross (Newton from a grid)."""
    found: list[complex] = []
    grid = size * np.linspace(-2.5, 2.5, 11)
    for x0, y0 in itertools.product(grid, grid):
        z = complex(x0, y0)
        for _ in range(60):
            f = np.array([cross_ratio_im(p, alpha, np.array([z]), w)[0] for w in ((0, 1, 2, 3), (0, 1, 2, 4))])
            if not np.isfinite(f).all():
                break
            h = 1e-7 * size
            jac = np.array([[(cross_ratio_im(p, alpha, np.array([z + d]), w)[0] - fk) / h for d in (h, 1j * h)]
                            for w, fk in zip(((0, 1, 2, 3), (0, 1, 2, 4)), f)])
            try:
                step = np.linalg.solve(jac, -f)
            except np.linalg.LinAlgError:
                break
            z += complex(*step)
            if abs(complex(*step)) < 1e-14 * size:
                break
        if _concyclic(p, alpha, z, size) and all(abs(z - q) > 1e-6 * size for q in found):
            found.append(z)
    return found


def _concyclic(p, alpha, z: complex, size: float) -> bool:
    """Whether the body point z is on one circle in every pose (a finite one)."""
    q = p + np.exp(1j * alpha) * z
    c = circumcentre(q[0], q[1], q[2])
    if not np.isfinite(c) or abs(c - q[0]) > 1e3 * size:
        return False
    r = np.abs(q - c)
    return bool(np.max(np.abs(r - r[0])) <= 1e-9 * max(size, r[0]))


def four_bar_of(p: np.ndarray, alpha: np.ndarray, za: complex,
                zb: complex) -> tuple[Optional[np.ndarray], float, float]:
    """The four-bar with moving pivots za (the crank's) and zb (the rocker's), body points in
    the body's frame, drawn in the first pose: its numbers, the line's angle from A→B, and
    its branch σ (B left (+1) or right (−1) of A→O4)."""
    qa = p + np.exp(1j * alpha) * za
    qb = p + np.exp(1j * alpha) * zb
    o2, o4 = circumcentre(*qa[:3]), circumcentre(*qb[:3])
    if not (np.isfinite(o2) and np.isfinite(o4)) or abs(zb - za) < 1e-12:
        return None, 0.0, 0.0
    a, b = qa[0], qb[0]
    u = b - a
    c = (p[0] - a) * np.conj(u) / abs(u)
    w = np.array([o2.real, o2.imag, o4.real, o4.imag, abs(a - o2), abs(u), abs(b - o4), c.real, c.imag,
                  np.angle(a - o2)])
    d = o4 - a
    sigma = float(np.sign(d.real * u.imag - d.imag * u.real))
    return w, float(wrap(alpha[0] - np.angle(u))), sigma


__all__ = ["circle_points", "four_bar_of", "starts"]
