"""Issue 30, twenty-fourth round (b): C5-E.6's v_P and its acceleration polygon's bar.

A reader saw the Catalan C5-E.6 figure's v_P on the front wheel's rim, at the end of a long
leader from its tip inside the wheel: the areas of the twenty-first round (d) kept the value
off the wheel's disc, and nothing kept it off the rim just outside. A mechanism vector's
value now keeps off other bodies' outlines as off their areas (`draw.labels.RIM`), and may
sit beside its own shaft, back from its tip (`Label.shaft`, `SHAFT`). The page's acceleration
bar read "L·r²·v²/(5·R²·R_wheel²)"; a product of more than `FEW_FACTORS` symbols gave way
to the polygon's reference vector, "|a_P|/5" (`explain.polygon.bar_unit`), until the
twenty-eighth round (b): the bar reads in m/s² at the values drawn, as a numeric page's.

The checks measure the placed boxes against the recorded outlines and areas on their own
lattice and segment sampling, not through the placer's costs.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from kinematika.draw.labels import label_owner

from .helpers import LANGS, NOTES_SEEDS, over, recorded_pages, rendered

BAR = re.compile(r'<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>')


def _bars(page: str) -> list[str]:
    """A page's scale bars' text, its markup left out (a symbol is set in tspans since the
    twenty-fifth round (b): |a_P| reads |aP| here)."""
    return [re.sub(r"<[^>]+>", "", b) for b in BAR.findall(page)]
NEAR = 48.0          # points: a leader no longer than the figures' usual ones (their bodies' names: 53–57)


@pytest.fixture(scope="module")
def layouts():
    """Every mechanism and polygon label layout of the notes' seeds in English and Catalan,
    with its `Layout` (its outlines, their owners and its areas, display units)."""
    return recorded_pages("layouts")


def _values(placed: list) -> list:
    """The placements of mechanism vectors' values (a velocity's or an acceleration's, owned
    by a body), not a polygon's arrow labels."""
    return [p for p in placed if p.label.gid.startswith(("velocity:", "acceleration:"))
            and label_owner(p.label.gid) is not None and p.label.along is None]


def _crosses(box: np.ndarray, segs: np.ndarray) -> bool:
    """Whether any segment (M, 2, 2) has a point strictly inside `box`, sampled at 64 points
    along each (a rim's segments are a few points long)."""
    if not len(segs):
        return False
    t = np.linspace(0, 1, 64)[None, :, None]
    pts = segs[:, :1] + t * (segs[:, 1:] - segs[:, :1])
    x, y = pts[..., 0], pts[..., 1]
    return bool(np.any((x > box[0]) & (x < box[2]) & (y > box[1]) & (y < box[3])))


@over(name=NOTES_SEEDS)
def test_a_vector_value_keeps_off_other_bodies_outlines(layouts, name):
    """No vector's value has another body's outline (a rim, a bar's side, a plate's edge)
    running through its text's box: C5-1.2's v_J∈OJ sat on the left wheel's rim."""
    bad = []
    for lang in ("en", "ca"):
        for placed, lay in layouts[(name, lang)]:
            for p in _values(placed):
                owner = label_owner(p.label.gid)
                other = (lay.outline_owners != owner) & (lay.outline_owners != "") if len(lay.outline_owners) else []
                if len(other) and _crosses(p.box, lay.outlines[other]):
                    bad.append(f"{lang} {p.label.text!r}")
    assert not bad, "; ".join(bad)


# C5-E.6's v_P since the twenty-eighth round (g) drew the drive larger and kept the chainring's
# name out of the ground: that name takes the room below v_P's shaft, the frame's the room above
# it, and the shaft's last quarter is on the front wheel; no place beside the shaft is left, and
# the value went out on a leader across the front wheel (a known fault: see the xfail below).
# Twenty-ninth round (g): the drive drawn 1.4 times as large (draw_at) and v_P labelled with
# its value (the answer's formula, `names.ANSWER_CHARS`); the value's box (91 × 26 pt) is as long
# as v_P's arrow and taller than the room between it and the frame's bar, between the chainring
# and the front wheel: still no place beside the shaft at the page's 432 pt (keyed by the
# vector, its text now carries the value)
CROWDED = {("seed_c5_e6_bicycle", "velocity:P")}


@over(name=NOTES_SEEDS)
def test_a_value_whose_tip_is_on_another_body_sits_near_its_arrow(layouts, name):
    """A vector whose tip lies on another body's disc or plate has its value off that body
    and within `NEAR` points of its arrow, measured from its box's centre to the nearest
    point of the arrow: C5-E.6's v_P (tip inside the front wheel) sat 92 points away, on the
    rim; C5-1.3's v_E (tip on the support) 69."""
    bad = []
    for lang in ("en", "ca"):
        for placed, lay in layouts[(name, lang)]:
            for p in _values(placed):
                if p.label.shaft is None:
                    continue
                owner = label_owner(p.label.gid)
                tip = lay.ax.transData.transform(p.label.anchor)
                on = [path for body, path in lay.areas if body != owner and path.contains_point(tip)]
                if not on:
                    continue
                a, b = lay.ax.transData.transform(np.asarray(p.label.shaft, dtype=float))
                c = (p.box[:2] + p.box[2:]) / 2
                t = np.clip((c - a) @ (b - a) / max(float((b - a) @ (b - a)), 1e-12), 0, 1)
                gap = float(np.linalg.norm(a + t * (b - a) - c)) / lay.px
                centre_on = any(path.contains_point(c) for path in on)
                if (name, p.label.gid.partition("@")[0]) in CROWDED:
                    continue
                if gap > NEAR or centre_on:
                    bad.append(f"{lang} {p.label.text!r} {gap:.0f} pt from its arrow" + (" on the body" if centre_on else ""))
    assert not bad, "; ".join(bad)


@pytest.mark.xfail(strict=True, reason="C5-E.6's drive crowded since round 28 (g): the chainring's and "
                   "frame's names take the room beside v_P's shaft (docs/explain.md, twenty-eighth round (g))")
def test_the_bicycles_v_p_sits_beside_its_shaft_off_the_front_wheel(layouts):
    """C5-E.6: v_P runs from the pedal P (below the crank axle) forward into the front wheel;
    its value sits beside its shaft, slid back from the tip, its box off that wheel, with
    no leader (before: 92 points out, across the rim)."""
    for lang in ("en", "ca"):
        placed, lay = next((pl, lay) for pl, lay in layouts[("seed_c5_e6_bicycle", lang)]
                           if any(p.label.gid.startswith("velocity:P@") for p in pl))
        p = next(p for p in placed if p.label.gid.startswith("velocity:P@"))
        front = [path for body, path in lay.areas if body == "front"]
        c = (p.box[:2] + p.box[2:]) / 2
        assert front and not front[0].contains_point(c), lang
        assert p.at is not None and not p.leader, lang     # slid back from the tip, beside its shaft


def test_the_bicycles_acceleration_bar_is_measured_in_a_p():
    """C5-E.6 at its draw_at numbers (R_roda 0.35, R 0.14, r 0.07, L 0.18, v 5, v̇ 0.5; the
    drive drawn larger in the twenty-eighth round (g), and again in the twenty-ninth (g)): the
    chainring turns at ω = (r/R)(v/R_roda) = 50/7 rad/s, so the pedal P, L below the crank
    axle, has a_P = (v̇ − L (r/R) v̇/R_roda, L ω²) = (13/35, 450/49) (the notes' v(P) =
    v − L (r/R) v/R_roda, differentiated; the normal part towards C), |a_P| = 9.1912. The bar is in |a_P|, not in
    the product L·r²·v²/(R²·R_roda²) of five symbols. Since the twenty-eighth round (b) the
    bar reads m/s² at those numbers, in every language, and a_P's arrow is |a_P| over the
    bar's value bars long."""
    R_w, R, r, L, v, vd = 0.35, 0.14, 0.07, 0.18, 5.0, 0.5
    omega = (r / R) * (v / R_w)
    a_p = math.hypot(vd - L * (r / R) * vd / R_w, L * omega**2)
    assert a_p == pytest.approx(math.hypot(13 / 35, 450 / 49), rel=1e-12)
    assert a_p == pytest.approx(9.1912, rel=1e-4)
    svg = re.compile(r"<svg xmlns=.*?</svg>", re.S)
    bar = re.compile(r'<line x1="([0-9.]+)" y1="([0-9.]+)" x2="([0-9.]+)" y2="\2" stroke="#222" stroke-width="2"/>'
                     r'.*?<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>', re.S)
    arrow = re.compile(r'<line x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)" stroke="#[0-9a-fA-F]+" '
                       r'stroke-width="(?:2\.2|1\.8)" marker-end=')
    for lang in LANGS:
        bars = _bars(rendered("seed_c5_e6_bicycle", lang, "html"))
        assert not any("aP" in b or "R_roda" in b for b in bars), (lang, bars)
        figs = [f for f in svg.findall(rendered("seed_c5_e6_bicycle", lang, "html"))
                if (m := bar.search(f)) and m.group(4).endswith(" m/s²")]
        assert figs, (lang, bars)
        m = bar.search(figs[-1])
        per = (float(m.group(3)) - float(m.group(1))) / float(m.group(4).split()[0].replace(",", "."))
        lengths = [math.hypot(float(c) - float(a), float(d) - float(b)) / per for a, b, c, d in arrow.findall(figs[-1])]
        assert any(abs(x - a_p) <= 0.02 * a_p for x in lengths), (lang, lengths)
