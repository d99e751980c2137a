"""Issue 30, eighteenth round (a): a relative acceleration written as the reverse of one a
step found (a_{F∈R rel N} = −a_{F∈N rel R}) says why — in general the two differ by
2 (ω_R − ω_N) × v_{F∈R rel N}; they are opposite only because v_{F∈R rel N} = 0 (a rolling
contact), which kills both Coriolis terms."""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

# a_{P∈b rel a} = −a_{P∈a rel b} = (…): the derivation by reversal, in any language
# round 29 c: the sentence may lead with its reason ("No slip: v_rel = 0, so … a_{F∈R rel N} = −a_{F∈N rel R} = …")
REVERSE = re.compile(r"^.*?(a_\{(\S+)∈(\S+) (?:rel\.?) (\S+)\}) = −a_\{\2∈\4 (?:rel\.?) \3\} = .*$", re.M)


@over(name=SEEDS, lang=LANGS)
def test_a_reversed_relative_acceleration_says_why(name: str, lang: str) -> None:
    page = rendered(name, lang)
    for m in REVERSE.finditer(page):
        velocity = "v" + m.group(1)[1:]
        assert f"{velocity} = 0" in m.group(0), (name, lang, m.group(0))
        assert "Coriolis" in m.group(0), (name, lang, m.group(0))


@pytest.mark.parametrize("lang", LANGS)
def test_rolling_pair_reverse_by_hand(lang: str) -> None:
    """001's rolling pair: the roller R rolls on the lever N at F, so v_{F∈R rel N} = 0 and
    the composition's a_{F∈R rel N} is the reverse of Step 3's a_{F∈N rel R}."""
    page = rendered("seed_001_rolling_pair", lang)
    lines = [m.group(0) for m in REVERSE.finditer(page)]
    assert len(lines) == 1, lines
    rel = "rel"              # the slides' word in every language (notation.relative, round 19a)
    assert f"v_{{F∈R {rel} N}} = 0" in lines[0]
