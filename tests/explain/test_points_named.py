"""Points named as the notes name them (issue 30, fifth round): a contact point is never
labelled with its joint's number (C5-E.2's J5 … J8, C5-1.4's J7 … J12: the joints' ids are
the file's, not the notes'), in the text, the tables or the figures, in Markdown and HTML,
in the four languages; and every contact point the text names is in the points table."""
from __future__ import annotations

import re

import pytest

import kinematika
from kinematika.draw.names import CONTACT_LETTERS, contact_names
from kinematika.explain.document import Table

from .helpers import EXAMPLES, LANGS, SEEDS, explained, rendered
from .helpers import words_of as _words

# J and a number, as a name (J5, v_J5∈2, {J7-O}) or a figure's label ($J_{\mathrm{10}}$)
JOINT_LABEL = re.compile(r"(?<![A-Za-z0-9])J(?:\d+|_\{(?:\\mathrm\{)?\d+)")


@pytest.mark.parametrize("fmt", ["md", "html"])
@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_no_point_is_labelled_with_a_joints_number(name, lang, fmt):
    """No `J5`, `v_{J5∈2}`, `J7-O`, $J_{10}$ anywhere a reader looks."""
    words = _words(rendered(name, lang, fmt))
    assert not JOINT_LABEL.findall(words), (name, lang, fmt, sorted(set(JOINT_LABEL.findall(words))))


def _points_table(doc) -> set[str]:
    table = next(b for b in doc.sections[0].blocks if isinstance(b, Table)
                 and getattr(b.header[0], "key", "") == "col.point")
    return {row[0].text for row in table.rows}


def _without_marks(text: str) -> str:
    """The page without the M / D / ? marks over and under its equations and the legend
    that explains them: an M there is "magnitude known", not a contact named M (C5-1.4's
    contact M, which the page names nowhere else, is not listed)."""
    out, in_code = [], False
    for line in text.splitlines():
        if line.startswith("```"):
            in_code = not in_code
        elif not (in_code and "=" not in line) and not re.search(r"(?<!\S)\?(?!\S)", line):
            out.append(line)
    return "\n".join(out)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_every_contact_the_text_names_is_in_the_points_table(name, lang):
    """A contact point the text writes (v_{J∈wheel}, the centre at J) is defined in the Data
    section's points table, with where it is (C5-E.4's J6 was used and not listed)."""
    sol, doc = explained(name)
    text = _without_marks(rendered(name, lang, "md", drawings=False))
    used = [c for c in set(contact_names(sol.model, sol).values())
            if re.search(rf"(?<![A-Za-z0-9]){re.escape(c)}(?![A-Za-z0-9'′])", text)]
    missing = sorted(set(used) - _points_table(doc))
    assert not missing, (name, lang, missing)


def test_contacts_are_lettered_in_the_joints_order():
    """By hand, C5-E.2 (gear change): its four gear contacts, in the file's order, are J, K, N
    and Q — its points (O, A1, A2) start with no such letter and it has no such
    parameter; C5-1.4: six contacts J, K, N, Q, S, U (L, O are left out: the polygon's l
    reads as I, O is a centre's letter; M and D are the equations' marks, fourteenth
    round (b))."""
    sol, _ = explained("seed_c5_e2_gear_change")
    assert list(contact_names(sol.model, sol).values()) == ["J", "K", "N", "Q"]
    sol, _ = explained("seed_c5_1_4_epicyclic")
    assert list(contact_names(sol.model, sol).values()) == ["J", "K", "N", "Q", "S", "U"]


def test_a_contact_letter_skips_the_models_names(tmp_path):
    """A letter a point's name starts with (K beside K1) or a parameter's, in either case
    (m: M), is skipped: two wheels on the ground with points J, K1 and a parameter m get
    the contacts N and Q."""
    model = tmp_path / "m.yaml"
    model.write_text("""
parameters: {m: 1}
points: {J: [0, 1], K1: [3, 1]}
bodies:
  ground: {points: [], line: {through: [0, 0], direction: [1, 0]}}
  w1: {points: [J], circle: {center: J, radius: m}}
  w2: {points: [K1], circle: {center: K1, radius: m}}
joints:
  - {type: rolling, bodies: [ground, w1]}
  - {type: rolling, bodies: [ground, w2]}
drivers:
  - {omega: w1, value: 1}
  - {omega: w2, value: 1}
""")
    sol = kinematika.solve(model)
    assert list(contact_names(sol.model, sol).values()) == ["N", "Q"]
    assert CONTACT_LETTERS.startswith("JKNQ") and not {"M", "D"} & set(CONTACT_LETTERS)


def test_a_contact_on_a_welded_body_is_the_point_there():
    """C5-1.2: the planes are welded to the ground, which carries K1 and K2 where the wheels
    touch them (s = 3 from K0 up each plane): the contacts are K1 and K2, one label a point."""
    sol = kinematika.solve(EXAMPLES / "seed_c5_1_2_bar_on_inclined_wheels.yaml")
    assert list(contact_names(sol.model, sol).values()) == ["K1", "K2"]


def _spelt_otherwise(sol) -> list[str]:
    """The parameters with a digit whose symbol the formulas write otherwise (r1 as r₁)."""
    from kinematika.explain.render.names import unicode_name

    wording = sol.model.wording
    return [p for p in sol.model.parameters if any(c.isdigit() for c in p)
            and unicode_name(wording.symbol(p, "en") or p) != p]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_the_models_words_write_parameters_as_the_formulas_do(name, lang):
    """C5-E.5's point P "at r1 below its centre" sat over (L; r₂ − r₁), and its notes wrote
    (r2 − r1)²/r1 beside the page's (r₂ − r₁)²/r₁: the model's own words (what a point is,
    the Data's statements, the notes) write a parameter as the formulas do."""
    sol, _ = explained(name)
    names = _spelt_otherwise(sol)
    text = rendered(name, lang, "md", drawings=False)
    for p in names:
        assert not re.search(rf"(?<![A-Za-z0-9_.]){re.escape(p)}(?![A-Za-z0-9_])", text), (name, lang, p)
    if name == "seed_c5_e5_unequal_wheels":
        assert sorted(names) == ["r1", "r2"]
        assert any("ℜ = r₂/(r₂ − r₁)²" in line for line in text.splitlines())      # the note on the print
        point_p = next(line for line in text.splitlines() if line.startswith("| P |"))
        assert "r₁" in point_p and "r1" not in point_p
