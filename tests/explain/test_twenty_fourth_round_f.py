"""Issue 30, twenty-fourth round (f): a label keeps off the drawing of other bodies; a hyphen in
a name is a hyphen.

Four readers saw names and values lying ACROSS bodies' lines, clear of other bodies' areas:
C5-1.2's v_J∈OJ across the left wheel's rim, C5-E.2's names on the hatched fixed wheel, C5-1.4's
names across a planet's rim, C5-E.5's wheel name across its own rim, C5-1.1's ezkerreko kable-zatia across a dash-dot construction line
(`draw.labels.Layout._lines_under`). A Basque reader read I_{eskuineko kable-zatia} as
"kable − zatia": mathtext sets "-" as a minus (`draw.names._roman`).

The mechanism drawings of the notes' seeds in the four languages, every label layout
recorded with the lines drawn under it as the pages are written (`helpers._recording`: from the
label board, outlines, bars, rims and hatching with their bodies; and every construction line
as painted, whether or not the placer was told of it). A line's crossing of a label's text box
is measured here by sampling the line every half pixel, not by the placer's arithmetic.
"""
from __future__ import annotations

import re

import numpy as np

from .helpers import LANGS, NOTES_SEEDS, over, recorded_pages

# where no label place clear of every other body's line exists near the label (docs/explain.md):
# (seed, label text or gid) -> the bodies whose lines it may cross
# (none left: C5-E.2's "gurpil zentral finkoa" and C5-E.1's "arm OC" found clear places in the
# twenty-seventh round (c), the one named without its bracket, the other led from along its bar)
# (twenty-eighth round (g): C5-1.4's two centres at O, the carrier's and the ring's, named on one
# line of 95 to 120 points in Spanish, Catalan and Basque, inside the sun's disc of 51 points'
# radius cut by the carrier's three arms and the sun's radii, and anywhere outside it nearer
# another point than O (twenty-seventh round (g)); C5-E.6's sprocket, on its own rear wheel's
# radii: the wheel's quadrants are narrower than its name, and outside the wheel the chain's
# and chainring's names take the room above the drive)
# (since the twenty-eighth round (c) the sun's centre is at O too: the three centres' label, on
# two lines, keyed by its gid, may cross the carrier's arms and the sun's radii, for the same reason;
# since the twenty-ninth round (g) the three are written into O's label, "… = O", a point's)
KNOWN: dict[tuple[str, str], set] = {
    **{("seed_c5_e6_bicycle", word): {"rear"} for word in ("sprocket", "piñón", "pinyó", "pinoia")},
    # twenty-ninth round (g): the drive drawn 1.4 times as large, the chainring's longer names
    # (ca, eu) cross the rear wheel's lines in layouts tried while the figure's limits grow
    **{("seed_c5_e6_bicycle", word): {"rear"} for word in ("plat amb els pedals", "plater pedalduna")},
}


def layouts(name: str, lang: str) -> list:
    """Each label layout of the seed's mechanism drawings in `lang`: (placements, lines), the
    lines as (display points (n, 2), body or "" or "construction"), recorded as its page was
    drawn (the page's own drawings, drawn once a run)."""
    return [(placed, lay.recorded_lines) for placed, lay in recorded_pages("drawings", LANGS)[(name, lang)]]


def crossed(points: np.ndarray, box: np.ndarray) -> bool:
    """Whether the polyline through `points` (display) runs through `box` (x0, y0, x1, y1):
    some point of it, sampled every half pixel, strictly inside (a polyline whose bounding
    box misses the box is not sampled)."""
    points = np.asarray(points, dtype=float)
    lo, hi = points.min(axis=0), points.max(axis=0)
    if lo[0] >= box[2] or hi[0] <= box[0] or lo[1] >= box[3] or hi[1] <= box[1]:
        return False
    p, q = points[:-1], points[1:]
    n = np.maximum(2, (np.linalg.norm(q - p, axis=1) / 0.5).astype(int) + 1)     # samples a segment
    seg = np.repeat(np.arange(len(p)), n)
    t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n - 1, n)
    s = p[seg] + t[:, None] * (q - p)[seg]
    return bool(np.any((s[:, 0] > box[0]) & (s[:, 0] < box[2]) & (s[:, 1] > box[1]) & (s[:, 1] < box[3])))


@over(name=NOTES_SEEDS, lang=LANGS)
def test_no_label_lies_across_another_bodys_line(name, lang):
    """No label but a point's has an outline, bar, rim or hatching line of a body (its own
    too: a name across its own rim), or a construction line, through its text."""
    bad = []
    for placed, lines in layouts(name, lang):
        for p in placed:
            if p.label.gid.startswith(("point:", "contact:")):
                continue
            hit = {body or "?" for pts, body in lines if crossed(pts, p.box)}
            hit -= KNOWN.get((name, p.label.text), set()) | KNOWN.get((name, p.label.gid), set())
            if hit:
                bad.append(f"{p.label.text!r} across {sorted(hit)}")
    assert not bad, "; ".join(bad)


@over(name=NOTES_SEEDS, lang=LANGS)
def test_a_hyphen_in_a_label_is_a_hyphen(name, lang):
    """No label's math sets a hyphen inside \\mathrm{…}, where mathtext draws a minus sign."""
    bad = [p.label.text for placed, _ in layouts(name, lang) for p in placed
           if re.search(r"\\mathrm\{[^{}]*-", p.label.text)]
    assert not bad, bad


def test_the_checks_see_a_crossing_and_a_hyphen():
    """The checks themselves: a line through a box crosses it, one beside it does not; a
    subscript with a hyphen is set with the hyphen as text."""
    from kinematika.draw.names import bare, subscript

    box = np.array([10.0, 10, 50, 20])
    assert crossed(np.array([[0.0, 15], [100, 15]]), box)
    assert crossed(np.array([[30.0, 0], [30.2, 40]]), box)
    assert not crossed(np.array([[0.0, 25], [100, 25]]), box)
    label = subscript("I", "eskuineko kable-zatia")
    assert not re.search(r"\\mathrm\{[^{}]*-", label)
    assert bare(label) == "I(eskuineko kable-zatia)"
