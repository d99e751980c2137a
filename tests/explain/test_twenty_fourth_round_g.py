"""Issue 30, twenty-fourth round (g): the velocity and acceleration polygons.

- Arrows that run along one another (collinear terms, or a term a hair's breadth beside
  another: C5-E.4's blue a_P over a_PU^n, 0.5 apart on a polygon 16 long) are drawn side by
  side, a label's height apart.
- A polygon's labels (the terms' symbols and the images' names) sit on no arrow, their own
  included (C5-E.1's "v_PC" and "p" on the collinear arrows), and a label that lies nearer
  another arrow (another image) than its own is drawn with its leader (C5-E.1's a_PC^n and
  a_C^n stacked beside three parallel arrows at c).
- An image's label names every point of the page whose motion lands there (C5-2.2's "c1, o′"
  left out c2, though v_C2 = v_C1).
"""
from __future__ import annotations

import math

import numpy as np

from kinematika.explain.context import Ctx
from kinematika.explain.document import Figure
from .helpers import NOTES_SEEDS, explained, over, recorded_pages

APART = 0.05        # of a polygon's size (its largest coordinate): two arrows side by side at least this far apart
SIN_PARALLEL = 0.02


def _level_figures(doc) -> list[Figure]:
    return [b for b in doc.blocks() if isinstance(b, Figure) and b.arrows and b.caption.key.startswith("fig.level")]


def _side_by_side(a, b) -> float | None:
    """How far apart two parallel arrows run where their extents overlap (None: not parallel,
    or no overlap)."""
    p, u = np.asarray(a.start, float), np.asarray(a.end, float) - np.asarray(a.start, float)
    q0, q1 = np.asarray(b.start, float), np.asarray(b.end, float)
    v = q1 - q0
    la, lb = np.linalg.norm(u), np.linalg.norm(v)
    if la == 0 or lb == 0 or abs(u[0] * v[1] - u[1] * v[0]) > SIN_PARALLEL * la * lb:
        return None
    t0, t1 = sorted(((q0 - p) @ u / la, (q1 - p) @ u / la))
    if min(t1, la) - max(t0, 0.0) <= 0.05 * min(la, lb):
        return None
    return max(abs(u[0] * w[1] - u[1] * w[0]) / la for w in (q0 - p, q1 - p))


def _from_the_pole(a, size: float) -> bool:
    """Whether `a` is an absolute motion (blue) drawn from the pole o: it is never moved
    aside, since it ends at its image (twenty-fifth round (c))."""
    return a.style == "result" and math.hypot(*a.start) <= 1e-9 * size


@over(name=NOTES_SEEDS)
def test_no_polygon_arrow_runs_over_another(name):
    """Two arrows of a level polygon that run along one another lie at least `APART` of the
    polygon's size apart (a label's height at the page's width): C5-E.4's a_P and a_PU^n
    were 0.5 apart on a polygon 16 long, read as one arrow over the other. Two absolute
    motions from the pole along one ray share it: each runs from o to its own image (a
    rolling wheel's v_C and v_P), as the notes draw them (twenty-fifth round (c))."""
    _, doc = explained(name)
    for fig in _level_figures(doc):
        size = max(abs(c) for a in fig.arrows for p in (a.start, a.end) for c in p)
        for i, a in enumerate(fig.arrows):
            for b in fig.arrows[i + 1:]:
                if _from_the_pole(a, size) and _from_the_pole(b, size):
                    continue        # two absolute motions on one ray from o: each ends at its image (round 25 (c))
                d = _side_by_side(a, b)
                assert d is None or d >= APART * size, (fig.caption.key, a.label, b.label, d / size)


def _through(box, p, q) -> bool:
    """Whether segment pq runs through `box` (x0, y0, x1, y1), sampled every 0.05 units."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    n = max(2, int(np.linalg.norm(q - p) / 0.05) + 1)
    pts = p + np.linspace(0, 1, n)[:, None] * (q - p)
    return bool(np.any((pts[:, 0] > box[0]) & (pts[:, 0] < box[2]) & (pts[:, 1] > box[1]) & (pts[:, 1] < box[3])))


def _to_box(box, p, q) -> float:
    pts = np.asarray(p, float) + np.linspace(0, 1, 200)[:, None] * (np.asarray(q, float) - np.asarray(p, float))
    dx = np.maximum(np.maximum(box[0] - pts[:, 0], pts[:, 0] - box[2]), 0)
    dy = np.maximum(np.maximum(box[1] - pts[:, 1], pts[:, 1] - box[3]), 0)
    return float(np.min(np.hypot(dx, dy)))


@over(name=NOTES_SEEDS)
def test_a_polygon_label_is_on_no_arrow_and_reads_as_its_own(name):
    """In every polygon of the seeds' pages (en, ca): no arrow runs through a label's text,
    its own arrow included; a term's label that lies nearer another arrow than its own, or an
    image's name nearer another image than its own, has a leader to what it names."""
    pages = recorded_pages("polygons")
    for lang in ("en", "ca"):
        for lay, items, placed in pages[(name, lang)]:
            arrows = [(lay.at(a.start), lay.at(a.end)) for a in lay.fig.arrows]
            dots = [lay.at(p) for _, p, _ in lay.fig.points]
            item_of = {id(item[0]): item for item in items}
            for spot in placed:
                _, _, anchor, _, _, along = item_of[id(spot.text)]
                under = [ab for ab in arrows if _through(spot.box, *ab)]
                assert not under, (lang, spot.text.markup, under)
                if along is not None:
                    own = (lay.at(along[0]), lay.at(along[1]))
                    others = [ab for ab in arrows if not (math.dist(ab[0], own[0]) < 0.5 and math.dist(ab[1], own[1]) < 0.5)]
                else:
                    own = (lay.at(anchor),) * 2
                    others = [(d, d) for d in dots if math.dist(d, own[0]) >= 0.5]
                mine = _to_box(spot.box, *own)
                nearer = [ab for ab in others if _to_box(spot.box, *ab) < mine - 1.0]
                if nearer and spot.leader is None:
                    # left where a leader would cross another arrow (nineteenth round (d) forbids it)
                    centre = ((spot.box[0] + spot.box[2]) / 2, (spot.box[1] + spot.box[3]) / 2)
                    starts = [own[0]] if along is None else [_closest(own, spot.box)] + [
                        tuple(np.asarray(own[0]) + t * (np.asarray(own[1]) - np.asarray(own[0])))
                        for t in (0.5, 0.35, 0.65, 0.22, 0.78)]
                    segs = [ab for ab in others if ab[0] != ab[1]]
                    assert any(_crossing(start, centre, segs) for start in starts), (lang, spot.text.markup, "nearer", nearer)


def _closest(seg, box):
    pts = np.asarray(seg[0], float) + np.linspace(0, 1, 200)[:, None] * (np.asarray(seg[1], float) - np.asarray(seg[0], float))
    c = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
    return tuple(pts[np.argmin(np.linalg.norm(pts - c, axis=1))])


def _crossing(p, q, segs) -> bool:
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return any(side(p, q, a) * side(p, q, b) < 0 and side(a, b, p) * side(a, b, q) < 0 for a, b in segs)


@over(name=NOTES_SEEDS)
def test_an_image_names_every_point_of_the_page_there(name):
    """Every point of the model that is one point of all its bodies and whose velocity
    (acceleration) ends at a lettered image of the level polygon is named in that image's
    label (C5-2.2: "c1, c2, o′, p1", the chassis S1 translating)."""
    sol, doc = explained(name)
    ctx = Ctx(sol)
    for fig in _level_figures(doc):
        level = "v" if fig.caption.key.startswith("fig.level_v") else "a"
        images = [(set(label.split(", ")), xy) for label, xy, kind in fig.points if kind == "image"]
        size = max(math.hypot(*xy) for _, xy in images) if images else 1.0
        for point in sol.model.points:
            bodies = sol.model.carriers(point)
            if not bodies or not ctx.shared(point):
                continue
            motion = sol.velocity(point) if level == "v" else sol.acceleration(point)
            xy = tuple(float(c) for c in ctx.drawn(tuple(motion))[:2])
            for names, at in images:
                if math.dist(xy, at) <= 1e-7 * size:
                    letter = point.lower()
                    assert any(n.split("∈")[0].rstrip("′") == letter for n in names), (fig.caption.key, point, names)
