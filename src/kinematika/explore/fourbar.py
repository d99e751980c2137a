"""The four-bar in closed form, for synthesis: positions, their derivatives, and feasibility.

A four-bar is its ground pivots O2 and O4, crank r2, coupler r3, rocker r4, the coupler
point's place c = cx + i cy in the coupler's frame (origin A, x along A→B, y its left
normal), and the branch σ = ±1 (B on the left (+1) or right (−1) of A→O4). Planar vectors
are complex numbers. At the crank's absolute angle φ:

    A = O2 + r2 e^{iφ},   d = O4 − A,   D = |d|²,
    f = 1/2 + (r3² − r4²) / (2D),   h = √(r3²/D − f²),
    B − A = d (f + iσh),   P = A + c (B − A) / r3,

(B is where the circles about A (r3) and O4 (r4) meet: f and h are its coordinates along
d and across it, in units of |d|.) Where r3²/D < f² the circles miss: the design cannot be
assembled at that angle and every value is NaN.

`Tangents` carry the derivatives of A, B, P with respect to the ten real variables
`VARIABLES` (forward mode, by the chain rule through the formulas above), so the
synthesis polish has the analytic Jacobian, crank angles included. Feasibility is decided
exactly: Grashof's inequalities, the crank's limit positions in closed form (where
|r3 − r4| ≤ |d| ≤ r3 + r4 stops holding), and the least transmission angle from the two
extreme values of |d| over the crank's range.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

# the real variables of a four-bar, in the order of the tangents' last axis
VARIABLES = ("o2x", "o2y", "o4x", "o4y", "r2", "r3", "r4", "cx", "cy", "phi")
NVAR = len(VARIABLES)
PHI = VARIABLES.index("phi")
CHANGE_POINT = 1e-9          # Grashof's s + l = p + q within this fraction of l: a change point


@dataclass
class FourBar:
    """D four-bars (each field an array that broadcasts to (D, 1), or a number shared by all):
    pivots, lengths, coupler point, branch, and `phi0`, the crank's absolute angle in the
    drawn configuration (radians)."""

    o2: Any
    o4: Any
    r2: Any
    r3: Any
    r4: Any
    c: Any
    sigma: Any
    phi0: Any

    @property
    def r1(self) -> np.ndarray:
        """The ground link |O4 − O2|."""
        return np.abs(self.o4 - self.o2)

    @property
    def theta0(self) -> np.ndarray:
        """The ground line's direction O2→O4 (radians)."""
        return np.angle(self.o4 - self.o2)

    def lengths(self) -> np.ndarray:
        """(4, D...): ground, crank, coupler, rocker."""
        return np.stack(np.broadcast_arrays(self.r1, self.r2, self.r3, self.r4))


@dataclass
class Pose:
    """A, B, P and the coupler's and rocker's directions at each crank angle (NaN where the
    four-bar cannot be assembled)."""

    a: np.ndarray
    b: np.ndarray
    p: np.ndarray

    @property
    def theta3(self) -> np.ndarray:
        """The coupler's direction A→B (radians)."""
        return np.angle(self.b - self.a)

    def theta4(self, o4: np.ndarray) -> np.ndarray:
        """The rocker's direction O4→B (radians)."""
        return np.angle(self.b - o4)


@dataclass
class Tangents:
    """The derivatives of A, B, P (complex, shape (..., NVAR)) with respect to `VARIABLES`."""

    a: np.ndarray
    b: np.ndarray
    p: np.ndarray

    def angle_of(self, z: np.ndarray, dz: np.ndarray) -> np.ndarray:
        """The derivatives of arg(z) given those of z: Im(dz / z)."""
        return (dz / z[..., None]).imag


def pose(fb: FourBar, phi: np.ndarray, tangents: bool = False,
         only_phi: bool = False) -> tuple[Pose, Optional[Tangents]]:
    """The four-bars at the crank's absolute angles `phi` (broadcast with the designs), and
    with `tangents` the derivatives of A, B, P with respect to `VARIABLES` (with `only_phi`,
    with respect to φ alone: the last axis has length 1 — the velocities at ω = 1)."""
    e = np.exp(1j * phi)
    a = fb.o2 + fb.r2 * e
    d = fb.o4 - a
    dd2 = d.real * d.real + d.imag * d.imag
    r3s, r4s = fb.r3 * fb.r3, fb.r4 * fb.r4
    f = 0.5 + (r3s - r4s) / (2 * dd2)
    with np.errstate(invalid="ignore"):
        h = np.sqrt(r3s / dd2 - f * f)
    g = f + 1j * fb.sigma * h
    u = d * g
    b = a + u
    e3 = u / fb.r3
    p = a + fb.c * e3
    out = Pose(a, b, p)
    if not tangents:
        return out, None
    base = np.broadcast_shapes(np.shape(p), np.shape(fb.r2), np.shape(fb.o4), np.shape(fb.c))
    ones = np.ones(base)
    if only_phi:
        da = (1j * fb.r2 * e * ones)[..., None]
        dd = -da
    else:
        da = np.zeros(base + (NVAR,), dtype=complex)
        da[..., 0], da[..., 1] = 1.0, 1j
        da[..., 4] = e
        da[..., PHI] = 1j * fb.r2 * e
        dd = -da
        dd[..., 2] += 1.0
        dd[..., 3] += 1j
    ddd2 = 2 * (np.conj(d)[..., None] * dd).real                  # dD
    df = (-(r3s - r4s) / (2 * dd2 * dd2))[..., None] * ddd2
    dratio = (-r3s / (dd2 * dd2))[..., None] * ddd2               # d(r3²/D)
    if not only_phi:
        df[..., 5] += fb.r3 / dd2
        df[..., 6] -= fb.r4 / dd2
        dratio[..., 5] += 2 * fb.r3 / dd2
    dh = (dratio - 2 * f[..., None] * df) / (2 * h)[..., None]
    dg = df + 1j * (fb.sigma * ones)[..., None] * dh
    du = dd * g[..., None] + d[..., None] * dg
    db = da + du
    de3 = du / (fb.r3 * ones)[..., None]
    if not only_phi:
        de3[..., 5] -= u / fb.r3 ** 2
    dp = da + (fb.c * ones)[..., None] * de3
    if not only_phi:
        dp[..., 7] += e3
        dp[..., 8] += 1j * e3
    return out, Tangents(da, db, dp)


# feasibility, exactly -----------------------------------------------------------------------
def grashof_gaps(fb: FourBar) -> np.ndarray:
    """(3, D...) the margins of a crank-rocker (each ≥ 0 when it holds, in lengths): the crank
    shorter than each other link, then Grashof's s + l ≤ p + q with s the crank and l each of
    the others in turn (r2 + l ≤ the other two): six margins in all, as (6, D...)."""
    r1, r2, r3, r4 = np.broadcast_arrays(fb.r1, fb.r2, fb.r3, fb.r4)
    return np.stack([r1 - r2, r3 - r2, r4 - r2,
                     r3 + r4 - r2 - r1, r1 + r4 - r2 - r3, r1 + r3 - r2 - r4])


def grashof_class(fb: FourBar) -> np.ndarray:
    """Grashof's class of the four-bars (`grashof_of` their lengths)."""
    return grashof_of(fb.lengths())


def grashof_of(lengths: np.ndarray) -> np.ndarray:
    """Grashof's class from the lengths (4, ...) ground, crank, coupler, rocker, as the
    `grashof` metric names it: `non-grashof` when s + l > p + q (s, l the shortest and
    longest), `change-point` when equal (within CHANGE_POINT of l), else by the shortest
    link: the ground `double-crank`, the crank `crank-rocker`, the coupler `double-rocker`,
    the rocker `rocker-crank`. None where a length is not a number."""
    s, l = lengths.min(axis=0), lengths.max(axis=0)
    gap = (s + l) - (lengths.sum(axis=0) - s - l)
    names = np.array(["double-crank", "crank-rocker", "double-rocker", "rocker-crank"], dtype=object)
    out = names[np.argmin(lengths, axis=0)]
    out = np.where(gap > CHANGE_POINT * l, "non-grashof", out)
    out = np.where(np.abs(gap) <= CHANGE_POINT * l, "change-point", out)
    return np.where(np.isfinite(gap), out, np.array(None, dtype=object))


def crank_rocker(fb: FourBar) -> np.ndarray:
    """A Grashof four-bar whose crank is the shortest link (the contract's `crank-rocker`)."""
    return grashof_class(fb) == "crank-rocker"


@dataclass
class CrankRange:
    """The crank angles the drawn branch reaches from the drawn configuration: the whole
    turn (`full`), or the interval [low, high] (absolute, radians, low ≤ phi0 ≤ high) whose
    ends are limit positions. `drawn` is False where the drawn angle itself cannot be
    assembled."""

    full: np.ndarray
    low: np.ndarray
    high: np.ndarray
    drawn: np.ndarray


def crank_range(fb: FourBar) -> CrankRange:
    """The crank's reachable range in closed form. With ψ = φ − θ0, |d|² = r1² + r2² −
    2 r1 r2 cos ψ, and the four-bar assembles where (r3 − r4)² ≤ |d|² ≤ (r3 + r4)², i.e.
    cos ψ ∈ [u_lo, u_hi]: |ψ| between arccos(min(u_hi, 1)) and arccos(max(u_lo, −1)). The
    range is the interval of that set that holds the drawn angle."""
    r1, r2, r3, r4 = fb.r1, fb.r2, fb.r3, fb.r4
    base = r1 * r1 + r2 * r2
    with np.errstate(divide="ignore", invalid="ignore"):
        u_lo = (base - (r3 + r4) ** 2) / (2 * r1 * r2)
        u_hi = (base - (r3 - r4) ** 2) / (2 * r1 * r2)
    inner = np.arccos(np.clip(u_hi, -1.0, 1.0))          # |ψ| ≥ inner
    outer = np.arccos(np.clip(u_lo, -1.0, 1.0))          # |ψ| ≤ outer
    full = (u_hi >= 1.0) & (u_lo <= -1.0)
    psi0 = np.angle(np.exp(1j * (fb.phi0 - fb.theta0)))   # (−π, π]
    inside = (np.abs(psi0) >= inner - 1e-12) & (np.abs(psi0) <= outer + 1e-12) & (inner <= outer)
    # the interval holding ψ0: [inner, outer] or [−outer, −inner]; around 0 when inner = 0,
    # around π when outer = π (then written as [inner, 2π − inner] in ψ0's turn)
    sign = np.where(psi0 >= 0, 1.0, -1.0)
    low_psi = np.where(sign > 0, inner, -outer)
    high_psi = np.where(sign > 0, outer, -inner)
    around_zero = inner <= 0.0
    low_psi = np.where(around_zero, -outer, low_psi)
    high_psi = np.where(around_zero, outer, high_psi)
    around_pi = (outer >= np.pi) & ~around_zero
    low_psi = np.where(around_pi, np.where(sign > 0, inner, inner - 2 * np.pi), low_psi)
    high_psi = np.where(around_pi, np.where(sign > 0, 2 * np.pi - inner, -inner), high_psi)
    shift = fb.phi0 - psi0
    return CrankRange(full, low_psi + shift, high_psi + shift, inside & np.isfinite(u_lo + u_hi))


def least_transmission(fb: FourBar) -> np.ndarray:
    """The least transmission angle over the crank's range, degrees: min(μ, 180° − μ), μ the
    angle between coupler and rocker, cos μ = (r3² + r4² − |d|²) / (2 r3 r4), monotonic in
    |d|, so its extremes are at |d| = |r1 − r2| and r1 + r2 (ψ = 0, π) when the crank turns;
    a crank with limit positions meets μ = 0 or 180° there (coupler and rocker in line)."""
    r1, r2, r3, r4 = fb.r1, fb.r2, fb.r3, fb.r4
    least = []
    for dist in (r1 - r2, r1 + r2):
        cos = np.clip((r3 * r3 + r4 * r4 - dist * dist) / (2 * r3 * r4), -1.0, 1.0)
        mu = np.degrees(np.arccos(cos))
        least.append(np.minimum(mu, 180.0 - mu))
    return np.where(crank_range(fb).full, np.minimum(*least), 0.0)


def transmission_gaps(fb: FourBar, least: float) -> np.ndarray:
    """(2, D...) margins ≥ 0 when the transmission angle stays at least `least` degrees at
    both extremes of |d| (cos(least) − |cos μ|, scaled by 2 r3 r4 to stay polynomial)."""
    r1, r2, r3, r4 = fb.r1, fb.r2, fb.r3, fb.r4
    bound = 2 * r3 * r4 * np.cos(np.radians(least))
    return np.stack([bound - np.abs(r3 * r3 + r4 * r4 - dist * dist) for dist in (r1 - r2, r1 + r2)])
