"""The contract's JSON answer of `kinematika solve MODEL --json`."""
from __future__ import annotations

from typing import Any

from ..questions import answer
from ..solution import Solution
from .values import plain


def solution_json(sol: Solution) -> dict[str, Any]:
    """name, dimension, dof, symbolic, bodies, points and answers, as the contract says.
    Round-off is cleaned against the scale of each kind of quantity (lengths, speeds,
    accelerations, rates), so that a large acceleration never hides a real speed."""
    sym = sol.symbolic
    length, speed, accel, rate = sol.inst.scale, sol.speed_scale(), sol.accel_scale(), sol.rate_scale()
    model = sol.model
    bodies = {}
    for name in model.bodies:
        s = sol.state(name)
        bodies[name] = {"omega": plain(s.omega, sym, rate), "alpha": plain(s.alpha, sym, accel / length)}
    points = {}
    for ref in model.material_points():
        points[str(ref)] = {"position": plain(sol.position(ref), sym, length),
                            "velocity": plain(sol.velocity(ref), sym, speed),
                            "acceleration": plain(sol.acceleration(ref), sym, accel)}
    kinds = {"length": length, "velocity": speed, "acceleration": accel, "omega": rate,
             "alpha": accel / length}
    smallest = min((x for x in kinds.values() if x > 0), default=1.0)    # answers of mixed kinds
    answers = [{"ask": q.echo, "value": plain(answer(sol, q), sym, kinds.get(q.kind) or smallest)}
               for q in model.questions]
    return {"name": model.name, "dimension": model.dimension, "dof": sol.dof, "symbolic": sym,
            "bodies": bodies, "points": points, "answers": answers}
