"""Issue 30, twenty-fifth round (b): a scale bar's symbols set as the labels' are.

The four readers saw C5-E.6's acceleration bar print "|a_P|/5", a raw underscore: the bar's
formula was written in plain Unicode, its symbols as a name's plain-text spelling. A bar's
symbols are now set as a label's (`explain.render.svg.name_markup`, `sym_markup`): an
italic letter and a smaller, shifted subscript, in HTML and Markdown (SVG); TikZ writes
them as math. Since the twenty-eighth round (b) a bar holds no symbol: it reads a number in
m/s or m/s² at the values drawn, as a numeric page's.
"""
from __future__ import annotations

import math
import re

from .helpers import LANGS, NOTES_SEEDS, RECORDED_LANGS, SEEDS, over, recorded_pages, rendered

BAR = re.compile(r'<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>')
TAG = re.compile(r"<[^>]+>")
SET = re.compile(r'<tspan (font-style="italic"|baseline-shift="(sub|super)" font-size="70%")>[^<]+</tspan>')


@over(name=SEEDS, lang=LANGS)
def test_a_scale_bars_symbols_are_set_as_symbols(name, lang):
    """No bar's text holds an underscore outside its markup (a_P), and each letter of a
    symbolic page's bar formula is set in italics, its subscript as a subscript."""
    for bar in BAR.findall(rendered(name, lang, "html")):
        text = TAG.sub("", bar)
        assert "_" not in text, (text, bar)
        letters = re.findall(r"[A-Za-zα-ωΑ-Ω]", SET.sub("", bar))
        # a numeric page's unit (m/s, m/s²) is a word, not a symbol: its bar holds no tspan
        assert not letters or "<tspan" not in bar, (letters, bar)


def test_the_bicycles_acceleration_bar_is_a_number_of_m_per_s_squared():
    """C5-E.6 (every language): the bar read |a_P|/5; it reads a round number of m/s², no
    tspan in it (twenty-eighth round (b)); in LaTeX no |a_P| either."""
    for lang in LANGS:
        bars = BAR.findall(rendered("seed_c5_e6_bicycle", lang, "html"))
        assert any(re.fullmatch(r"[0-9]+(?:[.,][0-9]+)? m/s²", b) for b in bars), (lang, bars)
        assert not any("<tspan" in b for b in bars), (lang, bars)
    tex = rendered("seed_c5_e6_bicycle", "en", "tex")
    assert r"\left|{a_{P}}\right|" not in tex


# --- a leader keeps off other points' dots and centres' rings --------------------------------

DOT = 4.0           # points: a leader this close to another labelled dot runs through it
DOTS = ("point:", "contact:", "icr:", "centre:", "pole:")


def _leaders_through_dots(found: list) -> list[str]:
    """The labels of points and centres (`DOTS`) whose leader, from its anchor to
    the nearest point of its text's box, passes within `DOT` points of another labelled
    dot (a point's, a centre's ring), its own anchor's place aside: measured on the placed
    boxes, not through the placer's costs."""
    import numpy as np

    bad = []
    for placed, lay in found:
        px = lay.px
        dots = [(p.label.text, lay.ax.transData.transform(p.label.anchor)) for p in placed
                if p.label.gid.startswith(DOTS)]
        for p in placed:
            if not p.leader or not p.label.gid.startswith(DOTS):
                continue
            a = lay.ax.transData.transform(p.anchor)
            c = (p.box[:2] + p.box[2:]) / 2
            # where the segment from the anchor to the box's centre enters the box
            d = c - a
            half = (p.box[2:] - p.box[:2]) / 2
            t = 1.0 - min(half[0] / abs(d[0]) if abs(d[0]) > 1e-9 else math.inf,
                          half[1] / abs(d[1]) if abs(d[1]) > 1e-9 else math.inf, 1.0)
            b = a + t * d
            for text, q in dots:
                if np.linalg.norm(q - a) <= DOT * px:
                    continue
                s = np.clip(np.dot(q - a, b - a) / max(np.dot(b - a, b - a), 1e-12), 0, 1)
                if np.linalg.norm(q - (a + s * (b - a))) <= DOT * px:
                    bad.append(f"{p.label.text!r}'s leader through {text!r}")
    return bad


@over(name=NOTES_SEEDS)
def test_no_leader_runs_through_another_points_dot(name):
    """A point's or centre's label set away from its dot has its leader to it; that leader runs
    through no other labelled point or centre, where it reads as that point's (C5-E.2's
    I_upper planet above A1, its leader hidden along the arm from J through A1), in English
    and Catalan (the recorded pages)."""
    found = recorded_pages("layouts")
    bad = [f"{lang}: {b}" for lang in RECORDED_LANGS for b in _leaders_through_dots(found[(name, lang)])]
    assert not bad, bad


# A centre written into its point's label since the twenty-ninth round (g) ("I_planet1 = J": the
# contact's letter and the centre in one label) goes on a leader to that point when the point's
# own place is taken (the planet's centre line, a bar: round 29 (e)); the leader says which dot it
# names, so it may sit nearer another dot (A1) than its own, within MERGED_NEAR points of it.
MERGED_NEAR = 72.0


def test_the_gear_changes_planets_centres_sit_by_their_rings():
    """C5-E.2 (every language): I of each planet sits within `NEAR` points of its own ring (J,
    K), nearer it than any other labelled dot (A1, A2, N, Q), its leader through none of them;
    written into its point's label ("I_planet1 = J"), within `MERGED_NEAR` on its leader."""
    import numpy as np

    drawings = recorded_pages("drawings", LANGS)          # the mechanism drawings' layouts, as drawn
    for lang in LANGS:
        found = drawings[("seed_c5_e2_gear_change", lang)]
        assert not _leaders_through_dots(found), lang
        # since the twenty-ninth round (g) a centre at a named point (the contacts J, K) is
        # written into that point's label, "I_planet1 = J": that label is the centre's
        centres = [(p, lay) for placed, lay in found for p in placed
                   if p.label.gid in ("centre:ground-planet1", "centre:ground-planet2")
                   or (p.label.gid.startswith(("point:", "contact:")) and p.label.text.startswith("$I_{")
                       and " = " in p.label.text)]
        assert len(centres) >= 2, lang
        for p, lay in centres:
            ring = lay.ax.transData.transform(p.label.anchor)
            box = p.box
            gap = np.hypot(*np.maximum(np.maximum(box[:2] - ring, ring - box[2:]), 0)) / lay.px
            merged = p.label.gid.startswith(("point:", "contact:"))
            if merged:
                assert gap <= MERGED_NEAR, (lang, p.label.text, gap)
            else:
                assert gap <= NEAR, (lang, p.label.text, gap)
            placed = next(q for q in found if q[1] is lay)[0]
            centre = (box[:2] + box[2:]) / 2
            own = np.linalg.norm(centre - ring)
            for q in placed:
                if q.label.gid.startswith(("point:", "contact:")):
                    other = lay.ax.transData.transform(q.label.anchor)
                    if np.linalg.norm(other - ring) > DOT * lay.px and not merged:
                        assert np.linalg.norm(centre - other) > own, (lang, p.label.text, q.label.text)


NEAR = 48.0         # points from a centre's ring to its label's box: a step of the placer's with a leader
