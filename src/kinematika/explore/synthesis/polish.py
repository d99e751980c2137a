"""The local polish: one design's residuals with their analytic Jacobian, minimised by scipy.

The variables are the varied parameters, then whichever the task leaves free: START
(degrees, `--timing JOINT`), the output's zero (function generation, `--output-zero free`:
the absolute angle of its line, radians) and, for free timing, each target's crank angle
(radians: the polish moves them along the motion with the design). Each target gives its
weighted residual rows (a path: the two components of √w (P − T); a motion: those and
√w ρ Δφ; a function: √w Δψ in degrees). Their Jacobian is the closed-form four-bar's
derivatives (`explore.fourbar.pose` with tangents) times dW/dp (`linkage`: in closed form
or by central differences of the model's constructions) — the crank angles' own columns
included. The requirements are rows g ≥ 0 with their Jacobians: Grashof's six margins, the
transmission angle's two, the order of the free crank angles along the motion.

`least_squares` (trust-region reflective, the parameters' intervals as bounds) minimises
the sum of the squared residuals plus the requirements as penalty rows RHO·min(g − margin, 0),
which vanish on feasible designs; for `--objective max`, SLSQP then minimises the largest
residual with the requirements as constraints.
"""
from __future__ import annotations

from typing import Callable, Optional

import numpy as np

from ..fourbar import PHI, pose
from .problem import MARGIN, RHO, TWO_PI, FourBarTask, Scores, four_bar, wrap

DEG = 180.0 / np.pi


class Residuals:
    """One design's residuals and requirement rows, as functions of the polish's variables."""

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
    def pack(self, z: np.ndarray, scores: Scores, i: int) -> np.ndarray:
        """The polish's variables of design `i` of a search's scores."""
        x = list(z[:self.n])
        if self.k_start is not None:
            x.append(z[self.n])
        if self.k_zero is not None:
            x.append(scores.zero[i])
        if self.free_phi:
            u = self.fbt.sign * scores.phi[i]
            u = u[0] + np.mod(u - u[0], TWO_PI)              # along the motion, within a turn
            u[1:] = np.where(u[1:] - u[0] < 1e-9, u[1:] + TWO_PI, u[1:]) if self._turns(z) else u[1:]
            x.extend(self.fbt.sign * u)
        return np.array(x, dtype=float)

    def _turns(self, z: np.ndarray) -> bool:
        from ..fourbar import crank_range

        fb = four_bar(self.fbt.map.canon(z[None, :self.n]))
        return bool(crank_range(fb).full[0, 0])

    def design(self, x: np.ndarray) -> np.ndarray:
        """The search's vector (parameters, START) of the variables x."""
        z = list(x[:self.n])
        if self.k_start is not None:
            z.append(float(np.mod(x[self.k_start], 360.0)))
        return np.array(z)

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
        """Residual rows R and their Jacobian J, requirement rows G (≥ 0 when they hold) and
        theirs."""
        fbt = self.fbt
        p = x[None, :self.n]
        canon, jw, je = fbt.map.jacobian(p)
        jw, je = jw[0], je[0]                                      # (NW, n), (3, n)
        fb = four_bar(canon)
        dphi = np.zeros((self.count, self.size))                   # dφ_i / dx
        if self.free_phi:
            phi = x[None, self.k_phi:]
            dphi[np.arange(self.count), self.k_phi + np.arange(self.count)] = 1.0
        else:
            start = np.radians(x[self.k_start]) if self.k_start is not None else np.radians(fbt.start_of(p)[0])
            phi = fb.phi0 + fbt.sign * (start + fbt.x[None, :])
            dphi[:, :self.n] = jw[9][None, :]
            if self.k_start is not None:
                dphi[:, self.k_start] = fbt.sign / DEG
        with np.errstate(all="ignore"):
            at, tg = pose(fb, phi, True)
        assert tg is not None
        chain = lambda t: self._chain(t[0], jw, dphi)
        r, j = self._target_rows(x, fb, canon, at, tg, chain, je, jw)
        g, jg = self._requirement_rows(x, fb, jw)
        return r, j, g, jg

    def _chain(self, tangent: np.ndarray, jw: np.ndarray, dphi: np.ndarray) -> np.ndarray:
        """d/dx of a quantity whose four-bar tangents are `tangent` (count, NVAR)."""
        out = np.zeros((len(tangent), self.size), dtype=tangent.dtype)
        out[:, :self.n] = tangent[:, :9] @ jw[:9]
        return out + tangent[:, PHI][:, None] * dphi

    def _target_rows(self, x, fb, canon, at, tg, chain: Callable, je, jw) -> tuple[np.ndarray, np.ndarray]:
        fbt, task = self.fbt, self.fbt.task
        sw = fbt.sqrtw[:, None]
        if task.kind == "path":
            e = (at.p - task.xy[None, :])[0]
            de = chain(tg.p)
            return np.concatenate([fbt.sqrtw * e.real, fbt.sqrtw * e.imag]), np.vstack([sw * de.real, sw * de.imag])
        line, dline = self._line(at, tg, chain, fb, canon, je)
        if task.kind == "motion":
            e = (at.p - task.xy[None, :])[0]
            de = chain(tg.p)
            rho = canon.rho[0]
            turn = wrap(line - np.radians(task.angle))
            dturn = rho * dline
            dturn[:, :self.n] += turn[:, None] * je[2][None, :]
            return (np.concatenate([fbt.sqrtw * e.real, fbt.sqrtw * e.imag, fbt.sqrtw * rho * turn]),
                    np.vstack([sw * de.real, sw * de.imag, sw * dturn]))
        y = np.radians(task.angle)
        if isinstance(task.output_zero, float):
            ref, dref = np.radians(task.output_zero), np.zeros(self.size)
        elif self.k_zero is not None:
            ref, dref = x[self.k_zero], np.eye(self.size)[self.k_zero]
        else:
            ref, dref = self._drawn_line(fb, canon, je, jw)
        d = wrap(line - ref - y)
        return DEG * fbt.sqrtw * d, DEG * sw * (dline - dref[None, :])

    def _line(self, at, tg, chain: Callable, fb, canon, je) -> tuple[np.ndarray, np.ndarray]:
        """The followed line's angle at each target and its derivatives."""
        if self.fbt.line == "rocker":
            u = (at.b - fb.o4)[0]
            du = tg.b.copy()
            du[..., 2] -= 1.0
            du[..., 3] -= 1j
            kappa, dk = canon.kappa4[0], je[1]
        else:
            u = (at.b - at.a)[0]
            du = tg.b - tg.a
            kappa, dk = canon.kappa3[0], je[0]
        d = (chain(du) / u[:, None]).imag
        d[:, :self.n] += dk[None, :]
        return np.angle(u) + kappa, d

    def _drawn_line(self, fb, canon, je, jw) -> tuple[float, np.ndarray]:
        """The followed line's angle in the drawn configuration, and its derivatives."""
        at0, tg0 = pose(fb, fb.phi0, True)
        dphi0 = np.zeros((1, self.size))
        dphi0[0, :self.n] = jw[9]
        line, d = self._line(at0, tg0, lambda t: self._chain(t[0], jw, dphi0), fb, canon, je)
        return float(line[0]), d[0]

    def _requirement_rows(self, x, fb, jw) -> tuple[np.ndarray, np.ndarray]:
        req, fbt = self.fbt.task.requires, self.fbt
        rows: list[np.ndarray] = []
        jac: list[np.ndarray] = []
        if req.crank_rocker or req.transmission is not None:
            o2, o4 = fb.o2[0, 0], fb.o4[0, 0]
            e = (o4 - o2) / abs(o4 - o2)
            dl = np.zeros((4, self.size))                          # d(r1, r2, r3, r4)/dx
            dl[0, :self.n] = e.real * (jw[2] - jw[0]) + e.imag * (jw[3] - jw[1])
            dl[1:, :self.n] = jw[4:7]
            r1, r2, r3, r4 = (float(np.ravel(v)[0]) for v in (fb.r1, fb.r2, fb.r3, fb.r4))
        if req.crank_rocker:
            scale = max(r1, r2, r3, r4)
            combos = np.array([[1, -1, 0, 0], [0, -1, 1, 0], [0, -1, 0, 1],
                               [-1, -1, 1, 1], [1, -1, -1, 1], [1, -1, 1, -1]], dtype=float)
            values = combos @ np.array([r1, r2, r3, r4])
            rows.append(values / scale)
            jac.append(combos @ dl / scale)
        if req.transmission is not None:
            cos = np.cos(np.radians(req.transmission))
            scale = 2 * r3 * r4
            for sign in (-1.0, 1.0):
                dist = r1 + sign * r2
                inner = r3 * r3 + r4 * r4 - dist * dist
                value = 2 * r3 * r4 * cos - abs(inner)
                dinner = 2 * r3 * dl[2] + 2 * r4 * dl[3] - 2 * dist * (dl[0] + sign * dl[1])
                dvalue = 2 * cos * (r4 * dl[2] + r3 * dl[3]) - np.sign(inner) * dinner
                rows.append(np.array([value / scale]))
                jac.append(dvalue[None, :] / scale)
        if req.ordered and self.free_phi:
            u = fbt.sign * x[self.k_phi:]
            k = self.count
            d = np.zeros((k, self.size))
            for i in range(k - 1):
                d[i, self.k_phi + i], d[i, self.k_phi + i + 1] = -fbt.sign, fbt.sign
            d[-1, self.k_phi], d[-1, self.k_phi + k - 1] = fbt.sign, -fbt.sign
            gaps = np.concatenate([np.diff(u), [u[0] + TWO_PI - u[-1]]])
            rows.append(gaps / TWO_PI)
            jac.append(d / TWO_PI)
        if not rows:
            return np.zeros(0), np.zeros((0, self.size))
        return np.concatenate(rows), np.vstack(jac)

    def penalised(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Residuals with the requirements as penalty rows RHO·min(g − margin, 0) and the
        Jacobian of both (NaN residuals, where the design does not assemble, become large)."""
        r, j, g, jg = self.rows(x)
        short = g - MARGIN
        active = short < 0
        rows = np.concatenate([r, RHO * np.where(active, short, 0.0)])
        jac = np.vstack([j, RHO * np.where(active[:, None], jg, 0.0)])
        bad = ~np.isfinite(rows)
        rows = np.where(bad, 1e6, rows)
        jac = np.where(np.isfinite(jac) & ~bad[:, None], jac, 0.0)
        return rows, jac


def polish(fbt: FourBarTask, z: np.ndarray, scores: Scores, i: int, evaluations: int = 400) -> Optional[np.ndarray]:
    """The design z (search vector) polished: least squares, then for `max` a minimax step.
    Returns the polished search vector (parameters, START), or None when it failed to run."""
    from scipy.optimize import least_squares

    res = Residuals(fbt)
    x0 = res.pack(z, scores, i)
    lo, hi = res.bounds()
    x0 = np.clip(x0, lo, hi)
    cache: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def both(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        key = x.tobytes()
        if key not in cache:
            cache.clear()
            with np.errstate(all="ignore"):
                cache[key] = res.penalised(x)
        return cache[key]

    try:
        sol = least_squares(lambda x: both(x)[0], x0, jac=lambda x: both(x)[1], bounds=(lo, hi),
                            method="trf", x_scale="jac", max_nfev=evaluations, xtol=1e-13, ftol=1e-13,
                            gtol=1e-13)
    except (ValueError, np.linalg.LinAlgError):
        return None
    x = sol.x
    if fbt.task.objective == "max":
        x = minimax(res, x, lo, hi, evaluations) if res.rows_per else x
    return res.design(x)


def minimax(res: Residuals, x0: np.ndarray, lo: np.ndarray, hi: np.ndarray, evaluations: int) -> np.ndarray:
    """Minimise the largest weighted target error t: variables (x, t), t² ≥ each target's
    squared residual (its rows summed), the requirements g ≥ margin (SLSQP)."""
    from scipy.optimize import minimize

    per = res.rows_per
    count = res.count

    def pieces(x: np.ndarray):
        with np.errstate(all="ignore"):
            r, j, g, jg = res.rows(x)
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
