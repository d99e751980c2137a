"""Issue 30, twentieth round (b): words two readers marked on main's pages.

1. Spanish: every body that rolls, a wheel too, "rueda sin deslizar" (plural "ruedan"), the
   textbook's verb: never "la rueda gira sin deslizar" (round 15a's choice, reversed).
2. Spanish: a body welded to the fixed one "está fijado al techo: forma parte de él",
   never "es fijo al techo: es parte de él".
3. The reverse of a relative vector names its quantity: "the reverse of the relative
   acceleration found in Step 3", never "of the relative motion" (four languages).
4. English and Spanish: a vehicle's point "moves perpendicular to the line joining it to
   I_chassis" ("se mueve perpendicularmente a la recta que lo une con"), never "to its line to".
5. Catalan "díade" (DIEC, TERMCAT; plural "díades"), never "díada"; "el punt de contacte K1 n’és el CIR",
   never "el seu punt K1 del contacte" (both revised in the twenty-first round (a)).
6. C5-E.5's R: "radius of the rear wheel (the wheel of radius R)", an apposition in brackets.
7. C5-E.3 (es): "Los apuntes dan el método, pero no números".
8. C5-E.2 (eu): the arm "bertikalean marrazten da", an adverb of manner.
"""
from __future__ import annotations

import re

import pytest

from kinematika.explain.catalogue import catalogue

from .helpers import LANGS, NOTES_SEEDS, over, plain_page

NINETEEN = NOTES_SEEDS      # the notes' nineteen worked examples




def plain(name: str, lang: str) -> str:
    return plain_page(name, lang).replace("*", "")


# ---- 1. Spanish: la rueda rueda sin deslizar ---------------------------------------------------

@over(name=NINETEEN)
def test_spanish_a_wheel_rolls(name):
    text = plain(name, "es")
    assert not re.search(r"\bgiran? sin deslizar", text)


def test_spanish_the_wheels_roll_on_the_planes():
    """The reader's example ("La rueda izquierda gira sin deslizar", C5-1.2's idle line, gone
    since round 27b: the wheels are read off their equations): C5-E.6's front wheel."""
    text = plain("seed_c5_e6_bicycle", "es")
    assert "La rueda delantera rueda sin deslizar sobre el suelo" in text


def test_spanish_plural_wheels_roll():
    """A subject of two wheels takes the plural: "Las ruedas ruedan sin deslizar" (the
    catalogue's COUNT on a name that says a plural)."""
    text = catalogue("es").format("rolling-noslip", {"gear": 0, "b": "Las ruedas", "a": "el suelo", "point": "J"})
    assert text.startswith("Las ruedas ruedan sin deslizar sobre el suelo")


# ---- 2. Spanish: fijado (not "unido rígidamente": thirteenth round (a), no weld words)

@over(name=NINETEEN)
def test_spanish_welded_is_rigidly_joined(name):
    text = plain(name, "es")
    assert not re.search(r"\b(es|son) fij[oa]s? a(l)? ", text)
    assert not re.search(r": (es|son) parte de él", text)


def test_spanish_cable_strand_part_of_the_ceiling():
    assert "El tramo 1 está fijado al techo: forma parte de él" in plain("seed_c5_1_5_pulley_block", "es")


def test_spanish_planes_part_of_the_ground():
    text = plain("seed_c5_1_2_bar_on_inclined_wheels", "es")
    assert "están fijados al suelo: forman parte de él" in text


# ---- 3. the reverse of the relative acceleration ------------------------------------------------

REVERSE = {"en": "the reverse of the relative acceleration found in Step",
           "es": "la opuesta de la aceleración relativa hallada en el paso",
           "ca": "l'oposada de l'acceleració relativa trobada al pas",
           "eu": "urratsean aurkitutako azelerazio erlatiboaren aurkakoa"}
MOTION = {"en": "relative motion found", "es": "movimiento relativo hallado",
          "ca": "moviment relatiu trobat", "eu": "aurkitutako mugimendu erlatibo"}


@over(name=NINETEEN, lang=LANGS)
def test_reverse_names_the_quantity(name, lang):
    assert MOTION[lang] not in plain(name, lang)


@pytest.mark.parametrize("lang", LANGS)
def test_rolling_reverse_is_an_acceleration(lang):
    assert REVERSE[lang] in plain("seed_001_rolling_pair", lang).replace("’", "'")


# ---- 4. perpendicular to the line joining it to I -----------------------------------------------

@pytest.mark.parametrize("name", ["seed_c5_2_1_tricycle", "seed_c5_2_2_articulated"])
def test_vehicle_point_moves_perpendicular_to_the_joining_line(name):
    en, es = plain(name, "en"), plain(name, "es")
    assert "perpendicular to its line to" not in en and "perpendicular a su recta" not in es
    assert re.search(r"moves perpendicular to the line joining it to I_", en)
    assert re.search(r"se mueve perpendicularmente a la recta que lo une con I_", es)


# ---- 5. Catalan díada, punt de contacte ---------------------------------------------------------

@over(name=NINETEEN)
def test_catalan_diada(name):
    text = plain(name, "ca")
    assert not re.search(r"\bdíada\b", text)          # DIEC/TERMCAT "díade" (twenty-first round (a))
    assert not re.search(r"\bpunt \S+ del contacte", text)


def test_catalan_diada_in_a_four_bar():
    assert "díade RRR" in plain("seed_001_r_pairs", "ca")


def test_catalan_contact_point_before_its_name():
    text = plain("seed_c5_1_2_bar_on_inclined_wheels", "ca")
    # twenty-first round (a); the idle line "el punt de contacte K1 n’és el CIR" gone since
    # round 27b, the centres' line says it
    assert re.search(r"el punt de contacte K1 \(rodolament sense lliscament\)", text)


# ---- 6.–8. the example's own words -------------------------------------------------------------

# (twenty-ninth round (d): the wheel is the rear wheel, no longer "wheel R": R is its radius)
RADIUS = {"en": "| radius of the rear wheel |",
          "es": "| radio de la rueda trasera |",
          "ca": "| radi de la roda del darrere |",
          "eu": "| atzeko gurpilaren erradioa |"}


@pytest.mark.parametrize("lang", LANGS)
def test_rear_wheel_radius_in_brackets(lang):
    assert RADIUS[lang] in plain("seed_c5_e5_unequal_wheels", lang)


def test_spanish_method_but_no_numbers():
    text = plain("seed_c5_e3_wheels_with_rod", "es")
    assert "Los apuntes dan el método, pero no números:" in text
    assert "ningún número" not in text


def test_basque_arm_drawn_vertically():
    text = plain("seed_c5_e2_gear_change", "eu")
    assert "besoa bertikalean marrazten da" in text
    assert "bertikal marrazten" not in text


# ---- 10. an absolute instant centre is relative to the ground -----------------------------------

GROUND = {"en": "relative to the *ceiling*", "es": "respecto del *techo*", "ca": "respecte del *sostre*",
          "eu": "*sabaiarekiko*"}     # twenty-seventh round (e): the fixed body's own name, as everywhere
CEILING = {"en": "ground", "es": "suelo", "ca": "terra", "eu": "lurr"}


@pytest.mark.parametrize("name", ["seed_c5_1_1_pulley_on_cable", "seed_c5_1_5_pulley_block"])
@pytest.mark.parametrize("lang", LANGS)
def test_centre_relative_to_the_ground(name, lang):
    """The notes: "El seu CIR respecte al terra" (C5-1.1), though the cable is tied to the
    ceiling: the centre's rows said the ground; since the twenty-seventh round (e) the fixed
    body keeps its own name on the page ("*techo* (fijo)", a page with no floor): the centre's
    rows say the ceiling, never the ground."""
    text = plain_page(name, lang)
    rows = [line for line in text.splitlines() if re.search(r"CIR|instant centre|biraketa-zentro", line)
            and (GROUND[lang] in line or CEILING[lang] in line.lower())]
    centre_rows = [line for line in rows if line.startswith("|")]
    assert centre_rows and all(GROUND[lang] in line for line in centre_rows)
    assert not any(re.search(rf"(CIR|instant centre|zentro instantaneoa)[^.|]*{CEILING[lang]}", line, re.I)
                   for line in rows)


# the quantity a slider's relative motion is, word by word (a word variable goes through
# WORD(): a token would match no key and every line would say "velocity")
QUANTITY = {"en": ("velocity", "acceleration"), "es": ("velocidad", "aceleración"),
            "ca": ("velocitat", "acceleració"), "eu": ("abiadura", "azelerazio")}


@over(lang=LANGS)
def test_a_sliders_relative_motion_names_its_quantity(lang):
    """001 P pair: B's relative velocity and acceleration, each line naming its own quantity."""
    lines = [line for line in plain("seed_001_p_pair_coriolis", lang).splitlines()
             if re.search(r"_\{B∈N \w+\.? M\} =", line) and re.search(r"(B too|también B|també B|B puntuak ere)", line)]   # 29 (b): the body slides, B too
    speed, accel = QUANTITY[lang]
    assert len(lines) == 2, lines
    assert speed in lines[0] and accel not in lines[0], lines[0]
    assert accel in lines[1] and speed not in lines[1], lines[1]


def test_spanish_fixed_participle_agrees_with_a_feminine_name():
    """"La polea 1 está fijada al techo", "El tramo 1 está fijado al techo": the participle
    takes the name's gender from its article; a list takes the masculine."""
    from kinematika.explain.render.base import Slot

    def slot(text: str, n: int = 1) -> Slot:
        s = Slot(text)
        s.plain, s.n_names = text, n
        return s
    cat = catalogue("es")
    said = {name: cat.format("structure-welded", {"bodies": slot(name, n), "bodies_n": n, "frame": slot("el techo")})
            for name, n in (("La polea 1", 1), ("El tramo 1", 1), ("El plano y la guía", 2), ("Las ruedas", 1))}
    assert said["La polea 1"].startswith("La polea 1 está fijada a el techo")
    assert said["El tramo 1"].startswith("El tramo 1 está fijado a el techo")
    assert said["El plano y la guía"].startswith("El plano y la guía están fijados a el techo")
    assert said["Las ruedas"].startswith("Las ruedas están fijadas a el techo: forman parte de él")   # a plural name
