"""Issue 30, fourteenth round (b): the figures and their captions, as the Catalan and Basque
teacher graded main's pages after the thirteenth round. Each test is a rule checked over the
19 seeds in the languages where it applies, and fails on the pages that teacher read (main
at a75cf3b): a contact given by its coordinates only ("roda dreta – roda superior
(R/2; R·(√3 + 2)/2)"), a contact lettered M beside the M/D marks, a contact's letter printed
twice ("F  F", "J  J"), a fixed wheel or cylinder drawn without its name."""
from __future__ import annotations

import base64
import re


from kinematika.draw.names import contact_names

from .helpers import LANGS, SEEDS, SVG, explained, rendered, over

MARKS = {"M", "D"}


def _figures(page: str) -> list[list[str]]:
    """Each `draw` figure's labels, in order, repeats kept (matplotlib's comment per text)."""
    return [[c.strip() for c in re.findall(r"<!--(.*?)-->", base64.b64decode(b64).decode("utf-8"), re.S)]
            for b64 in SVG.findall(page)]


def _letter(label: str) -> str:
    """A label's letter as the page writes it: F for F and $\\mathrm{F}$, J3 for $J_{3}$."""
    m = re.fullmatch(r"\$\\mathrm\{(.+)\}\$", label) or re.fullmatch(r"\$(\w)_\{?(\w+)\}?\$", label)
    if m is None:
        return label
    return "".join(m.groups())


def _section(page: str, k: int) -> str:
    return re.split(r"^## ", page, flags=re.M)[k]


def _contacts(name: str) -> dict[str, str]:
    sol, _ = explained(name)
    return {jid: c for jid, c in contact_names(sol.model, sol).items() if c not in sol.model.points}


@over(name=SEEDS, lang=LANGS)
def test_every_contact_has_its_letter_in_table_and_figure(name, lang):
    """Every contact of the page — the structure table gives each rolling joint's place —
    has a letter: a row of the Data's points table, the letter (never its coordinates
    alone) in the structure table, and the same letter in the mechanism's figure."""
    page = rendered(name, lang)
    data, structure = _section(page, 1), _section(page, 2)
    figures = _figures(page)
    for jid, contact in _contacts(name).items():
        assert re.search(rf"^\| {re.escape(contact)} \|", data, re.M), (name, lang, jid, contact, "not in Data")
        assert re.search(rf"\| {re.escape(contact)} \|$", structure, re.M), (name, lang, jid, contact, "structure")
        if figures:
            assert contact in {_letter(x) for x in figures[0]}, (name, lang, jid, contact, "figure")


def test_by_hand_the_upper_wheel_names_its_fourth_contact():
    """C5-E.4 by hand: the right wheel touches the upper wheel at (√2·R/2; R·(√2 + 2)/2) — the
    two wheels' centres (√2·R; R) and (0; R·(1 + √2)) are 2R apart (twenty-ninth round (d):
    the lower centres 2√2·R apart), the contact halfway. That place is the contact Q (J, K,
    N, Q: M is the equations' mark), named in the tables."""
    page = rendered("seed_c5_e4_upper_wheel", "ca")
    assert "| Q |" in _section(page, 1) and "(√2·R/2; R·(√2 + 2)/2)" in _section(page, 1)
    assert "| *roda dreta* – *roda superior* | Q |" in _section(page, 2)


@over(name=SEEDS)
def test_a_contact_letter_is_free(name):
    """A contact's made-up letter is no point's initial, no parameter, no one-letter body
    (001's N and R) and never M or D, the marks under every equation's terms."""
    sol, _ = explained(name)
    taken = {p[:1] for p in sol.model.points} | {p.upper() for p in sol.model.parameters}
    taken |= {b.upper() for b in sol.model.bodies if len(b) == 1}
    for jid, contact in _contacts(name).items():
        assert contact not in MARKS, (name, jid, contact)
        wording = getattr(sol.model, "wording", None)
        if jid in getattr(wording, "contacts", {}):
            continue                                  # the notes' own letter (001's F)
        assert contact[:1] not in taken, (name, jid, contact)


@over(name=SEEDS, lang=("ca", "eu"))
def test_a_place_has_one_letter_in_a_figure(name, lang):
    """No figure prints a point's or a contact's letter twice: 001's "F  F" (the contact's
    mark and the page's letter) and C5-1.8's "J  J"."""
    letters = set(_contacts(name).values())
    sol, _ = explained(name)
    letters |= set(sol.model.points)
    for k, labels in enumerate(_figures(rendered(name, lang))):
        written = [_letter(x) for x in labels]
        twice = sorted({x for x in written if x in letters and written.count(x) > 1})
        assert not twice, (name, lang, k + 1, twice)


@over(name=SEEDS, lang=LANGS)
def test_a_fixed_circle_is_named_in_the_figure(name, lang):
    """A fixed body drawn as a circle of its own (C5-E.2's fixed central wheel, C5-1.8's
    cylinder, C5-E.1's cavity) carries its name in the mechanism's figure, as the structure
    table writes it, like a moving wheel."""
    sol, _ = explained(name)
    frame = sol.model.bodies[sol.model.frame]
    if not any(type(s).__name__ == "Circle" for s in frame.shapes):
        return
    page = rendered(name, lang)
    row = re.search(r"^\| 1 \| \*([^*]+)\*", _section(page, 2), re.M)
    assert row is not None, (name, lang)
    labels = _figures(page)[0]
    assert any(x.startswith(row.group(1)) for x in labels), (name, lang, row.group(1), labels)
