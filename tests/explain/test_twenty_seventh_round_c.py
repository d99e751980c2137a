"""Issue 30, twenty-seventh round (c): what a body's label on a mechanism figure says, and
where a name, a value and a leader may go.

Teachers read the explanation pages' figures (mostly in Basque): "gurpil zentral finkoa
(zentrala)" written across C5-E.2's hatched fixed wheel, "euskarri erdizilindrikoa
(euskarria)" on C5-1.7, "polea mugikorra" above C5-1.6's belt, its pulley below it, a leader
across C5-E.5's chassis bar. The rules:

- a body is named on a figure by its name, as the text names it; a subscript read off the
  name (ω_zentrala) is not added in brackets (`draw.bodies._tag`, `BodyView.read_off`);
- no name or value lies on hatching, its own body's neither (`LabelBoard.area` with no
  owner, every hatched mark: `draw.paint`);
- no leader, nor the short way from a name or value to its anchor, crosses another body's
  bar (`BAR_CROSS`) or an arrow (`ARROW_CROSS`); a wheel's name may be led from any side of
  its disc, a bar's from along it (`Label.spots`), not from another body's bar;
- another body's line through a name's or a value's box is one rule, weighed as lying on
  that body (`AREA`), not twice (`RIM` and `LINE_OVER`) for a value and once for a name.

The figures are measured on what is painted (`tests/explain/figure_faults.py`), not on the
placer's arithmetic.
"""
from __future__ import annotations

import re

import numpy as np
import pytest

from .figure_faults import drawn, faults, part_inside
from .helpers import LANGS, NOTES_SEEDS, explained, over, scratch_axes


def _body_names(name: str, lang: str) -> dict[str, str]:
    """Each body -> its name in `lang` as the model gives it (the article the notes write
    before a Catalan or Spanish name dropped, l' too, as a figure writes it)."""
    sol, _ = explained(name)
    spelt = sol.model.wording.bodies.get(lang, {})
    out = {}
    for body in sol.model.bodies:
        words = spelt.get(body, body).split()
        if len(words) > 1 and words[0].lower() in ("el", "la", "els", "les", "los", "las"):
            words = words[1:]
        out[body] = re.sub(r"^[lL]['’]", "", " ".join(words))
    return out


@over(name=NOTES_SEEDS, lang=LANGS)
def test_a_body_is_named_on_a_figure_by_its_name(name, lang):
    """Every body's label on the page's figures is its name, nothing after it in brackets:
    these models name their bodies in every language, so the text's symbols write them by
    subscripts read off the names (ω_zentrala), which the notation line defines."""
    names = _body_names(name, lang)
    bad = []
    for fig in drawn(name, lang):
        for lab in fig.labels:
            if not lab.gid.startswith("body:"):
                continue
            body = lab.gid.removeprefix("body:")
            if re.search(r"\([^)]*\)\s*$", lab.text) or lab.text.lower() != names[body].lower():
                bad.append(f"{body}: {lab.text!r} (its name: {names[body]!r})")
    assert not bad, "; ".join(sorted(set(bad)))


def test_the_gear_changes_fixed_wheel_by_its_name_off_the_hatching():
    """C5-E.2 in Basque: the fixed central wheel is "gurpil zentral finkoa" on both
    figures, on no hatching and across no line of the arm (the label sampled every pixel)."""
    for fig in drawn("seed_c5_e2_gear_change", "eu"):
        lab = next(lb for lb in fig.labels if lb.gid == "body:ground")
        assert lab.text == "gurpil zentral finkoa"
        assert part_inside(lab.box, [f for f in fig.fills if f.hatched]) == 0.0
        assert not faults(fig)["line"]


@over(name=NOTES_SEEDS, lang=LANGS)
def test_no_name_or_value_lies_on_hatching(name, lang):
    """No body's name and no vector's value has more than a twentieth of its text box on
    hatching, its own body's neither."""
    bad = [x for fig in drawn(name, lang) for x in faults(fig)["hatch"]]
    assert not bad, "; ".join(bad)


# bodies inside another body's closed loop, whose names' leaders cross it wherever the names go
# (docs/explain.md, "Twenty-eighth round (g)"): C5-E.6's sprocket and chainring lie inside the
# chain's loop, and the loop's inside (between the runs: the frame's bars, v_H, H, C, T1, T2)
# holds no name, at the page's figure's size or at the drive drawn larger (its `draw_at`); the
# value of a velocity drawn inside the loop (v_H at the sprocket's hub, beside the chain's
# upper run since the twenty-ninth round (e) keeps arrows off lines) crosses the loop likewise
LOOPED = {"seed_c5_e6_bicycle": ({"sprocket", "chainring"}, "chain", {"H"})}


@over(name=NOTES_SEEDS, lang=LANGS)
def test_no_way_to_a_label_crosses_another_bodys_bar(name, lang):
    """No leader, and no short way from a name or a value to the anchor it is set beside,
    crosses a bar of another body (a chassis, an arm, a belt's or a chain's run); but the
    name of a body inside another's closed loop (`LOOPED`) crosses that loop's bar."""
    inside, loop, points = LOOPED.get(name, (set(), None, set()))
    names = _body_names(name, lang)
    allowed = {f"{names[b]}: leader across {loop}'s bar" for b in inside} | \
        {f"{names[b]}: link across {loop}'s bar" for b in inside}
    values = tuple(f"$v_{{\\mathrm{{{p}}}}}$ = " for p in points)      # a value's text: "$v_{\mathrm{H}}$ = $v$"
    bad = [x for fig in drawn(name, lang) for x in faults(fig)["bar"]
           if x not in allowed and not (values and x.startswith(values) and x.endswith(f"across {loop}'s bar"))]
    assert not bad, "; ".join(bad)


@over(name=NOTES_SEEDS, lang=LANGS)
def test_no_leader_crosses_an_arrow(name, lang):
    """No label's leader crosses a vector's arrow (it would point along it, or at it)."""
    bad = [x for fig in drawn(name, lang) for x in faults(fig)["arrow"]]
    assert not bad, "; ".join(bad)


@pytest.mark.parametrize("lang", LANGS)
def test_the_moving_pulley_is_named_on_its_side_of_the_belt(lang):
    """C5-1.6: the moving pulley's name is not set beyond the belt's straight run (T1 to
    T2), its way to its pulley crossing neither that run nor an arrow, on both figures."""
    for fig in drawn("seed_c5_1_6_belt", lang):
        found = faults(fig)
        lab = next(lb for lb in fig.labels if lb.gid == "body:pulley")
        assert not [x for x in found["bar"] + found["arrow"] if x.startswith(lab.text + ":")]


def _one_line_board(owner: str, gid: str):
    """A layout on a 400 × 400 pt axes with one outline of body "wheel" (a vertical line at
    x = 200) and a label of `gid`; the boxes: one across the line, one clear of it."""
    from kinematika.draw.labels import LabelBoard, Layout

    ax = scratch_axes()
    board = LabelBoard()
    board.avoid([200.0, 0.0], [200.0, 400.0], owner="wheel")
    board.add([150.0, 150.0], "label", "k", 5, gid)
    lay = Layout(board, ax)
    boxes = np.array([[180.0, 140.0, 230.0, 155.0], [100.0, 140.0, 150.0, 155.0]])
    label = lay.labels[0]
    return lay, label, boxes


@pytest.mark.parametrize("gid", ["velocity:P@arm", "body:arm"])
def test_another_bodys_line_through_a_label_is_weighed_once_as_its_area(gid):
    """A vector's value and a body's name across another body's outline pay `AREA` for it,
    once: the value paid `RIM` (400) and `LINE_OVER` (150) before, two rules for one
    fault, and a name `LINE_OVER` alone. The cost is read off the two functions that
    weighed it (what lies on areas, what lines run under)."""
    from kinematika.draw.labels import AREA

    lay, label, boxes = _one_line_board("wheel", gid)
    cost = lay._areas(label, boxes) + lay._lines_under(label, boxes)
    assert cost[1] == 0.0
    assert cost[0] == pytest.approx(AREA)


def test_its_own_line_through_a_name_reads_only_harder():
    """A name across its own body's outline pays `LINE_OVER`, less than across another
    body's (`AREA`): it reads as its own, only less easily."""
    from kinematika.draw.labels import AREA, LINE_OVER, LabelBoard, Layout

    ax = scratch_axes()
    board = LabelBoard()
    board.avoid([200.0, 0.0], [200.0, 400.0], owner="wheel")
    board.add([150.0, 150.0], "wheel", "k", 5, "body:wheel")
    lay = Layout(board, ax)
    boxes = np.array([[180.0, 140.0, 230.0, 155.0]])
    cost = lay._areas(lay.labels[0], boxes) + lay._lines_under(lay.labels[0], boxes)
    assert cost[0] == pytest.approx(LINE_OVER) and LINE_OVER < AREA


def test_a_leader_across_another_bodys_bar_weighs_more_than_across_a_rim():
    """The way from a name at (150, 150) to a box right of x = 200 crosses body "arm"'s line
    there: `BAR_CROSS` when it is a bar, `BODY_CROSS` when an outline; the name's own bar is
    free (it reaches into its body)."""
    from kinematika.draw.labels import BAR_CROSS, BODY_CROSS, LabelBoard, Layout

    def cost(bar: bool, gid: str) -> float:
        ax = scratch_axes()
        board = LabelBoard()
        board.avoid([200.0, 0.0], [200.0, 400.0], owner="arm", bar=bar)
        board.add([150.0, 150.0], "name", "k", 5, gid)
        lay = Layout(board, ax)
        boxes = np.array([[260.0, 140.0, 300.0, 155.0]])
        cand = (boxes, np.array([110.0]), np.array([[1.0, 0.0]]), np.array([[150.0, 150.0]]), np.zeros(1))
        return float(lay._leader_over(lay.labels[0], cand)[0])

    assert cost(True, "body:wheel") == pytest.approx(BAR_CROSS)
    assert cost(False, "body:wheel") == pytest.approx(BODY_CROSS)
    assert cost(True, "body:arm") == 0.0
    assert BODY_CROSS < BAR_CROSS


def test_a_hatched_mark_is_no_place_for_a_name():
    """Painting a hatched polygon puts its region on the label board as nobody's area: a
    name of the very body it hatches pays `AREA` for a box inside it."""
    from kinematika.draw.canvas import Canvas
    from kinematika.draw.geometry import Box
    from kinematika.draw.labels import AREA, Layout
    from kinematika.draw.paint import paint_mark
    from kinematika.joints.symbols import Mark

    ax = scratch_axes()
    cv = Canvas(ax, scene=None, view=Box(0, 0, 400, 400))
    paint_mark(cv, Mark("polygon", np.array([[100.0, 100], [300, 100], [300, 200], [100, 200]]),
                        colour="#424242", width=0, hatch=True, zorder=1, avoid=0.0))
    cv.board.add([200.0, 150.0], "ground", "k", 5, "body:ground")
    lay = Layout(cv.board, ax)
    boxes = np.array([[150.0, 140.0, 250.0, 160.0], [150.0, 240.0, 250.0, 260.0]])
    cost = lay._areas(lay.labels[0], boxes)
    assert cost[0] == pytest.approx(AREA) and cost[1] == 0.0
