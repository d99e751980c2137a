"""Issue 30, eighteenth round (d): the figures of the explanations.

- A fixed guide through a wheel (001's slider carrying the roller on its axle) is a slot: two
  thin parallel lines either side of the block, closed by walls hatched outwards beyond the
  wheel; no hatched band along it (it read as a floor the roller was sunk into).
- A long arrow's label may sit beside any of a few points of its arrow (`labels.SLIDE`), and a
  leader costs for every arrow it runs across: 001's acceleration polygon had a_AB^t's label
  led across two arrows to beside f∈N.
"""
from __future__ import annotations


import numpy as np
import pytest

import kinematika
from kinematika.draw.labels import LabelBoard
from kinematika.draw.build import build_scene
from kinematika.draw.geometry import Box
from kinematika.draw.joints import scene_symbols
from kinematika.draw.options import DrawOptions
from .helpers import EXAMPLES, NOTES_SEEDS, over, recorded_pages, scratch_axes



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




def test_a_long_arrows_label_slides_along_it_when_its_middle_is_taken():
    """A vertical arrow (200, 50) → (200, 350), its middle (200, 200) inside a block of drawn
    lines y = 150…250 (x 120…280, 5 pt apart): its label sits beside a point of the arrow
    outside the block (|y − 200| > 50), next to the arrow (within 12 pt of x = 200), with no
    leader. Without `along` it could only sit beside the middle: on the block or far off."""
    ax = scratch_axes()
    board = LabelBoard()
    board.add((200, 200), "$a_{AB}$", "k", 2, "arrow", prefer=(1, 0))
    board.labels[0].along = np.array([[200.0, 50.0], [200.0, 350.0]])
    board.avoid((200, 50), (200, 350), weight=3.0)
    for y in range(150, 251, 5):
        board.avoid((120, y), (280, y), weight=3.0)
    (spot,) = board.layout(ax)
    x0, y0, x1, y1 = spot.box
    assert not spot.leader
    assert abs(float(spot.anchor[1]) - 200) > 50, spot.anchor
    assert min(abs(x0 - 200), abs(x1 - 200)) < 12 + 1.5 and (y1 < 150 or y0 > 250), spot.box


def _off(p, a, b) -> float:
    """The distance from p to the segment ab (its own arrow, where a leader starts, is 0)."""
    p, a, b = (np.asarray(v, float) for v in (p, a, b))
    d = b - a
    t = float(np.clip((p - a) @ d / max(float(d @ d), 1e-12), 0, 1))
    return float(np.linalg.norm(a + t * d - p))


def _crossings(p, q, a, b) -> bool:
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


@pytest.fixture(scope="module")
def polygons():
    """Every polygon's layout of the seeds' pages (en, ca): (figure layout, placed labels),
    recorded as the pages were drawn."""
    return recorded_pages("polygons")


@over(name=NOTES_SEEDS)
def test_no_leader_runs_across_two_arrows(polygons, name):
    """In every velocity and acceleration polygon, a label's leader (from its arrow to its box,
    display units) crosses at most two other arrows: 001's acceleration polygon had a_AB^t
    led across four (to beside f∈N), C5-E.1's a_PC^t and a_PC^n across three (before this
    round; over the 19 seeds × en, ca: 68 crossings by 42 leaders then, 17 by 15 now)."""
    for lang in ("en", "ca"):
        for lay, _, placed in polygons[(name, lang)]:
            arrows = [(lay.at(a.start), lay.at(a.end)) for a in lay.fig.arrows]
            for spot in placed:
                if spot.leader is None:
                    continue
                start, end = spot.leader
                crossed = [ab for ab in arrows if _crossings(start, end, *ab) and _off(start, *ab) > 0.5]
                assert len(crossed) <= 2, (lang, spot.text.markup, crossed)
