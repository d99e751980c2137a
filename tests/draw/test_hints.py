"""What a model tells its figures: the numbers a symbolic model is drawn at (`draw_at`), the
vertical of a 3D model (`up`); and vehicles drawn with their wheels' normals, which locate
the chassis' instant centre."""
from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest

from kinematika.api import as_model
from kinematika.draw import draw
from kinematika.draw.projection import projection
from kinematika.errors import KinematikaError

from .artists import has_artist, line, lines_starting, marker, point_to_line

EXAMPLES = Path(__file__).parents[2] / "examples"

# a tricycle (plan view): rear axle along y through M = (0, 0), front wheel at F = (L, 0)
# steered 45° (rolling along (1, 1)); the chassis turns about where the normals to the
# wheels' planes meet: the rear axle x = 0 and the line through F along (−1, 1), at (0, L)
TRICYCLE = {
    "name": "Tricycle",
    "parameters": {"L": None, "s": None, "v0": None},
    "draw_at": {"L": 1.2, "s": 0.4, "v0": 2},
    "points": {"M": [0, 0], "RL": [0, "s"], "RR": [0, "-s"], "F": ["L", 0]},
    "bodies": {"ground": ["RL", "RR", "F"], "chassis": ["M", "RL", "RR", "F"], "front": ["F"]},
    "joints": [{"id": "steer", "type": "revolute", "bodies": ["chassis", "front"], "at": "F"},
               {"id": "wf", "type": "wheel", "bodies": ["ground", "front"], "at": "F",
                "along": [1, 1]},
               {"id": "wl", "type": "wheel", "bodies": ["ground", "chassis"], "at": "RL",
                "along": [1, 0]},
               {"id": "wr", "type": "wheel", "bodies": ["ground", "chassis"], "at": "RR",
                "along": [1, 0]}],
    "drivers": [{"velocity": "F@front", "along": [1, 1], "value": "v0"},
                {"joint": "steer", "rate": 0}],
    "ask": [{"icr": "chassis"}, {"velocity": "RR@chassis"}],
}


def test_symbolic_model_is_drawn_at_its_draw_at_values():
    fig = draw(TRICYCLE)
    assert np.allclose(marker(fig, "icr:chassis"), (0.0, 1.2), atol=1e-12)
    (wheel,) = [p for p in fig.axes[0].patches if p.get_gid() == "joint:wr"]
    assert np.allclose(wheel.get_xy()[:4].mean(axis=0), (0.0, -0.4), atol=1e-12)
    notes = " ".join(t.get_text() for t in fig.texts)
    assert "L = 1.2, s = 0.4, v0 = 2 (its draw_at values)" in notes


def test_wheel_normals_meet_at_the_chassis_centre():
    fig = draw(TRICYCLE, centres=True)
    centre = marker(fig, "centre:ground-chassis")
    assert np.allclose(centre, (0.0, 1.2), atol=1e-12)
    rear = line(fig, "normal:wl")              # one line for the two rear wheels of one axle
    assert not has_artist(fig, "normal:wr")
    for p in ((0.0, 0.4), (0.0, -0.4), centre):
        assert point_to_line(p, rear[0], rear[-1]) < 1e-9
    front = line(fig, "normal:wf")
    for p in ((1.2, 0.0), centre, (0.2, 1.0)):   # through F along (−1, 1)
        assert point_to_line(p, front[0], front[-1]) < 1e-9


def test_articulated_vehicle_has_wheels_and_no_pin_to_the_ground():
    fig = draw(EXAMPLES / "seed_c5_2_2_articulated.yaml", centres=True)
    patches = [p.get_gid() or "" for p in fig.axes[0].patches]
    assert sum(g.startswith("joint:j") for g in patches) >= 4      # four knife-edge wheels
    assert not any(g.startswith("slot:") for g in patches)
    assert lines_starting(fig, "normal:")


@pytest.mark.parametrize("change, message", [
    ({"draw_at": {"q": 1}}, "unknown parameter 'q'"),
    ({"draw_at": {"L": -1}}, "positive"),
    ({"draw_at": {"L": 1}, "parameters": {"L": 2, "s": None, "v0": None}}, "has a value"),
    ({"up": [0, 1, 0]}, "3D model"),
])
def test_bad_hints_are_schema_errors(change, message):
    tree = copy.deepcopy(TRICYCLE)
    tree.update(change)
    with pytest.raises(KinematikaError, match=message) as err:
        as_model(tree)
    assert err.value.kind == "schema"


def test_a_draw_at_that_breaks_the_geometry_is_refused():
    tree = copy.deepcopy(TRICYCLE)
    tree["points"]["M"] = [0, "sqrt(s - 1)"]
    with pytest.raises(KinematikaError, match="not real") as err:
        draw(tree)
    assert err.value.where == "draw_at"


def test_up_is_vertical_on_the_page():
    """The fan's shaft is along y: with `up: [0, 1, 0]` y is drawn straight up, in every view."""
    for view in ("iso", "front", "side"):
        axes = projection(3, view, (0, 1, 0)).axes()
        assert np.allclose(axes["y"] / np.linalg.norm(axes["y"]), (0, 1))
    iso = projection(3, "iso", (0, 1, 0)).axes()
    for a, b in (("x", "y"), ("y", "z"), ("z", "x")):       # still isometric
        u, v = iso[a], iso[b]
        assert np.degrees(np.arccos(u @ v / np.linalg.norm(u) / np.linalg.norm(v))) == \
            pytest.approx(120.0)


def test_the_fan_is_drawn_with_its_shaft_vertical():
    fig = draw(EXAMPLES / "fan_absolute.yaml")
    shaft = [ln.get_xydata() for ln in fig.axes[0].lines if ln.get_linestyle() == "-."]
    assert any(abs(s[1, 0] - s[0, 0]) < 1e-12 < abs(s[1, 1] - s[0, 1]) for s in shaft)
