"""The RSSR linkage: its coupler, held by two spherical joints, may spin about AB without
moving anything else. That idle spin is taken as zero, so one crank driver fixes the motion.

By hand: crank ω₂ = (0, 0, 1) about O; A = (0, 1, 0), B = (2, 1, 1); the rocker turns
about x through D = (2, 0, 1), so v_B = ω₄ x̂ × DB = (0, 0, ω₄) with DB = (0, 1, 0).
v_A = ω₂ × OA = (−1, 0, 0). The coupler is rigid: (v_B − v_A)·AB = 0 with AB = (2, 0, 1),
so 2 + ω₄ = 0, ω₄ = −2, v_B = (0, 0, −2). Its ω solves ω × AB = v_B − v_A = (1, 0, −2)
with ω·AB = 0: ω₃ = (0, 1, 0).
Accelerations (α₂ = 0): a_A = ω₂ × v_A = (0, −1, 0); a_B = α₄ x̂ × DB + ω₄ x̂ × (0, 0, ω₄)
= (0, −4, α₄); rigidity at acceleration level, (a_B − a_A)·AB + |v_B − v_A|² = 0, gives
α₄ + 5 = 0: α₄ = −5, a_B = (0, −4, −5).
"""
from __future__ import annotations

import pytest

from kinematika import KinematikaError, solve

from .derive import assert_close, cross, dot

RSSR = {
    "dimension": 3,
    "points": {"O": [0, 0, 0], "A": [0, 1, 0], "B": [2, 1, 1], "D": [2, 0, 1]},
    "bodies": {"ground": ["O", "D"], "crank": ["O", "A"], "coupler": ["A", "B"],
               "rocker": ["D", "B"]},
    "joints": [
        {"id": "j1", "type": "revolute", "bodies": ["ground", "crank"], "at": "O", "axis": [0, 0, 1]},
        {"type": "spherical", "bodies": ["crank", "coupler"], "at": "A"},
        {"type": "spherical", "bodies": ["coupler", "rocker"], "at": "B"},
        {"id": "j4", "type": "revolute", "bodies": ["ground", "rocker"], "at": "D", "axis": [1, 0, 0]},
    ],
    "drivers": [{"joint": "j1", "rate": 1}],
}


def test_rssr_is_solved_with_one_crank_driver():
    sol = solve(RSSR)
    assert sol.dof == 1
    assert_close(sol.omega("rocker"), (-2, 0, 0))
    assert_close(sol.alpha("rocker"), (-5, 0, 0))
    assert_close(sol.velocity("B@rocker"), (0, 0, -2))
    assert_close(sol.acceleration("B@rocker"), (0, -4, -5))
    assert_close(sol.velocity("B@coupler"), (0, 0, -2))
    assert_close(sol.acceleration("B@coupler"), (0, -4, -5))
    w3 = sol.omega("coupler")
    assert_close(w3, (0, 1, 0))
    assert_close(cross(w3, (2, 0, 1)), (1, 0, -2))
    assert abs(float(dot(sol.alpha("coupler"), (2, 0, 1)))) < 1e-12     # no idle spin either


def test_a_driven_coupler_spin_is_kept():
    """A driver that involves the coupler (the speed of a coupler point E off the line AB)
    fixes its spin s about AB, and then no zero-spin row is added: ω₃ = (0, 1, 0) + s AB."""
    tree = {**RSSR, "points": {**RSSR["points"], "E": [0, 2, 0]},
            "bodies": {**RSSR["bodies"], "coupler": ["A", "B", "E"]}}
    # E = A + (0, 1, 0); with ω₃ = (0, 1, 0) + s (2, 0, 1), v_E = v_A + ω₃ × AE
    # = (−1, 0, 0) + s (2, 0, 1) × (0, 1, 0) = (−1 − s, 0, 2 s): v_E along x = −1 − s
    tree["drivers"] = [{"joint": "j1", "rate": 1},
                       {"velocity": "E", "along": [1, 0, 0], "value": -1.5}]
    sol = solve(tree)
    assert_close(sol.omega("coupler"), (1.0, 1, 0.5))                             # s = 0.5
    assert_close(sol.omega("rocker"), (-2, 0, 0))


def test_a_link_between_two_spherical_joints_still_needs_the_other_drivers():
    tree = {**RSSR, "drivers": []}
    with pytest.raises(KinematikaError) as info:
        solve(tree)
    assert info.value.kind == "mobility" and "1 degree of freedom" in info.value.message


def test_the_rssr_example_answers_the_hand_derivation():
    import yaml

    from .derive import EXAMPLES

    tree = yaml.safe_load((EXAMPLES / "rssr_spatial_four_bar.yaml").read_text())
    assert tree["points"] == RSSR["points"]
    sol = solve(tree)
    assert_close(sol.omega("rocker"), (-2, 0, 0))
    assert_close(sol.alpha("rocker"), (-5, 0, 0))
    assert_close(sol.velocity("B"), (0, 0, -2))
    assert_close(sol.acceleration("B"), (0, -4, -5))
    assert_close(sol.omega("coupler"), (0, 1, 0))
