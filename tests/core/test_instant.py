"""The four-bar instant against its loop equations differentiated by hand (models.py)."""
from __future__ import annotations

import math

import pytest
import sympy

from kinematika import solve
from kinematika.report.json_answer import solution_json

from .models import BX, BY, four_bar, four_bar_closed_form


def test_angular_velocities_and_accelerations_match_the_loop_equations():
    w3, w4, a3, a4 = four_bar_closed_form(w2=10.0, al2=0.0)
    sol = solve(four_bar())
    assert sol.omega("crank") == pytest.approx(10.0)
    assert sol.omega("coupler") == pytest.approx(w3, rel=1e-10)
    assert sol.omega("rocker") == pytest.approx(w4, rel=1e-10)
    assert sol.alpha("coupler") == pytest.approx(a3, rel=1e-9)
    assert sol.alpha("rocker") == pytest.approx(a4, rel=1e-9)


def test_crank_angular_acceleration_enters_the_right_side():
    w3, w4, a3, a4 = four_bar_closed_form(w2=10.0, al2=-7.0)
    sol = solve(four_bar(drivers=[{"omega": "crank", "value": 10, "alpha": -7}]))
    assert sol.alpha("coupler") == pytest.approx(a3, rel=1e-9)
    assert sol.alpha("rocker") == pytest.approx(a4, rel=1e-9)


def test_point_motion_follows_the_rocker_rotation():
    _, w4, _, a4 = four_bar_closed_form()
    r = (BX - 4.0, BY)
    sol = solve(four_bar())
    vx, vy = sol.velocity("B")
    assert (vx, vy) == pytest.approx((-w4 * r[1], w4 * r[0]), rel=1e-10)
    ax, ay = sol.acceleration("B@rocker")
    assert (ax, ay) == pytest.approx((-a4 * r[1] - w4 ** 2 * r[0], a4 * r[0] - w4 ** 2 * r[1]),
                                     rel=1e-9)


def test_relative_motion_seen_from_the_crank():
    # seen from the crank, the coupler turns at ω3 − ω2 about A (A is fixed in the crank)
    w3, _, a3, _ = four_bar_closed_form()
    sol = solve(four_bar())
    assert sol.omega("coupler", relative_to="crank") == pytest.approx(w3 - 10.0)
    ab = (BX, BY - 1.0)
    w_rel, a_rel = w3 - 10.0, a3 - 0.0
    v = sol.velocity("B@coupler", relative_to="crank")
    assert v == pytest.approx((-w_rel * ab[1], w_rel * ab[0]), rel=1e-10)
    a = sol.acceleration("B@coupler", relative_to="crank")
    assert a == pytest.approx((-a_rel * ab[1] - w_rel ** 2 * ab[0],
                               a_rel * ab[0] - w_rel ** 2 * ab[1]), rel=1e-9)


def test_symbolic_crank_rate_gives_formulas_linear_in_it():
    w3, w4, _, _ = four_bar_closed_form(w2=1.0)
    tree = four_bar()
    tree["parameters"] = {"w2": None}
    data = solution_json(solve(tree))
    assert data["symbolic"] is True
    w2 = sympy.Symbol("w2", positive=True)
    got = sympy.sympify(data["bodies"]["rocker"]["omega"], locals={"w2": w2})
    assert float(got.subs(w2, 1)) == pytest.approx(w4, rel=1e-12)
    assert sympy.simplify(got.diff(w2, 2)) == 0
    # the exact value, derived by Cramer's rule with sqrt(2) kept exact
    bx = (48 + 8 * sympy.sqrt(2)) / 17
    by = 4 * bx - 11
    exact = bx / (bx * by - (bx - 4) * (by - 1)) * w2   # Cramer on the loop equation
    assert sympy.simplify(got - exact) == 0


def test_json_has_every_body_and_material_point():
    data = solution_json(solve(four_bar()))
    assert set(data["bodies"]) == {"ground", "crank", "coupler", "rocker"}
    assert set(data["points"]) == {"O2@ground", "O4@ground", "O2@crank", "A@crank", "A@coupler",
                                   "B@coupler", "B@rocker", "O4@rocker"}
    assert data["dof"] == 1 and data["dimension"] == 2 and data["symbolic"] is False
    assert data["points"]["A@crank"]["velocity"] == pytest.approx([-10.0, 0.0])
    assert data["points"]["A@crank"]["acceleration"] == pytest.approx([0.0, -100.0])
    assert data["points"]["B@rocker"]["position"] == pytest.approx([BX, BY])
    # no questions given: every moving body's ω, α and every moving point's v, a
    kinds = {next(iter(a["ask"])) for a in data["answers"]}
    assert kinds == {"omega", "alpha", "velocity", "acceleration"}


def test_icr_of_the_coupler_is_where_crank_and_rocker_lines_meet():
    sol = solve(four_bar(ask=[{"icr": "coupler"}]))
    data = solution_json(sol)
    # line O2A is x = 0; line O4B: (4, 0) + t (BX - 4, BY); at x = 0, t = -4 / (BX - 4)
    y = -4 / (BX - 4) * BY
    assert data["answers"][0]["value"]["point"] == pytest.approx([0.0, y], rel=1e-10)
    assert math.isfinite(y)
