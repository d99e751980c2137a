"""Issue 30, fifteenth round (b): what the Catalan and Basque teacher read on main (6808357).
Each test is a rule over the 19 seeds in the languages where it applies, and fails on that
output: "la velocitat de A1" where Catalan elides (d’A1), …"""
from __future__ import annotations

import re

import pytest

from kinematika.explain.catalogue import VOWEL_LETTERS

from .helpers import SEEDS, explained, rendered


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
