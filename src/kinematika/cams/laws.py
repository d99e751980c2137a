"""Motion laws: the normalised rise S(x) of a cam follower and its derivatives.

A rise of height h over a cam angle β is s(θ) = h·S(x), x = θ/β ∈ [0, 1], with S(0) = 0,
S(1) = 1; then ds/dθ = h·S'(x)/β, d²s/dθ² = h·S''(x)/β², d³s/dθ³ = h·S'''(x)/β³ (a return
is the same law with −h). Each law gives S, S', S'', S''' in closed form, as the textbooks
state them: R. L. Norton, *Design of Machinery*, ch. 8 (§8.3–8.4: SCCA family, cycloidal,
modified trapezoid, modified sine, polynomials) and J. J. Uicker, G. R. Pennock,
J. E. Shigley, *Theory of Machines and Mechanisms*, ch. 6 (the standard cam motions):

- uniform (constant velocity):  S = x (velocity jumps at the ends: infinite acceleration);
- simple harmonic:   S = (1 − cos πx)/2,           peak S'' = π²/2 ≈ 4.93;
- cycloidal:         S = x − sin(2πx)/(2π),         peak S'' = 2π ≈ 6.28;
- modified trapezoid (Norton eq. 8.16): S'' a quarter sine over x ∈ [0, 1/8], constant to
  3/8, a half cosine to 5/8, constant to 7/8, a quarter sine back to 0; peak S'' ≈ 4.888;
- modified sine (Norton eq. 8.17): cycloidal quarter waves of S'' over the first and last
  eighth, a sine of period 3/2 in between; peak S'' = 4π²/(4 + π) ≈ 5.528;
- 3-4-5 polynomial:  S = 10x³ − 15x⁴ + 6x⁵,         peak S'' = 10/√3 ≈ 5.7735;
- 4-5-6-7 polynomial: S = 35x⁴ − 84x⁵ + 70x⁶ − 20x⁷, peak S'' ≈ 7.5132;
- a polynomial from boundary conditions (Norton §8.4): S = Σ cₖxᵏ of the least degree that
  meets the given S, S', S'', S''' at x = 0 and x = 1 (a linear system in the cₖ).

The trigonometric laws are built from pieces on which S'' = A + B·sin(ωx + φ), integrated
in closed form piece by piece (S' and S continuous), then scaled so that S(1) = 1.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np

Values = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


class Law:
    """A normalised motion law: `law(x)` gives S, S', S'', S''' at x ∈ [0, 1]."""

    name = ""

    def __call__(self, x: np.ndarray | float) -> Values:
        raise NotImplementedError

    def factors(self, n: int = 20001) -> tuple[float, float, float]:
        """The peak factors (max |S'|, max |S''|, max |S'''|) sampled at n points: a rise of
        h over β has peak ds/dθ = C_v·h/β, d²s/dθ² = C_a·h/β², d³s/dθ³ = C_j·h/β³."""
        _, v, a, j = self(np.linspace(0.0, 1.0, n))
        return float(np.max(np.abs(v))), float(np.max(np.abs(a))), float(np.max(np.abs(j)))


@dataclass(frozen=True)
class Polynomial(Law):
    """S(x) = Σ cₖ xᵏ; derivatives term by term."""

    coefficients: tuple[float, ...]
    name: str = "polynomial"

    def __call__(self, x: np.ndarray | float) -> Values:
        x = np.asarray(x, dtype=float)
        return tuple(np.polyval(c, x) + 0 * x for c in self._derivatives)  # type: ignore[return-value]  # one per derivative kept: a tuple() of a generator is typed tuple[ndarray, ...]

    @property
    def _derivatives(self) -> tuple[np.ndarray, ...]:
        """The coefficients of S, S', S'', S''' (highest power first, for polyval), made once."""
        found = self.__dict__.get("_made")
        if found is None:
            c = np.polynomial.Polynomial(self.coefficients)
            found = tuple(c.deriv(k).coef[::-1].copy() for k in range(4))
            object.__setattr__(self, "_made", found)
        return found

    @classmethod
    def through(cls, start: Mapping[int, float], end: Mapping[int, float]) -> Polynomial:
        """The polynomial of least degree with S⁽ᵏ⁾(0) = start[k] and S⁽ᵏ⁾(1) = end[k]
        (k = 0…3): n conditions give degree n − 1; solved as a linear system (Norton §8.4).
        d^k/dx^k of x^m at x is m!/(m−k)!·x^(m−k)."""
        rows, rhs = [], []
        n = len(start) + len(end)
        for at, conditions in ((0.0, start), (1.0, end)):
            for k, value in sorted(conditions.items()):
                rows.append([_falling(m, k) * (at ** (m - k) if m >= k else 0.0) for m in range(n)])
                rhs.append(value)
        coefficients = np.linalg.solve(np.array(rows, dtype=float), np.array(rhs, dtype=float))
        return cls(tuple(float(c) for c in coefficients))


def _falling(m: int, k: int) -> float:
    """m·(m−1)·…·(m−k+1): the factor d^k/dx^k brings down from x^m (0 when k > m)."""
    return float(math.perm(m, k)) if k <= m else 0.0


@dataclass(frozen=True)
class Piece:
    """A stretch [x0, x1] of a law on which S'' = A + B·sin(ωx + φ) (before scaling)."""

    x0: float
    x1: float
    const: float = 0.0
    amp: float = 0.0
    freq: float = 1.0
    phase: float = 0.0


@dataclass(frozen=True)
class Trigonometric(Law):
    """A law whose S'' is a chain of `Piece`s. On a piece, with t = x − x0 and S0, V0 the
    values carried from the previous piece:

        S''' = Bω cos(ωx + φ)
        S''  = A + B sin(ωx + φ)
        S'   = V0 + A t − (B/ω)[cos(ωx + φ) − cos(ωx0 + φ)]
        S    = S0 + V0 t + A t²/2 + (B/ω) cos(ωx0 + φ) t − (B/ω²)[sin(ωx + φ) − sin(ωx0 + φ)]

    and everything is divided by the unscaled S(1), so that S(1) = 1."""

    pieces: tuple[Piece, ...]
    name: str = ""
    _starts: tuple[tuple[float, float], ...] = field(init=False, repr=False, compare=False)
    _scale: float = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        starts, s0, v0 = [], 0.0, 0.0
        for piece in self.pieces:
            starts.append((s0, v0))
            s, v, _, _ = _on_piece(piece, np.array(piece.x1), s0, v0)
            s0, v0 = float(s), float(v)
        object.__setattr__(self, "_starts", tuple(starts))
        object.__setattr__(self, "_scale", s0)

    def __call__(self, x: np.ndarray | float) -> Values:
        x = np.asarray(x, dtype=float)
        out = [np.zeros_like(x) for _ in range(4)]
        edges = np.array([p.x1 for p in self.pieces[:-1]])
        index = np.searchsorted(edges, x, side="right")
        for i, (piece, (s0, v0)) in enumerate(zip(self.pieces, self._starts)):
            mask = index == i
            if np.any(mask):
                for k, value in enumerate(_on_piece(piece, x[mask], s0, v0)):
                    out[k][mask] = value
        return tuple(o / self._scale for o in out)  # type: ignore[return-value]  # as many as `out`'s rows (a tuple() of a generator has no length to mypy)


def _on_piece(p: Piece, x: np.ndarray, s0: float, v0: float) -> Values:
    """The closed forms of `Trigonometric` on one piece."""
    w, t = p.freq, x - p.x0
    arg, arg0 = w * x + p.phase, w * p.x0 + p.phase
    j = p.amp * w * np.cos(arg)
    a = p.const + p.amp * np.sin(arg)
    v = v0 + p.const * t - (p.amp / w) * (np.cos(arg) - math.cos(arg0))
    s = (s0 + v0 * t + p.const * t**2 / 2 + (p.amp / w) * math.cos(arg0) * t
         - (p.amp / w**2) * (np.sin(arg) - math.sin(arg0)))
    return s, v, a, j


FOUR_PI = 4 * math.pi

DWELL = Polynomial((0.0,), "dwell")
UNIFORM = Polynomial((0.0, 1.0), "uniform")
HARMONIC = Trigonometric((Piece(0.0, 1.0, amp=1.0, freq=math.pi, phase=math.pi / 2),), "harmonic")
CYCLOIDAL = Trigonometric((Piece(0.0, 1.0, amp=1.0, freq=2 * math.pi),), "cycloidal")
MODIFIED_TRAPEZOID = Trigonometric((
    Piece(0.0, 1 / 8, amp=1.0, freq=FOUR_PI),                   # quarter sine up
    Piece(1 / 8, 3 / 8, const=1.0),                              # constant acceleration
    Piece(3 / 8, 5 / 8, amp=1.0, freq=FOUR_PI, phase=-math.pi),  # half cosine down
    Piece(5 / 8, 7 / 8, const=-1.0),                             # constant deceleration
    Piece(7 / 8, 1.0, amp=1.0, freq=FOUR_PI),                    # quarter sine back to 0
), "modified-trapezoid")
MODIFIED_SINE = Trigonometric((
    Piece(0.0, 1 / 8, amp=1.0, freq=FOUR_PI),
    Piece(1 / 8, 7 / 8, amp=1.0, freq=FOUR_PI / 3, phase=math.pi / 3),
    Piece(7 / 8, 1.0, amp=1.0, freq=FOUR_PI),
), "modified-sine")
POLYNOMIAL_345 = Polynomial((0.0, 0.0, 0.0, 10.0, -15.0, 6.0), "3-4-5")
POLYNOMIAL_4567 = Polynomial((0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0), "4-5-6-7")

LAWS: dict[str, Law] = {law.name: law for law in (
    DWELL, UNIFORM, HARMONIC, CYCLOIDAL, MODIFIED_TRAPEZOID, MODIFIED_SINE, POLYNOMIAL_345,
    POLYNOMIAL_4567)}
"""The named laws of a motion program (`polynomial` is built from its conditions)."""


def law_named(name: str) -> Law:
    """The law called `name` (a key of `LAWS`)."""
    return LAWS[name]


def names() -> Sequence[str]:
    """Every law a program can name, `polynomial` included."""
    return (*LAWS, "polynomial")
