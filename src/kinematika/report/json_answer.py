"""The contract's JSON answer of `kinematika solve MODEL --json`."""
from __future__ import annotations

from typing import Any, Optional

from ..questions import QUESTIONS, answer, field_kinds
from ..solution import Solution
from .values import numbers, plain


def answer_scales(sol: Solution, kinds: Optional[tuple[str, ...]] = None) -> tuple[dict[str, float], dict[str, float]]:
    """The scale of each kind of quantity, and of each field of the compound answers of
    `kinds` (question kinds' names, default all: their `fields`)."""
    length = sol.inst.scale
    scale = {"position": length, "velocity": sol.speed_scale(), "acceleration": sol.accel_scale(),
             "omega": sol.rate_scale(), "alpha": sol.accel_scale() / length}
    return scale, {field: scale[kind] if kind else 1.0 for field, kind in field_kinds(kinds).items()}


def solution_json(sol: Solution) -> dict[str, Any]:
    """name, dimension, dof, symbolic, bodies, points and answers, as the contract says.
    Round-off is cleaned against the scale of each kind of quantity (lengths, speeds,
    accelerations, rates), so that a large acceleration never hides a real speed."""
    sym = sol.symbolic
    model = sol.model
    scale, fields = answer_scales(sol, tuple(dict.fromkeys(q.kind for q in model.questions)))
    if sym:
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
    else:
        bodies, points = _numeric_tables(sol, scale)
    answers = [{"ask": q.echo, "value": _answer(sol, q, bodies, points, scale[QUESTIONS[q.kind].unit_kind], fields)}
               for q in model.questions]
    out = {"name": model.name, "dimension": model.dimension, "dof": sol.dof, "symbolic": sym,
           "bodies": bodies, "points": points, "answers": answers}
    named = where(sol) if sym else {}
    if named:
        out["where"] = named
    if sol.inst.warnings:                       # an extension: likely mistakes answered as written
        out["warnings"] = [w.as_json() for w in sol.inst.warnings]
    return out


def where(sol: Solution) -> dict[str, str]:
    """The named quantities of a symbolic answer, each with its formula in the parameters
    and the names before it, in that order: coordinates (x_E, y_E) and then velocities
    (omega_link), what the answers' formulas use besides the parameters where written out
    they would be too long to read (or to print)."""
    return {str(s): plain(formula, True) for s, formula in sol.inst.names.items()}


def _numeric_tables(sol: Solution, scale: dict[str, float]) -> tuple[dict, dict]:
    """The bodies' and points' tables of a numeric instant, every column rounded at once
    (`numbers`): the values `plain` gives one by one."""
    omega, _, alpha, _ = sol.motion.arrays()
    if sol.space.rot == 1:
        omega, alpha = omega[:, 0], alpha[:, 0]
    rates = zip(numbers(omega, scale["omega"]).tolist(), numbers(alpha, scale["alpha"]).tolist())
    bodies = {name: {"omega": w, "alpha": a} for name, (w, a) in zip(sol.motion.states, rates)}
    names, places, velocity, acceleration = sol.point_fields()
    columns = [numbers(values, scale[kind]).tolist() for values, kind in
               ((places, "position"), (velocity, "velocity"), (acceleration, "acceleration"))]
    points = {name: {"position": p, "velocity": v, "acceleration": a}
              for name, p, v, a in zip(names, *columns)}
    return bodies, points


def _answer(sol: Solution, q: Any, bodies: dict, points: dict, scale: float,
            fields: dict[str, float]) -> Any:
    """A question's answer as plain data: read from the tables when it is one of their
    entries (a body's ω or α, a material point's velocity or acceleration, in the fixed
    frame, at the same scale), else answered and converted."""
    frame = q.relative_to in (None, sol.model.frame)
    kind = QUESTIONS[q.kind]
    if not sol.symbolic and frame and kind.column:          # its `unit_kind` names the column
        if kind.about == "body" and q.target in bodies:
            return _copy(bodies[q.target][kind.unit_kind])
        if kind.about == "point" and str(q.target) in points:
            return _copy(points[str(q.target)][kind.unit_kind])
    return plain(answer(sol, q), sol.symbolic, scale, fields)


def _copy(value: Any) -> Any:
    return list(value) if isinstance(value, list) else value
