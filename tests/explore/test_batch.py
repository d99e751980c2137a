"""The batch kernel (designs × positions) gives, design by design, the numbers of a sweep
on the same model with the same parameter values over its input's coordinate (not through
limit positions, as `explore` sweeps), including where a sweep stops and why."""
from __future__ import annotations

import numpy as np
import pytest

from kinematika.api import as_model
from kinematika.errors import KinematikaError
from kinematika.model.overrides import with_parameters
from kinematika.sweep.run import Sweeper
from kinematika.sweep.batch import BatchSweeper, describe

from .models import FOUR_BAR, QUICK_RETURN, SLIDER_CRANK

CASES = {
    # crank-rockers, a non-Grashof design that stops mid-turn, one whose B cannot be built
    "four-bar": (FOUR_BAR, {"a": [2.25, 1.0, 2.0, 3.5, 3.0], "c": [4.35, 4.0, 3.0, 5.5, 1.0]}),
    # a crank that turns, one that cannot (r + e > l), offsets either side
    "slider-crank": (SLIDER_CRANK, {"r": [1.0, 0.8, 2.0, 1.2], "e": [0.5, -0.3, 0.5, 2.5]}),
    "quick-return": (QUICK_RETURN, {"r": [0.1, 0.2, 0.15], "c": [0.3, 0.35, 0.3]}),
}


def per_design(text: str, values: dict[str, float]):
    """The sweep of the model with the design's values over the input's coordinate (not
    through limit positions: a study's cycle, as `explore` sweeps a design the batch kernel
    does not take), and the error it stops with (if any)."""
    model = with_parameters(as_model(text), {k: repr(v) for k, v in values.items()})
    try:
        Sweeper(model).run(steps=72, through=False)
        reason = ""
    except KinematikaError as err:
        reason = describe(err)
    try:
        return Sweeper(model).run(steps=72, skip_bad=True, through=False), reason
    except KinematikaError:
        return None, reason


@pytest.mark.parametrize("case", CASES)
def test_batch_rows_equal_run_sweep_per_design(case):
    text, designs = CASES[case]
    model = as_model(text)
    sweeper = BatchSweeper(model, list(designs), steps=72)
    assert sweeper.batchable
    batch = sweeper.run({k: np.array(v) for k, v in designs.items()})
    reasons = batch.reasons()
    tracks = batch.outcome.tracks
    for d in range(len(next(iter(designs.values())))):
        result, reason = per_design(text, {k: v[d] for k, v in designs.items()})
        if result is None:                      # the drawn configuration cannot be built
            assert not batch.drawn[d] and reason
            continue
        assert batch.drawn[d]
        assert reasons[d] == reason
        ok = result.ok
        assert (batch.ok[d] == ok).all()
        for body, values in result.bodies.items():
            t = tracks[body]
            angle = np.degrees(np.broadcast_to(t.theta, batch.ok.shape)[d])
            assert angle[ok] == pytest.approx(values["angle"][ok], abs=1e-9)
            for q, mine in (("omega", t.omega), ("alpha", t.alpha)):
                got = np.broadcast_to(mine, batch.ok.shape)[d]
                assert got[ok] == pytest.approx(values[q][ok], rel=1e-9, abs=1e-9)
        for name, values in result.points.items():
            point, _, body = name.partition("@")
            owner = model.place_owner(point)
            if not any(body in c and owner in c for c in model.motion_classes(point, model.carriers(point))):
                continue        # a sweep gives the body's point coinciding with the pin; tracks, its own
            for q, mine in zip(("position", "velocity", "acceleration"), tracks[body].point(point)):
                got = np.broadcast_to(mine, batch.ok.shape)[d][ok]
                assert np.column_stack([got.real, got.imag]) == pytest.approx(values[q][ok], rel=1e-9,
                                                                              abs=1e-9)


def test_a_slider_driven_by_its_velocity_is_left_to_the_per_design_path():
    model = as_model(SLIDER_CRANK.replace("{joint: j1, rate: 10, accel: 2}",
                                          "{velocity: B@slider, along: [1, 0], value: 1, acceleration: 0}"))
    sweeper = BatchSweeper(model, ["r"], by=0.5)
    assert sweeper.joint.type == "prismatic" and not sweeper.batchable
