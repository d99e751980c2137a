"""The contract's JSON answer of `kinematika solve MODEL --json`."""
from __future__ import annotations

from typing import Any

from ..questions import answer
from ..solution import Solution
from .values import plain


def solution_json(sol: Solution) -> dict[str, Any]:
    """name, dimension, dof, symbolic, bodies, points and answers, as the contract says."""
    sym = sol.symbolic
    scale = max(sol.speed_scale(), sol.accel_scale(), sol.inst.scale, sol.rate_scale())
    model = sol.model
    bodies = {}
    for name in model.bodies:
        s = sol.state(name)
        bodies[name] = {"omega": plain(s.omega, sym, scale), "alpha": plain(s.alpha, sym, scale)}
    points = {}
    for ref in model.material_points():
        points[str(ref)] = {"position": plain(sol.position(ref), sym, scale),
                            "velocity": plain(sol.velocity(ref), sym, scale),
                            "acceleration": plain(sol.acceleration(ref), sym, scale)}
    answers = [{"ask": q.echo, "value": plain(answer(sol, q), sym, scale)} for q in model.questions]
    return {"name": model.name, "dimension": model.dimension, "dof": sol.dof, "symbolic": sym,
            "bodies": bodies, "points": points, "answers": answers}
