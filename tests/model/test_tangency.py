"""Constructions at their limits: circles (or a circle and a line) that touch, within the
tolerance, meet in one point whatever the round-off; angles that are whole quarter turns
give exact coordinates. Expected points by hand: the touching point lies on the line of
centres, r1 from the first centre."""
from __future__ import annotations

import math

import pytest

import kinematika
from kinematika import KinematikaError
from kinematika.engine.instant import instantiate


def points_of(points: dict, bodies: dict | None = None) -> dict:
    tree = {"points": points, "bodies": bodies or {"ground": list(points)}}
    return instantiate(kinematika.as_model(tree)).points


@pytest.mark.parametrize("angle", [37, 61, 100, 145, 300])
def test_touching_circles_meet_in_their_one_point(angle):
    # crank 2 at `angle` from O2, O4 = (4, 0); coupler + rocker = |AO4| exactly on paper,
    # so the circles touch; in floats the gap is round-off of either sign
    t = math.radians(angle)
    a = (2 * math.cos(t), 2 * math.sin(t))
    span = math.hypot(4 - a[0], a[1])
    got = points_of({"O2": [0, 0], "O4": [4, 0], "A": {"from": "O2", "distance": 2, "angle": f"deg({angle})"},
                     "B": {"circles": [["A", f"sqrt(20 - 16*cos(deg({angle}))) - 1.5"], ["O4", 1.5]]}})["B"]
    r1 = span - 1.5
    assert got == pytest.approx((a[0] + r1 * (4 - a[0]) / span, a[1] + r1 * (0 - a[1]) / span), abs=1e-9)


def test_a_circle_inside_touching_the_other_meets_it_in_one_point():
    # the circle about O4 (radius 1) inside the one about A (radius |AO4| + 1), touching it
    # beyond O4
    got = points_of({"A": [0, 0], "O4": {"from": "A", "distance": 3, "angle": "deg(41)"},
                     "B": {"circles": [["A", 4], ["O4", 1]]}})["B"]
    assert got == pytest.approx((4 * math.cos(math.radians(41)), 4 * math.sin(math.radians(41))), abs=1e-9)


def test_a_line_touching_the_circle_meets_it_in_one_point():
    # the slider's line y = 2 sin(35°) − 3 is 3 below the crank pin: a rod of 3 touches it
    t = math.radians(35)
    got = points_of({"O": [0, 0], "A": {"from": "O", "distance": 2, "angle": "deg(35)"},
                     "B": {"circle": ["A", 3], "line": {"through": [0, "2*sin(deg(35)) - 3"],
                                                        "direction": [1, 0]}}})["B"]
    assert got == pytest.approx((2 * math.cos(t), 2 * math.sin(t) - 3), abs=1e-9)


def test_a_side_keeps_the_true_intersection_of_nearly_touching_circles():
    # circles 1e-9 (relative) short of touching: within the tolerance, yet with a side the
    # point is the real intersection, at its distances from both centres
    span = math.hypot(4 - 2 * math.cos(math.radians(61)), 2 * math.sin(math.radians(61)))
    b = span * (1 + 1e-9) - 1.5
    pts = points_of({"O2": [0, 0], "O4": [4, 0], "A": {"from": "O2", "distance": 2, "angle": "deg(61)"},
                     "B": {"circles": [["A", b], ["O4", 1.5]], "side": "left"}})
    assert math.dist(pts["B"], pts["A"]) == pytest.approx(b, abs=1e-12)
    assert math.dist(pts["B"], pts["O4"]) == pytest.approx(1.5, abs=1e-12)


@pytest.mark.parametrize("angle, expected", [("deg(90)", (0, 3)), ("deg(180)", (-3, 0)), ("deg(270)", (0, -3)),
                                             ("deg(-90)", (0, -3)), ("deg(450)", (0, 3)), ("pi", (-3, 0)),
                                             ("0", (3, 0))])
def test_quarter_turns_are_exact(angle, expected):
    # cos(π/2) in floats is 6e-17: a whole quarter turn gives exact zeros, as on paper
    got = points_of({"O": [0, 0], "A": {"from": "O", "distance": 3, "angle": angle}})["A"]
    assert got == expected


def test_a_small_angle_is_not_taken_for_zero():
    got = points_of({"O": [0, 0], "A": {"from": "O", "distance": 3, "angle": "deg(1e-9)"}})["A"]
    assert got[1] == pytest.approx(3 * math.radians(1e-9), rel=1e-12) and got[1] > 0


def test_two_fitting_points_are_named_by_their_side():
    with pytest.raises(KinematikaError) as info:
        points_of({"O2": [0, 0], "O4": [7, 0], "A": {"from": "O2", "distance": 2, "angle": "deg(40)"},
                   "B": {"circles": [["A", 6.5], ["O4", 5.5]]}})
    assert "two points fit, one on each side of A→O4: (" in info.value.message
    with pytest.raises(KinematikaError) as info:
        points_of({"O": [0, 0], "G": [0, -1], "H": [1, -1], "A": {"from": "O", "distance": 1, "angle": 1},
                   "B": {"circle": ["A", 3], "line": ["G", "H"]}})
    assert "two points fit on the line GH: (" in info.value.message and "side: ahead or behind" in info.value.message
