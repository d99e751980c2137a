"""The acceleration pole (planar): the point of a body with zero acceleration.

a(P) = a₀ + α k × r − ω² r = 0 with r = P − ref: a 2×2 linear system of determinant
ω⁴ + α², singular only when the body neither turns nor changes its turning.
"""
from __future__ import annotations

from typing import Any

from ..algebra.vectors import add
from .base import Asked, Figure, QuestionKind, Solved


def pole(sol: Solved, q: Asked) -> dict[str, Any]:
    """The acceleration pole of body `q.name` relative to `q.relative_to` (planar): the point
    with a₀ + α k × r − ω² r = 0, r = ((ω² a_x − α a_y), (α a_x + ω² a_y)) / (ω⁴ + α²) from the
    reference; when ω = α = 0 the body translates: a uniform field says `uniform`, else the pole
    is at infinity, perpendicular to a₀."""
    state = sol.state(q.name, q.relative_to)
    w2, al = state.omega ** 2, state.alpha
    det = w2 ** 2 + al ** 2
    ax, ay = state.a0
    if sol.is_zero(det, sol.rate_scale() ** 4):
        if sol.is_zero(state.a0, sol.accel_scale()):
            return {"point": None, "uniform": True}
        size = sol.norm(state.a0)
        return {"point": None, "direction": (-ay / size, ax / size)}
    # solve [[-w2, -al], [al, -w2]] r = -a0
    rx = (w2 * ax - al * ay) / det
    ry = (al * ax + w2 * ay) / det
    return {"point": add(sol.motion.ref, (rx, ry))}


class Pole(QuestionKind):
    """A body's acceleration pole (planar)."""

    name = "pole"
    summary = "the acceleration pole of a body: its point of zero acceleration (planar)"
    dimensions = (2,)
    level = "acceleration"
    fields = {"point": "position", "direction": None}

    def answer(self, sol: Solved, q: Asked) -> Any:
        """r = ((ω² a_x − α a_y), (α a_x + ω² a_y)) / (ω⁴ + α²) from the reference (`pole`)."""
        return pole(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """A marked point Γ."""
        figure.acceleration_pole(q)


KIND = Pole()
