"""Issue 30, twenty-eighth round (g): the mechanism figures as the fifth reading saw them
(docs/explain.md, "Twenty-eighth round (g)").

Three readers read a velocity drawn ENDING at its point as applied elsewhere (C5-1.2's
v_J∈OJ, C5-E.3's v_B: round 27 (f) turned an arrow that ran into the ground round); a velocity
starts at its point, across the ground's line if it must, its value off the ground. C5-E.6's
drive was unreadable (the sprocket hidden under the hub H; the chainring's name under the
ground, the sprocket's across the chain and the rear wheel's lines): it is drawn larger than
a bicycle's, as a teacher draws it, and a name under the ground's line costs more than a
leader across a bar.
"""
from __future__ import annotations

import numpy as np

from .helpers import NOTES_SEEDS, RECORDED_LANGS, over
from .helpers import figures
from .test_twenty_seventh_round_f import arrows_of, ground_edges


def _point_of(gid: str) -> str:
    """The point a vector's arrow is drawn at: `velocity:P@body/ref` -> P."""
    return gid.partition(":")[2].split("@", 1)[0]


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_a_velocity_starts_at_its_point(name, lang):
    """Every velocity's arrow starts at the dot of its point (where the figure sets the
    point's letter), never ends there: C5-1.2's v_J∈OJ and C5-E.3's v_B ended at J and B."""
    bad = []
    for _, marks, placed, _ in figures(name, lang):
        dots = {p.label.gid.partition(":")[2]: np.asarray(p.label.anchor, float) for p in placed
                if p.label.gid.startswith(("point:", "contact:"))}
        for s, e, m in arrows_of(marks):
            at = dots.get(_point_of(m.gid))
            if m.layer != "velocity" or at is None:
                continue
            size = float(np.linalg.norm(e - s))
            if np.linalg.norm(s - at) > 1e-6 * max(size, 1.0):
                bad.append(f"{m.gid}: from {np.round(s, 3).tolist()}, its point at {np.round(at, 3).tolist()}")
    assert not bad, bad


@over(name=["seed_c5_1_2_bar_on_inclined_wheels", "seed_c5_e3_wheels_with_rod"], lang=RECORDED_LANGS)
def test_a_velocity_across_the_ground_keeps_its_value_above_it(name, lang):
    """Where a velocity starts at its point and runs across the ground's line (C5-E.3's v_B),
    its value is not set beyond that line, in the ground (the box's centre on the hatched side
    of an edge, over the edge's length)."""
    bad = []
    for _, marks, placed, transform in figures(name, lang):
        edges = ground_edges(marks)
        for p in placed:
            if not p.label.gid.startswith("velocity:"):
                continue
            c = transform.inverted().transform((p.box[:2] + p.box[2:]) / 2)
            for a, b, side, _ in edges:
                u = (b - a) / np.linalg.norm(b - a)
                if 0 <= (c - a) @ u <= np.linalg.norm(b - a) and (c - a) @ side > 0:
                    bad.append(p.label.text)
    assert not bad, bad


def test_a_name_under_the_ground_costs_more_than_on_another_body():
    """The placer's weights: a body's name wholly beyond the ground's line (`LabelBoard.area`'s
    `ground`) costs more than wholly on another body's disc, and more than a leader across
    two bars (`BAR_CROSS`): no reader looks under the ground for a moving body's name."""
    from kinematika.draw.labels import BAR_CROSS, LabelBoard, Layout

    from .helpers import scratch_axes
    ax = scratch_axes()
    board = LabelBoard()
    board.area("ground", [[0.0, 0.0], [400.0, 0.0], [400.0, 100.0], [0.0, 100.0]], ground=True)
    board.area("wheel", [[0.0, 200.0], [400.0, 200.0], [400.0, 300.0], [0.0, 300.0]])
    board.add([200.0, 150.0], "name", "k", 5, "body:crank")
    lay = Layout(board, ax)
    boxes = lay.ax.transData.transform(np.array([[150.0, 40.0], [250.0, 60.0], [150.0, 240.0], [250.0, 260.0]]))
    boxes = np.array([[*boxes[0], *boxes[1]], [*boxes[2], *boxes[3]]])
    under, on = lay._areas(lay.labels[0], boxes)
    assert under > on > 0
    assert under > 2 * BAR_CROSS

