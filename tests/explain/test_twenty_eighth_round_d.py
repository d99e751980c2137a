"""Issue 30, twenty-eighth round (d): the solution's sentences, as the fifth reading's four
teachers read them (/work/audit_r_{en,es,ca,eu}/report.md).

1. The sentence that finds an instant centre from two velocities says "the instant centre"
   (es/ca: el CIR, eu: BZIa), never "the centre": the wheels' own centres lie on the same line.
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, over, plain_page

# ---- 1. "the instant centre", never "the centre" ------------------------------------------------------------
# the words the sentences finding a centre used for it, and the words the notes use
BARE = {"en": re.compile(r"\b(so the centre (lies|is)|from the centre(?! [A-Z])|the centre is perpendicular|the centre is that of)"),
        "eu": re.compile(r"(beraz, zentroa\b|zentrorainoko distantziarekiko|eta zentroa gidaren|zentroarekin lotzen)"),
        "es": re.compile(r"(así que el centro|distancia al centro\b)"),
        "ca": re.compile(r"(de manera que el centre|distància al centre\b)")}
BETWEEN = {"en": "so the instant centre lies between them", "es": "así que el CIR está entre ambos",
           "ca": "de manera que el CIR és entre tots dos", "eu": "beraz, BZIa bien artean dago"}


@over(name=SEEDS, lang=LANGS)
def test_d1_the_instant_centre_is_named_so(name: str, lang: str) -> None:
    """No sentence placing an instant centre calls it "the centre"."""
    found = BARE[lang].findall(plain_page(name, lang))
    assert not found, found


@over(name=("seed_c5_1_4_epicyclic", "seed_c5_1_5_pulley_block"), lang=LANGS)
def test_d1_between_the_two_points_lies_the_instant_centre(name: str, lang: str) -> None:
    """C5-1.4 (A1 at 2rω, Q at −3rω: the planet's centre 2r/5 from A1) and C5-1.5 (T4 up at 2v,
    C3 down at 2v: r/2 from C3): the opposite senses put the instant centre between them."""
    assert BETWEEN[lang] in plain_page(name, lang)
