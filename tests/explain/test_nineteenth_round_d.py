"""Issue 30, nineteenth round (d): the figures of the explanations.

- A centre the text places where lines meet is drawn with those lines, from each point the
  text names on to the ring (C5-1.1: the strands' lines stopped at J and K, I_pulley below).
- Two points' labels closer than `labels.CLOSE` sit on opposite sides (C5-E.6's H and T1).
- A polygon label's leader costs for each arrow it crosses, counted exactly (001's a_FB^n).
- A level polygon's caption names the steps whose equations draw its black arrows.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import kinematika
from kinematika.draw.build import build_scene
from kinematika.draw.labels import CLOSE, LabelBoard, _arrows_crossed
from kinematika.draw.options import DrawOptions
from kinematika.explain import build, render
from kinematika.explain.document import Drawing, Figure as DocFigure, Section
from kinematika.explain.render import svg as svg_module
from .helpers import EXAMPLES, explained, rendered, scratch_axes


def _cross(u, v) -> float:
    return float(u[0]) * float(v[1]) - float(u[1]) * float(v[0])


def _blocks(sec):
    for b in sec.blocks:
        if isinstance(b, Section):
            yield from _blocks(b)
        else:
            yield b


def _all(doc):
    for s in doc.sections:
        yield from _blocks(s)


def test_the_strands_lines_are_drawn_on_to_the_pulleys_centre():
    """C5-1.1 at r = 0.1: G1 = (−2√3 r, 4r), J = (−√3 r/2, −r/2) (the left strand tangent at
    60°), K = (√3 r/2, −r/2), I_pulley = (0, −2r) — G1, J and I_pulley collinear: (J − G1) =
    3 (I − J) = (3√3 r/2, −9r/2). The centres' figure draws a line through J and through
    K, each reaching I_pulley (its anchors)."""
    sol, doc = explained("seed_c5_1_1_pulley_on_cable")
    fig = next(b for b in _all(doc) if isinstance(b, Drawing) and b.caption.key == "fig.centres")
    scene = build_scene(sol.inst, sol, DrawOptions(**fig.options))
    r = 0.1
    centre = np.array([0.0, -2 * r])
    for w in ((-math.sqrt(3) * r / 2, -r / 2), (math.sqrt(3) * r / 2, -r / 2)):
        w = np.array(w)
        on = [k for k in scene.kennedy + scene.normals
              if abs(float(_cross(k.direction, w - np.asarray(k.through, float)))) < 1e-9
              and abs(float(_cross(k.direction, centre - np.asarray(k.through, float)))) < 1e-9]
        assert on, w
        assert any(any(np.allclose(a, centre, atol=1e-9) for a in k.anchors) for k in on)
    assert "perpendiculars to the points' velocities" in rendered("seed_c5_1_1_pulley_on_cable", "en")




@pytest.mark.parametrize("gap", [6.0, 9.0, 12.0])
def test_two_close_points_labels_sit_on_opposite_sides(gap):
    """H at (200, 200), T1 `gap` pt above (display points = data here): each label's box
    centre lies on its own side, (centre − own point)·(other − own) ≤ 0 — never both above
    or both beside (C5-E.6 drew "H" and "T1" side by side above the two dots)."""
    assert gap < CLOSE
    ax = scratch_axes()
    board = LabelBoard()
    h, t = np.array([200.0, 200.0]), np.array([200.0, 200.0 + gap])
    board.add(h, "H", "k", 3, "point:H")
    board.add(t, "T1", "k", 3, "point:T1")
    board.avoid(h, radius=3.0)
    board.avoid(t, radius=3.0)
    spots = {s.label.gid: s for s in board.layout(ax)}
    for me, other, gid in ((h, t, "point:H"), (t, h, "point:T1")):
        box = spots[gid].box
        c = (box[:2] + box[2:]) / 2
        assert float((c - me) @ (other - me)) <= 1e-9, (gid, box)


def test_the_bicycles_h_and_t1_labels_are_apart():
    """C5-E.6's mechanism: H (the rear hub, (0, R_wheel)) and T1 (r = 0.04 above it) — their
    labels, in display units, lie each on its own side of the line between the dots."""
    from kinematika.draw import labels as labels_module

    sol, doc = explained("seed_c5_e6_bicycle")
    fig = next(b for b in _all(doc) if isinstance(b, Drawing) and b.caption.key == "fig.mechanism")
    orig, found = labels_module.Layout.run, []

    def run(self):
        out = orig(self)
        found.append((self, out))
        return out

    labels_module.Layout.run = run
    try:
        kinematika.draw.svg(sol, bare=True, lang="ca", **fig.options)
    finally:
        labels_module.Layout.run = orig
    lay, out = found[-1]
    spot = {p.label.gid: p for p in out}
    h, t = spot["point:H"], spot["point:T1"]
    ph, pt = (lay.ax.transData.transform(p.label.anchor) for p in (h, t))
    assert np.linalg.norm(pt - ph) / lay.px < CLOSE
    for me, other, p in ((ph, pt, h), (pt, ph, t)):
        c = (p.box[:2] + p.box[2:]) / 2
        assert float((c - me) @ (other - me)) <= 1e-9, (p.label.gid, p.box)


def test_a_leaders_crossings_are_counted_exactly():
    """Arrows (0, 0)→(100, 0) and (50, −50)→(50, 50): a leader from (20, 0) (on the first) to
    (80, 10) crosses the second once and does not count the first it starts on; one from
    (20, 0) to (48.5, 30) runs within 2.5 of the second without crossing: counted; one to
    (20, 40) crosses nothing. Samples 4 apart on both would miss a crossing between them."""
    segs = np.array([[[0.0, 0.0], [100.0, 0.0]], [[50.0, -50.0], [50.0, 50.0]]])
    starts = np.array([[20.0, 0.0]] * 3)
    ends = np.array([[80.0, 10.0], [48.5, 30.0], [20.0, 40.0]])
    assert list(_arrows_crossed(starts, ends, segs, 2.5)) == [1.0, 1.0, 0.0]


def _crosses(p, q, a, b) -> bool:
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


def _off(p, a, b) -> float:
    p, a, b = (np.asarray(v, float) for v in (p, a, b))
    d = b - a
    t = float(np.clip((p - a) @ d / max(float(d @ d), 1e-12), 0, 1))
    return float(np.linalg.norm(a + t * d - p))


@pytest.mark.parametrize("lang", ["ca", "en"])
def test_the_rolling_pairs_leaders_cross_no_arrow(lang):
    """001's rolling pair, every polygon (figure units): no label's leader crosses an arrow
    other than its own (the ca acceleration polygon led a_FB^n across a_FA^n at o), unless
    no place within reach is free for that label: none that reads as its own arrow's
    (twenty-seventh round (a): beside it, nearer it than any other arrow; set off, by no
    other arrow) with a leader from its arrow crossing none (`_free_place`). At o, a_AB^n
    and a_FB^n are short and meet three other arrows: a_AB^n's label lay 1.4 pt from a_FB^n
    and 15.6 from its own; it is now set below with its leader across a_FB^n."""
    orig, found = svg_module._place, []

    def place(lay, items):
        out = orig(lay, items)
        found.append((lay, items, out))
        return out

    svg_module._place = place
    try:
        render(build(kinematika.solve(EXAMPLES / "seed_001_rolling_pair.yaml")), lang, "md")
    finally:
        svg_module._place = orig
    assert found
    for lay, items, placed in found:
        arrows = [(lay.at(a.start), lay.at(a.end)) for a in lay.fig.arrows]
        item_of = {id(item[0]): item for item in items}
        for spot in placed:
            if spot.leader is None:
                continue
            start, end = spot.leader
            crossed = [ab for ab in arrows if _crosses(start, end, *ab) and _off(start, *ab) > 0.5]
            along = item_of[id(spot.text)][5]
            if crossed and along is not None:
                own = (lay.at(along[0]), lay.at(along[1]))
                boxes = [other.box for other in placed if other is not spot]
                heads = [svg_module.arrowhead(lay.at(a.start), lay.at(a.end), svg_module.LINE.get(a.style, 1.8))
                         for a in lay.fig.arrows]
                free = _free_place(own, arrows, boxes, spot.box, lay.height, heads)
                assert free is None, (spot.text.markup, crossed, "free at", free)
            else:
                assert not crossed, (spot.text.markup, crossed)


def _free_place(own, arrows, boxes, box, height, heads=(), reach=90.0, step=2.0):
    """A centre (figure units) for a label of `box`'s size near the middle of its arrow `own`
    where it reads as that arrow's and its leader crosses no other arrow, or None: inside the
    figure above the scale bar's row, over no other label (`boxes`) and no arrow, and either
    beside its arrow (within 16 pt) with no other arrow within 4 pt as near as its own, or
    set off with a straight leader from the arrow's middle that crosses no other arrow and
    no other arrow within 4 pt of the box. Each arrow is measured without 8 pt at its ends
    (at most a quarter), where a label is read beside the arrow it lies along. A place over
    an arrowhead (`heads`: each head's outline, tip first) is not free (twenty-ninth round
    (f): no label covers a head)."""
    w, h = box[2] - box[0], box[3] - box[1]
    mid = ((own[0][0] + own[1][0]) / 2, (own[0][1] + own[1][1]) / 2)
    others = [ab for ab in arrows if not (math.dist(ab[0], own[0]) < 0.5 and math.dist(ab[1], own[1]) < 0.5)]

    def part(p, q):
        p, q = np.asarray(p, float), np.asarray(q, float)
        n = float(np.linalg.norm(q - p))
        cut = min(8.0, n / 4) / max(n, 1e-12)
        return p + cut * (q - p), q - cut * (q - p)

    def to_box(p, q, b):
        p, q = np.asarray(p, float), np.asarray(q, float)
        pts = p + np.linspace(0, 1, 120)[:, None] * (q - p)
        dx = np.maximum(np.maximum(b[0] - pts[:, 0], pts[:, 0] - b[2]), 0)
        dy = np.maximum(np.maximum(b[1] - pts[:, 1], pts[:, 1] - b[3]), 0)
        return float(np.min(np.hypot(dx, dy)))
    for x in np.arange(mid[0] - reach, mid[0] + reach, step):
        for y in np.arange(mid[1] - reach, mid[1] + reach, step):
            b = (x - w / 2, y - h / 2, x + w / 2, y + h / 2)
            if b[0] < 0 or b[1] < 0 or b[2] > 460 or b[3] > height - 24:
                continue
            if any(min(b[2], o[2]) > max(b[0], o[0]) and min(b[3], o[3]) > max(b[1], o[1]) for o in boxes):
                continue
            if any(to_box(*ab, b) == 0.0 for ab in arrows):
                continue
            if any(min(to_box(t, c, b), to_box(t, d, b), to_box(c, d, b)) == 0.0 for t, c, d in (hd for hd in heads if hd)):
                continue
            mine = to_box(*part(*own), b)
            nearest = min((to_box(*part(*ab), b) for ab in others), default=math.inf)
            if mine < 16.0:
                if nearest >= mine + 4.0:
                    return x, y
            elif nearest >= 4.0 and not any(_passes(mid, _entry(mid, b), *ab) for ab in others):
                return x, y
    return None


def _entry(start, box):
    """Where the segment from `start` to the middle of `box` enters it."""
    c = ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
    dx, dy = c[0] - start[0], c[1] - start[1]
    hw, hh = (box[2] - box[0]) / 2, (box[3] - box[1]) / 2
    t = min(hw / abs(dx) if abs(dx) > 1e-9 else math.inf, hh / abs(dy) if abs(dy) > 1e-9 else math.inf, 1.0)
    return c[0] - t * dx, c[1] - t * dy


def _passes(p, q, a, b, pad=2.5) -> bool:
    """Whether a leader pq crosses the arrow ab or runs within `pad` of it (through its end),
    an arrow that meets the leader where it starts (within `pad` of p) excepted."""
    if _off(p, a, b) <= pad:
        return False
    if _crosses(p, q, a, b):
        return True
    return min(_off(q, a, b), _off(a, p, q), _off(b, p, q)) <= pad


# the steps whose equations draw a black arrow of the level's velocity polygon, read off the
# pages' equations by hand: 001's revolute pairs find v_A and v_B from the pins (Steps 1, 2:
# blue only) and Step 3's v_B = v_A + v_BA draws v_BA; C5-E.4, E.5 and E.6 find their wheels'
# rates first and relate two points in the last step (E.6's chain after the front wheel's
# step since round 27b); C5-1.4's planets all turn about their centres since round 27b: no
# black arrow, and the caption names no step (`test_the_epicyclic_polygon_names_no_step`)
# (C5-E.4's velocity polygon is left out since the twenty-ninth round (d): two arrows on one
# line, v_U and v_PU, and four images at u with the T's foot B: `polygon.degenerate`)
# Since round 29a a step whose one term is a point's own arrow, from an image at the pole
# (o1 = o, j∈wheel1 = o) to the point's image, is drawn too, and named: 001's Step 1
# v_A = v_AO1, the wheels' Step 2 v_C = v_CJ (the sixth reading: "Steps 2 and 3" left out
# Step 1's a_AO1^n, the arrow from o to a)
@pytest.mark.parametrize("name, first, last", [
    ("seed_001_r_pairs", 1, 3), ("seed_c5_e5_unequal_wheels", 2, 4),
    ("seed_c5_e6_bicycle", 2, 4), ("seed_001_p_pair_coriolis", 1, 2)])
def test_a_velocity_polygons_caption_names_the_steps_it_draws(name, first, last):
    _, doc = explained(name)
    fig = next(b for b in _all(doc) if isinstance(b, DocFigure) and b.caption.key == "fig.level_v")
    args = fig.caption.args
    assert (args["first"], args["last"]) == (first, last)
    said = {0: f"Step {first},", 1: f"Steps {first} and {last},"}.get(last - first, f"Steps {first} to {last},")
    assert f"of the equations of {said}" in rendered(name, "en")


def test_the_epicyclic_polygon_names_no_step():
    """C5-1.4: every planet and the sun turn about a point at rest (round 27b), so the velocity
    polygon has only absolute velocities from the pole: its caption names no step's terms."""
    page = rendered("seed_c5_1_4_epicyclic", "en")
    caption = next(line for line in page.splitlines() if line.startswith("*Velocity polygon"))
    assert "of the equations of Step" not in caption and "between the images" not in caption
