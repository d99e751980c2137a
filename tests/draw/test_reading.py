"""Figures a teacher can read: the absolute vector beside an asked relative one, the parts of
an asked composition (the Coriolis term in a figure about it), the data the model gives (the
tractor's v_F), arrows off the bars they would lie along, belts wrapped round both pulleys."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinematika.draw import draw

from .artists import arrow, axes, pixel

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2] / "examples"


def gids(fig) -> set[str]:
    return {p.get_gid() for p in axes(fig).patches if p.get_gid()}


def test_absolute_beside_relative():
    fig = draw(ROOT / "fan_composition.yaml")
    assert {"velocity:P@blades/block", "velocity:P@blades"} <= gids(fig)


def test_composition_parts_with_coriolis():
    """P pair (seed 001 §4.3): the block's acceleration seen from the guide, its absolute one,
    the drag and the Coriolis term 2 ω_M × v_rel, at B."""
    fig = draw(ROOT / "seed_001_p_pair_coriolis.yaml")
    keys = gids(fig)
    assert {"acceleration:B@N/M", "acceleration:B@N", "acceleration:B@N:coriolis", "acceleration:B@N:drag"} <= keys
    start, tip = arrow(fig, "acceleration:B@N:coriolis")
    # 2 ω_M k × v_rel: ω_M = 4, v_rel along the guide (30°): perpendicular to it, to its left or right
    d = (tip - start) / np.linalg.norm(tip - start)
    guide = np.array([math.cos(math.radians(30)), math.sin(math.radians(30))])
    assert abs(float(d @ guide)) < 1e-6


def test_given_velocity_is_drawn():
    fig = draw(ROOT / "tractor_trailer.yaml")
    assert "velocity:F@front" in gids(fig)


def test_an_arrow_along_its_bar_ends_at_the_point():
    """A crank O–A at steady ω: a_A = −ω² OA points from A into the crank; drawn ending at A,
    coming from beyond it."""
    model = {"points": {"O": [0, 0], "A": [1, 0]}, "bodies": {"ground": ["O"], "crank": ["O", "A"]},
             "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"}],
             "drivers": [{"omega": "crank", "value": 2}], "ask": [{"acceleration": "A"}]}
    fig = draw(model)
    start, tip = arrow(fig, "acceleration:A@crank")
    assert np.linalg.norm(tip - np.array([1.0, 0.0])) <= 4 * pixel(fig)
    assert start[0] > 1.0                   # from beyond A, pointing towards O
    assert abs(start[1]) < 1e-9


def test_belt_wrapped_round_both_pulleys():
    """The pulley train's first belt: its run y = 0 under pulleys of radii 0.05 (at x = 0) and
    0.2 (at x = 0.5); the loop also goes round the far sides (x < −0.045, x > 0.69) and back
    along the other common tangent."""
    fig = draw(ROOT / "pulley_train.yaml")
    lines = [ln for ln in axes(fig).lines if ln.get_gid() == "shape:belt1"]
    assert len(lines) == 1
    xy = np.column_stack(lines[0].get_data())
    assert xy[:, 0].min() < -0.045 and xy[:, 0].max() > 0.69
    c1, r1, c2, r2 = np.array([0, 0.05]), 0.05, np.array([0.5, 0.2]), 0.2
    on_rims = [min(abs(np.linalg.norm(p - c1) - r1), abs(np.linalg.norm(p - c2) - r2)) for p in xy]
    straight = sum(d > 1e-6 for d in on_rims)
    assert straight == pytest.approx(0, abs=4)   # every vertex on a rim: runs are tangent lines between them


@pytest.mark.parametrize("name,radius", [("seed_c5_1_4_epicyclic", 3 * 0.05), ("seed_c5_e2_gear_change", 3 * 0.05)])
def test_a_rings_name_sits_on_its_rim(name, radius):
    """A ring (an internal gear's outline) is named at its rim, outside its circle: the fourth
    audit found C5-1.4's "corona" inside satellite 3, a wheel the ring holds. The label's box
    (data coordinates) lies wholly outside the ring's circle (radius 3r, r = 0.05 at draw_at,
    centre O at the origin) and within the band's width and a half of it."""
    from matplotlib.text import Text

    fig = draw(ROOT / f"{name}.yaml")
    ax, renderer = axes(fig), fig.canvas.get_renderer()
    (text,) = [t for t in ax.texts if t.get_gid() == "label:body:ring"]
    if hasattr(text, "update_positions"):             # an annotation (a label with a leader)
        text.update_positions(renderer)
    box = Text.get_window_extent(text, renderer)
    (x0, y0), (x1, y1) = ax.transData.inverted().transform([[box.x0, box.y0], [box.x1, box.y1]])
    nearest = np.hypot(np.clip(0.0, x0, x1), np.clip(0.0, y0, y1))     # the box's point nearest O
    assert radius < nearest < 1.5 * radius, (x0, y0, x1, y1)
