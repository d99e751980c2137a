"""Issue 30, sixteenth round (b): what the readers still marked, each a rule checked over the
seeds and the four languages where it applies:

1. the composition's relative motion is one symbol (the notes' v_REL), its frame said in
   words, never "v_REL,E = v_{Q∈bar rel support}": two names of one vector in a row;
2. a relative motion a later section uses that no step wrote (001's rolling pair:
   a_{F∈R rel N}), where a step found its reverse, is derived where first used:
   a_{F∈R rel N} = −a_{F∈N rel R} = (value), naming the step;
3. a contact point's velocity is written once, as the material point's (C5-1.5: never
   v_T1 = v_{T1∈pulley1}; the strand's points then have v_T2 = v_{T1∈pulley1});
4. the steps follow the order of the asked quantities where the dependencies allow (C5-E.4
   asks the left wheel first: its step comes before the right wheel's).
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over, model_tree

COMPOSITION = {"en": "## Composition of motions", "es": "## Composición de movimientos",
               "ca": "## Composició de moviments", "eu": "## Mugimenduen konposizioa"}


def _composition(text: str, lang: str) -> str:
    """The composition section of a page ('' when it has none)."""
    start = text.find(COMPOSITION[lang])
    if start < 0:
        return ""
    end = text.find("\n## ", start + 3)
    return text[start:end if end > 0 else len(text)]


# ---- 1. one symbol for the relative motion --------------------------------------------------

# v_{rel,E} (v_{REL,E}) written equal to another symbol: v_{REL,E} = v_{Q∈barra rel. suport}
REL_RENAMED = re.compile(r"[va]_\{(?:REL|rel),[^}]+\} = [va]_[{A-Za-z]")


@over(name=SEEDS, lang=LANGS)
def test_relative_motion_is_one_symbol(name, lang):
    """C5-1.3 (ca): "Relatiu: …, v_{REL,E} = v_{E∈barra rel suport}" and "v_{REL,E} =
    v_{Q∈barra rel. suport} = (…)" named one vector twice; the notes write v_REL only."""
    text = rendered(name, lang, "md", drawings=False)
    assert not REL_RENAMED.search(text), REL_RENAMED.search(text).group(0)


# the relative motion under the steps' one symbol, both bodies named (round 19a: the
# composition's point-only v_{rel,E} was a second name of the steps' vector)
FRAME_SAID = {"en": "Relative: v_{E∈bar rel support}, the motion seen from the moving frame, the *support*:",
              "ca": "Relatiu: v_{E∈barra rel suport}, el moviment vist des de la referència mòbil, el *suport*:",
              "eu": "Erlatiboa: v_{E∈barra rel euskarria}, *euskarria* erreferentzia mugikorretik ikusten den "
                    "mugimendua:"}
FRAME_SYM = {"en": "v_{E∈bar rel support}", "ca": "v_{E∈barra rel suport}", "eu": "v_{E∈barra rel euskarria}"}


@pytest.mark.parametrize("lang", sorted(FRAME_SAID))
def test_relative_motion_says_its_frame_in_words(lang):
    text = rendered("seed_c5_1_3_bar_in_sleeve", lang, "md", drawings=False)
    assert FRAME_SAID[lang] in text
    # the slider's relative motion read off Step 2 by its value, under the one symbol
    sym = FRAME_SYM[lang]
    assert f"{sym} = (−4{',' if lang != 'en' else '.'}364" in text


# ---- 2. a reversed relative motion derived where first used ---------------------------------

# a relative motion of a point of one body seen from another: a_{F∈R rel N} (ca: rel.)
RELATIVE_SYM = re.compile(r"[va]_\{[^{}∈ ]+∈[^{}]+ rel\.? [^{}]+\}")


@over(name=SEEDS, lang=LANGS)
def test_composition_relative_terms_are_derived_before_use(name, lang):
    """Every relative motion the composition's equations use is written before the
    composition (a step) or derived in it before the equation that uses it: 001's
    rolling pair used a_{F∈R rel N} = (1.667, −2.887) with no line deriving it."""
    text = rendered(name, lang, "md", drawings=False)
    comp = _composition(text, lang)
    if not comp:
        return
    before = text[:text.find(comp)]
    for block in re.finditer(r"```\n(.*?)```", comp, re.S):
        prior = before + comp[:block.start()]
        for sym in set(RELATIVE_SYM.findall(block.group(1))):
            line = re.compile(re.escape(sym) + r" = ")
            assert sym in before or line.search(comp[:block.start()]), (sym, prior[-300:])


def _vector(s: str, lang: str) -> tuple[float, float]:
    sep = "; " if lang != "en" else ", "
    x, y = s.strip("()").split(sep)
    conv = (lambda t: float(t.replace("−", "-").replace(",", "."))) if lang != "en" else \
        (lambda t: float(t.replace("−", "-")))
    return conv(x), conv(y)


@pytest.mark.parametrize("lang", LANGS)
def test_rolling_pair_reverse_is_derived_from_its_step(lang):
    """a_{F∈R rel N} = −a_{F∈N rel R} = (value): the reverse of Step 3's term, with the step
    named. By hand: F rolls without slipping, v_{F∈R rel N} = 0, so the Coriolis terms vanish
    and a_{F∈R rel N} = a_{F∈R} − a_{F∈N}, read here off the contact section's a_{F∈R} and
    a_{F∈N}: the value the line states is that difference."""
    text = rendered("seed_001_rolling_pair", lang, "md", drawings=False)
    rel = "rel "             # the slides' word in every language (notation.relative, round 19a)
    comp = _composition(text, lang)
    sym = f"a_{{F∈R {rel}N}}"
    line = re.search(re.escape(f"{sym} = −a_{{F∈N {rel}R}} = ") + r"(\([^)]*\))[^\n]*3", comp)
    assert line is not None
    used = next(m.start() for m in re.finditer(r"```\n(.*?)```", comp, re.S) if sym in m.group(1))
    assert line.start() < used                          # said where it is first used, before
    stated = _vector(line.group(1), lang)
    f_r = _vector(re.search(r"- a_\{F∈R\} = (\([^)]*\))", text).group(1), lang)
    f_n = _vector(re.search(r"- a_\{F∈N\} = (\([^)]*\))", text).group(1), lang)
    assert stated == pytest.approx((f_r[0] - f_n[0], f_r[1] - f_n[1]), abs=2e-3)


# ---- 3. a contact point's velocity written once -----------------------------------------------

# v_T1 = v_{T1∈pulley1}: a point's bare label equated with the same point of a body
TRIVIAL = re.compile(r"\bv_([A-Z][A-Za-z0-9]*) = v_\{\1∈")


@over(name=SEEDS, lang=LANGS)
def test_no_contact_point_equated_with_its_material_point(name, lang):
    text = rendered(name, lang, "md", drawings=False)
    assert not TRIVIAL.search(text), TRIVIAL.search(text).group(0)


def test_pulley_block_strand_has_the_material_points_velocity():
    """C5-1.5, the notes: the velocity ↓2v of pulley 1's point "is transmitted to all the
    points of the second strand"."""
    text = rendered("seed_c5_1_5_pulley_block", "en", "md", drawings=False)
    assert "v_T2 = v_{T1∈pulley1} = (0, −2·v)" in text
    assert "v_T4 = v_{T3∈pulley2} = (0, 2·v)" in text
    assert "at the contact T1 both material points have the same velocity." in text


# ---- 4. the steps in the order of the asked quantities ----------------------------------------

def _names(lang: str) -> dict:
    data = model_tree("seed_c5_e4_upper_wheel")
    return data["names"][lang]["bodies"]


@pytest.mark.parametrize("lang", LANGS)
def test_upper_wheel_steps_follow_the_asked_order(lang):
    """C5-E.4 asks ω of the left wheel (wheel1), then of the right (wheel2); both are found
    from the chassis alone: the left wheel's step comes first, in the order of solution and
    in each level."""
    text = rendered("seed_c5_e4_upper_wheel", lang, "md", drawings=False)
    names = _names(lang)
    left, right = names["wheel1"].split()[-1], names["wheel2"].split()[-1]
    left, right = (names["wheel1"], names["wheel2"]) if lang in ("en", "eu") else (left, right)
    heads = [line for line in text.splitlines() if line.startswith("### ") or re.match(r"^\d\. ", line)]
    order = [("L" if left in h else "R") for h in heads if (left in h) != (right in h)]
    assert order and order == ["L", "R"] * (len(order) // 2), heads
