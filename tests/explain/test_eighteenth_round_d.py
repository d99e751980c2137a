"""Issue 30, eighteenth round (d): the figures of the explanations.

- A fixed guide through a wheel (001's slider carrying the roller on its axle) is a slot: two
  thin parallel lines either side of the block, closed by walls hatched outwards beyond the
  wheel; no hatched band along it (it read as a floor the roller was sunk into).
"""
from __future__ import annotations

import numpy as np

import kinematika
from kinematika.draw.build import build_scene
from kinematika.draw.geometry import Box
from kinematika.draw.joints import scene_symbols
from kinematika.draw.options import DrawOptions
from tests.explain.helpers import EXAMPLES


def _marks(name: str) -> tuple:
    sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    view = Box(*scene.box).grow(0.6 * scene.size)
    return scene, scene_symbols(scene, view)


def test_the_rollers_guide_is_a_slot_not_a_floor():
    """001's rolling pair: A = (ρ/sin β, 0) = (0.2, 0), ρ = 0.1, B = (0, 0). The block (height
    h = 0.06·size) runs between two thin lines y = ±h/2 crossing the roller (x from below
    0.1 to beyond 0.3) and stopping short of B's pivot (x > 0); each end wall lies outside the
    roller (|x − 0.2| > ρ) and is hatched outwards, away from the roller; no hatching lies
    along the slot (nothing hatched between the walls)."""
    scene, marks = _marks("seed_001_rolling_pair")
    h = 0.06 * scene.size
    assert not [m for m in marks if m.gid.startswith("ground:guide")]
    rails = [np.asarray(m.points, float) for m in marks if m.gid == "ground:slot"]
    assert len(rails) == 2
    ys = sorted(float(r[:, 1].mean()) for r in rails)
    assert np.allclose(ys, [-h / 2, h / 2], atol=1e-9), ys
    for r in rails:
        assert np.allclose(r[:, 1], r[0, 1]) and r[:, 0].min() < 0.1 and r[:, 0].max() > 0.3
        assert r[:, 0].min() > 0.0                                  # not over B's pivot
    x0 = min(float(r[:, 0].min()) for r in rails)
    x1 = max(float(r[:, 0].max()) for r in rails)
    walls = [np.asarray(m.points, float) for m in marks if m.gid == "ground:slot-end"]
    assert len(walls) == 2
    for w in walls:
        assert np.allclose(w[:, 0], w[0, 0]) and abs(w[0, 0] - 0.2) > 0.1
    hatches = [np.asarray(m.points, float) for m in marks if m.hatch and m.moves_with is None
               and m.gid.startswith("ground:slot")]
    assert len(hatches) == 2
    for hp in hatches:
        xs = hp[:, 0]
        assert xs.max() <= x0 + 1e-9 or xs.min() >= x1 - 1e-9, xs    # beyond the walls, outwards
    between = [m for m in marks if m.hatch and m.kind == "polygon" and abs(float(np.mean(m.points[:, 1]))) < h
               and x0 + 1e-9 < float(np.mean(m.points[:, 0])) < x1 - 1e-9]
    assert not between
