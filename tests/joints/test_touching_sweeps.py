"""Sliding contacts over a motion: every pair the instant solver accepts can be swept and
moved, and follows the closed forms derived by hand — the disc in the hole as its equivalent
four-bar over a whole turn (the four-bar solved here by intersecting circles), a circle on
either side of a line, the same circles drawn as curves, a pin in a circular slot, and the
eccentric cam's flat follower, y = e sin θ + R."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from kinematika.commands import How, solve_data, sweep_run
from tests.conftest import DEEP, sampled

from .pairs import T2, circle_on_line, circles, line_on_circle, pin_on_circle
from .test_higher_pairs import cam_model, cycloidal

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _swept(tree: dict, steps: int) -> tuple[np.ndarray, dict]:
    """θ₂ at every row (the crank advances from the drawing) and rocker 4's angle (radians
    from the drawing), ω and α."""
    _, result = sweep_run(tree, by=360, steps=steps)
    assert result.ok.all()
    t2 = T2 + np.radians(np.asarray(result.coordinate))
    rocker = result.bodies["l4"]
    return t2, {"angle": np.radians(rocker["angle"]), "omega": rocker["omega"], "alpha": rocker["alpha"]}


def _compare(pair, tree: dict, steps: int, rel: float = 1e-8) -> None:
    t2, got = _swept(tree, steps)
    want = pair.over(t2)
    scale = {q: float(np.max(np.abs(want[q]))) for q in ("omega", "alpha")}
    assert got["angle"] == pytest.approx(want["angle"] - want["angle"][0], abs=1e-8)
    assert got["omega"] == pytest.approx(want["omega"], abs=rel * scale["omega"])
    assert got["alpha"] == pytest.approx(want["alpha"], abs=rel * scale["alpha"])


def test_the_disc_in_the_hole_turns_as_its_equivalent_four_bar_over_a_turn():
    """Hole of radius 80 on the crank (centre 30 from O2), disc of radius 30 on the rocker
    (centre 45 from O4): the four-bar 30–50–45 on a ground of √(40² + 20²), a crank-rocker,
    over a whole turn of the crank."""
    pair = circles("disc in a hole", 80.0, 30.0, "b inside a")
    _compare(pair, pair.tree(), 72 if DEEP else 36)


SWEPT = [
    circles("outside", 20.0, 30.0, "outside"),
    circles("hole about a disc", 30.0, 80.0, "a inside b"),
    circle_on_line("circle left of the line", 1),
    circle_on_line("circle right of the line", -1),
    line_on_circle("line, circle on its left", 1),
    line_on_circle("line, circle on its right", -1),
]


@pytest.mark.parametrize("pair", SWEPT, ids=lambda p: p.name)
def test_every_exact_pair_sweeps_as_derived_by_hand(pair):
    _compare(pair, pair.tree(), 36 if DEEP else 18)             # a row every 20° (10° in a deep run)


CURVES = [
    circles("curve disc in a hole", 80.0, 30.0, "b inside a", outline_b="curve"),
    circles("curve inside a ring", 30.0, 80.0, "a inside b", outline_a="curve"),
    circles("curve outside a circle", 20.0, 30.0, "outside", outline_a="curve"),
    circles("two curves outside", 20.0, 30.0, "outside", outline_a="curve", outline_b="curve"),
]


# one of each kind in a default run: a curve against a circle inside and outside, two curves
# (the disc drawn as a curve in the hole, the rocker's twin of "curve inside a ring": deep run)
@pytest.mark.parametrize("pair", sampled(CURVES, {"curve inside a ring", "curve outside a circle", "two curves outside"}),
                         ids=lambda p: p.name)
def test_curves_through_points_of_circles_sweep_as_the_circles(pair):
    _compare(pair, pair.tree(), 24 if DEEP else 8, rel=1e-4)        # a row every 45° (15° in a deep run)


@pytest.mark.parametrize("kind", ["curved_slot", "contact"])
def test_a_pin_in_a_circular_slot_sweeps_as_the_four_bar(kind):
    """Rocker 4's pin on a circle of radius 50 about the crank's C2: the four-bar 30–50–45."""
    pair = pin_on_circle("pin in a slot")
    _compare(pair, pair.tree(kind), 36)


def test_the_eccentric_cams_follower_rises_and_falls_as_e_sin_theta_plus_r_over_a_turn():
    """examples/eccentric_cam.yaml (e = 0.02, R = 0.05, drawn at 30°, ω = 10, α = 0): the
    flat face's height y = e sin θ + R, v = e ω cos θ, a = −e ω² sin θ at every row."""
    _, result = sweep_run(EXAMPLES / "eccentric_cam.yaml", by=360, steps=72)
    assert result.ok.all()
    theta = math.radians(30) + np.radians(np.asarray(result.coordinate))
    e, r, w = 0.02, 0.05, 10.0
    f = result.points["F@follower"]
    assert np.asarray(f["position"])[:, 1] == pytest.approx(e * np.sin(theta) + r, abs=1e-12)
    assert np.asarray(f["velocity"])[:, 1] == pytest.approx(e * w * np.cos(theta), abs=1e-11)
    assert np.asarray(f["acceleration"])[:, 1] == pytest.approx(-e * w * w * np.sin(theta), abs=1e-10)
    assert np.asarray(f["position"])[:, 0] == pytest.approx(0.0, abs=1e-12)


def test_the_eccentric_cam_moves_to_where_its_sweep_goes():
    """`move: {j1: 100}`: the follower's height and velocity at θ = 130°."""
    data = solve_data(EXAMPLES / "eccentric_cam.yaml", how=How(move={"j1": 100}))
    v, a = (x["value"] for x in data["answers"][:2])
    theta = math.radians(130)
    assert v == pytest.approx([0.0, 0.02 * 10 * math.cos(theta)], abs=1e-12)
    assert a == pytest.approx([0.0, -0.02 * 100 * math.sin(theta)], abs=1e-11)
    assert data["points"]["F@follower"]["position"][1] == pytest.approx(0.02 * math.sin(theta) + 0.05, abs=1e-12)


def test_a_cam_moves_as_its_program_says():
    """`kinematika solve examples/cam_roller_follower.yaml --move j1=30` (an internal error):
    the roller at θ = 112.5° + 30° of the cycloidal rise, s = h(x − sin 2πx / 2π),
    v = s'θ̇, a = s''θ̇² (Norton's eq. 8.6), ω = 2π."""
    data = solve_data(EXAMPLES / "cam_roller_follower.yaml", how=How(move={"j1": 30}))
    s, ds, dds = cycloidal(142.5)
    w = 2 * math.pi
    v, a = (x["value"] for x in data["answers"][:2])
    assert data["points"]["F@follower"]["position"] == pytest.approx([0.0, 50 + s], abs=1e-9)
    assert v == pytest.approx([0.0, ds * w], abs=1e-7)
    assert a == pytest.approx([0.0, dds * w * w], abs=1e-5)


# clockwise in a default run (a counter-clockwise cam moved: the test above), both in a deep run
@pytest.mark.parametrize("rotation", sampled(["ccw", "cw"], {"cw"}))
def test_a_cam_moved_either_way_is_where_its_sweep_goes(rotation):
    """A clockwise cam's program runs the other way: moved by −15° (its own sense), the
    follower is where the program puts it, s(θ) at θ = 112.5° + 15° (not 97.5°: the rise's
    other side)."""
    tree = cam_model(112.5, "knife", s=cycloidal(112.5)[0])
    tree["bodies"]["cam"]["cam"]["rotation"] = rotation
    by = 15 if rotation == "ccw" else -15
    data = solve_data(tree, how=How(move={"j1": by}))
    assert data["points"]["F@follower"]["position"] == pytest.approx([0.0, 40 + cycloidal(127.5)[0]], abs=1e-9)


@pytest.mark.parametrize("kind", ["curved_slot", "contact"])
def test_a_curve_moves_with_its_body(kind):
    """The pin on a curve through 360 points of a circle, the crank moved 40°: the rocker's
    ω, α there as the four-bar's (the spline's curvature is the circle's to O(h²), h = 1°:
    a few parts in 10⁴)."""
    pair = pin_on_circle("pin on a curve", kind_a="curve")
    tree = pair.tree(kind)
    tree["ask"] = tree["ask"][:2]
    data = solve_data(tree, how=How(move={"j1": 40}))
    t2 = T2 + math.radians(40)
    want = pair.motion(t2, float(pair.placed(np.array(t2))))
    omega, alpha = (x["value"] for x in data["answers"])
    assert omega == pytest.approx(want["omega"], rel=1e-6)
    assert alpha == pytest.approx(want["alpha"], rel=1e-3)
