"""Curvature of a point's path, and the intrinsic components of its acceleration.

The normal acceleration aₙ = a − (a·v̂) v̂ points to the centre of curvature, at distance
ρ = v²/|aₙ| from the point: centre = P + (v²/|aₙ|²) aₙ. In the plane this is
P + (v·v)/(v × a) (k × v), with no absolute value needed.

In exact answers the structure is asked first: a material point that moves as a point of a
body pinned to the frame of reference (its own body, or one joined to it by a pin there: the
coupler's B is the rocker's pin) moves on a circle about that pin, so the centre is the pin
and ρ = |P − pin| brought to its canonical form (the rocker's length of a four-bar, whatever
the formulas of its speed), and the general form |v|³/|v × a| — long, and the costliest
exact work of the answer — is not formed at all.
"""
from __future__ import annotations

from typing import Any, Optional

from ..algebra.vectors import add, dot, scale, sub
from .base import Asked, Figure, QuestionKind, Solved, Steps, Words


def curvature(sol: Solved, q: Asked) -> dict[str, Any]:
    """The curvature of material point `q.target`'s path seen from `q.relative_to`: ρ = v³/|v ×
    a| and the centre P + (v·v)/(v × a) (k × v) (`path_curvature`); exactly, when the point
    moves as a point of a body pinned to that frame, the pin and ρ = |P − pin|."""
    p = sol.position(q.target)
    v = sol.velocity(q.target, q.relative_to)
    a = sol.acceleration(q.target, q.relative_to)
    pin = _pin(sol, q) if sol.symbolic else None
    if pin is not None and not sol.is_zero(v, sol.speed_scale()):
        return {"radius": _distance(p, pin), "center": pin}
    return path_curvature(sol, p, v, a)


def _pin(sol: Solved, q: Asked) -> tuple | None:
    """The place of a pin joining the frame of reference to a body the point moves with
    (planar: its own body, or one pinned to it at the point): the point's path relative to
    that frame is a circle about the pin. None when there is none."""
    model = sol.model
    ref = sol.point(q.target)
    frame = q.relative_to or model.frame
    if sol.space.dim != 2 or ref.body == frame:
        return None
    moving = next((c for c in model.motion_classes(ref.point, model.carriers(ref.point)) if ref.body in c),
                  [ref.body])
    for body in sorted(moving, key=lambda b: b != ref.body):      # its own body first
        if body == frame:
            return None                                           # the point is the frame's
        for name in model.bodies[body].points:
            classes = model.motion_classes(name, model.carriers(name))
            if any(body in c and frame in c for c in classes):
                return sol.position(name)
    return None


def _distance(p: tuple, q: tuple) -> Any:
    """|p − q| exactly, its square first brought to its canonical form (counted work)."""
    import sympy

    from ..algebra.fields import canonical

    d = sub(p, q)
    return sympy.sqrt(canonical(dot(d, d)))


def path_curvature(sol: Solved, p: tuple, v: tuple, a: tuple) -> dict[str, Any]:
    """Radius and centre of curvature of a path through `p` with velocity `v` and acceleration
    `a`. In the plane ρ = |v|³/|v × a|, centre = P + (v·v)/(v × a) (k × v); in space aₙ = a −
    (a·v̂) v̂, ρ = v²/|aₙ|, centre = P + (v²/|aₙ|²) aₙ. A point at rest says `rest`; a zero
    normal acceleration (a straight path, an inflection) has no centre."""
    sp = sol.space
    if sol.is_zero(v, sol.speed_scale()):
        return {"radius": None, "rest": True}
    cross = sp.cross_vv(v, a)
    vv = dot(v, v)
    if sol.is_zero(cross, sol.size(v) * sol.accel_scale()):
        return {"radius": None, "center": None}    # aₙ = |v × a|/|v| is zero: straight or inflection
    bk = sol.inst.backend
    if sp.dim == 2:
        center = add(p, scale(vv / cross, sp.cross(1, v)))
        radius = bk.sqrt(vv) ** 3 / abs(cross) if not sol.symbolic else \
            _symbolic_radius(vv, cross)
        return {"radius": radius, "center": center}
    a_n = sub(a, scale(dot(a, v) / vv, v))
    nn = dot(a_n, a_n)
    return {"radius": vv / bk.sqrt(nn), "center": add(p, scale(vv / nn, a_n))}


def _symbolic_radius(vv: Any, cross: Any) -> Any:
    """|v|³/|v × a| with both factored first, so that roots and absolute values resolve."""
    import sympy

    from ..algebra.fields import canonical

    return sympy.sqrt(canonical(vv)) ** 3 / sympy.Abs(canonical(cross))


def intrinsic(sol: Solved, q: Asked) -> dict[str, Any]:
    """Speed, unit tangent, tangential (signed) and normal components of the acceleration."""
    v = sol.velocity(q.target, q.relative_to)
    a = sol.acceleration(q.target, q.relative_to)
    if sol.is_zero(v, sol.speed_scale()):
        return {"speed": 0, "tangent": None, "tangential": None, "normal": None,
                "normal_vector": None, "acceleration": a, "rest": True}
    speed = sol.norm(v)
    t = scale(1 / speed, v)
    at = dot(a, t)
    an = sub(a, scale(at, t))
    return {"speed": speed, "tangent": t, "tangential": at, "normal": sol.norm(an),
            "tangential_vector": scale(at, t), "normal_vector": an}


class Curvature(QuestionKind):
    """The radius and centre of curvature of a point's path."""

    name = "curvature"
    summary = "the radius and centre of curvature of a material point's path"
    about = "point"
    level = "acceleration"
    fields = {"radius": "position", "center": "position"}
    page = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """ρ = |v|³/|v × a| and its centre (`curvature`)."""
        return curvature(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """The osculating circle."""
        figure.path_circle(q)

    def explain(self, steps: Steps, q: Asked) -> None:
        """The curvature section: a = aᵗ + aⁿ, then ρ = |v|² / |aⁿ| (planar)."""
        steps.path_curvature(q)

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """ℜ_C (the notes' radius of curvature; ρ is a circle's radius), a length, not a vector."""
        return words.sym("ℜ", words.point(q), vector=False) if key == "radius" else None


KIND = Curvature()
