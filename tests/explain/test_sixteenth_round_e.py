"""Issue 30, sixteenth round (e): what a Catalan and Basque teacher read on main (158f758).
Each test is a rule over the 19 seeds in the languages where it applies, and fails on that
output: ω_central, ω_plat, ω_rodaR written with nothing saying which body they are; one body
under two names (suport semicilíndric / semicilindre, terra cilíndric / cilindre fix, roda C1 /
roda posterior esquerra); "trobat més amunt" for a centre the CIR section placed; Basque
"(erlojuaren orratzen aurka)" beside "(erlojuaren orratzen noranzkoan)"."""
from __future__ import annotations

import re

import pytest

from .helpers import SEEDS, explained, rendered, over

LANGS = ("en", "es", "ca", "eu")
LEGEND = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
SMALL = {"de", "del", "d", "of", "the", "el", "la", "l", "les", "els", "los", "las"}


def _shortened(label: str, name: str) -> bool:
    """By hand: the subscript drops a word of the body's name (central of *roda central*,
    plat of *plat amb els pedals*, rodaR of *roda de radi R*), not counting the article,
    "de"/"of", an ordinal's dot or a Basque article -a; a code the name holds (N of *bloc N*)
    is the slides' own and is not shortened."""
    words = [w.rstrip(".").lower() for w in re.split(r"[\s’']+", name) if w]
    words = [w for w in words if w not in SMALL]
    if label in name.split():                 # a code the name holds, or the name's one word
        return len(words) > 1 and not re.fullmatch(r"[A-Z][A-Z0-9]{0,3}", label)
    text = label.lower().replace(" ", "")
    return any(w not in text and w.rstrip("a") not in text for w in words)


@over(name=SEEDS, lang=LANGS)
def test_a_shortened_subscript_is_said(name: str, lang: str) -> None:
    """A page writing ω_X where X drops words of the body's name (ω_central for the *roda
    central*, ω_plat for the *plat amb els pedals*, ω_rodaR for the *roda de radi R*) says once
    which body X is; a subscript that is the name's words run together (politja1) needs no
    saying."""
    sol, doc = explained(name)
    spelt = sol.model.wording.bodies.get(lang, {})
    page = rendered(name, lang, "md", drawings=False)
    legend = next((ln for ln in page.splitlines() if ln.startswith(LEGEND[lang])), "")
    for body, label in _labels(name, lang).items():
        if body not in spelt or label.isdigit() or not _shortened(label, spelt[body]):
            continue
        sym = f"ω_{{{label}}}" if " " in label else f"ω_{label}"
        if not re.search(re.escape(sym) + r"(?![\w{])", page):
            continue
        assert sym in legend, (name, lang, sym, spelt[body])


def _labels(name: str, lang: str) -> dict[str, str]:
    sol, doc = explained(name)
    order = sorted(doc.numbers, key=lambda b: doc.numbers[b])
    return sol.model.wording.labels(order, lang, tuple(getattr(doc, "parameters", ())))


def test_the_shortened_subscripts_the_reader_named_are_said() -> None:
    """The reader's own cases, each by hand."""
    for name, sym in (("seed_c5_1_4_epicyclic", "ω_central"), ("seed_c5_e2_gear_change", "ω_central"),
                      ("seed_c5_e6_bicycle", "ω_plat")):   # C5-E.5's ω_rodaR: its wheel is the notes' *roda R*
                                                            # since the twenty-seventh round (e), the label its name
        page = rendered(name, "ca", "md", drawings=False)
        assert any(ln.startswith("Notació: ") and sym in ln for ln in page.splitlines()), (name, sym)


# one body, one name: the words the model's own text (title, points, parameters, data, notes)
# uses for a body the page names otherwise
TWO_NAMES = {("seed_c5_1_7_semicylinder", "ca"): "semicilindre",
             ("seed_c5_1_7_semicylinder", "es"): "semicilindro",
             ("seed_c5_1_7_semicylinder", "eu"): "erdizilindro",
             ("seed_c5_1_8_contact_points", "ca"): "cilindre fix",
             ("seed_c5_2_1_tricycle", "ca"): "roda posterior esquerra",
             ("seed_c5_2_1_tricycle", "es"): "rueda trasera izquierda",
             ("seed_c5_2_1_tricycle", "en"): "rear left wheel",
             ("seed_c5_2_1_tricycle", "eu"): "atzeko ezkerreko gurpilaren"}


@pytest.mark.parametrize(("name", "lang"), sorted(TWO_NAMES))
def test_one_name_per_body(name: str, lang: str) -> None:
    """The semicylinder the structure calls *suport semicilíndric* is not also "semicilindre"
    (C5-1.7), C5-1.8's *terra cilíndric* not also "cilindre fix", C5-2.1's wheel "roda C1" not
    also "roda posterior esquerra" unless beside its name."""
    page = rendered(name, lang, "md", drawings=False)
    other = TWO_NAMES[(name, lang)]
    text = page.replace("roda C1 (posterior esquerra)", "").replace("rueda C1 (trasera izquierda)", "")
    assert not re.search(rf"(?<![\w]){re.escape(other)}(?!\w)", text, re.I), (name, lang, other)


ABOVE = {"ca": ("més amunt",), "es": ("hallado arriba",), "en": ("placed above", "found above"),
         "eu": ("goian aurkitu", "gorago aurkitu")}


@over(name=SEEDS, lang=LANGS)
def test_a_centre_at_rest_names_where_it_was_found(name: str, lang: str) -> None:
    """"I_rodeta1, trobat més amunt, no té velocitat" (C5-1.1, 1.2, 1.3, 1.4, E.3, E.4): the
    step names the section that placed the centre, «Centres instantanis de rotació (CIR)»."""
    page = rendered(name, lang, "md", drawings=False)
    for line in page.splitlines():
        if "= 0." in line and ("I_" in line):
            assert not any(w in line for w in ABOVE[lang]), (name, lang, line)


@over(name=SEEDS)
def test_basque_senses_are_a_pair(name: str) -> None:
    """Basque writes a rate's sense as "(erlojuaren orratzen aurkako noranzkoan)" beside
    "(erlojuaren orratzen noranzkoan)", never the bare "(erlojuaren orratzen aurka)"."""
    page = rendered(name, "eu", "md", drawings=False)
    assert "orratzen aurka)" not in page, name
