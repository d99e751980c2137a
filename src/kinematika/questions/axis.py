"""The instantaneous screw axis (3D): the line of points whose velocity is along ω.

With ω and v_O, the velocity of the body's point at the origin, the axis' point nearest
the origin is p = ω × v_O / |ω|²; the sliding speed s = v·ω̂ is the same for every point.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import cross3, dot, scale
from .base import Asked, Figure, QuestionKind, Solved, Words


def axis(sol: Solved, q: Asked) -> dict[str, Any]:
    """The instantaneous screw axis of body `q.name` relative to `q.relative_to` (3D): its point
    nearest the origin p = ω × v_O / |ω|², direction ω̂, angular speed |ω| and sliding speed s =
    v_O·ω̂; a translation has no point (its direction is v̂), and a body at rest says `rest`."""
    state = sol.state(q.name, q.relative_to)
    w = state.omega
    v_origin = sol.motion.velocity(state, sol.space.zero())
    if sol.is_zero(w, sol.rate_scale()):
        if sol.is_zero(v_origin, sol.speed_scale()):
            return {"point": None, "direction": None, "omega": 0, "slide": 0, "rest": True}
        speed = sol.norm(v_origin)
        return {"point": None, "direction": scale(1 / speed, v_origin), "omega": 0, "slide": speed}
    ww = dot(w, w)
    size = sol.inst.backend.sqrt(ww)
    point = scale(1 / ww, cross3(w, v_origin))
    return {"point": point, "direction": scale(1 / size, w), "omega": size,
            "slide": dot(v_origin, w) / size}


class Axis(QuestionKind):
    """A body's instantaneous screw axis (3D)."""

    name = "axis"
    summary = "the instantaneous screw axis of a body (3D)"
    dimensions = (3,)
    fields = {"point": "position", "direction": None, "omega": "omega", "slide": "velocity"}

    def answer(self, sol: Solved, q: Asked) -> Any:
        """p = ω × v_O / |ω|², ω̂, |ω| and s = v_O·ω̂ (`axis`)."""
        return axis(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """A line through its point along ω̂."""
        figure.screw_axis(q)

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """Its angular velocity as the vector ω of the body."""
        return words.rate("ω", q, vector=True) if key == "omega" else None


KIND = Axis()
