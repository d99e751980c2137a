"""The integrated poses are brought back onto the joints' position conditions: a pin's two
points together, a slider on its line, a disc touching its plane (whose gap's rate is the
engine's rolling rows along the normal), while a knife edge, which has no such condition,
leaves the poses as they are."""
from __future__ import annotations

import numpy as np
import pytest

from kinematika.simulate.run import Simulator

from .test_closed_forms import EXAMPLES, coin_tree


def projected(sim: Simulator, y: np.ndarray):
    poses = sim.state.poses(y)

    def matrix(q):
        return sim.engine_at(0.0, q).a_num

    return sim.projection.project(poses, matrix, sim.solver.unknowns)


@pytest.mark.parametrize("source", [coin_tree(), EXAMPLES / "slider_crank.yaml"], ids=["coin", "slider-crank"])
def test_poses_off_the_conditions_are_brought_back(source):
    sim = Simulator(source)
    y0 = sim.state.drawn()
    rng = np.random.default_rng(7)
    scale = sim.inst.scale
    # 1e-4 off in every rotation (radians, quaternion components) and 1e-4 of the size in every translation
    y = y0 + 1e-4 * rng.standard_normal(len(y0)) * sim.state.tolerances(scale, 1.0)
    before = sim.projection.residual(sim.state.poses(y))
    assert np.abs(before).max() > 1e-7 * scale             # the perturbation left the conditions
    q, drift = projected(sim, y)
    assert drift == pytest.approx(np.abs(before).max() / scale)
    assert np.abs(sim.projection.residual(q)).max() <= 1e-12 * scale
    # the least change: the correction is of the size of what was off, not more
    back = sim.state.vector(q, y)
    assert np.abs(back - y).max() < 1e-2 * max(scale, 1.0)


def test_a_knife_edge_has_no_position_condition():
    sim = Simulator(EXAMPLES / "tractor_trailer_turning.yaml")
    counts = {j.id: len(part.values(sim.state.poses(sim.state.drawn()), 0.0))
              for j, (part, _) in zip(sim.model.joints, sim.projection.parts)}
    assert counts == {"steer_pin": 2, "front_wheel": 0, "rear_wheels": 0, "hitch": 2, "trailer_wheels": 0}
