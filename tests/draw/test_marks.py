"""Instant centres, Kennedy lines and curvature circles, read back from the figure.

Expected centres are intersections of lines through known centres (the pins and the
normals to the pins' velocities); curvature radii are |v|³/|v × a| with v, a from the
closed form, and exact for B on the rocker (a circle about O4 of radius |O4B|).
"""
from __future__ import annotations

import numpy as np

from kinematika.draw import draw

from .artists import angle_between, arrow, has_artist, label, line, lines_starting, marker, point_to_line
from .mechanisms import (A, B, O2, O4, P, coupler_icr, cross, four_bar_motion, four_bar_tree,
                         line_meet, slider_crank_tree, xy)


def test_asked_icr_marker_sits_at_the_crossing_of_the_pin_normals():
    fig = draw(four_bar_tree([{"icr": "coupler"}]))
    assert np.allclose(marker(fig, "icr:coupler"), xy(coupler_icr()), atol=1e-9)
    assert label(fig, "icr:coupler") == r"$I_{\mathrm{13}}$"        # ground 1, crank 2, coupler 3


def test_all_centres_and_their_kennedy_lines():
    fig = draw(four_bar_tree([]), centres=True)
    i13 = coupler_icr()                          # 1 ground, 2 crank, 3 coupler, 4 rocker
    i24 = line_meet(A, B, O2, O4)                # on I23–I34 and on I12–I14
    expected = {"ground-crank": O2, "crank-coupler": A, "coupler-rocker": B, "ground-rocker": O4,
                "ground-coupler": i13, "crank-rocker": i24}
    for pair, point in expected.items():
        assert np.allclose(marker(fig, f"centre:{pair}"), xy(point), atol=1e-9), pair
    kennedy = lines_starting(fig, "kennedy:")
    assert len(kennedy) == 4                     # two lines for each of I13 and I24
    for found, knowns in ((i13, [(O2, A), (O4, B)]), (i24, [(A, B), (O2, O4)])):
        for p, q in knowns:   # a drawn line through the two known centres passes the found one
            drawn = [k for k in kennedy if point_to_line(xy(p), k[0], k[-1]) < 1e-9
                     and point_to_line(xy(q), k[0], k[-1]) < 1e-9]
            assert drawn, (p, q)
            assert point_to_line(xy(found), drawn[0][0], drawn[0][-1]) < 1e-9


def test_far_centre_is_shown_at_the_edge_with_its_coordinates():
    """A near-parallelogram four-bar: the coupler's centre lies far away."""
    tree = four_bar_tree([{"icr": "coupler"}])
    tree["points"]["B"] = [3.0, 1.0]
    tree["points"]["O4"] = [2.0, 0.02]
    tree["points"]["P"] = [2.0, 1.5]
    fig = draw(tree)
    far = line_meet(O2, A, complex(2.0, 0.02), complex(3.0, 1.0))
    assert abs(far) > 20
    assert not has_artist(fig, "icr:coupler")
    tail, tip = arrow(fig, "icr:coupler:far")
    ax = fig.axes[0]
    for end in (tail, tip):
        assert ax.get_xlim()[0] <= end[0] <= ax.get_xlim()[1]
        assert ax.get_ylim()[0] <= end[1] <= ax.get_ylim()[1]
    assert angle_between(tip - tail, xy(far) - tip) < 1e-6       # pointing at the centre
    assert f"({far.real:.3g}, {far.imag:.3g})" in label(fig, "icr:coupler")


def test_centre_at_infinity_is_a_double_arrow_at_the_edge_along_its_direction():
    """The slider translates along x: its centre relative to ground is at infinity along ±y."""
    tree = slider_crank_tree()
    tree["ask"] = [{"icr": "slider"}]
    fig = draw(tree)
    start, tip = arrow(fig, "icr:slider:infinity")
    d = (tip - start) / np.linalg.norm(tip - start)
    assert abs(d[0]) < 1e-9 and abs(abs(d[1]) - 1) < 1e-9
    ax = fig.axes[0]
    for end in (start, tip):
        assert ax.get_xlim()[0] <= end[0] <= ax.get_xlim()[1]
        assert ax.get_ylim()[0] <= end[1] <= ax.get_ylim()[1]
    assert "∞" in label(fig, "icr:slider")


def _circle_radius(points: np.ndarray, centre) -> np.ndarray:
    pts = points[~np.isnan(points).any(axis=1)]
    return np.linalg.norm(pts - np.asarray(centre), axis=1)


def test_curvature_circle_of_a_rocker_point_is_the_rocker_circle():
    fig = draw(four_bar_tree([{"curvature": "B@rocker"}]))
    assert np.allclose(marker(fig, "curvature-centre:B@rocker"), xy(O4), atol=1e-9)
    radii = _circle_radius(line(fig, "curvature:B@rocker"), xy(O4))
    assert len(radii) > 20
    assert np.allclose(radii, abs(B - O4), rtol=1e-9)


def test_curvature_circle_of_the_coupler_point_has_the_closed_form_radius():
    v, a = four_bar_motion("P")
    radius = abs(v) ** 3 / abs(cross(v, a))
    centre = P + 1j * v / abs(v) * radius * np.sign(cross(v, a))   # towards the normal acceleration
    fig = draw(four_bar_tree([{"curvature": "P"}]))
    assert np.allclose(marker(fig, "curvature-centre:P@coupler"), xy(centre), atol=1e-9)
    radii = _circle_radius(line(fig, "curvature:P@coupler"), xy(centre))
    assert np.allclose(radii, radius, rtol=1e-9)
    assert f"{radius:.3g}" in label(fig, "curvature:P@coupler")
