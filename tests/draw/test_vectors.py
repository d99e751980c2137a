"""Velocity and acceleration arrows: where they start, where they point, how long they are.

Expected vectors come from the closed forms in `mechanisms`; the figure is read back from
its artists (the arrow patches' drawn paths).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinematika.draw import draw
from kinematika.draw.style import LONGEST, SHORTEST

from .artists import angle_between, arrow, label, pixel
from .mechanisms import (A, B, O2, P, R, four_bar_motion, four_bar_tree, slider_crank_tree,
                         slider_position, slider_speed, xy)

ASK = [{"velocity": "A"}, {"velocity": "B"}, {"velocity": "P"},
       {"acceleration": "A"}, {"acceleration": "B"}, {"acceleration": "P"}]


@pytest.fixture(scope="module")
def four_bar_fig():
    return draw(four_bar_tree(ASK))


def size_of(fig) -> float:
    """The mechanism's extent in this four-bar: its larger side (x from O2 to O4 is 3.5)."""
    return 3.5


@pytest.mark.parametrize("kind, index", [("velocity", 0), ("acceleration", 1)])
def test_four_bar_arrows_start_at_points_along_closed_form_vectors(four_bar_fig, kind, index):
    positions = {"A": A, "B": B, "P": P}
    lengths = {}
    for name, body in (("A", "crank"), ("B", "coupler"), ("P", "coupler")):
        start, tip = arrow(four_bar_fig, f"{kind}:{name}@{body}")
        expected = four_bar_motion(name)[index]
        assert at_point(four_bar_fig, start, tip, xy(positions[name]))
        assert angle_between(tip - start, xy(expected)) < 1e-3     # degrees
        lengths[name] = (np.linalg.norm(tip - start), abs(expected))
    longest = max(m for _, m in lengths.values())
    for name, (drawn, magnitude) in lengths.items():   # to scale, longest = LONGEST of the size
        assert drawn == pytest.approx(LONGEST * size_of(four_bar_fig) * magnitude / longest,
                                      abs=3 * pixel(four_bar_fig)), name


def at_point(fig, start, tip, point) -> bool:
    """An arrow starts at its point, or ends there when starting there would lay it along a
    bar of the mechanism (then its drawn tip stops within a few pixels of the point)."""
    return bool(np.allclose(start, point, atol=1e-9) or np.linalg.norm(tip - point) <= 4 * pixel(fig))


def test_labels_give_name_and_closed_form_magnitude(four_bar_fig):
    v_b, a_p = abs(four_bar_motion("B")[0]), abs(four_bar_motion("P")[1])
    assert label(four_bar_fig, "velocity:B@coupler") == rf"$v_{{\mathrm{{B}}}}$ = {v_b:.3g}"
    assert label(four_bar_fig, "acceleration:P@coupler") == rf"$a_{{\mathrm{{P}}}}$ = {a_p:.3g}"


def test_relative_velocity_arrow():
    """v of B seen from the crank: v_B − (velocity of the crank's point at B)."""
    fig = draw(four_bar_tree([{"velocity": "B@coupler", "relative_to": "crank"}]))
    start, tip = arrow(fig, "velocity:B@coupler/crank")
    expected = four_bar_motion("B")[0] - 1j * 10.0 * (B - O2)
    assert at_point(fig, start, tip, xy(B))
    assert angle_between(tip - start, xy(expected)) < 1e-3     # degrees
    assert label(fig, "velocity:B@coupler/crank").startswith(r"$v_{\mathrm{B}{\in}\mathrm{3}\ \mathrm{rel}\ \mathrm{2}}$")  # B of the coupler (3) seen from the crank (2): no slash
    assert "bodies: 1 ground, 2 crank, 3 coupler, 4 rocker" in [t.get_text() for t in fig.texts]


def test_slider_crank_slider_velocity_along_the_guide():
    fig = draw(slider_crank_tree())
    start, tip = arrow(fig, "velocity:B@rod")
    v_a = R * 12.0
    assert tip[1] == pytest.approx(start[1], abs=1e-12)                 # horizontal
    assert math.copysign(1, tip[0] - start[0]) == math.copysign(1, slider_speed())
    a_start, a_tip = arrow(fig, "velocity:A@crank")
    longest = max(abs(slider_speed()), v_a)
    for (p, q), speed in (((start, tip), slider_speed()), ((a_start, a_tip), v_a)):
        assert np.linalg.norm(q - p) == pytest.approx(LONGEST * slider_position() * abs(speed) / longest,
                                                      abs=3 * pixel(fig))


def test_tiny_vector_next_to_huge_one_stays_visible_and_says_so():
    """A crank point 0.002 from the pivot moves 500 times slower than A."""
    c = O2 + 0.002 * (A - O2) / abs(A - O2) * 1j     # normal to the crank, so v_C ∥ crank
    fig = draw(four_bar_tree([{"velocity": "A"}, {"velocity": "C"}], C=c))
    a0, a1 = arrow(fig, "velocity:A@crank")
    c0, c1 = arrow(fig, "velocity:C@crank")
    size = np.ptp([O2.real, A.real, B.real, 3.5, P.real, c.real]), \
        np.ptp([O2.imag, A.imag, B.imag, 0.0, P.imag, c.imag])
    size = max(size)
    assert np.linalg.norm(a1 - a0) == pytest.approx(LONGEST * size, abs=3 * pixel(fig))
    assert np.linalg.norm(c1 - c0) == pytest.approx(SHORTEST * size, abs=3 * pixel(fig))
    assert angle_between(c1 - c0, xy(1j * 10.0 * c)) < 1e-3     # degrees
    assert "enlarged" in label(fig, "velocity:C@crank")
    assert "enlarged" not in label(fig, "velocity:A@crank")


def test_zero_vector_has_no_arrow_but_a_label():
    fig = draw(four_bar_tree([{"velocity": "O2@crank"}, {"velocity": "A"}]))
    assert not any(p.get_gid() == "velocity:O2@crank" for p in fig.axes[0].patches)
    assert label(fig, "velocity:O2@crank").endswith("= 0")


def test_options_choose_the_vectors():
    tree = four_bar_tree([{"velocity": "B"}, {"acceleration": "B"}])
    gids = lambda fig: {p.get_gid() for p in fig.axes[0].patches
                        if (p.get_gid() or "").startswith(("velocity", "acceleration"))}
    assert gids(draw(tree)) == {"velocity:B@coupler", "acceleration:B@coupler"}
    assert gids(draw(tree, accelerations=False)) == {"velocity:B@coupler"}
    assert gids(draw(tree, velocities=False, accelerations=False)) == set()
    assert gids(draw(tree, points=["A", "P"], accelerations=False)) == \
        {"velocity:A@crank", "velocity:P@coupler"}


def test_a_model_without_questions_shows_the_velocities_of_its_moving_points_only():
    """No `ask`: every body and point is answered (the frame's too), but the figure shows
    only the velocities of moving points, with no labels at the fixed pivots."""
    tree = four_bar_tree()
    tree.pop("ask", None)
    fig = draw(tree)
    texts = [t.get_gid() or "" for t in fig.axes[0].texts]
    assert not [g for g in texts if g.startswith(("label:velocity:O", "label:acceleration"))]
    gids = {p.get_gid() for p in fig.axes[0].patches if (p.get_gid() or "").startswith("velocity")}
    assert {"velocity:A@crank", "velocity:B@coupler"} <= gids
