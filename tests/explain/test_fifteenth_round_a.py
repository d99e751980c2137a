"""Issue 30, fifteenth round (a): what a strict English and Spanish teacher still marked on
main's pages, each a rule checked over the seeds and the four languages where it applies:

1. a centre placed as a point of no body is one symbol throughout: "I_pulley, found above,
   has no velocity: v_{I_pulley} = 0", never "the instant centre I_pulley … is the point I";
2. a centre from a rate found through a drive names the rate before the route: "from
   ω_chainring (found in Step 3 through the *chain*)", never "from the angular velocity found
   in Step 3 through the *chain*", which reads as if the centre lay on the chain;
3. Spanish: a body rolling without slipping "gira sin deslizar sobre …", never "La rueda
   rueda sin deslizar" (the verb doubles the noun); the Catalan "la roda rodola" is two words;
4. Spanish writes the sine sen: sen(β) in the text (HTML, Markdown), LaTeX and the figures'
   labels; Catalan and Basque keep sin (their notes write no trigonometric function);
5. C5-E.4: the notes ask for the wheels' angular velocities: the right wheel's is asked
   (the model's `ask`), derived by its own equation and answered;
6. a witness's perpendicular that is a wheel's axle itself is said once, inside the axle's
   words in the centre's sentence (C5-2.2), never as a sentence of its own before it;
7. a velocity given on one body at a pin, used as another body's: the pin common to both
   said first, v_{F∈chassis} = v_{F∈fork} (C5-2.1).
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

# ---- 1. one symbol for a placed centre ----------------------------------------------------

FOUND = {"en": "placed in “Instant centres”, has no velocity",
         "es": "hallado en «Centros instantáneos de rotación (CIR)», no tiene velocidad",
         "ca": "trobat a «Centres instantanis de rotació (CIR)», no té velocitat", "eu": "zentroak ez du abiadurarik"}


@over(name=SEEDS, lang=LANGS)
def test_a_placed_centre_is_never_renamed_i(name, lang):
    """The pulley's centre was "I_pulley … is the point I: v_I = 0" (two symbols for one
    point): no point I stands on a page beside a centre's symbol, and the equations start at
    v_{I_body}."""
    page = rendered(name, lang, "md", drawings=False)
    assert not re.search(r"\bv_I\b|\bv_I ", page)
    assert not re.search(r"(point|punto|punt|puntua) I\b", page)


@pytest.mark.parametrize("lang", LANGS)
def test_the_pulleys_centre_is_said_once_by_its_symbol(lang):
    """C5-1.1: the sentence names the centre by its symbol once, and the first equation
    starts there."""
    page = rendered("seed_c5_1_1_pulley_on_cable", lang, "md", drawings=False)
    line = next(ln for ln in page.splitlines() if FOUND[lang] in ln)
    centre = re.search(r"I_\{(\w+)\}", line).group(0)         # I_{pulley} (twenty-seventh round (g))
    assert line.endswith(f"v_{{{centre}}} = 0.")
    assert line.count("I_") == 2
    # columns as wide as their marks (eu's worded "norab" on a page with a point D: round 16f)
    assert re.search(rf"v_C +=  v_\{{{re.escape(centre)}\}} +\+", page)


# ---- 2. the rate named before the route it was found by -----------------------------------

OLD_RATE = {"en": "from the angular velocity found", "es": "a partir de la velocidad angular hallada",
            "ca": "a partir de la velocitat angular trobada", "eu": "aurkitutako abiadura angeluarretik"}
NEW_RATE = {"en": r"from (ω\S*) \(found [^)]*\): it lies on",
            "es": r"a partir de (ω\S*) \(hallada [^)]*\): está en",
            "ca": r"a partir de (ω\S*) \(trobada [^)]*\): és a",
            "eu": r"(ω\S*) abiadura angeluarretik \([^)]*aurkitua\): "}


@over(name=SEEDS, lang=LANGS)
def test_a_centre_from_a_rate_names_the_rate_first(name, lang):
    """C5-1.6, E.5, E.6: the rate is named, its route in brackets, and it is the rate the
    distance |v_Q| / |ω| divides by."""
    page = rendered(name, lang, "md", drawings=False)
    assert OLD_RATE[lang] not in page
    for m in re.finditer(NEW_RATE[lang] + r".*?\| / \|(ω\S*)\|", page):
        assert m.group(1) == m.group(2)


@pytest.mark.parametrize("lang", LANGS)
def test_the_chainrings_centre_from_its_rate(lang):
    """C5-E.6: the chainring's centre is found from ω of the chainring, by the chain."""
    page = rendered("seed_c5_e6_bicycle", lang, "md", drawings=False)
    assert len(re.findall(NEW_RATE[lang], page)) >= 1


# ---- 3. Spanish: gira sin deslizar ---------------------------------------------------------

@over(name=SEEDS)
def test_spanish_never_says_the_wheel_turns(name):
    """Reversed by the twentieth round (b): the readers want the textbook's verb for a wheel
    too, "La rueda rueda sin deslizar", "Las ruedas ruedan sin deslizar"; never "gira(n)"."""
    page = rendered(name, "es", "md", drawings=False)
    assert not re.search(r"\bgiran? sin deslizar", page)


def test_spanish_the_wheel_turns_without_slipping_on_the_ground():
    """C5-E.5: the left wheel on the ground, in the words the teacher asked for."""
    page = rendered("seed_c5_e5_unequal_wheels", "es", "md", drawings=False)
    assert re.search(r"\*rueda [^*]+\* rueda sin deslizar sobre el \*suelo\*", page)


# ---- 4. Spanish sen ------------------------------------------------------------------------

@pytest.mark.parametrize("fmt", ("md", "html"))
@pytest.mark.parametrize("name", SEEDS)
def test_spanish_writes_the_sine_sen(name, fmt):
    """001's rolling pair read "(ρ/sin(β); 0)" and "(cos(β); sin(β))" in Spanish."""
    page = rendered(name, "es", fmt, drawings=False)
    assert not re.search(r"(?<![\w\\])sin\(", page)


def test_the_rolling_pairs_sines_in_each_language():
    """The roller's centre (ρ/sen β, 0) and the lever's direction (cos β, sen β): sen in
    Spanish only; the other languages keep sin."""
    assert rendered("seed_001_rolling_pair", "es", "md", drawings=False).count("sen(β)") == 2
    for lang in ("en", "ca", "eu"):
        page = rendered("seed_001_rolling_pair", lang, "md", drawings=False)
        assert page.count("sin(β)") == 2 and "sen(" not in page


def test_the_sine_is_renamed_only_as_a_call():
    """A symbol or another function spelt with sin (asin, sinh) is never renamed; the
    figures' labels and LaTeX write \\operatorname{sen}, which mathtext sets."""
    import sympy

    from kinematika.draw.names import formula, settable
    from kinematika.numerals import function_names

    assert function_names("asin(x) + sin(x)·sinh(y)", "es") == "asin(x) + sen(x)·sinh(y)"
    assert function_names("sin(x)", "ca") == "sin(x)"
    assert function_names(r"\sin{\left(x \right)} + \sinh{x}", "es", latex=True) \
        == r"\operatorname{sen}{\left(x \right)} + \sinh{x}"
    beta, r = sympy.symbols("beta r")
    label = formula(r * sympy.sin(beta), 1.0, "es")
    assert "operatorname{sen}" in label and settable(label)
    assert r"\sin" in formula(r * sympy.sin(beta), 1.0, "eu")


# ---- 5. C5-E.4: the right wheel's ω --------------------------------------------------------

# the wheels' short indices, declared in the notation line (twenty-seventh round (g))
RIGHT = {"en": "wheel2", "es": "rueda2", "ca": "roda2", "eu": "gurpila2"}
LEFT = {"en": "wheel1", "es": "rueda1", "ca": "roda1", "eu": "gurpila1"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_right_wheels_rate_is_derived_and_answered(lang):
    """By hand: the chassis translates with v_U = (−v, 0), so v_A2 = (−v, 0); the right wheel
    (radius R) rolls on the ground at K below A2: v_A2 = ω × KA2 = (−ω·R, 0), ω = v/R
    (counter-clockwise), from its own equation at K, and in the answers after the left wheel's."""
    page = rendered("seed_c5_e4_upper_wheel", lang, "md", drawings=False)
    right, left = f"ω_{RIGHT[lang]}", f"ω_{LEFT[lang]}"
    # its x component (twenty-fifth round d), the arm KA2 = (0, R) written first (twenty-eighth round d)
    assert re.search(rf"KA2 = \(0[,;] R\); [^:]+: v_A2K = −{right}·R ⇒ {right} = v/R", page)
    # with its sense, positive: counter-clockwise (twenty-eighth round d)
    assert page.index(f"| {left} | v/R (") < page.index(f"| {right} | v/R (")


# ---- 6. the axle that is the witness's perpendicular, said once ----------------------------

OWN_AXLE = {"en": "is the axle of wheel", "es": "es el propio eje", "ca": "és l’eix mateix", "eu": "ardatza bera da"}
ALSO = {"en": "perpendicular to v_P through P", "es": "perpendicular a v_P por P",
        "ca": "perpendicular a v_P per P", "eu": "P puntuan v_P abiadurarekiko perpendikularra"}


@over(name=SEEDS, lang=LANGS)
def test_no_sentence_says_the_axle_is_the_perpendicular_apart(name, lang):
    """C5-2.2 read "The perpendicular to v_P through P is the axle of wheel C3 itself: the
    second line is the perpendicular to v_O through O." and then the centre's sentence named
    both lines again."""
    assert OWN_AXLE[lang] not in rendered(name, lang, "md", drawings=False)


@pytest.mark.parametrize("lang", LANGS)
def test_the_articulated_chassis_centre_names_the_axle_once(lang):
    """C5-2.2: the trailing chassis's centre lies on C3's axle (which is also the
    perpendicular to v_P through P) and on the perpendicular to v_O through O: said once."""
    page = rendered("seed_c5_2_2_articulated", lang, "md", drawings=False)
    assert page.count(ALSO[lang]) == 1
    line = next(ln for ln in page.splitlines() if ALSO[lang] in ln)
    assert "I_{S2} = (0" in line and "v_O" in line


# ---- 7. the pin common to the two bodies ----------------------------------------------------

# one point of the two pinned bodies, one label: v_{F∈fork}, the given one (twenty-first round (e))
SHARED = {"en": "v_{F∈fork} is the velocity of both.", "es": "v_{F∈horquilla} es la velocidad de ambos.",
          "ca": "v_{F∈forquilla} és la velocitat de tots dos.", "eu": "v_{F∈furka} bien abiadura da."}


@pytest.mark.parametrize("lang", LANGS)
def test_the_tricycles_pin_carries_the_given_velocity(lang):
    """C5-2.1 gives v_{F∈fork} only; the chassis's equation starts from that point, F, the pin
    common to the fork and the chassis, said before the equation that uses it."""
    page = rendered("seed_c5_2_1_tricycle", lang, "md", drawings=False)
    chassis = SHARED[lang].split(" ")[0]
    said = page.index(SHARED[lang])
    assert said < page.index(f"{chassis}  =")


@over(name=SEEDS, lang=LANGS)
def test_a_point_of_a_body_used_is_given_or_said(name, lang):
    """Every "Given: v_{P∈a}" whose P starts an equation as v_{P∈b} (another body) has the
    equality v_{P∈b} = v_{P∈a} said on the page."""
    page = rendered(name, lang, "md", drawings=False)
    for m in re.finditer(r"Given: (v_\{(\w+)∈[^}]+\})|Dado: (v_\{(\w+)∈[^}]+\})", page):
        given, point = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        for other in set(re.findall(rf"^(v_\{{{point}∈[^}}]+\}})  =", page, re.M)) - {given}:
            assert f"{other} = {given}" in page
