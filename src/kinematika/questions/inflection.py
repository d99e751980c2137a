"""The inflection circle and the pole tangent of a planar body (Euler–Savary).

At an instant, the points of a body whose paths have an inflection (zero normal
acceleration, a straight stretch) lie on a circle through the instant centre I. With
r = P − I, v_P = ω k × r, so the normal to P's path is along r, and
a_P = a_I + α k × r − ω² r (a_I the acceleration of the body's point at I); the normal
acceleration vanishes where

    a_P · r = a_I · r − ω² r · r = 0,   the circle |r − D/2| = |D|/2,   D = a_I / ω²,

through I, of diameter d = |a_I| / ω² along the pole normal from I to the inflection pole
W = I + D. The pole tangent, perpendicular to it, is the common tangent of the fixed and
moving centrodes: differentiating v_P = ω k × (P − I) at P = I gives a_I = −ω k × u, so the
instant centre moves along it at u = k × a_I / ω, and d = |u| / |ω|. A point P on a ray
from I at ψ from the pole tangent has the centre of curvature C of its path by the
Euler–Savary equation (1/IP − 1/IC) sin ψ = 1/d.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import add, dot, scale
from .base import Asked, QuestionKind, Solved, Words
from .icr import instant_centre


def inflection(sol: Solved, q: Asked) -> dict[str, Any]:
    """{pole: I, center, diameter, inflection_pole: W, pole_tangent, pole_normal, pole_velocity: u};
    for a body translating or at rest relative to the frame, no circle (`translation`,
    `rest`). A body turning about a fixed point (I does not move: u = 0) has the circle of
    diameter 0 at I and no pole tangent."""
    centre = instant_centre(sol, q.name, q.relative_to)
    if centre["point"] is None:
        return {"pole": None, "center": None, "diameter": None,
                **({"rest": True} if centre.get("rest") else {"translation": True})}
    i = centre["point"]
    state = sol.state(q.name, q.relative_to)
    w = state.omega
    a_i = sol.motion.acceleration(state, i)          # a₀ + α k × r − ω² r, r = I − ref
    if sol.is_zero(a_i, sol.accel_scale()):
        zero = (0, 0)
        return {"pole": i, "center": i, "diameter": 0, "inflection_pole": i, "pole_tangent": None,
                "pole_normal": None, "pole_velocity": zero}
    d_vec = scale(1 / (w * w), a_i)
    u = (-a_i[1] / w, a_i[0] / w)
    return {"pole": i, "center": add(i, scale(_half(sol), d_vec)), "diameter": _length(sol, d_vec),
            "inflection_pole": add(i, d_vec), "pole_tangent": _unit(sol, u), "pole_normal": _unit(sol, a_i),
            "pole_velocity": u}


def _half(sol: Solved) -> Any:
    """1/2, exact in an exact solution."""
    if not sol.symbolic:
        return 0.5
    import sympy

    return sympy.Rational(1, 2)


def _length(sol: Solved, v: tuple) -> Any:
    """|v|: exactly, its square first brought to its canonical form."""
    if not sol.symbolic:
        return sol.norm(v)
    import sympy

    from ..algebra.fields import canonical

    return sympy.sqrt(canonical(dot(v, v)))


def _unit(sol: Solved, v: tuple) -> tuple:
    return scale(1 / _length(sol, v), v)


WORDS = {"pole": "ans.inflection_pole", "center": "ans.inflection_center", "diameter": "ans.inflection_diameter",
         "inflection_pole": "ans.inflection_point", "pole_tangent": "ans.pole_tangent",
         "pole_normal": "ans.pole_normal", "pole_velocity": "ans.pole_velocity"}   # the fields' words


class Inflection(QuestionKind):
    """A body's inflection circle and pole tangent (planar)."""

    name = "inflection"
    summary = "the inflection circle and pole tangent of a body (planar, Euler–Savary)"
    dimensions = (2,)
    level = "acceleration"
    fields = {"pole": "position", "center": "position", "diameter": "position", "inflection_pole": "position",
              "pole_tangent": None, "pole_normal": None, "pole_velocity": "velocity"}

    def answer(self, sol: Solved, q: Asked) -> Any:
        """The circle of diameter D = a_I / ω² through I, and the pole tangent (`inflection`)."""
        return inflection(sol, q)

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """Each field in the course's words (the inflection pole W, the pole tangent …)."""
        return words.msg(WORDS[key])


KIND = Inflection()
