"""Issue 30, twenty-fourth round (a): readers' items on main's pages.

- Basque says one word for a contact point, "kontaktu-puntua" (`what-contact` said
  "ukipen-puntua" beside "kontaktu-puntua" everywhere else);
- the fixed body's row ties the model's name to the ground's word only where the name does
  not already say it (C5-1.8's Catalan "*terra cilíndric* (*terra*)");
- a printed sum writes its positive terms first (C5-E.6's "(b, −R + R_wheel + r)" is
  "(b, R_wheel + r − R)"), `report.values.positive_first`.
"""

from __future__ import annotations

import re

import sympy

from kinematika.explain.catalogue import same
from kinematika.explain.render.unicode import unicode_formula
from kinematika.report.values import written_latex

from .helpers import LANGS, SEEDS, over, rendered


@over(name=SEEDS)
def test_basque_says_one_word_for_a_contact_point(name: str) -> None:
    """No Basque page says "ukipen(-puntua)": the catalogue's word is "kontaktu-puntua"."""
    md = rendered(name, "eu")
    assert "ukipen" not in md.casefold(), [x for x in md.splitlines() if "ukipen" in x.casefold()][:3]


def test_the_basque_contact_row() -> None:
    """C5-1.1's points table, the reader's row."""
    assert "| J | kontaktu-puntua (errodadura), *ezkerreko kable-zatia* eta *polea* solidoen artean |" \
        in rendered("seed_c5_1_1_pulley_on_cable", "eu")


# a structure table's row whose body is tied in parentheses to a word in asterisks
TIED = re.compile(r"^\| \d+ \| \*([^*]+)\* \(([^)]*?)\*([^*]+)\*")


@over(name=SEEDS, lang=LANGS)
def test_a_fixed_row_does_not_repeat_the_ground_word(name: str, lang: str) -> None:
    """No body row reads "*X* (*Y*)" or "*X* (fixed: the *Y*)" where Y is X or a word of X:
    the parenthesis would only repeat the name."""
    for line in rendered(name, lang).splitlines():
        m = TIED.match(line)
        if m:
            body, word = m.group(1).casefold(), m.group(3).casefold()
            assert not re.search(rf"(?<![\w-]){re.escape(word)}(?![\w-])", body), line


def test_the_catalan_ground_cylinder() -> None:
    """C5-1.8: the Catalan *terra cilíndric* stands alone; the other languages' names (a fixed
    cylinder) do not say the ground's word and keep the tie."""
    # twenty-ninth round (b): every fixed part by its own name, marked fixed, no "(*ground*)"
    row = {"ca": "| 1 | *terra cilíndric* (fix), circumferència de radi 2·r |",
           "en": "| 1 | *fixed cylinder* (fixed), circle of radius 2·r |",
           "es": "| 1 | *cilindro fijo* (fijo), circunferencia de radio 2·r |",
           "eu": "| 1 | *zilindro finkoa* (finkoa), 2·r erradioko zirkunferentzia |"}
    for lang, want in row.items():
        assert want in rendered("seed_c5_1_8_contact_points", lang), lang


def test_same_reads_a_word_of_the_name() -> None:
    """`SAME`: the whole name or one word of it, never a part of a word."""
    assert same("terra cilíndric", "el terra") == "yes"
    assert same("cylindrical ground", "the ground") == "yes"
    assert same("el suelo", "suelo") == "yes"
    assert same("fixed cylinder", "ground") == "no"
    assert same("underground", "ground") == "no"


def _sums(md: str) -> list[str]:
    """Every stretch of formula that opens with a minus right after a coordinate's or an
    equation side's start ("(", ", ", "; ", "= ") and runs, at its own bracket depth, to the
    coordinate's or side's end: the sum a reader reads there."""
    found = []
    for m in re.finditer(r"(?:\(|, |; |= )(?=−)", md):
        depth, end = 0, m.end()
        while end < len(md):
            c = md[end]
            if c in "([":
                depth += 1
            elif c in ")]":
                if depth == 0:
                    break
                depth -= 1
            elif depth == 0 and (c in ",;=|\n:" or md.startswith(". ", end)):
                break
            end += 1
        found.append(md[m.end():end])
    return found


def _plus_at_top(text: str) -> bool:
    """Whether `text` holds a " + " outside brackets."""
    depth = 0
    for i, c in enumerate(text):
        depth += (c in "([") - (c in ")]")
        if depth == 0 and text.startswith(" + ", i):
            return True
    return False


@over(name=SEEDS, lang=LANGS)
def test_a_sum_opens_with_a_positive_term(name: str, lang: str) -> None:
    """No printed sum in a coordinate or on an equation's side starts with "−" while it holds
    a "+" term: a teacher writes R_wheel + r − R, never −R + R_wheel + r."""
    bad = [s for s in _sums(rendered(name, lang)) if _plus_at_top(s)]
    assert not bad, bad[:3]


def test_the_bicycle_crank_axle() -> None:
    """C5-E.6, the reader's points, four languages (the symbol R_wheel as each names it)."""
    wheel = {"en": "R_wheel", "es": "R_rueda", "ca": "R_roda", "eu": "R_gurpila"}
    sep = {"en": ", ", "es": "; ", "ca": "; ", "eu": "; "}
    for lang in LANGS:
        md = rendered("seed_c5_e6_bicycle", lang)
        w, s = wheel[lang], sep[lang]
        assert f"(b{s}{w} + r − R)" in md, lang
        assert f"(b{s}{w} + r − L − R)" in md, lang


def test_the_printer_writes_positive_terms_first() -> None:
    """−R + R_w + r reads R_w + r − R, in Unicode and in LaTeX; a sum of negative terms keeps
    its order, and the positive terms keep sympy's order among themselves."""
    R, Rw, r, L, a, b = sympy.symbols("R R_w r L a b")
    assert unicode_formula(-R + Rw + r) == "R_w + r − R"
    assert unicode_formula(-L - R + Rw + r) == "R_w + r − L − R"
    assert unicode_formula(r - R) == "r − R"
    assert unicode_formula(-a - b) == "−a − b"
    assert written_latex(-R + Rw + r) == "R_{w} + r - R"
