"""Issue 30, twenty-seventh round (a): crowded corners of the velocity and acceleration
polygons, where several terms meet at one image and labels sat by a neighbour's line.

Teachers read 001's revolute pairs (the corner at e), C5-1.3 (at q), C5-E.1 (at c) and 001's
rolling pair (at o), and "a_FB^t" and "v_{Q∈bar rel support}" beside another arrow's line,
read as that arrow's label. Three rules, each checked here on every polygon of the 19 seeds
in the four languages, from the figure as laid out (in drawn points):

- a term's label set beside its arrow (no leader) lies nearer its own arrow than any other,
  by a margin; one set off with a leader lies by no other arrow (`draw.labels.Layout._not_own`);
- two terms set side by side leave room between them for a label: the narrower of their two
  labels, turned across them, and its clearance on both sides (`explain.polygon._label_across`);
  a term beside a blue arrow leaves room for its own label;
- no image's dot has three labels or more around it (the crowded corner).
"""
from __future__ import annotations

import math

import numpy as np

from kinematika.explain.document import Figure
from .helpers import LANGS, SEEDS, explained, over, rendered

POLYGONS = ("fig.level", "fig.step", "fig.polygon")
END = 8.0           # points of an arrow's end (at most a quarter of it) no label is read beside
MARGIN = 3.5        # points: a label beside its arrow is this much nearer it than any other (the rule says 4)
CLEAR = 3.5         # points: a label with a leader is this far from any other arrow (the rule says 4)
BESIDE = 3.5        # points: a label's text from its own arrow, at its nearest (`PAD` + 2.5 pt)
AROUND = 20.0       # points around an image's dot
CROWD = 3           # labels around one dot that make a crowded corner


def _polygons(doc) -> list[Figure]:
    return [b for b in doc.blocks() if isinstance(b, Figure) and b.arrows and b.caption.key.startswith(POLYGONS)]


def _laid_out(name: str, lang: str) -> list[tuple[Figure, object, dict]]:
    """Every polygon of the page in `lang` as laid out: (figure, layout, {arrow index: its
    label as placed}). A layout is keyed by its labels' texts, the arrows' first, in the
    order of the figure's labelled arrows (`render.svg.layout`)."""
    _, doc = explained(name)
    rendered(name, lang, "html")
    out = []
    for fig in _polygons(doc):
        labelled = [i for i, a in enumerate(fig.arrows) if a.label is not None]
        for key, lay in fig.layouts.items():
            markups = [m for m, _ in key[:len(labelled)]]
            if len(set(markups)) < len(markups):
                continue                    # two arrows written alike: not told apart here
            by_markup = {lb.text.markup: lb for lb in lay.labels}
            out.append((fig, lay, {i: by_markup[m] for i, m in zip(labelled, markups) if m in by_markup}))
    return out


def _segment_to_box(p, q, box) -> float:
    """The distance (points) from segment pq to the box (x0, y0, x1, y1): 0 where they meet;
    else the least of the segment's ends to the box and the box's corners to the segment."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    lo, hi = np.array(box[:2], float), np.array(box[2:], float)
    n = max(2, int(np.linalg.norm(q - p) / 0.05) + 1)
    pts = p + np.linspace(0, 1, n)[:, None] * (q - p)
    if np.any(np.all((pts >= lo) & (pts <= hi), axis=1)):
        return 0.0
    ends = min(float(np.linalg.norm(np.maximum(np.maximum(lo - e, e - hi), 0))) for e in (p, q))
    d = q - p
    corners = [np.array(c) for c in ((lo[0], lo[1]), (hi[0], lo[1]), (lo[0], hi[1]), (hi[0], hi[1]))]
    t = [min(1.0, max(0.0, float((c - p) @ d) / max(float(d @ d), 1e-12))) for c in corners]
    return min(ends, *(float(np.linalg.norm(p + s * d - c)) for s, c in zip(t, corners)))


def _read_part(p, q) -> tuple:
    """The part of arrow pq a label is read beside: without `END` points at each end (at most
    a quarter of it)."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    length = float(np.linalg.norm(q - p))
    if length == 0:
        return p, q
    cut = min(END, length / 4) / length
    return p + cut * (q - p), q - cut * (q - p)


@over(name=SEEDS, lang=LANGS)
def test_a_terms_label_reads_as_its_own_arrows(name, lang):
    """A term's label without a leader lies at least `MARGIN` nearer its own arrow than any
    other arrow of the polygon (each without its ends: at a corner a label just past one
    arrow's end reads as the label of the line it lies along); one with a leader lies at
    least `CLEAR` from every other arrow. 001's a_FB^t lay 1.9 pt from a_F∈N/R and 12.5 from
    its own; C5-1.3's v_{Q∈bar rel support} by the blue o→e."""
    for fig, lay, placed in _laid_out(name, lang):
        parts = [_read_part(lay.at(a.start), lay.at(a.end)) for a in fig.arrows]
        for i, label in placed.items():
            own = _segment_to_box(*parts[i], label.box)
            other = min((_segment_to_box(*s, label.box) for j, s in enumerate(parts) if j != i), default=math.inf)
            if label.leader is None:
                assert other >= own + MARGIN, (fig.caption.key, label.text.raw or label.text.markup, own, other)
            else:
                assert other >= CLEAR, (fig.caption.key, label.text.markup, "leader", other)


def _side_by_side(a, b, sin: float = 0.02) -> float | None:
    """How far apart (drawn points) the drawn arrows a and b run where their extents overlap,
    when they are parallel within about 1°; None else."""
    p, u = np.asarray(a[0], float), np.asarray(a[1], float) - np.asarray(a[0], float)
    q0, q1 = np.asarray(b[0], float), np.asarray(b[1], float)
    v = q1 - q0
    la, lb = np.linalg.norm(u), np.linalg.norm(v)
    if la == 0 or lb == 0 or abs(u[0] * v[1] - u[1] * v[0]) > sin * la * lb:
        return None
    t0, t1 = sorted(((q0 - p) @ u / la, (q1 - p) @ u / la))
    if min(t1, la) - max(t0, 0.0) <= 0.05 * min(la, lb):
        return None
    return float(min(abs(u[0] * w[1] - u[1] * w[0]) / la for w in (q0 - p, q1 - p)))


def _across(label, arrow) -> float:
    """The extent (points) of a label's box across the direction of a drawn arrow."""
    (x0, y0, x1, y1), (p, q) = label.box, arrow
    dx, dy = q[0] - p[0], q[1] - p[1]
    n = math.hypot(dx, dy)
    return (x1 - x0) * abs(dy) / n + (y1 - y0) * abs(dx) / n


@over(name=SEEDS, lang=LANGS)
def test_terms_side_by_side_leave_room_for_a_label(name, lang):
    """Two terms (black) set side by side lie apart by at least the narrower of their labels
    turned across them, `BESIDE` from its own arrow and `BESIDE` + `MARGIN` from the other;
    a term beside an absolute motion (blue, which has no label of its own) by its own label's.
    001's rolling pair set a_FB^t and a_F∈N/R 10.6 pt apart, C5-E.1 its three vertical terms
    15.6 pt apart for labels 21 to 28 pt wide: no label fitted between them, and each sat
    outside, by the other's line."""
    for fig, lay, placed in _laid_out(name, lang):
        drawn = [(lay.at(a.start), lay.at(a.end)) for a in fig.arrows]
        for i, a in enumerate(fig.arrows):
            for j in range(i + 1, len(fig.arrows)):
                b = fig.arrows[j]
                if a.style == "result" and b.style == "result":
                    continue                # two absolute motions: neither moves (twenty-fifth round (c))
                if any(x.style != "result" and x.label is None for x in (a, b)):
                    continue                # a term too short to be seen, named in the caption and set
                                            # no label (twenty-eighth round (f)): no label goes between
                gap = _side_by_side(drawn[i], drawn[j])
                terms = [k for k in (i, j) if fig.arrows[k].style != "result" and k in placed]
                if gap is None or not terms:
                    continue
                need = min(_across(placed[k], drawn[k]) for k in terms) + 2 * BESIDE + MARGIN
                assert gap >= need - 0.5, (fig.caption.key, a.label, b.label, round(gap, 1), round(need, 1))


@over(name=SEEDS, lang=LANGS)
def test_no_image_is_a_crowded_corner(name, lang):
    """Fewer than `CROWD` labels (names and terms' symbols) lie within `AROUND` points of any
    image's dot or the pole: C5-E.1's corner at c had c, a_C^n, a_CO^t and a_CO^n's labels
    piled round it (four languages)."""
    for fig, lay, _ in _laid_out(name, lang):
        for label, p, _ in fig.points:
            dot = lay.at(p)
            near = [lb.text.markup for lb in lay.labels if _segment_to_box(dot, dot, lb.box) < AROUND]
            assert len(near) < CROWD, (fig.caption.key, label, near)


def _crosses(a, b) -> bool:
    """Whether segments a and b cross, each end of one clearly (beyond rounding) on either
    side of the other: a segment that only touches another (a join from an image lying on a
    blue arrow) does not cross it."""
    eps = 1e-9 * math.dist(*a) * math.dist(*b)

    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])

    def apart(p, q):
        return (p > eps and q < -eps) or (p < -eps and q > eps)
    return apart(side(*a, b[0]), side(*a, b[1])) and apart(side(*b, a[0]), side(*b, a[1]))


def test_the_revolute_pairs_a_eo2_n_is_moved_outside():
    """001's revolute pairs, the acceleration polygon: a_EO2^n runs out of the pole 4.6° off
    the blue o→e and is moved aside (twenty-fifth round (c)); it was moved towards b, across
    the blue o→b and into the narrow angle between the two, its label then beside o→a. Moved
    to the other side of o→e, away from b, neither it nor its joins cross an arrow."""
    _, doc = explained("seed_001_r_pairs")
    fig = next(f for f in _polygons(doc) if f.caption.key.startswith("fig.level_a"))
    images = {label: p for label, p, _ in fig.points}
    term = next(a for a in fig.arrows if a.label is not None and (a.label.sub, a.label.sup) == ("EO2", "n"))
    e, b = images["e"], images["b"]

    def side(p) -> float:               # which side of the line o→e the point p lies on
        return e[0] * p[1] - e[1] * p[0]
    middle = ((term.start[0] + term.end[0]) / 2, (term.start[1] + term.end[1]) / 2)
    assert side(middle) * side(b) < 0, (middle, b)
    joins = [ln for ln in fig.lines if term.start in ln or term.end in ln]
    assert len(joins) == 2
    for drawn in [(term.start, term.end)] + joins:
        crossed = [o.label for o in fig.arrows if o is not term and _crosses(drawn, (o.start, o.end))]
        assert not crossed, (drawn, crossed)
