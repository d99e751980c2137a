"""Issue 30, twenty-sixth round (a), after the third full reading of stop 46 (docs/explain.md,
"The state at stop 46").

- The Data's sentence on relative quantities defines ω_{b rel a} only where the page writes
  it (`builder.writes_rate`): an English reader met "ω_{N rel M} the angular velocity of the
  block N relative to the guide M" on 001's P pair and "ω_{bar rel support}" on C5-1.3, pages
  that never write either; 001's rolling pair writes ω_{R rel N} and keeps it.
- A rate read off an oblique arm's component writes the arm's components first
  (`context.read_along`: "KS = (√3·r, r); along x: v_SK = −ω·r ⇒", C5-1.4), so the factor
  is read off them: tests/explain/test_twenty_fifth_round_d.py.
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, over, rendered

# the Data's sentence: its defined rate, "ω_{b rel a}" after the velocity it defines
# (twenty-seventh round (e): "the notation of" a relative quantity names them, ca R3)
SENTENCE = {"en": "The notation of a relative quantity names both bodies",
            "es": "La notación de una magnitud relativa indica los dos sólidos",
            "ca": "La notació d’una magnitud relativa indica els dos sòlids",
            "eu": "Magnitude erlatibo baten notazioak bi solidoak adierazten ditu"}
RATE = re.compile(r"ω_\{[^}]* rel [^}]*\}")


@over(name=SEEDS, lang=LANGS)
def test_the_data_defines_a_relative_rate_only_where_the_page_writes_it(name, lang):
    page = rendered(name, lang, drawings=False)
    line = next((l for l in page.splitlines() if l.startswith(SENTENCE[lang])), None)
    if line is None:
        return
    for rate in RATE.findall(line):
        rest = page.replace(line, "")
        assert rate in rest, (rate, line)


def test_the_p_pair_and_the_rolling_pair_by_hand():
    """001's P pair composes B's motion on the guide M, a block that does not turn on it: no
    ω_{N rel M} is written; its rolling pair reads ω_{R rel N} off the roller on the lever."""
    for lang in LANGS:
        pair, rolling = (rendered(n, lang, drawings=False) for n in ("seed_001_p_pair_coriolis", "seed_001_rolling_pair"))
        told = next(l for l in pair.splitlines() if l.startswith(SENTENCE[lang]))
        assert "ω_" not in told and "v_{B∈N rel M}" in told, (lang, told)
        told = next(l for l in rolling.splitlines() if l.startswith(SENTENCE[lang]))
        assert "ω_{R rel N}" in told, (lang, told)
