"""Every way two outlines touch — circles outside each other, a disc in a hole, a hole about a
disc, a circle on either side of a line (either body holding the line), a pin on a circle,
and the same circles drawn as curves through points or as a cam's measured profile — against
the pair's motion derived by hand (`pairs`: the closed-form condition differentiated by
sympy): the driven-by-contact rocker's ω and α, and the contact point's velocity and
acceleration (the `contact` question's geometric point; the bodies' points there)."""
from __future__ import annotations

import numpy as np
import pytest

from kinematika.commands import solve_data

from .pairs import circles, circle_on_line, line_on_circle, pin_on_circle

EXACT = [
    circles("outside", 20.0, 30.0, "outside"),
    circles("disc in a hole", 80.0, 30.0, "b inside a"),
    circles("hole about a disc", 30.0, 80.0, "a inside b"),
    circle_on_line("circle left of the line", 1),
    circle_on_line("circle right of the line", -1),
    line_on_circle("line, circle on its left", 1),
    line_on_circle("line, circle on its right", -1),
    pin_on_circle("pin on a circle"),
]


def _answers(tree: dict) -> tuple[float, float, dict]:
    omega, alpha, contact = (a["value"] for a in solve_data(tree)["answers"])
    return omega, alpha, contact


def test_the_disc_in_the_hole_turns_its_rocker_as_the_equivalent_four_bar():
    """Issue 31's case: hole of radius 80 about C2 (30 from O2 at 150°), disc of radius 30 about
    C4 (45 from O4 = (40, 20)), ω₂ = −3, α₂ = 6: the four-bar O2–C2–C4–O4 with coupler
    80 − 30 = 50 gives ω₄ = −1.95098, α₄ = 2.67583 (the tool answered −22.0446)."""
    omega, alpha, _ = _answers(circles("disc in a hole", 80.0, 30.0, "b inside a").tree())
    assert omega == pytest.approx(-1.95098, abs=1e-5)
    assert alpha == pytest.approx(2.67583, abs=1e-5)


@pytest.mark.parametrize("pair", EXACT, ids=lambda p: p.name)
def test_every_way_of_touching_moves_as_derived_by_hand(pair):
    want = pair.motion()
    omega, alpha, contact = _answers(pair.tree())
    assert omega == pytest.approx(want["omega"], rel=1e-9, abs=1e-12)
    assert alpha == pytest.approx(want["alpha"], rel=1e-9, abs=1e-10)
    assert contact["point"] == pytest.approx(list(want["J"]), abs=1e-9)
    assert contact["geometric"]["velocity"] == pytest.approx(list(want["J_v"]), abs=1e-8)
    assert contact["geometric"]["acceleration"] == pytest.approx(list(want["J_a"]), abs=1e-7)
    j = np.asarray(want["J"])
    for key, pivot, w, a in (("body_a", (0.0, 0.0), -3.0, 6.0), ("body_b", (40.0, 20.0), omega, alpha)):
        r = j - pivot
        v = w * np.array([-r[1], r[0]])
        acc = a * np.array([-r[1], r[0]]) - w * w * r
        assert contact[key]["velocity"] == pytest.approx(list(v), abs=1e-8)
        assert contact[key]["acceleration"] == pytest.approx(list(acc), abs=1e-7)


@pytest.mark.parametrize("pair", EXACT[:3], ids=lambda p: p.name)
def test_circles_touching_roll_or_slide_the_same_way_whichever_body_is_first(pair):
    """The pair written b then a: the same rocker motion (the inside/outside decision and the
    signs of the radii follow the order)."""
    tree = pair.tree()
    tree["joints"][2]["bodies"] = ["l4", "l2"]
    omega, alpha, _ = _answers(tree)
    want = pair.motion()
    assert omega == pytest.approx(want["omega"], rel=1e-9)
    assert alpha == pytest.approx(want["alpha"], rel=1e-9)


CURVES = [
    circles("curve outside a circle", 20.0, 30.0, "outside", outline_a="curve"),
    circles("circle outside a curve", 20.0, 30.0, "outside", outline_b="curve"),
    circles("disc in a hole drawn as a curve", 80.0, 30.0, "b inside a", outline_a="curve"),
    circles("curve disc in a hole", 80.0, 30.0, "b inside a", outline_b="curve"),
    circles("curve inside a ring", 30.0, 80.0, "a inside b", outline_a="curve"),
    circles("ring drawn as a curve about a disc", 30.0, 80.0, "a inside b", outline_b="curve"),
    circles("two curves outside", 20.0, 30.0, "outside", outline_a="curve", outline_b="curve"),
    circles("curve in a curve", 80.0, 30.0, "b inside a", outline_a="curve", outline_b="curve"),
    pin_on_circle("pin on a curve", kind_a="curve"),
    circles("roller on a measured cam", 25.0, 15.0, "outside", crank=10.0, rocker=30.0, outline_a="cam"),
    circles("measured cam in a ring", 25.0, 40.0, "a inside b", crank=10.0, rocker=45.0, outline_a="cam"),
]


@pytest.mark.parametrize("pair", CURVES, ids=lambda p: p.name)
def test_curves_through_points_of_circles_move_as_the_circles(pair):
    """A closed spline through 360 points of a circle is that circle to O(h²) in curvature
    (h = 1°: a few parts in 10⁴ between the points, less at them): the rocker moves as derived
    for the circles."""
    tree = pair.tree()
    tree["ask"] = tree["ask"][:2]
    omega, alpha = (a["value"] for a in solve_data(tree)["answers"])
    want = pair.motion()
    assert omega == pytest.approx(want["omega"], rel=1e-6)
    assert alpha == pytest.approx(want["alpha"], rel=1e-3)
