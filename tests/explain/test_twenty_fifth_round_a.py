"""Issue 30, twenty-fifth round (a): four readers' items on main's pages (docs/explain.md,
"Twenty-fifth round (a)").

- "rel" is said where the page writes it, before its first use: the centres' first sentence
  says what two names joined by "rel" mean only where the page writes a centre I_{a rel b}
  (it said it on 14 pages that write none); a page that writes another symbol with "rel"
  (C5-1.6's ω_{politja fixa rel braç}, in step 2, before the centres) defines its first one
  on the notation line under the structure, unless the data's sentence on relative
  quantities (seed 001, C5-1.3) has said it;
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, over, rendered

# the word that joins two bodies in a relative symbol, and the clause of the centres' intro
REL = re.compile(r"_\{[^}]* rel [^}]*\}")
CENTRE_REL = re.compile(r"I_\{[^}]* rel [^}]*\}")
INTRO = {"en": "The symbol I with a body's name", "es": "El símbolo I, con el nombre de un sólido",
         "ca": "El símbol I, amb el nom d’un sòlid", "eu": "I ikurrak, solido baten izenarekin"}
# what says "rel": the data's sentence on relative quantities, or the notation line's clause
TOLD = {"en": ("The notation of a relative quantity names both bodies", "two names joined by “rel”"),
        "es": ("La notación de una magnitud relativa indica los dos sólidos", "dos nombres unidos por «rel»"),
        "ca": ("La notació d’una magnitud relativa indica els dos sòlids", "dos noms units per «rel»"),
        "eu": ("Magnitude erlatibo baten notazioak bi solidoak adierazten ditu", "«rel» hitzaz lotutako bi izen")}


@over(name=SEEDS, lang=LANGS)
def test_rel_is_said_where_written_and_before_its_first_use(name, lang):
    """The centres' intro says the "rel" clause iff the page writes a centre with "rel"; a
    page that writes any symbol with "rel" says what it means on a line at or before the
    first such symbol (the data's sentence, or the notation line), and a page that writes
    none says nothing of "rel"."""
    lines = rendered(name, lang, drawings=False).splitlines()
    intro = next((ln for ln in lines if ln.startswith(INTRO[lang])), None)
    if intro is not None:
        assert ("rel" in intro.replace("relati", "").replace("erlatibo", "")) == \
            any(CENTRE_REL.search(ln) for ln in lines if ln is not intro), intro
    first = next((k for k, ln in enumerate(lines) if REL.search(ln)), None)
    told = [k for k, ln in enumerate(lines) if any(t in ln for t in TOLD[lang])]
    if first is None:
        assert not told, lines[told[0]]
        return
    assert told and told[0] <= first, (lines[first][:120], told)
    assert len(told) == 1, [lines[k][:80] for k in told]


# the intrinsic derivation's opening words, each language
WITH = {"en": "With |v_", "es": "Con |v_", "ca": "Amb |v_", "eu": "izanik, ukitzaile unitarioa"}


@over(name=SEEDS, lang=LANGS)
def test_the_intrinsic_split_is_derived_before_its_bullets(name, lang):
    """The tangential and normal acceleration are worked out (|v|, t = v/|v|, aᵗ = (a · t) t,
    aⁿ = a − aᵗ) in one sentence ending in a colon, just before the split a = aᵗ + aⁿ and its
    bullets, never after them (C5-1.7 read as a repetition of its bullets)."""
    lines = [ln for ln in rendered(name, lang, drawings=False).splitlines() if ln.strip()]
    said = [k for k, ln in enumerate(lines) if WITH[lang] in ln]
    if name == "seed_c5_1_7_semicylinder":
        assert said, "no derivation"
    n, t = ("N", "T") if lang == "eu" else ("n", "t")          # the Basque slides' a^N, a^T (27th round (g))
    for k in said:
        ln = lines[k]
        assert ln.endswith(":") and " t = v_" in ln and f"^{t} = (a_" in ln and " − a_" in ln, ln
        assert lines[k + 1] == "```" and re.search(rf"a_\S+ += +a_\S+\^{t} +\+ +a_\S+\^{n}", lines[k + 3]), lines[k + 1:k + 4]


# the units line, and its word for accelerations
UNITS = {"en": ("Units:", "accelerations"), "es": ("Unidades:", "aceleraciones"),
         "ca": ("Unitats:", "acceleracions"), "eu": ("Unitateak:", "azelerazio")}
ACCEL = re.compile(r"\ba_|α_|m/s²")


@over(name=SEEDS, lang=LANGS)
def test_the_units_line_lists_the_pages_quantities(name, lang):
    """The units line names accelerations only on a page that writes one (C5-1.2, 2.1, 2.2
    ask velocities alone and listed "acceleracions en m/s²")."""
    lines = rendered(name, lang, drawings=False).splitlines()
    units = next((ln for ln in lines if ln.startswith(UNITS[lang][0])), None)
    if units is None:
        return
    rest = "\n".join(ln for ln in lines if ln is not units)
    assert (UNITS[lang][1] in units) == bool(ACCEL.search(rest)), units
