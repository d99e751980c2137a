"""Every bundled example moves: `sweep` follows it over its driven joint, or `simulate`
follows it in time over its own `simulate:` section (issue 31). The list below names each
example and how it moves, so that a new example is seen and placed (docs/examples.md says
the same to a reader, and a test keeps the two equal).

An example moves in time when a sweep cannot follow it: a joint of it constrains velocities
only (a knife edge, a disc rolling on a plane), or no driver drives a joint a sweep can
advance (the notes' wheels and pulleys, driven by a body's ω or a point's velocity). Such
an example carries a `simulate:` section with a time it can really be followed — before the
dead point or the end of travel its comments derive — so that `kinematika simulate MODEL`
and the page's slider need nothing more. Each is run over that whole time (the costliest —
two 3D vehicles with a few thousand velocity solutions each, and the tractor with its trailer
over a minute — over their first eighth unless KINEMATIKA_DEEP=1), with few rows: the
integrator's work is set by its tolerance, not by the rows asked for. A default run moves
one example of each kind (and the coin, a disc rolling on a plane); a deep run moves every
example.
"""
from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from kinematika import load_model
from kinematika.simulate import Simulator, needs_time
from kinematika.simulate.clock import make_clock
from kinematika.sweep import run_sweep
from kinematika.sweep.plan import swept_joint
from kinematika.sweep.summary import summary_lines
from tests.conftest import DEEP, EXAMPLES, KINDS, ROOT, sampled

SWEEP, TIME = "sweep", "simulate"
MOVES = {
    "cam_roller_follower": SWEEP, "car_wheel_steering": TIME, "coin_rolling": TIME, "eccentric_cam": SWEEP,
    "fan_absolute": SWEEP, "fan_common_point_B": SWEEP, "fan_composition": SWEEP, "fan_symbolic": SWEEP,
    "four_bar": SWEEP, "gyroscope": SWEEP, "hooke_joint": SWEEP, "inverted_slider_crank": SWEEP,
    "jansen_leg": SWEEP, "pin_in_circular_slot": SWEEP, "planetary_gears": SWEEP, "pulley_train": SWEEP,
    "quick_return": SWEEP, "robot_arm_3d": SWEEP, "rssr_spatial_four_bar": SWEEP,
    "seed_001_p_pair_coriolis": SWEEP, "seed_001_r_pairs": SWEEP, "seed_001_rolling_pair": SWEEP,
    "seed_c5_1_1_pulley_on_cable": TIME, "seed_c5_1_2_bar_on_inclined_wheels": TIME,
    "seed_c5_1_3_bar_in_sleeve": SWEEP, "seed_c5_1_4_epicyclic": SWEEP, "seed_c5_1_5_pulley_block": TIME,
    "seed_c5_1_6_belt": SWEEP, "seed_c5_1_7_semicylinder": TIME, "seed_c5_1_8_contact_points": TIME,
    "seed_c5_2_1_tricycle": TIME, "seed_c5_2_2_articulated": TIME, "seed_c5_e1_cavity": SWEEP,
    "seed_c5_e2_gear_change": SWEEP, "seed_c5_e3_wheels_with_rod": TIME, "seed_c5_e4_upper_wheel": TIME,
    "seed_c5_e5_unequal_wheels": TIME, "seed_c5_e6_bicycle": TIME, "slider_crank": SWEEP,
    "spherical_four_bar": SWEEP, "tractor_trailer": TIME, "tractor_trailer_turning": TIME,
    "triad_six_bar": SWEEP, "vehicle_upper_wheel": TIME, "watt_six_bar": SWEEP, "wheel_rolling": TIME,
}
COSTLY = {"car_wheel_steering", "coin_rolling", "tractor_trailer_turning"}   # an eighth of their time, unless deep


def test_every_example_is_listed_with_how_it_moves():
    """The list is the examples folder, and each moves the way its model says: in time when a
    sweep cannot follow it (and then it has its own `simulate:` section), else swept."""
    assert sorted(MOVES) == sorted(p.stem for p in EXAMPLES.glob("*.yaml"))
    for name, how in MOVES.items():
        model = load_model(EXAMPLES / f"{name}.yaml")
        try:
            swept_joint(model, model.sweep.joint if model.sweep else None)
            sweepable = not needs_time(model)
        except Exception:
            sweepable = False
        assert how == (SWEEP if sweepable else TIME), name
        assert how == SWEEP or model.simulate is not None, f"{name}: no simulate section"


def test_the_docs_list_how_every_example_moves():
    """docs/examples.md's table of motions names every example once, as the list does."""
    text = (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
    table = text.split("## How each example moves", 1)[1]
    rows = dict(re.findall(r"^\| `(\w+)\.yaml` \| (sweep|simulate) \|", table, re.M))
    assert rows == MOVES


def _moved(positions: dict) -> float:
    """The largest distance any point travels from its first row (over the drawing's size)."""
    first = np.array([p["position"][0] for p in positions.values()])
    size = float(np.ptp(first, axis=0).max()) or 1.0
    return max(float(np.nanmax(np.linalg.norm(p["position"] - p["position"][0], axis=-1)))
               for p in positions.values()) / size


@pytest.mark.parametrize("name", sampled(sorted(n for n, how in MOVES.items() if how == SWEEP), KINDS))
def test_the_example_sweeps(name):
    """Its sweep (its own section, else a full turn) in 4 steps: every row assembled, the
    mechanism moving; where the input meets limit positions the summary gives them and the
    range."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")           # "swept at the draw_at numbers": said, and true
        result = run_sweep(EXAMPLES / f"{name}.yaml", steps=4)
    assert result.ok.all()
    assert _moved(result.points) > 1e-3
    if result.limits:
        text = "\n".join(summary_lines(result))
        assert f"limit positions of {result.joint}:" in text and f"range of {result.joint}:" in text


@pytest.mark.parametrize("name", sampled(sorted(n for n, how in MOVES.items() if how == TIME),
                                          KINDS | {"coin_rolling"}))
def test_the_example_moves_in_time_over_its_section(name):
    """Its `simulate:` section's time (the costliest over its first eighth), in 2 steps:
    every row solved, the drift small, the mechanism moving."""
    sim = Simulator(EXAMPLES / f"{name}.yaml")
    time = make_clock(sim.model, sim.timing.start).duration
    if name in COSTLY and not DEEP:
        time /= 8
    result = sim.run(time, 2)
    assert result.ok.all() and len(result) == 3
    assert result.drift.max() < 1e-7
    assert _moved(result.points) > 1e-3
