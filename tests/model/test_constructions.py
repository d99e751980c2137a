"""Points by construction against independent trigonometry.

Expected values come from the textbook position analysis written out here (Freudenstein's
equation for the four-bar as Norton solves it, the slider-crank's closed form, similar
triangles), never from the tool's own output.
"""
from __future__ import annotations

import copy
import math

import pytest
import sympy

import kinematika
from kinematika import KinematikaError
from kinematika.report.json_answer import solution_json
from tests.conftest import deep_only, hand_derivations

_hand = hand_derivations()


def four_bar_tree(a=2.25, b=6.1, c=4.35, d=5.2, theta=52, side="left", w=9.5, alpha=-21.0) -> dict:
    return {
        "name": "four-bar by lengths",
        "parameters": {"a": a, "b": b, "c": c, "d": d, "theta": f"deg({theta})"},
        "points": {"O2": [0, 0], "O4": ["d", 0],
                   "A": {"from": "O2", "distance": "a", "angle": "theta"},
                   "B": {"circles": [["A", "b"], ["O4", "c"]], "side": side}},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"],
                   "rocker": ["O4", "B"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                   {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                   {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                   {"type": "revolute", "bodies": ["ground", "rocker"], "at": "O4"}],
        "drivers": [{"omega": "crank", "value": w, "alpha": alpha}],
        "ask": [{"omega": "coupler"}, {"omega": "rocker"}, {"alpha": "coupler"}, {"alpha": "rocker"}],
    }


# Freudenstein's equation as Norton solves it (eqs. 4.10-4.13) and Norton's rate equations
# (6.18, 7.12), written out once in tests/cases/derive.py
freudenstein, norton_rates = _hand.freudenstein, _hand.norton_rates


def values(tree: dict) -> list:
    return [a["value"] for a in solution_json(kinematika.solve(tree))["answers"]]


@pytest.mark.parametrize("theta", [0, 52, 100, 181, 275])
def test_four_bar_by_lengths_matches_freudenstein(theta):
    a, b, c, d = 2.25, 6.1, 4.35, 5.2
    tree = four_bar_tree(a, b, c, d, theta)
    t2 = math.radians(theta)
    # "left of A→O4" is the open circuit for this crank-rocker drawn above the ground
    t3, t4 = freudenstein(a, b, c, d, t2, open_circuit=True)
    sol = kinematika.solve(tree)
    bx, by = (float(v) for v in solution_json(sol)["points"]["B@rocker"]["position"])
    assert bx == pytest.approx(d + c * math.cos(t4), abs=1e-9)
    assert by == pytest.approx(c * math.sin(t4), abs=1e-9)
    expected = norton_rates(a, b, c, t2, t3, t4, 9.5, -21.0)
    assert values(tree) == pytest.approx(list(expected), rel=1e-9, abs=1e-9)


def test_right_side_is_the_crossed_circuit():
    a, b, c, d = 2.25, 6.1, 4.35, 5.2
    t3, t4 = freudenstein(a, b, c, d, math.radians(52), open_circuit=False)
    sol = kinematika.solve(four_bar_tree(side="right"))
    bx, by = solution_json(sol)["points"]["B@rocker"]["position"]
    assert (bx, by) == pytest.approx((d + c * math.cos(t4), c * math.sin(t4)), abs=1e-9)


def test_near_picks_the_nearest_intersection():
    tree = four_bar_tree()
    del tree["points"]["B"]["side"]
    t3, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, math.radians(52), open_circuit=False)
    crossed = (5.2 + 4.35 * math.cos(t4), 4.35 * math.sin(t4))
    tree["points"]["B"]["near"] = [round(crossed[0], 1), round(crossed[1], 1)]
    bx, by = solution_json(kinematika.solve(tree))["points"]["B@rocker"]["position"]
    assert (bx, by) == pytest.approx(crossed, abs=1e-9)


def test_polar_with_reference_and_frame():
    # a triangle plate on AB: Q at 2.5 from A, 30° from AB (counter-clockwise); P in AB's frame
    tree = four_bar_tree()
    tree["points"]["Q"] = {"from": "A", "distance": 2.5, "angle": "deg(30)", "reference": ["A", "B"]}
    tree["points"]["P"] = {"frame": ["A", "B"], "at": [3.4, -1.15]}
    tree["bodies"]["coupler"] = ["A", "B", "P", "Q"]
    js = solution_json(kinematika.solve(tree))["points"]
    ax, ay = 2.25 * math.cos(math.radians(52)), 2.25 * math.sin(math.radians(52))
    t3, _ = freudenstein(2.25, 6.1, 4.35, 5.2, math.radians(52))
    assert js["Q@coupler"]["position"] == pytest.approx(
        [ax + 2.5 * math.cos(t3 + math.radians(30)), ay + 2.5 * math.sin(t3 + math.radians(30))], abs=1e-9)
    # 3.4 along AB, 1.15 to its right (negative y in the frame)
    assert js["P@coupler"]["position"] == pytest.approx(
        [ax + 3.4 * math.cos(t3) + 1.15 * math.sin(t3), ay + 3.4 * math.sin(t3) - 1.15 * math.cos(t3)], abs=1e-9)


def slider_crank_tree(r=3.0, l=11.0, e=-2.0, theta=40.0, side="ahead") -> dict:
    return {
        "parameters": {"theta": f"deg({theta})"},
        "points": {"O2": [0, 0], "G": [0, e], "H": [5, e],
                   "A": {"from": "O2", "distance": r, "angle": "theta"},
                   "C": {"circle": ["A", l], "line": ["G", "H"], "side": side}},
        "bodies": {"ground": ["O2", "G", "H"], "crank": ["O2", "A"], "rod": ["A", "C"], "slider": ["C"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                   {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                   {"type": "revolute", "bodies": ["rod", "slider"], "at": "C"},
                   {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
        "drivers": [{"omega": "crank", "value": 4}],
        "ask": [{"velocity": "C"}, {"omega": "rod"}],
    }


@pytest.mark.parametrize("theta", [0, 40, 90, 215])
def test_offset_slider_crank_circle_and_line(theta):
    r, l, e, w = 3.0, 11.0, -2.0, 4.0
    t = math.radians(theta)
    root = math.sqrt(l * l - (r * math.sin(t) - e) ** 2)
    x = r * math.cos(t) + root                    # slider ahead of the crank pin
    xdot = w * (-r * math.sin(t) - r * math.cos(t) * (r * math.sin(t) - e) / root)
    w3 = -w * r * math.cos(t) / root              # the rod's angle: sin θ3 = (e − r sin θ)/l
    js = solution_json(kinematika.solve(slider_crank_tree(r, l, e, theta)))
    assert js["points"]["C@slider"]["position"] == pytest.approx([x, e], abs=1e-9)
    vc, w_rod = (a["value"] for a in js["answers"])
    assert vc == pytest.approx([xdot, 0], abs=1e-9)
    assert w_rod == pytest.approx(w3, abs=1e-9)


def test_circle_and_line_through_point_and_direction_behind():
    tree = slider_crank_tree(side="behind")
    tree["points"]["C"] = {"circle": ["A", 11], "line": {"through": [0, -2], "direction": [-1, 0]},
                           "side": "ahead"}     # ahead along −x is the left intersection
    t = math.radians(40)
    x = 3 * math.cos(t) - math.sqrt(121 - (3 * math.sin(t) + 2) ** 2)
    js = solution_json(kinematika.solve(tree))
    assert js["points"]["C@slider"]["position"] == pytest.approx([x, -2], abs=1e-9)


def test_two_lines_meet():
    tree = four_bar_tree()
    tree["points"]["S"] = {"lines": [["O2", "A"], ["O4", "B"]]}   # the crank-rocker centre I24
    tree["bodies"]["ground"] = ["O2", "O4", "S"]
    js = solution_json(kinematika.solve(tree))["points"]
    t2 = math.radians(52)
    _, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, t2)
    # O2 + s (cos t2, sin t2) = O4 + u (cos t4, sin t4): solve by Cramer's rule by hand
    det = math.cos(t2) * (-math.sin(t4)) - math.sin(t2) * (-math.cos(t4))
    s = (5.2 * (-math.sin(t4)) - 0 * (-math.cos(t4))) / det
    assert js["S@ground"]["position"] == pytest.approx([s * math.cos(t2), s * math.sin(t2)], abs=1e-9)


def test_constructions_in_any_order_and_used_by_shapes_and_directions():
    # a wheel whose centre is constructed after the point that uses it
    tree = {
        "points": {"P": {"from": "C", "distance": 1, "angle": "-pi/2"},
                   "C": {"lines": [{"through": [0, 1], "direction": [1, 0]},
                                   {"through": [2, 0], "direction": [0, 1]}]},
                   "G": [0, 0], "H": [1, 0]},
        "bodies": {"ground": {"points": ["G", "H"], "line": {"through": "G", "direction": ["G", "H"]}},
                   "wheel": {"points": ["C", "P"], "circle": {"center": "C", "radius": 1}}},
        "joints": [{"type": "rolling", "bodies": ["ground", "wheel"]}],
        "drivers": [{"velocity": "C", "along": ["G", "H"], "value": 2}],
        "ask": [{"omega": "wheel"}, {"velocity": "P@wheel"}],
    }
    js = solution_json(kinematika.solve(tree))
    assert js["points"]["C@wheel"]["position"] == pytest.approx([2, 1])
    assert js["points"]["P@wheel"]["position"] == pytest.approx([2, 0])
    omega, vp = (a["value"] for a in js["answers"])
    assert omega == pytest.approx(-2)            # rolling to +x: clockwise, v = ω r
    assert vp == pytest.approx([0, 0], abs=1e-12)


# exact formulas ---------------------------------------------------------------------------
def test_symbolic_slider_crank_at_general_angle():
    th = sympy.Symbol("theta", positive=True)
    tree = slider_crank_tree()
    tree["parameters"] = {"theta": None}
    js = solution_json(kinematika.solve(tree))
    vc, w_rod = (a["value"] for a in js["answers"])
    root = sympy.sqrt(121 - (3 * sympy.sin(th) + 2) ** 2)
    expected_w = -12 * sympy.cos(th) / root
    expected_v = 4 * (-3 * sympy.sin(th) - 3 * sympy.cos(th) * (3 * sympy.sin(th) + 2) / root)
    for got, exp in ((w_rod, expected_w), (vc[0], expected_v)):
        formula = sympy.sympify(got, locals={"theta": th})
        for value in (0.3, 1.1, 2.0, 4.0):
            assert float(formula.subs(th, value)) == pytest.approx(float(exp.subs(th, value)), abs=1e-12)
    assert vc[1] == "0"


# seconds: a four-bar built by its circles at a general crank angle against Freudenstein and
# Norton at five angles is also tests/examples/test_from_a_problem.py's symbolic crank angle
@deep_only
def test_symbolic_four_bar_at_general_crank_angle_is_freudenstein():
    th, w = sympy.symbols("theta w", positive=True)
    tree = four_bar_tree(a=2, b=7, c=9, d=6)
    tree["parameters"].update(theta=None, w=None)
    tree["drivers"] = [{"omega": "crank", "value": "w"}]
    tree["ask"] = [{"omega": "coupler"}, {"omega": "rocker"}]
    w3, w4 = (sympy.sympify(v, locals={"theta": th, "w": w}) for v in values(tree))
    for deg in (10, 75, 160, 250, 330):
        t2 = math.radians(deg)
        t3, t4 = freudenstein(2, 7, 9, 6, t2)
        e3, e4, _, _ = norton_rates(2, 7, 9, t2, t3, t4, 1.0, 0.0)
        assert float(w3.subs({th: t2, w: 1})) == pytest.approx(e3, abs=1e-10)
        assert float(w4.subs({th: t2, w: 1})) == pytest.approx(e4, abs=1e-10)


# errors -----------------------------------------------------------------------------------
def error_of(tree: dict) -> KinematikaError:
    with pytest.raises(KinematikaError) as info:
        kinematika.solve(tree)
    return info.value


def test_circles_that_do_not_meet_say_by_how_much():
    err = error_of(four_bar_tree(b=1.0, c=1.0, d=8.0, theta=180))
    assert err.kind == "geometry" and err.where == "points.B"
    # |A O4| = 8 + 2.25 = 10.25; 10.25 − (1 + 1) = 8.25
    assert "do not meet" in err.message and "10.25 apart, 8.25 more than 1 + 1" in err.message


def test_circle_inside_another():
    err = error_of(four_bar_tree(a=1, b=10, c=2, d=4, theta=0))
    assert err.kind == "geometry" and "inside" in err.message
    assert "3 apart, 5 less than |10 − 2|" in err.message


def test_two_fitting_points_are_listed():
    tree = four_bar_tree()
    del tree["points"]["B"]["side"]
    err = error_of(tree)
    assert err.kind == "geometry" and err.where == "points.B"
    t2 = math.radians(52)
    for circuit in (True, False):
        _, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, t2, open_circuit=circuit)
        assert f"{5.2 + 4.35 * math.cos(t4):.6g}, {4.35 * math.sin(t4):.6g}" in err.message
    assert "side: left or right" in err.message


def test_tangent_circles_meet_in_one_point_without_side():
    tree = four_bar_tree(a=1, b=3, c=2, d=6, theta=180)    # |A O4| = 7 > 5: apart
    tree["parameters"]["d"] = 4                            # |A O4| = 5 = 3 + 2: tangent
    del tree["points"]["B"]["side"]
    tree["drivers"] = []
    tree["ask"] = []
    model = kinematika.as_model(tree)
    from kinematika.engine.instant import instantiate

    assert instantiate(model).points["B"] == pytest.approx((-1 + 3, 0.0))


def test_circle_that_misses_its_line():
    err = error_of(slider_crank_tree(l=1.0, e=-5.0, theta=90))
    assert err.kind == "geometry" and err.where == "points.C"
    assert "misses the line GH" in err.message and "8 from A, 7 more than the radius" in err.message


def test_parallel_lines():
    tree = four_bar_tree()
    tree["points"]["S"] = {"lines": [["O2", "O4"], {"through": "A", "direction": [2, 0]}]}
    tree["bodies"]["ground"] = ["O2", "O4", "S"]
    err = error_of(tree)
    assert err.kind == "geometry" and err.where == "points.S" and "parallel" in err.message


def test_a_cycle_is_a_schema_error():
    tree = four_bar_tree()
    tree["points"]["A"] = {"from": "B", "distance": 1, "angle": 0}
    err = error_of(tree)
    assert err.kind == "schema" and "cycle" in err.message and "A" in err.message and "B" in err.message


def test_near_in_a_symbolic_model_is_a_schema_error():
    tree = four_bar_tree()
    tree["parameters"]["theta"] = None
    del tree["points"]["B"]["side"]
    tree["points"]["B"]["near"] = [6, 4]
    err = error_of(tree)
    assert err.kind == "schema" and err.where == "points.B.near"


@pytest.mark.parametrize("change, kind, where", [
    ({"A": {"from": "Z", "distance": 1, "angle": 0}}, "schema", "points.A.from"),
    ({"A": {"from": "O2", "distance": 1}}, "schema", "points.A.angle"),
    ({"A": {"from": "O2", "distance": 1, "angle": 0, "spin": 2}}, "schema", "points.A.spin"),
    ({"A": {"radius": 2}}, "schema", "points.A"),
    ({"B": {"circles": [["A", 6.1], ["O4", 4.35]], "side": "up"}}, "schema", "points.B.side"),
    ({"B": {"circles": [["A", 6.1], ["A", 4.35]], "side": "left"}}, "schema", "points.B.circles"),
    ({"B": {"circles": [["A", -6.1], ["O4", 4.35]], "side": "left"}}, "schema", "points.B.circles[0][1]"),
    ({"B": {"circles": [["A", 6.1]], "side": "left"}}, "schema", "points.B.circles"),
    ({"A": {"frame": ["O2", "O2"], "at": [1, 0]}}, "schema", "points.A.frame"),
])
def test_malformed_constructions_name_their_place(change, kind, where):
    tree = four_bar_tree()
    tree["points"].update(copy.deepcopy(change))
    err = error_of(tree)
    assert (err.kind, err.where) == (kind, where), err


def test_constructions_are_planar():
    tree = four_bar_tree()
    tree["points"]["O4"] = [5.2, 0, 0]
    err = error_of(tree)
    assert err.kind == "schema" and "planar" in err.message


def test_a_rounded_point_off_its_slot_says_the_tolerance_and_the_fix():
    tree = {"points": {"O2": [-1, 0], "O4": [0, -1], "A": [0.00001, 0], "B": [0, 2]},
            "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "rocker": ["O4", "A", "B"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                       {"type": "revolute", "bodies": ["ground", "rocker"], "at": "O4"},
                       {"type": "slot", "bodies": ["rocker", "crank"], "at": "A", "along": ["O4", "B"]}],
            "drivers": [{"omega": "crank", "value": 1}]}
    err = error_of(tree)
    assert err.kind == "geometry" and err.where == "joints[2] (j3)"
    assert "gap -1e-05, more than the tolerance" in err.message
    assert "write A by construction, or with more digits" in err.message
    tree["points"]["A"] = {"lines": [["O2", [1, 0]], ["O4", "B"]]}      # the same point, constructed
    # by hand: v_A = ω k × (A − O2) = (0, 1), along the slot x = 0, so the rocker does not turn
    assert kinematika.solve(tree).omega("rocker") == pytest.approx(0, abs=1e-12)
