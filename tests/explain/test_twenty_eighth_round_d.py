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


# ---- 2. a translating body: it translates, ω = 0 --------------------------------------------------------------
OMEGA_ZERO = {"en": "so the *chassis* translates relative to the *ground* (ω_chassis = 0): every point has the velocity "
                    "v_A1; its instant centre is at infinity, in the direction perpendicular to v_A1.",
              "es": "así que el *chasis* se traslada respecto del *suelo* (ω_chasis = 0)",
              "ca": "de manera que el *xassís* es trasllada respecte del *terra* (ω_xassís = 0)",
              "eu": "beraz, *txasisa* traslatzen da *lurrarekiko* (ω_txasisa = 0)"}
S1 = {"en": "so the *chassis S1* translates: every point has the velocity (r·ω, 0).\n\nω_S1 = 0 (it translates)",
      "es": "así que el *chasis S1* se traslada: todos sus puntos tienen la velocidad (r·ω; 0).\n\nω_S1 = 0 (se traslada)",
      "ca": "de manera que el *xassís S1* es trasllada: tots els seus punts tenen la velocitat (r·ω; 0).\n\n"
            "ω_S1 = 0 (es trasllada)",
      "eu": "beraz, *S1 txasisa* traslatzen da: puntu guztiek (r·ω; 0) abiadura dute.\n\nω_S1 = 0 (traslatzen da)"}
AT_INFINITY_PERPENDICULAR = {"en": re.compile(r"at infinity, perpendicular to")}


@over(name=SEEDS, lang=LANGS)
def test_d2_a_translating_body_says_omega_zero(name: str, lang: str) -> None:
    """A body whose points all have one velocity translates, ω = 0 (the notes: "es trasllada");
    a point at infinity is "in the direction perpendicular to v", never "perpendicular to v"."""
    page = plain_page(name, lang)
    if lang in AT_INFINITY_PERPENDICULAR:
        assert not AT_INFINITY_PERPENDICULAR[lang].search(page)
    if name == "seed_c5_e4_upper_wheel":
        # A1 and A2 are the centres of wheels rolling on the ground at one speed: v_A1 = v_A2
        assert OMEGA_ZERO[lang] in page
    if name == "seed_c5_2_2_articulated":
        # C1 and C2 turn at ω about their contacts, each at r above it: v_C1 = v_C2 = (rω, 0);
        # the step finds v_O from it, and S1's centre is asked nowhere
        assert S1[lang] in page
