"""Exact curvature answers read as what they are: a point of a body pinned to the frame of
reference moves on a circle about the pin, so its radius is the body's length (a symbol,
not a long formula) and its centre the pin; a point of a body with no such pin keeps the
general answer, checked here against the curvature of its path written out by hand."""
from __future__ import annotations

import functools

import pytest
import sympy

import kinematika
from kinematika.questions import answer
from kinematika.report.values import plain

from tests.conftest import deep_only
from tests.model.test_constructions import four_bar_tree, slider_crank_tree

theta, a, b, c, d = sympy.symbols("theta a b c d", positive=True)
NAMES = {"theta": theta, "a": a, "b": b, "c": c, "d": d}


def asked(tree: dict) -> list:
    """The answers of `solve --json` to the tree's questions, as it writes a symbolic one
    (without the tables of every point's motion, seconds of formulas not read here)."""
    sol = kinematika.solve(tree)
    assert sol.symbolic
    return [plain(answer(sol, q), True) for q in sol.model.questions]


def answers(symbols, ask):
    tree = four_bar_tree()
    for s in symbols:
        tree["parameters"][s] = None
    tree["ask"] = ask
    return asked(tree)


@functools.cache
def every_length_a_symbol() -> list:
    """The four-bar with a, b, c, d and θ symbols, asked the curvature of B's path: on the
    rocker, on the coupler relative to the crank, to the ground and to the rocker (solved
    once for the tests that read them: each solve is seconds)."""
    return answers(["theta", "a", "b", "c", "d"],
                   [{"curvature": "B@rocker"}, {"curvature": "B@coupler", "relative_to": "crank"},
                    {"curvature": "B@coupler"}, {"curvature": "B@coupler", "relative_to": "rocker"}])


def exact(text):
    return sympy.sympify(text, locals=NAMES)


@deep_only     # seconds: B@rocker's radius c about the pin is test_every_length_a_symbol_the_radii_are_the_links's
def test_the_rockers_pin_is_at_the_rockers_length_however_long_its_speed():
    """The issue's case: the crank angle θ and the rocker's length c symbols; B moves on the
    circle of radius c about O4 = (5.2, 0) (the rocker turns about O4)."""
    (rocker,) = answers(["theta", "c"], [{"curvature": "B@rocker"}])
    assert exact(rocker["radius"]) == c and len(rocker["radius"]) == 1
    assert [exact(x) for x in rocker["center"]] == [sympy.Rational(26, 5), 0]


def test_every_length_a_symbol_the_radii_are_the_links():
    """All of a, b, c, d and θ symbols: B's path relative to the ground is the circle of
    radius c about O4 = (d, 0); relative to the crank, the circle of radius b about A =
    a (cos θ, sin θ) (the coupler turns about A on the crank)."""
    rocker, relative = every_length_a_symbol()[:2]
    assert exact(rocker["radius"]) == c and [exact(x) for x in rocker["center"]] == [d, 0]
    assert exact(relative["radius"]) == b
    assert [exact(x) for x in relative["center"]] == [a * sympy.cos(theta), a * sympy.sin(theta)]


def test_the_couplers_b_moves_on_the_rockers_circle():
    """Issue 31: every length a symbol, the curvature of B's path on the coupler (relative to
    the ground). B is the rocker's pin, so B@coupler moves as B@rocker: on the circle of
    radius c about O4 = (d, 0) — the answer was a formula of 37 000 characters equal to c."""
    coupler = every_length_a_symbol()[2]
    assert coupler["radius"] == "c"
    assert [exact(x) for x in coupler["center"]] == [d, 0]


def test_the_couplers_b_relative_to_the_rocker_is_at_rest():
    """Seen from the rocker, the coupler's B stays where it is: a point at rest, no circle
    (every length and θ a symbol)."""
    seen = every_length_a_symbol()[3]
    assert seen == {"radius": None, "rest": True}


def test_a_point_of_the_rod_keeps_the_curvature_of_its_path():
    """The rod's midpoint M of the offset slider-crank (r = 3, l = 11, e = −2) with θ a
    symbol (the rod has no pin to the ground): its radius against ρ = (x'² + y'²)^{3/2} /
    |x'y'' − y'x''| of its path written by hand, M = (A + C)/2, A = r(cos θ, sin θ),
    C = (r cos θ + √(l² − (r sin θ − e)²), e)."""
    tree = slider_crank_tree()
    tree["parameters"] = {"theta": None}
    tree["points"]["M"] = {"frame": ["A", "C"], "at": [5.5, 0]}
    tree["bodies"]["rod"] = ["A", "C", "M"]
    tree["ask"] = [{"curvature": "M"}]
    (rod,) = asked(tree)
    A = sympy.Matrix([3 * sympy.cos(theta), 3 * sympy.sin(theta)])
    C = sympy.Matrix([3 * sympy.cos(theta) + sympy.sqrt(121 - (3 * sympy.sin(theta) + 2) ** 2), -2])
    M = (A + C) / 2
    x1, y1 = M.diff(theta)
    x2, y2 = M.diff(theta, 2)
    rho = (x1 ** 2 + y1 ** 2) ** sympy.Rational(3, 2) / sympy.Abs(x1 * y2 - y1 * x2)
    for t in (0.4, 2.2, 4.0):
        assert float(exact(rod["radius"]).subs(theta, t)) == pytest.approx(float(rho.subs(theta, t)), rel=1e-10)
