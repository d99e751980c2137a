"""The fan of the course notes (seed 000), solved the notes' three ways, against a derivation
with sympy.physics.vector: shaft frame A turned by q1 about the vertical y, blades frame turned
by q2 about A's x (the axis BC), at q1 = q2 = 0 with q1' = 0.1, q1'' = 0.2 (the notes'
solution; the statement's alpha1 = 2 is a typo), q2' = 0.5, q2'' = 0.01."""
from __future__ import annotations

import functools

import pytest
import sympy as sp
from sympy.physics.vector import ReferenceFrame

from kinematika import KinematikaError, solve
from kinematika.api import answers
from kinematika.report.json_answer import solution_json

from .derive import (EXAMPLES, carried, assert_close, components, coordinates, cross, fixed_point, instant,
                     minus, plus, times)


@functools.cache
def fan_derivation(w1=0.1, a1=0.2, w2=0.5, a2=0.01, L=sp.Rational(3, 5), h=sp.Rational(3, 10)):
    """Frames, points and the instant's values of the fan, derived independently."""
    q1, q2 = coordinates("q1 q2")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (q1, N.y))
    Bl = A.orientnew("Bl", "Axis", (q2, A.x))
    B = fixed_point("B", N)
    C = carried(B, "C", L * A.x, N, A)
    P = carried(C, "P", h * Bl.y, N, Bl)
    s = instant({q1: (0, w1, a1), q2: (0, w2, a2)})
    # the shaft's material point at P (drag); P seen from the shaft is CP differentiated in A
    drag = carried(B, "D", P.pos_from(B), N, A)
    return {
        "omega": components(Bl.ang_vel_in(N), N, s),
        "alpha": components(Bl.ang_acc_in(N), N, s),
        "omega_shaft": components(A.ang_vel_in(N), N, s),
        "alpha_shaft": components(A.ang_acc_in(N), N, s),
        "omega_rel": components(Bl.ang_vel_in(A), N, s),
        "alpha_rel": components(Bl.ang_acc_in(A), N, s),
        "v_C": components(C.vel(N), N, s), "a_C": components(C.acc(N), N, s),
        "v_P": components(P.vel(N), N, s), "a_P": components(P.acc(N), N, s),
        "v_rel": components(P.pos_from(C).dt(A), N, s),
        "a_rel": components(P.pos_from(C).dt(A).dt(A), N, s),
        "v_drag": components(drag.vel(N), N, s), "a_drag": components(drag.acc(N), N, s),
    }

NOTES_V_P, NOTES_A_P = (0, 0, 0.09), (0.024, -0.075, -0.117)


def test_derivation_reproduces_the_notes():
    # guards the derivation itself: the notes' printed results (with alpha1 = 0.2)
    assert_close(fan_derivation()["v_P"], NOTES_V_P)
    assert_close(fan_derivation()["a_P"], NOTES_A_P)
    assert_close(fan_derivation()["alpha"], (0.01, 0.2, -0.05))
    assert_close(fan_derivation()["v_C"], (0, 0, -0.06))
    assert_close(fan_derivation()["a_C"], (-0.006, 0, -0.12))


def test_alpha1_of_the_statement_would_change_a_p():
    # with the statement's alpha1 = 2 the blades' point would have a_z = -1.197, not -0.117:
    # the notes' solution used 0.2 (the typo is in the statement)
    assert float(fan_derivation(a1=2)["a_P"][2]) == pytest.approx(-1.197)


def test_absolute_method_with_common_point_c():
    sol = solve(EXAMPLES / "fan_absolute.yaml")
    assert_close(sol.omega("blades"), fan_derivation()["omega"])
    assert_close(sol.alpha("blades"), fan_derivation()["alpha"])
    assert_close(sol.velocity("C"), fan_derivation()["v_C"])
    assert_close(sol.acceleration("C"), fan_derivation()["a_C"])
    assert_close(sol.velocity("P"), fan_derivation()["v_P"])
    assert_close(sol.acceleration("P"), fan_derivation()["a_P"])


def test_absolute_method_with_common_point_b():
    sol = solve(EXAMPLES / "fan_common_point_B.yaml")
    # B is fixed: its acceleration is zero, not the a_C the notes' line 1b writes
    assert_close(sol.velocity("B@blades"), (0, 0, 0))
    assert_close(sol.acceleration("B@blades"), (0, 0, 0))
    assert max(abs(c) for c in fan_derivation()["a_C"]) > 0.1
    # and the field from B gives the same P: a_P = alpha x BP + omega x (omega x BP)
    bp = (sp.Rational(3, 5), sp.Rational(3, 10), 0)
    w, al = fan_derivation()["omega"], fan_derivation()["alpha"]
    assert_close(fan_derivation()["a_P"], plus(cross(al, bp), cross(w, cross(w, bp))))
    assert_close(sol.velocity("P"), fan_derivation()["v_P"])
    assert_close(sol.acceleration("P"), fan_derivation()["a_P"])


def test_composition_method_drag_relative_coriolis():
    sol = solve(EXAMPLES / "fan_composition.yaml")
    dec = answers(sol)[0][1]
    assert_close(dec["velocity"]["drag"], fan_derivation()["v_drag"])
    assert_close(dec["velocity"]["relative"], fan_derivation()["v_rel"])
    assert_close(dec["acceleration"]["drag"], fan_derivation()["a_drag"])
    assert_close(dec["acceleration"]["relative"], fan_derivation()["a_rel"])
    coriolis = times(2, cross(fan_derivation()["omega_shaft"], fan_derivation()["v_rel"]))
    assert_close(dec["acceleration"]["coriolis"], coriolis)
    # the three parts add up to the absolute motion, which is the notes' answer
    assert_close(plus(dec["velocity"]["drag"], dec["velocity"]["relative"]), NOTES_V_P)
    assert_close(plus(dec["acceleration"]["drag"], dec["acceleration"]["relative"],
               dec["acceleration"]["coriolis"]), NOTES_A_P)
    # the notes' numbers for each part
    assert_close(fan_derivation()["a_rel"], (0, -0.075, 0.003))
    assert_close(coriolis, (0.03, 0, 0))


def test_relative_alpha_is_the_derivative_seen_from_the_shaft():
    sol = solve(EXAMPLES / "fan_composition.yaml")
    assert_close(sol.omega("blades", "block"), fan_derivation()["omega_rel"])
    assert_close(sol.alpha("blades", "block"), fan_derivation()["alpha_rel"])
    # alpha_rel = alpha - alpha_frame - omega_frame x omega_rel, with the solver's own values
    w_f, w_rel = sol.omega("block"), sol.omega("blades", "block")
    assert_close(sol.alpha("blades", "block"),
          minus(minus(sol.alpha("blades"), sol.alpha("block")), cross(w_f, w_rel)))


def test_the_three_methods_agree_in_the_json_answer():
    for name in ("fan_absolute", "fan_common_point_B", "fan_composition"):
        out = solution_json(solve(EXAMPLES / f"{name}.yaml"))
        assert out["dimension"] == 3 and out["dof"] == 2
        point = out["points"]["P@blades"]
        assert point["velocity"] == pytest.approx(list(NOTES_V_P), abs=1e-12)
        assert point["acceleration"] == pytest.approx(list(NOTES_A_P), abs=1e-12)
        assert out["bodies"]["blades"]["alpha"] == pytest.approx([0.01, 0.2, -0.05], abs=1e-12)


def test_symbolic_fan_equals_the_derivation_in_symbols():
    w1, a1, w2, a2, L, h = sp.symbols("w1 a1 w2 a2 L h", positive=True)
    expected = fan_derivation(w1, a1, w2, a2, L, h)
    out = solution_json(solve(EXAMPLES / "fan_symbolic.yaml"))
    names = {str(s): s for s in (w1, a1, w2, a2, L, h)}
    got = [[sp.sympify(c, locals=names) for c in a["value"]] for a in out["answers"][:4]]
    for value, key in zip(got, ("v_P", "a_P", "omega", "alpha")):
        assert [sp.simplify(g - e) for g, e in zip(value, expected[key])] == [0, 0, 0], key


def _blades_driven_absolutely(alpha):
    return {
        "dimension": 3,
        "points": {"B": [0, 0, 0], "C": [0.6, 0, 0], "P": [0.6, 0.3, 0]},
        "bodies": {"ground": ["B"], "block": ["B", "C"], "blades": ["C", "P"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "block"], "at": "B", "axis": [0, 1, 0]},
                   {"type": "revolute", "bodies": ["block", "blades"], "at": "C", "axis": [1, 0, 0]}],
        "drivers": [{"omega": "blades", "value": [0.5, 0.1, 0], "alpha": alpha}],
    }


def test_blades_driven_by_their_absolute_omega_and_alpha():
    # three conditions on a two-degree-of-freedom fan, consistent: the block's motion follows
    sol = solve(_blades_driven_absolutely([0.01, 0.2, -0.05]))
    assert_close(sol.omega("block"), fan_derivation()["omega_shaft"])
    assert_close(sol.alpha("block"), fan_derivation()["alpha_shaft"])
    assert_close(sol.acceleration("P"), fan_derivation()["a_P"])


def test_alpha_that_forgets_omega1_x_omega2_is_a_conflict():
    with pytest.raises(KinematikaError) as info:
        solve(_blades_driven_absolutely([0.01, 0.2, 0]))
    assert info.value.kind == "mobility"


def test_axes_may_be_written_as_two_points():
    """The hub axis written [B, C] (from B to C: +x) and the shaft's as [B, Y] with Y on
    +y give the notes' v_P and a_P, as the vectors do."""
    import yaml

    tree = yaml.safe_load((EXAMPLES / "fan_composition.yaml").read_text())
    tree["points"]["Y"] = [0, 2, 0]
    tree["bodies"]["ground"].append("Y")
    tree["joints"][0]["axis"] = ["B", "Y"]
    tree["joints"][1]["axis"] = ["B", "C"]
    sol = solve(tree)
    assert_close(sol.velocity("P@blades"), NOTES_V_P)
    assert_close(sol.acceleration("P@blades"), NOTES_A_P)
