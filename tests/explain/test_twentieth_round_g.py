"""Issue 30, twentieth round (g): C5-1.1's "J moves with the left strand" skipped the
no-slip step. When a centre's line goes through a point W of b taken to move with a third
body k and W is a rolling (no-slip) contact of b on k, the page says why: b does not slip
on k (the notes: "la politja no llisca al damunt del cable"), so b's point W has k's
velocity there."""
from __future__ import annotations

import dataclasses
import re

import pytest

from kinematika.draw.names import contact_name
from kinematika.explain.document import Msg
from kinematika.explain.kinds import rolls

from .helpers import LANGS, SEEDS, explained, over, rendered, words_of

# the words a no-slip reason is said with, per language (the rolling-noslip messages' verbs)
NO_SLIP = {"en": "not slip on", "es": "no desliza sobre", "ca": "no llisca sobre", "eu": "ez da irristatzen"}


def _msgs(x, seen=None):
    """Every catalogue message in a document, however deep."""
    seen = set() if seen is None else seen
    if id(x) in seen:
        return
    seen.add(id(x))
    if isinstance(x, Msg):
        yield x
        for v in x.args.values():
            yield from _msgs(v, seen)
    elif isinstance(x, (list, tuple)):
        for v in x:
            yield from _msgs(v, seen)
    elif isinstance(x, dict):
        for v in x.values():
            yield from _msgs(v, seen)
    elif dataclasses.is_dataclass(x) and not isinstance(x, type):
        for f in dataclasses.fields(x):
            yield from _msgs(getattr(x, f.name), seen)


def _rolling_contacts(name: str) -> dict[str, frozenset]:
    sol, _ = explained(name)
    return {contact_name(sol.model, j.id, sol): frozenset((j.a, j.b)) for j in sol.model.joints if rolls(j)}


@over(name=SEEDS)
def test_a_rolling_contact_is_not_said_to_just_move_with_a_body(name: str) -> None:
    """A perpendicular through a point that 'moves with k' never stands on a rolling contact
    of k: there the reason is the no-slip condition, said with the rolls message."""
    _, doc = explained(name)
    contacts = _rolling_contacts(name)
    bad = []
    for m in _msgs(doc):
        if m.key.startswith("centre.line.moves"):
            point, body = str(m.args["point"].text), str(m.args["body"].text)
            if point in contacts and body in contacts[point]:
                bad.append((point, body))
        if m.key.startswith("centre.line.rolls"):
            point, body, b = (str(m.args[k].text) for k in ("point", "body", "b"))
            assert contacts.get(point) == frozenset((body, b)), (m.key, point, body, b)
    assert not bad, bad


@over(name=SEEDS, lang=LANGS)
def test_the_no_slip_reason_is_said_in_every_language(name: str, lang: str) -> None:
    """Each rolls line, rendered, names the no-slip condition in the page's language."""
    _, doc = explained(name)
    n = sum(1 for m in _msgs(doc) if m.key.startswith("centre.line.rolls"))
    page = rendered(name, lang)
    said = sum(line.count(NO_SLIP[lang]) for line in page.splitlines() if line.startswith("I_"))
    assert said >= n, (n, said)


@pytest.mark.parametrize("lang", LANGS)
def test_pulley_on_cable_by_hand(lang: str) -> None:
    """C5-1.1 as the notes reason: the pulley does not slip on the cable, so its points J, K
    have the strands' velocities; each strand turns about the point where it is tied."""
    page = rendered("seed_c5_1_1_pulley_on_cable", lang)
    line = next(x for x in page.splitlines() if x.startswith(("I_{pulley}", "I_{polea}", "I_{politja}")))
    assert line.count(NO_SLIP[lang]) == 2, line
    assert re.search(r"\(J (moves with|se mueve con|es mou amb|puntua)", line) is None, line
    assert "G1" in line and "G2" in line


def _rates_rows(doc) -> set[str]:
    from kinematika.explain.document import Section, Table

    sec = next(s for s in doc.sections if isinstance(s, Section)
               and s.title.key in ("sec.rates_summary", "sec.rates_summary_v"))
    table = next(b for b in sec.blocks if isinstance(b, Table))
    return {r[0].text for r in table.rows}


@over(name=SEEDS)
def test_every_rate_a_step_finds_is_in_the_table(name: str) -> None:
    """Item 2: a body whose ω a step finds (a line ω_body = …) is a row of the table of rates;
    a belt's or chain's run has neither line nor row (round 29 c: the notes give it no rate)."""
    from kinematika.explain.document import Derived

    sol, doc = explained(name)
    if not sol.model.bodies or sol.space.dim != 2:
        return
    found = {b.body for b in doc.blocks() if isinstance(b, Derived) and b.sym.base == "ω" and b.body}
    runs = {str(m.args["line"].text) for m in _msgs(doc) if m.key == "drive.relation" and "line" in m.args}
    rows = _rates_rows(doc)
    assert not runs & found, ("a run has an ω line", runs & found)
    assert not runs & rows, ("a run is in the table", runs & rows)
    assert found <= rows, ("found, not in the table", found - rows)


def test_belt_and_chain_by_hand() -> None:
    """C5-1.6 and C5-E.6: the belt and the chain get no row of rates (round 29 c); the fixed
    pulley the belt wraps does, with its 0."""
    page = rendered("seed_c5_1_6_belt", "en")
    assert not re.search(r"\| \*belt\* \| ω \|", page) and re.search(r"\| \*fixed pulley\* \| 0 \|", page)
    page = rendered("seed_c5_e6_bicycle", "en")
    assert not re.search(r"\| \*chain\* \| 0 \| 0 \|", page)


@over(name=SEEDS)
def test_a_body_row_lists_every_point_on_it(name: str) -> None:
    """Item 3: the structure table's row of a body lists its model points and the contact
    point of each touching joint it is in (C5-1.6's fixed pulley had O but not T1, while the
    moving pulley had T2)."""
    from kinematika.draw.names import welded_to_frame
    from kinematika.explain.document import Table

    sol, doc = explained(name)
    if sol.space.dim != 2:
        return
    sec = next(s for s in doc.sections if s.title.key == "sec.structure")
    table = next(b for b in sec.blocks if isinstance(b, Table) and b.header[-1].key == "col.points")
    # r[0]: the body, set as its number; a fixed body's contacts said as such (twenty-third round (a))
    rows = {str(r[0].text): {str(q.text) for p in r[2] for q in (p.args["points"].items if hasattr(p, "args") else [p])}
            for r in table.rows}
    bad = []
    for j in sol.model.joints:
        if getattr(j.kind, "touches", False):
            c = contact_name(sol.model, j.id, sol)
            # a body welded to the frame is the frame's row (twenty-ninth round (b))
            bad += [(body, c) for body in (j.a, j.b)
                    if c not in rows[sol.model.frame if body in welded_to_frame(sol.model) else body]]
    assert not bad, bad


def test_belt_structure_by_hand() -> None:
    page = rendered("seed_c5_1_6_belt", "en")
    assert "| 1 | *fixed pulley* (fixed), circle of radius 2·r | O, contact point T1 |" in page   # twenty-third round (a), 29 (b)
    assert "| 3 | *moving pulley*, circle of radius r | A, T2 |" in page


# the geometric contact point's spellings the reader saw on one page (001's rolling pair)
OTHER_GEOM = re.compile(r"\^geom|,geom\b|[A-Z]\d*\}\^\{?geom|_[A-Z]\d*\^\{?geom")


@over(name=SEEDS, lang=LANGS)
def test_the_geometric_point_has_one_spelling(name: str, lang: str) -> None:
    """Item 4: the geometric contact point is F^{geom} wherever it is written — the point,
    v_{F^{geom}}, a_{F^{geom}}, and its motion about the centre v_{F^{geom}A} — never F^geom,
    v_F^geom or v_{FA,geom} (one name, `document.geometric_name`)."""
    page = words_of(rendered(name, lang))
    bad = OTHER_GEOM.findall(page)
    assert not bad, bad


def test_rolling_pair_geometric_point_by_hand() -> None:
    """001: F^{geom} moves with the bar AF that turns with the lever: v_{F^{geom}} = v_A +
    v_{F^{geom}A}; the HTML sets the superscript inside the subscript."""
    page = rendered("seed_001_rolling_pair", "en")
    assert "v_{F^{geom}}  =  v_A  +  v_{F^{geom}A}" in page
    assert "a_{F^{geom}}  =  a_A  +  a_{F^{geom}A}^n  +  a_{F^{geom}A}^t" in page
    assert "F^{geom}, the geometric contact point" in page
    html = rendered("seed_001_rolling_pair", "ca", "html")
    assert '<b class="v">v</b><sub>F<sup>geom</sup></sub>' in html
    assert '<b class="v">v</b><sub>F<sup>geom</sup>A</sub>' in html
