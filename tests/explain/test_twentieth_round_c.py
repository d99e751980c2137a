"""Issue 30, twentieth round (c): figures. A polygon's scale bar says its unit (in the
symbols on a symbolic page until the twenty-eighth round (b): m/s, m/s² now); a leader costs for each drawn body it crosses; a caption says which images sit
at the pole; the notes' M and D are kept on every page."""
from __future__ import annotations

import re

import numpy as np
import pytest
from matplotlib.figure import Figure as MplFigure

from kinematika.draw.labels import BODY_CROSS, LEADER, Label, LabelBoard, Layout

from .helpers import LANGS, SEEDS, explained, over, rendered

BAR = re.compile(r'<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>')


def _bars(page: str) -> list[str]:
    """A page's scale bars' text, its markup left out (a symbol is set in tspans since the
    twenty-fifth round (b): |a_P| reads |aP| here)."""
    return [re.sub(r"<[^>]+>", "", b) for b in BAR.findall(page)]


def _polygons(doc) -> list:
    from kinematika.explain.document import Figure

    return [b for sec in doc.sections for b in getattr(sec, "blocks", []) if isinstance(b, Figure)
            and b.unit in ("speed", "accel")]


@over(name=SEEDS)
def test_every_scale_bar_says_its_unit(name):
    """No bar is a bare number (C5-E.4's "5", C5-1.4's "1" before): it says m/s or m/s², a
    symbolic page's too since the twenty-eighth round (b)."""
    _, doc = explained(name)
    bars = _bars(rendered(name, "en", "html"))
    assert bars or not _polygons(doc)          # C5-1.5 draws no polygon (all its images on one line)
    for text in bars:
        assert not re.fullmatch(r"[0-9.,]+", text.strip()), (name, text)


def test_the_upper_wheels_acceleration_bar_is_in_m_per_s_squared():
    """C5-E.4: the acceleration polygon's bar read "v²/(5·R)"; drawn at R = 0.25, v = 2, it
    reads a round number of m/s² (twenty-eighth round (b); that it measures a_P = v²/R =
    16 m/s² is checked in test_twenty_eighth_round_b.py)."""
    _, doc = explained("seed_c5_e4_upper_wheel")
    assert [f for f in _polygons(doc) if f.unit == "accel"]
    bars = _bars(rendered("seed_c5_e4_upper_wheel", "en", "html"))
    assert any(re.fullmatch(r"[0-9.]+ m/s²", b) for b in bars) and not any("R" in b for b in bars), bars


def _layout(labels: list[Label], board: LabelBoard) -> tuple[Layout, object]:
    fig = MplFigure(figsize=(4, 4), dpi=72)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, 288)
    ax.set_ylim(0, 288)
    board.labels = labels
    return Layout(board, ax), ax


def _ring(c, r, n=48):
    t = np.linspace(0, 2 * np.pi, n + 1)
    return [(c[0] + r * np.cos(a), c[1] + r * np.sin(a)) for a in t]


def test_a_leader_across_a_body_costs_once_per_crossing():
    """A label anchored 10 pt left of a wheel of radius 60 pt: a box far to the right has a
    leader through the wheel (two crossings of its rim), one far to the left none. A body's
    own name does not pay for its own outline (its leader reaches into it)."""
    board = LabelBoard()
    board.avoid(*_ring((150, 150), 60), owner="wheel")
    label = Label(np.array([80.0, 150.0]), "v", "k", 1, "velocity:A")
    own = Label(np.array([150.0, 150.0]), "wheel", "k", 1, "body:wheel")
    lay, ax = _layout([label, own], board)
    size = np.array([20.0, 10.0])
    for lb, through in ((label, 2), (own, 1)):
        cand = lay._candidates(lb, ax.transData.transform(lb.anchor), size)
        cost = lay._leader_over(lb, cand)
        far = cand[1] >= LEADER
        right = far & (cand[2][:, 0] > 0.99)
        left = far & (cand[2][:, 0] < -0.99)
        if lb is label:
            # the farthest right boxes lie beyond the wheel: their leaders cross the rim twice
            assert cost[right].max() == pytest.approx(through * BODY_CROSS)
            assert cost[left].max() == 0
        else:
            assert cost[far].max() == 0


@pytest.mark.parametrize("lang", LANGS)
def test_the_rolling_pairs_polygons_say_which_images_are_at_the_pole(lang):
    """001's rolling pair: B is fixed (v_B = a_B = 0) and A's acceleration is zero (the notes:
    a_A = 0), so the images b, and a of the acceleration polygon, are the pole o: each caption
    says so, with the reason."""
    md = rendered("seed_001_rolling_pair", lang)
    words = {"en": "are at the pole o, since", "es": "están en el polo o, ya que",
             "ca": "són al pol o, ja que", "eu": "o poloan daude"}[lang]
    assert re.search(r"a (and|y|i|eta) b " + re.escape(words) + r".{0,20}a_A = a_B = 0", md), lang


@pytest.mark.parametrize("name", [s for s in SEEDS if s.startswith("seed_001")])
def test_a_fixed_point_of_a_polygon_is_said_at_the_pole(name):
    """Every 001 polygon whose equations end a point's motion at the pole says it (en)."""
    md = rendered(name, "en")
    assert " at the pole o, since " in md


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["seed_001_p_pair_coriolis", "seed_c5_1_1_pulley_on_cable",
                                  "seed_c5_2_1_tricycle", "seed_c5_e5_unequal_wheels"])
def test_the_notes_marks_are_kept_where_a_point_is_m_or_d(name, lang):
    """Pages that named a point M or D wrote "mag/dir": they keep M and D. Since the
    twenty-eighth round (b) no seed names a point M or D (C5-1.1's and C5-2.1's are P, C5-E.5's
    the notes' C), so the legend is plain: the sentence "… not the point D" is a user's
    model's (tests/explain/test_twenty_eighth_round_b.py)."""
    md = rendered(name, lang)
    assert re.search(r"\bM: \w+ \w+; D: \w+ \w+;", md)
    assert not re.search(r"(not the point|no es el punto|no és el punt|ez da [MD] puntua)", md)
    assert not re.search(r"(?m)^\s*(?:mag|mòd|mód|mod|dir|norab)(?:\s|$)", md)
