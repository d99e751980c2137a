"""The contract's JSON answer of `kinematika solve MODEL --json`."""
from __future__ import annotations

from typing import Any

from ..questions import answer
from ..solution import Solution
from .values import plain


# the kind of each field of a compound answer (None: a unit vector or a pure number)
FIELD_KINDS = {"point": "position", "center": "position", "radius": "position",
               "velocity": "velocity", "speed": "velocity", "slide": "velocity",
               "acceleration": "acceleration", "tangential": "acceleration", "normal": "acceleration",
               "tangential_vector": "acceleration", "normal_vector": "acceleration",
               "coriolis": "acceleration", "omega": "omega", "direction": None, "tangent": None}


def answer_scales(sol: Solution) -> tuple[dict[str, float], dict[str, float]]:
    """The scale of each kind of quantity, and of each field of compound answers."""
    length = sol.inst.scale
    scale = {"position": length, "velocity": sol.speed_scale(), "acceleration": sol.accel_scale(),
             "omega": sol.rate_scale(), "alpha": sol.accel_scale() / length}
    return scale, {field: scale[kind] if kind else 1.0 for field, kind in FIELD_KINDS.items()}


def solution_json(sol: Solution) -> dict[str, Any]:
    """name, dimension, dof, symbolic, bodies, points and answers, as the contract says.
    Round-off is cleaned against the scale of each kind of quantity (lengths, speeds,
    accelerations, rates), so that a large acceleration never hides a real speed."""
    sym = sol.symbolic
    length = sol.inst.scale
    scale, fields = answer_scales(sol)
    model = sol.model
    bodies = {}
    for name in model.bodies:
        s = sol.state(name)
        bodies[name] = {"omega": plain(s.omega, sym, scale["omega"]),
                        "alpha": plain(s.alpha, sym, scale["alpha"])}
    points = {}
    for ref in model.material_points():
        points[str(ref)] = {"position": plain(sol.position(ref), sym, scale["position"]),
                            "velocity": plain(sol.velocity(ref), sym, scale["velocity"]),
                            "acceleration": plain(sol.acceleration(ref), sym, scale["acceleration"])}
    answers = [{"ask": q.echo, "value": plain(answer(sol, q), sym, scale.get(q.kind, length), fields)}
               for q in model.questions]
    return {"name": model.name, "dimension": model.dimension, "dof": sol.dof, "symbolic": sym,
            "bodies": bodies, "points": points, "answers": answers}
