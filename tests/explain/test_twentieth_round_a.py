"""Issue 30, twentieth round (a): the one-line derivations of bodies no step works out
(C5-1.2's wheels, C5-1.4's planet 3, C5-E.6's front wheel) stand before the table of rates
that prints their values, and use no velocity (acceleration) the page has not written
earlier: the centre's motion is written first (v_Q = ω_OQ × I_{OQ}Q, v_F = v_H), and α of
a wheel whose centre moves on a straight line is read off |a_F| (no normal part)."""
from __future__ import annotations

import re

import pytest

from kinematika.explain.document import Derived, Equation, Section, Sym, Table

from .helpers import LANGS, SEEDS, explained, over, rendered

RATES = ("sec.rates_summary", "sec.rates_summary_v")


def _motions(items: list) -> set[tuple[str, str]]:
    return {(x.base, str(x.sub)) for x in items if isinstance(x, Sym) and x.base in ("v", "a") and not x.sup}


def _walk(blocks: list, seen: set, bad: list, in_rates: bool, table_seen: list) -> None:
    for b in blocks:
        if isinstance(b, Section):
            _walk(b.blocks, seen, bad, b.title.key in RATES, [False])
            continue
        if isinstance(b, Table) and in_rates:
            table_seen[0] = True
        if isinstance(b, Equation):
            seen |= _motions([b.target.sym] + [t.sym for side in b.sides for t in side])
        if isinstance(b, Derived):
            if in_rates:
                if table_seen[0]:
                    bad.append(("after the table", str(b.sym)))
                missing = _motions(b.how) - seen
                if missing:
                    bad.append(("uses what no line wrote", str(b.sym), sorted(missing)))
            seen |= _motions([b.sym])


@over(name=SEEDS)
def test_rates_read_off_before_the_table_from_written_motions(name: str) -> None:
    _, doc = explained(name)
    bad: list = []
    _walk(doc.sections, set(), bad, False, [False])
    assert not bad, (name, bad)


@pytest.mark.parametrize("lang", LANGS)
def test_bicycle_front_wheel_by_hand(lang: str) -> None:
    """C5-E.6: the frame translates (ω = α = 0), so F moves as H, whose motion is given:
    v_F = v_H = (v, 0), a_F = a_H = (v̇, 0); F moves on a straight line parallel to the road,
    so a_F has no normal part and α = −v̇/R_wheel, read off a_F's x component (twenty-fifth
    round d: a_F = −α·JF); since round 27b the front wheel's step writes its vector equations,
    v_F = v_J + v_FJ and a_F = α × JF, as the rear wheel's does."""
    page = rendered("seed_c5_e6_bicycle", lang)
    assert re.search(r"v_F = v_H = \(v[,;] 0\)", page)
    assert re.search(r"a_F = a_H = \(v̇[,;] 0\)", page)
    assert "|a_F^t|" not in page
    assert page.index("v_F = v_H") < page.index(": v_FJ = −ω_")
    assert page.index("a_F = a_H") < page.index(": a_F^t = −α_" if "^t" in page else ": a_F^T = −α_")   # a_F = a_F^t (round 29 c)


@pytest.mark.parametrize("lang", LANGS)
def test_inclined_wheels_right_wheel_centre_written(lang: str) -> None:
    """C5-1.2: Q moves with the bar OQ about I_OQ, so v_Q = v_{I_{OQ}} + v_{QI_{OQ}} is written
    (in the bar's step, round 24d) before ω of the right wheel is read off its equation about
    the contact K2 (v_Q = v_{K2∈wheel} + v_QK2, round 27b), and both before the table of rates."""
    page = rendered("seed_c5_1_2_bar_on_inclined_wheels", lang)
    at = page.index("v_{QI_{OQ}} = ω_OQ × I_{OQ}Q = ")
    assert at < page.index("|v_QK2| /")
    # the table comes after the last line read off
    table = page.index("| --- | --- |", page.index("|v_QK2| /") - 3000)
    assert table > page.index("|v_QK2| /")


@over(name=SEEDS, lang=LANGS)
def test_a_direction_along_a_segment_is_said_as_the_line(name: str, lang: str) -> None:
    """A velocity whose direction is the segment of the equiprojectivity (C5-2.2: the wheel's
    plane through P is the line PO) is written v_P = |v_P| PO/|PO|, never through a unit
    vector e whose product with PO/|PO| is 1."""
    page = rendered(name, lang)
    assert not re.search(r"e · (\S+)/\|\1\| = 1\b", page), name
