"""Issue 30, nineteenth round (c): notation a reader graded on main (661f5f2). Each test is a
rule over the 19 seeds in the four languages and fails on that output: the notation line
under the structure table defined the shortened subscripts of ω only, so a page writing
v_{J∈cylinder} never said what J∈cylinder is (the point of the cylinder at J)."""
from __future__ import annotations

import re


from .helpers import SEEDS, over, rendered

LANGS = ("en", "es", "ca", "eu")
NOTATION = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
# v_{J∈wheel}: one point, one body, no relative part (those have the Data's own sentence)
MEMBER = re.compile(r"v_\{(\w+)∈([^{}]+?)\}")
# what the line says J∈b is, in each language's words (the point of b at J)
SAYS = {"en": r"is the velocity of the point of (?:the )?\*[^*]+\* at {p}\b",
        "es": r"es la velocidad del punto de.{{0,6}}\*[^*]+\* situado en {p}\b",
        "ca": r"és la velocitat del punt d.{{0,6}}\*[^*]+\* situat a {p}\b",
        "eu": r"\*[^*]+\*(?: solidoaren)? {p} puntuarekin bat datorren puntuaren abiadura da"}   # round 28 e


def _members(page: str, lang: str) -> list:
    """The v_{J∈b} symbols the page writes, relative ones (… rel …) left out."""
    return [m for m in MEMBER.finditer(page) if not re.search(r"\brel\b", m.group(2))]


@over(name=SEEDS, lang=LANGS)
def test_a_point_on_a_body_is_defined_once_under_the_structure(name: str, lang: str) -> None:
    """A page that writes a point's velocity on a body (v_{J∈cylinder}) says once, in the
    notation line under the structure table, that it is the velocity of the cylinder's point
    at J; a page that writes none says nothing of it."""
    page = rendered(name, lang, "md", drawings=False)
    lines = [ln for ln in page.splitlines() if ln.startswith(NOTATION[lang])]
    assert len(lines) <= 1, (name, lang, lines)
    members = _members(page, lang)
    said = _members(lines[0], lang) if lines else []
    if not members:
        assert not said, (name, lang, lines)
        return
    # one, and (twenty-fourth round (e)) one more for each other body whose subscript after ∈
    # is shortened from its name (C5-1.8's v_{J∈cylinder}), never a body twice; the drag's
    # equality v_ar,B = v_B∈M names the first again (twenty-fourth round (c))
    assert said, (name, lang, lines)
    bodies = [d.split("∈", 1)[1] for d in {m.group(0) for m in said}]
    assert len(bodies) == len(set(bodies)), (name, lang, lines)
    first = said[0]
    assert first.group(0) == members[0].group(0), (name, lang, first.group(0), members[0].group(0))
    assert re.search(SAYS[lang].format(p=re.escape(first.group(1))), lines[0]), (name, lang, lines[0])
