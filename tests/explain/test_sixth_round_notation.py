"""The sixth round of issue 30 (the fourth audit's notation): segments run together as the
slides write them, legends only for symbols the page writes, Markdown with no backslash a
reader sees, an even power of a difference with its positive value first."""
from __future__ import annotations

import re

import pytest
import sympy

from kinematika.explain import builder
from kinematika.explain.catalogue import LANGS
from kinematika.explain.context import ambiguous, point_labels, segment
from kinematika.explain.render.unicode import formula_values, unicode_formula

from .helpers import SEEDS, explained, rendered, over

# two labels joined by a hyphen (A-O1, v_{A1-J}): a capital, then letters, digits or primes
HYPHENATED = re.compile(r"(?<![\w′'-])([A-Z][A-Za-z0-9′']*)-([A-Z][A-Za-z0-9′']*)(?![\w′'])")
TABLE_LABEL = re.compile(r"^\| ([A-Z][A-Za-z0-9′']*) \|", re.M)


def _text(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


def _labels(name: str, text: str) -> set[str]:
    """The page's point labels: the model's points and the first cells of its tables' rows
    (the contacts and centres the Data section lists)."""
    sol, _ = explained(name)
    return set(sol.inst.points) | set(TABLE_LABEL.findall(text))


def _split_ways(joined: str, labels: set[str]) -> set[tuple[str, str]]:
    """Every way `joined` reads as two labels (by hand: each cut tried)."""
    return {(joined[:k], joined[k:]) for k in range(1, len(joined))
            if joined[:k] in labels and joined[k:] in labels}


@over(name=SEEDS, lang=LANGS)
def test_no_hyphen_between_two_point_labels_unless_ambiguous(name, lang):
    """A segment or a subscript of two points (v_BA, OA1, v_AO1) never joins them with a
    hyphen, which reads as the difference B − A; only where the run-together text reads as
    two labels in two ways is a separator kept."""
    text = _text(name, lang)
    labels = _labels(name, text)
    for q, p in HYPHENATED.findall(text):
        if q in labels and p in labels:
            assert len(_split_ways(q + p, labels | {q, p})) > 1, f"{q}-{p}"


@pytest.mark.parametrize("q,p,labels,written", [
    ("B", "A", {"A", "B"}, "BA"),
    ("O1", "A", {"O1", "A", "O"}, "O1A"),              # O + 1A: no point 1A
    ("A1", "A2", {"A1", "A2", "A"}, "A1A2"),
    ("O1", "A", {"O1", "A", "O", "1A"}, "O1-A"),       # O1 | A and O | 1A
    ("R", "RF", {"R", "RF", "RR", "F"}, "R-RF"),       # R | RF and RR | F
])
def test_a_separator_only_where_the_juxtaposition_splits_two_ways(q, p, labels, written):
    """The rule on its own, labels chosen by hand."""
    assert ambiguous(q, p, labels) is (written != q + p)
    with point_labels(lambda: labels):
        assert segment(q, p) == written
        assert segment(q, p).ends == (q, p)


def test_the_page_is_built_once(monkeypatch):
    """One build a page: the pair notation no longer asks for a second one (001's pairs of
    points mixed O1A with BA, which used to build the page twice)."""
    calls = []
    real = builder._build
    monkeypatch.setattr(builder, "_build", lambda ctx, unit: calls.append(1) or real(ctx, unit))
    sol, _ = explained("seed_001_r_pairs")
    builder.build(sol)
    assert len(calls) == 1


LEGEND = {"eu": "Notazioa: ", "ca": "Notació: ", "es": "Notación: ", "en": "Notation: "}
SAID = {"eu": r" \S.*? abiadura angeluarra da", "ca": " és la velocitat angular", "es": " es la velocidad angular",
        "en": " is the angular velocity"}


@over(name=SEEDS, lang=LANGS)
def test_a_shortened_subscript_is_said_only_when_the_page_writes_it(name, lang):
    """The legend under the structure table (ω_pista: *pista zilindrikoa*) names only labels
    that some symbol of the page writes (a subscript _pista, _{… pista …}, ∈pista)."""
    text = _text(name, lang)
    lines = [x for x in text.splitlines() if x.startswith(LEGEND[lang])]
    assert len(lines) <= 1
    rest = text.replace(lines[0], "") if lines else text
    for label in re.findall(r"ω_(\{[^}]*\}|[^\s:]+)" + SAID[lang], lines[0] if lines else ""):
        label = label.strip("{}")
        used = re.search(rf"(?:_|∈|_\{{[^}}]*?)(?<![A-Za-z0-9]){re.escape(label)}(?![\w])", rest)
        assert used, label


@over(name=["seed_c5_1_7_semicylinder", "seed_c5_e1_cavity"])
def test_the_audits_unused_legends_are_gone(name):
    """C5-1.7 and C5-E.1 write no ω of their fixed part: no legend for it (the notation
    line may still say what v_{J∈b} is: nineteenth round (c))."""
    assert not [ln for ln in _text(name, "eu").splitlines() if ln.startswith("Notazioa") and "ω_" in ln]


@over(name=SEEDS, lang=LANGS)
def test_no_backslash_a_plain_text_reader_sees(name, lang):
    """Neither \\| nor \\> in a page's Markdown: a magnitude in a table's cell keeps the
    notes' bars (the table written as a list), a comparison is written as it is."""
    text = _text(name, lang)
    assert "\\|" not in text and "\\>" not in text


def test_magnitudes_and_comparisons_read_as_written():
    """C5-1.7's answers write |v_P| (a list: a bar would end a table's cell); C5-E.5's note
    compares (r₂ − r₁)² > r₁²."""
    assert "|v_P| = 2·r·ω" in _text("seed_c5_1_7_semicylinder", "eu")
    assert "(r₂ − r₁)² > r₁²" in _text("seed_c5_e5_unequal_wheels", "eu")


@pytest.mark.parametrize("lang", LANGS)
def test_a_squared_difference_has_its_positive_value_first(lang):
    """C5-E.5 (r₂ = 0.2 > r₁ = 0.15 in the figure): ℜ_P = (r₂ − r₁)²/r₁, as the notes'
    Oharra writes it, never (r₁ − r₂)²."""
    text = _text("seed_c5_e5_unequal_wheels", lang)
    assert "ℜ_P = (r₂ − r₁)²/r₁" in text and "(r₁ − r₂)²" not in text


def test_the_square_turns_with_the_values_only():
    """(a − b)² is written with the larger first at the given numbers, and as sympy orders it
    without them; an odd power is never turned (its sign would change)."""
    a, b = sympy.symbols("a b")
    with formula_values({"a": 1.0, "b": 2.0}):
        assert unicode_formula((a - b) ** 2) == "(b − a)²"
        assert unicode_formula((a - b) ** 3) == "(a − b)³"
    with formula_values({"a": 2.0, "b": 1.0}):
        assert unicode_formula((a - b) ** 2) == "(a − b)²"
    assert unicode_formula((a - b) ** 2) == "(a − b)²"
