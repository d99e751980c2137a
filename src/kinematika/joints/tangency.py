"""How two circles touch — outside each other, or one inside the other, and which — decided
once, here, for every joint whose circles touch (`contact`, `rolling`, `gear`) and for the
sweeps and moves that follow them (`sweep.carried`).

Two circles a, b (centres Cₐ, C_b, radii Rₐ, R_b, centres D apart) touch

- outside each other when D = Rₐ + R_b,
- one inside the other when D = |Rₐ − R_b|: b inside a when Rₐ ≥ R_b (a is the hole, the
  ring), a inside b otherwise;

the way nearer to the drawing is the one (`tangency`). With u the unit vector from Cₐ to
C_b, the contact J lies on the line of centres at signed places

    J = Cₐ + sₐ u = C_b + s_b u:   outside (Rₐ, −R_b);  b inside a (Rₐ, R_b);  a inside b (−Rₐ, −R_b)

(`Tangency.places`), so J = Cₐ + μ (C_b − Cₐ) with μ = sₐ / (sₐ − s_b) (`ratio`), and the
common normal from a's material into b's is n = σ u, σ = +1 outside, −1 inside (`sense`):
outside, b lies beyond J along u; inside, b's material is on −u's side of J both when b is
the disc in a's hole (C_b = J − R_b u) and when b is the ring about a (its material beyond
its circle, away from C_b = J + R_b u). With n so, the radii of curvature signed as
`touching` wants them (Cₐ = J − ρₐ n, C_b = J + ρ_b n, positive where the outline is convex
towards the other) are ρₐ = σ sₐ, ρ_b = −σ s_b: outside (Rₐ, R_b), b inside a (−Rₐ, R_b),
a inside b (Rₐ, −R_b) (`radii`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Tangency:
    """How circles a and b touch: `internal` (one inside the other) or not, `a_outer` (a is
    the outer circle; meaningful when internal) and the gap left (D less Rₐ + R_b, or less
    |Rₐ − R_b|: 0 when they touch)."""

    internal: bool
    a_outer: bool
    gap: float

    @property
    def kind(self) -> str:
        """"internal" or "external", as the joints and answers name it."""
        return "internal" if self.internal else "external"

    @property
    def sense(self) -> int:
        """σ: the normal from a's material into b's is σ u (u from Cₐ towards C_b)."""
        return -1 if self.internal else 1

    def places(self, ra: Any, rb: Any) -> tuple[Any, Any]:
        """(sₐ, s_b): J = Cₐ + sₐ u = C_b + s_b u (numbers or formulas)."""
        if not self.internal:
            return ra, -rb
        return (ra, rb) if self.a_outer else (-ra, -rb)

    def ratio(self, ra: Any, rb: Any) -> Any:
        """μ = sₐ / (sₐ − s_b): J = Cₐ + μ (C_b − Cₐ), constant while the circles touch."""
        sa, sb = self.places(ra, rb)
        return sa / (sa - sb)

    def radii(self, ra: Any, rb: Any) -> tuple[Any, Any]:
        """(ρₐ, ρ_b) along the normal n = σ u: ρₐ = σ sₐ, ρ_b = −σ s_b (see the module)."""
        sa, sb = self.places(ra, rb)
        return (sa, -sb) if self.sense == 1 else (-sa, sb)


def tangency(distance: float, ra: float, rb: float) -> Tangency:
    """How circles of radii `ra`, `rb` whose centres are `distance` apart touch (numbers: the
    drawing's, or the probe values of a model with symbols): the way with the smaller gap,
    outside on a tie."""
    outside = distance - (ra + rb)
    inside = distance - abs(ra - rb)
    internal = abs(inside) < abs(outside)
    return Tangency(internal, ra >= rb, inside if internal else outside)


def circles_tangency(a: Any, b: Any, num: Any = float) -> Tangency:
    """`tangency` of two circles (`shapes.Circle`s, or anything with `center` and `radius`),
    their numbers read by `num` (an instant's `num` for formulas)."""
    centres = [[float(num(x)) for x in c.center] for c in (a, b)]
    return tangency(math.dist(*centres), float(num(a.radius)), float(num(b.radius)))
