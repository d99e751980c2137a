"""The local polish: designs' residuals with their analytic Jacobian, minimised.

The variables are the varied parameters, then whichever the task leaves free: START
(degrees, `--timing JOINT`), the output's zero (function generation, `--output-zero free`:
the absolute angle of its line, radians) and, for free timing, each target's crank angle
(radians: the polish moves them along the motion with the design). Each target gives its
weighted residual rows (a path: the two components of √w (P − T); a motion: those and
√w ρ Δφ; a function: √w Δψ in degrees). Their Jacobian is the closed-form four-bar's
derivatives (`explore.fourbar.pose` with tangents) times dW/dp (`linkage`: in closed form
or by central differences of the model's constructions) — the crank angles' own columns
included. The requirements are rows g ≥ 0 with their Jacobians: Grashof's six margins, the
transmission angle's two, the order of the free crank angles along the motion. Everything is
computed for K designs at once (arrays (K, rows, variables)).

During the search, `batch_lm` polishes many designs together (Levenberg–Marquardt, one
damping per design, steps projected into the parameters' intervals); the designs written
are polished last by scipy's `least_squares` (trust-region reflective, the intervals as
bounds). Both minimise the sum of the squared residuals plus the requirements as penalty
rows RHO·min(g − margin, 0), which vanish on feasible designs; for `--objective max`,
SLSQP then minimises the largest residual with the requirements as constraints.
"""
from __future__ import annotations

from typing import Optional

import numpy as np

from ..fourbar import PHI, crank_range, pose
from .problem import MARGIN, RHO, TWO_PI, FourBarTask, Scores, four_bar, wrap

DEG = 180.0 / np.pi
LM_STEPS = 25           # Levenberg–Marquardt iterations of a polish during the search


class Residuals:
    """Designs' residuals and requirement rows, as functions of the polish's variables."""

    def __init__(self, fbt: FourBarTask) -> None:
        self.fbt = fbt
        task = fbt.task
        self.n = fbt.n
        self.count = task.count
        self.free_phi = task.free_timing
        self.k_start = self.n if fbt.free_start else None
        self.k_zero = self.n + (1 if fbt.free_start else 0) if fbt.free_zero else None
        self.k_phi = self.n + int(fbt.free_start) + int(fbt.free_zero)
        self.size = self.k_phi + (self.count if self.free_phi else 0)
        self.rows_per = {"path": 2, "motion": 3, "function": 1}[task.kind]

    # variables ----------------------------------------------------------------------------
    def pack(self, z: np.ndarray, scores: Scores) -> np.ndarray:
        """The polish's variables (K, size) of designs z (K, dims) scored by `scores`."""
        z = np.atleast_2d(z)
        parts = [z[:, :self.n]]
        if self.k_start is not None:
            parts.append(z[:, self.n:self.n + 1])
        if self.k_zero is not None:
            parts.append(scores.zero[:, None])
        if self.free_phi:
            s = self.fbt.sign
            u = s * scores.phi
            u = u[:, :1] + np.mod(u - u[:, :1], TWO_PI)            # along the motion, within a turn
            turns = crank_range(four_bar(self.fbt.map.canon(z[:, :self.n]))).full[:, 0]
            later = np.where((u[:, 1:] - u[:, :1] < 1e-9) & turns[:, None], u[:, 1:] + TWO_PI, u[:, 1:])
            u[:, 1:] = later
            parts.append(s * u)
        return np.concatenate(parts, axis=1)

    def design(self, x: np.ndarray) -> np.ndarray:
        """The search's vectors (parameters, START) of the variables x (K, size)."""
        x = np.atleast_2d(x)
        z = x[:, :self.n]
        if self.k_start is not None:
            z = np.concatenate([z, np.mod(x[:, self.k_start:self.k_start + 1], 360.0)], axis=1)
        return z

    def angles(self, x: np.ndarray) -> Optional[np.ndarray]:
        """The free timing's crank angles (K, n) of the variables x, or None (timed task)."""
        return np.atleast_2d(x)[:, self.k_phi:] if self.free_phi else None

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """The parameters' intervals; the other variables are free."""
        lo = np.full(self.size, -np.inf)
        hi = np.full(self.size, np.inf)
        lo[:self.n], hi[:self.n] = self.fbt.low, self.fbt.high
        fixed = self.fbt.low == self.fbt.high
        hi[:self.n] = np.where(fixed, self.fbt.high + 1e-12 * np.maximum(1, np.abs(self.fbt.high)), hi[:self.n])
        return lo, hi

    # rows ---------------------------------------------------------------------------------
    def rows(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """For variables x (K, size): residual rows R (K, m) and their Jacobian J (K, m, size),
        requirement rows G (K, q) (≥ 0 when they hold) and theirs (K, q, size)."""
        fbt = self.fbt
        x = np.atleast_2d(x)
        k = len(x)
        p = x[:, :self.n]
        canon, jw, je = fbt.map.jacobian(p)                          # (K, NW, n), (K, 3, n)
        fb = four_bar(canon)
        dphi = np.zeros((k, self.count, self.size))                  # dφ_i / dx
        if self.free_phi:
            phi = x[:, self.k_phi:]
            dphi[:, np.arange(self.count), self.k_phi + np.arange(self.count)] = 1.0
        else:
            start = np.radians(x[:, self.k_start]) if self.k_start is not None else np.radians(fbt.start_of(p))
            phi = fb.phi0 + fbt.sign * (start[:, None] + fbt.x[None, :])
            dphi[:, :, :self.n] = jw[:, None, 9, :]
            if self.k_start is not None:
                dphi[:, :, self.k_start] = fbt.sign / DEG
        with np.errstate(all="ignore"):
            at, tg = pose(fb, phi, True)
            assert tg is not None
            r, j = self._target_rows(x, fb, canon, at, tg, jw, je, dphi)
            g, jg = self._requirement_rows(x, fb, jw)
        return r, j, g, jg

    def _chain(self, tangent: np.ndarray, jw: np.ndarray, dphi: np.ndarray) -> np.ndarray:
        """d/dx (K, c, size) of a quantity whose four-bar tangents are `tangent` (K, c, NVAR)."""
        out = tangent[..., PHI, None] * dphi
        out[..., :self.n] += np.einsum("kcv,kvn->kcn", tangent[..., :9], jw[:, :9, :])
        return out

    def _target_rows(self, x, fb, canon, at, tg, jw, je, dphi) -> tuple[np.ndarray, np.ndarray]:
        fbt, task = self.fbt, self.fbt.task
        sw = fbt.sqrtw
        if task.kind == "path":
            e = at.p - task.xy[None, :]
            de = self._chain(tg.p, jw, dphi)
            return (np.concatenate([sw * e.real, sw * e.imag], axis=1),
                    np.concatenate([sw[:, None] * de.real, sw[:, None] * de.imag], axis=1))
        line, dline = self._line(at, tg, fb, canon, jw, je, dphi)
        if task.kind == "motion":
            e = at.p - task.xy[None, :]
            de = self._chain(tg.p, jw, dphi)
            rho = canon.rho[:, None]
            turn = wrap(line - np.radians(task.angle)[None, :])
            dturn = rho[..., None] * dline
            dturn[..., :self.n] += turn[..., None] * je[:, None, 2, :]
            return (np.concatenate([sw * e.real, sw * e.imag, sw * rho * turn], axis=1),
                    np.concatenate([sw[:, None] * de.real, sw[:, None] * de.imag, sw[:, None] * dturn], axis=1))
        y = np.radians(task.angle)[None, :]
        k = len(x)
        if isinstance(task.output_zero, float):
            ref, dref = np.full(k, np.radians(task.output_zero)), np.zeros((k, self.size))
        elif self.k_zero is not None:
            ref, dref = x[:, self.k_zero], np.zeros((k, self.size))
            dref[:, self.k_zero] = 1.0
        else:
            ref, dref = self._drawn_line(fb, canon, jw, je)
        d = wrap(line - ref[:, None] - y)
        return DEG * sw * d, DEG * sw[:, None] * (dline - dref[:, None, :])

    def _line(self, at, tg, fb, canon, jw, je, dphi) -> tuple[np.ndarray, np.ndarray]:
        """The followed line's angle at each target (K, c) and its derivatives (K, c, size)."""
        if self.fbt.line == "rocker":
            u = at.b - fb.o4
            du = tg.b.copy()
            du[..., 2] -= 1.0
            du[..., 3] -= 1j
            kappa, dk = canon.kappa4, je[:, 1, :]
        else:
            u = at.b - at.a
            du = tg.b - tg.a
            kappa, dk = canon.kappa3, je[:, 0, :]
        d = (self._chain(du, jw, dphi) / u[..., None]).imag
        d[..., :self.n] += dk[:, None, :]
        return np.angle(u) + kappa[:, None], d

    def _drawn_line(self, fb, canon, jw, je) -> tuple[np.ndarray, np.ndarray]:
        """The followed line's angle in the drawn configuration (K,), and its derivatives."""
        at0, tg0 = pose(fb, fb.phi0, True)
        dphi0 = np.zeros((len(jw), 1, self.size))
        dphi0[:, 0, :self.n] = jw[:, 9, :]
        line, d = self._line(at0, tg0, fb, canon, jw, je, dphi0)
        return line[:, 0], d[:, 0, :]

    def _requirement_rows(self, x, fb, jw) -> tuple[np.ndarray, np.ndarray]:
        req, fbt = self.fbt.task.requires, self.fbt
        k = len(x)
        rows: list[np.ndarray] = []
        jac: list[np.ndarray] = []
        if req.crank_rocker or req.transmission is not None:
            o2, o4 = fb.o2[:, 0], fb.o4[:, 0]
            e = (o4 - o2) / np.abs(o4 - o2)
            dl = np.zeros((k, 4, self.size))                       # d(r1, r2, r3, r4)/dx
            dl[:, 0, :self.n] = e.real[:, None] * (jw[:, 2] - jw[:, 0]) + e.imag[:, None] * (jw[:, 3] - jw[:, 1])
            dl[:, 1:, :self.n] = jw[:, 4:7]
            lengths = np.stack([np.abs(o4 - o2), fb.r2[:, 0], fb.r3[:, 0], fb.r4[:, 0]], axis=1)    # (K, 4)
        if req.crank_rocker:
            scale = lengths.max(axis=1)[:, None]
            combos = np.array([[1, -1, 0, 0], [0, -1, 1, 0], [0, -1, 0, 1],
                               [-1, -1, 1, 1], [1, -1, -1, 1], [1, -1, 1, -1]], dtype=float)
            rows.append(lengths @ combos.T / scale)
            jac.append(np.einsum("gl,kls->kgs", combos, dl) / scale[..., None])
        if req.transmission is not None:
            cos = np.cos(np.radians(req.transmission))
            r1, r2, r3, r4 = lengths.T
            scale = 2 * r3 * r4
            for sign in (-1.0, 1.0):
                dist = r1 + sign * r2
                inner = r3 * r3 + r4 * r4 - dist * dist
                dinner = (2 * r3[:, None] * dl[:, 2] + 2 * r4[:, None] * dl[:, 3]
                          - 2 * dist[:, None] * (dl[:, 0] + sign * dl[:, 1]))
                dvalue = 2 * cos * (r4[:, None] * dl[:, 2] + r3[:, None] * dl[:, 3]) - np.sign(inner)[:, None] * dinner
                rows.append(((2 * r3 * r4 * cos - np.abs(inner)) / scale)[:, None])
                jac.append((dvalue / scale[:, None])[:, None, :])
        if req.ordered and self.free_phi:
            s, c = fbt.sign, self.count
            u = s * x[:, self.k_phi:]
            d = np.zeros((c, self.size))
            for i in range(c - 1):
                d[i, self.k_phi + i], d[i, self.k_phi + i + 1] = -s, s
            d[-1, self.k_phi], d[-1, self.k_phi + c - 1] = s, -s
            gaps = np.concatenate([np.diff(u, axis=1), u[:, :1] + TWO_PI - u[:, -1:]], axis=1)
            rows.append(gaps / TWO_PI)
            jac.append(np.broadcast_to(d / TWO_PI, (k, c, self.size)))
        if not rows:
            return np.zeros((k, 0)), np.zeros((k, 0, self.size))
        return np.concatenate(rows, axis=1), np.concatenate(jac, axis=1)

    def penalised(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Residuals with the requirements as penalty rows RHO·min(g − margin, 0) and the
        Jacobian of both (NaN residuals, where a design does not assemble, become large)."""
        r, j, g, jg = self.rows(x)
        short = g - MARGIN
        active = short < 0
        rows = np.concatenate([r, RHO * np.where(active, short, 0.0)], axis=1)
        jac = np.concatenate([j, RHO * np.where(active[..., None], jg, 0.0)], axis=1)
        bad = ~np.isfinite(rows)
        rows = np.where(bad, 1e6, rows)
        jac = np.where(np.isfinite(jac) & ~bad[..., None], jac, 0.0)
        return rows, jac


def batch_lm(fbt: FourBarTask, z: np.ndarray, scores: Scores,
             steps: int = LM_STEPS) -> tuple[np.ndarray, Optional[np.ndarray]]:
    """Many designs polished together: Levenberg–Marquardt on the penalised residuals, one
    damping λ per design (Marquardt's scaling by diag JᵀJ), steps projected into the
    parameters' intervals, a step kept only where it lowers the design's sum of squares.
    Returns the polished search vectors (K, dims) and, for free timing, the targets' crank
    angles (K, n)."""
    res = Residuals(fbt)
    x = res.pack(z, scores)
    lo, hi = res.bounds()
    x = np.clip(x, lo, hi)
    r, j = res.penalised(x)
    cost = np.einsum("km,km->k", r, r)
    lam = np.full(len(x), 1e-3)
    eye = np.eye(res.size)
    for _ in range(steps):
        jtj = np.einsum("kmi,kmj->kij", j, j)
        g = np.einsum("kmi,km->ki", j, r)
        diag = np.maximum(np.einsum("kii->ki", jtj), 1e-12)
        a = jtj + lam[:, None, None] * diag[:, :, None] * eye
        try:
            step = -np.linalg.solve(a, g[..., None])[..., 0]
        except np.linalg.LinAlgError:
            step = -g / diag
        trial = np.clip(x + np.where(np.isfinite(step), step, 0.0), lo, hi)
        rt, jt = res.penalised(trial)
        ct = np.einsum("km,km->k", rt, rt)
        better = ct < cost
        x = np.where(better[:, None], trial, x)
        r = np.where(better[:, None], rt, r)
        j = np.where(better[:, None, None], jt, j)
        cost = np.where(better, ct, cost)
        lam = np.where(better, np.maximum(lam / 3, 1e-12), np.minimum(lam * 4, 1e12))
    return res.design(x), res.angles(x)


def polish(fbt: FourBarTask, z: np.ndarray, scores: Scores, i: int,
           evaluations: int = 400) -> Optional[tuple[np.ndarray, Optional[np.ndarray]]]:
    """One design z (search vector) polished to the end: scipy's least squares, then for `max`
    a minimax step. Returns the polished search vector and free timing's crank angles, or
    None when it failed to run."""
    from scipy.optimize import least_squares

    res = Residuals(fbt)
    one = Scores(*(np.atleast_1d(getattr(scores, f))[i:i + 1] for f in ("objective", "violation", "phi", "zero",
                                                                           "start")))
    x0 = res.pack(z[None, :], one)[0]
    lo, hi = res.bounds()
    x0 = np.clip(x0, lo, hi)
    cache: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def both(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        key = x.tobytes()
        if key not in cache:
            cache.clear()
            r, j = res.penalised(x[None, :])
            cache[key] = (r[0], j[0])
        return cache[key]

    try:
        sol = least_squares(lambda x: both(x)[0], x0, jac=lambda x: both(x)[1], bounds=(lo, hi),
                            method="trf", x_scale="jac", max_nfev=evaluations, xtol=1e-13, ftol=1e-13,
                            gtol=1e-13)
    except (ValueError, np.linalg.LinAlgError):
        return None
    x = sol.x
    if fbt.task.objective == "max":
        x = minimax(res, x, lo, hi, evaluations)
    phi = res.angles(x)
    return res.design(x)[0], None if phi is None else phi[0]


def minimax(res: Residuals, x0: np.ndarray, lo: np.ndarray, hi: np.ndarray, evaluations: int) -> np.ndarray:
    """Minimise the largest weighted target error t: variables (x, t), t² ≥ each target's
    squared residual (its rows summed), the requirements g ≥ margin (SLSQP)."""
    from scipy.optimize import minimize

    per, count = res.rows_per, res.count

    def pieces(x: np.ndarray):
        r, j, g, jg = res.rows(x[None, :])
        r, j, g, jg = r[0], j[0], g[0], jg[0]
        r2 = (r.reshape(per, count) ** 2).sum(axis=0)
        dr2 = 2 * (r.reshape(per, count)[:, :, None] * j.reshape(per, count, -1)).sum(axis=0)
        return r2, dr2, g, jg

    r2, _, _, _ = pieces(x0)
    if not np.isfinite(r2).all():
        return x0
    y0 = np.concatenate([x0, [np.sqrt(r2.max())]])

    def cons(y):
        r2, _, g, _ = pieces(y[:-1])
        return np.concatenate([y[-1] ** 2 - r2, g - MARGIN])

    def cons_jac(y):
        _, dr2, _, jg = pieces(y[:-1])
        top = np.hstack([-dr2, 2 * y[-1] * np.ones((count, 1))])
        return np.vstack([top, np.hstack([jg, np.zeros((len(jg), 1))])])

    bounds = [(a if np.isfinite(a) else None, b if np.isfinite(b) else None) for a, b in zip(lo, hi)] + [(0, None)]
    try:
        sol = minimize(lambda y: y[-1], y0, jac=lambda y: np.eye(len(y))[-1], method="SLSQP",
                       constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}], bounds=bounds,
                       options={"maxiter": evaluations, "ftol": 1e-16})
    except (ValueError, np.linalg.LinAlgError):
        return x0
    return sol.x[:-1] if np.isfinite(sol.x).all() else x0
