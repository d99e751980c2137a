"""Issue 30, fifteenth round (b): what the Catalan and Basque teacher read on main (6808357).
Each test is a rule over the 19 seeds in the languages where it applies, and fails on that
output: "la velocitat de A1" where Catalan elides (d’A1), and a legend "Notació: ω_politja1 és la
velocitat angular de la politja 1" defining a subscript that is the body's name run together."""
from __future__ import annotations

import re

import pytest

from kinematika.explain.catalogue import VOWEL_LETTERS

from .helpers import SEEDS, explained, rendered, over


def _vowel_points(name: str) -> list[str]:
    """The page's point names read with an initial vowel sound in Catalan (A, E, O4, F, …)."""
    sol, _ = explained(name)
    return [p for p in sol.inst.points if p[:1] in VOWEL_LETTERS]


@pytest.mark.parametrize("name", SEEDS)
def test_catalan_elides_de_before_a_vowel_point(name: str) -> None:
    """Catalan writes d’ before a point name read with a vowel ("la velocitat d’A1", "les
    velocitats d’O, P i C4", "el moviment d’A"): the figure captions' point lists and the
    rolling pair's intro wrote "de A1" (C5-1.4, 1.6, 2.2, E.2, 001_rolling)."""
    page = rendered(name, "ca")
    points = _vowel_points(name)
    if not points:
        pytest.skip("no point read with a vowel")
    alternatives = "|".join(re.escape(p) for p in sorted(points, key=len, reverse=True))
    found = re.findall(rf"\bde (?:{alternatives})(?![\w′'])", page)
    assert not found, (name, found)


LEGEND = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
LEGEND_ENTRY = re.compile(r"ω_(\{[^}]*\}|\S+?)(?= )")


def _spelt_as_written(name: str, lang: str) -> dict[str, str]:
    """Each subscript the legend could define, with the body's name in `lang` it stands for."""
    sol, _ = explained(name)
    return sol.model.wording.bodies.get(lang, {})


def _run_together(label: str, body: str, lang: str) -> bool:
    """By hand: the label is the name's words joined with no space, in any order, an
    ordinal's dot dropped (politja 1 → politja1, 1. polea → polea1:
    every word of the name), a Basque word with its article a; one word of a longer name
    (roda central → central) is shortened and the legend says it (sixteenth round (e))."""
    words = [w.rstrip(".") for w in re.split(r"\s+", re.sub(r"^(?:els|les|el|la|l’|l')\s*", "", body)) if w]
    words += [w + "a" for w in words] if lang == "eu" else []
    # every word of the name (sixteenth round (e): one word of it, central of *roda central*,
    # is a shortened subscript the legend says)
    from itertools import product
    small = {"de", "del", "of", "the"}
    content = [w for w in words[: len(words) // 2 if lang == "eu" else len(words)] if w not in small]
    forms = [(w, w + "a") if lang == "eu" else (w,) for w in content]
    from itertools import permutations
    return any("".join(p) == label for choice in product(*forms) for p in permutations(choice))


@over(name=SEEDS, lang=("en", "es", "ca", "eu"))
def test_no_legend_entry_for_a_subscript_read_off_the_name(name: str, lang: str) -> None:
    """"Notació: ω_politja1 és la velocitat angular de la politja 1; …" (C5-1.4, 1.5, 2.1,
    E.2, E.5, E.6 in every language) is a line a teacher deletes: a subscript that is the
    body's name run together needs no definition. The legend keeps only abbreviations."""
    page = rendered(name, lang, "md", drawings=False)
    spelt = _spelt_as_written(name, lang)
    for line in page.splitlines():
        if not line.startswith(LEGEND[lang]):
            continue
        for label in LEGEND_ENTRY.findall(line):
            label = label.strip("{}")
            assert not any(_run_together(label, body, lang) for body in spelt.values()), (name, lang, label)
