"""Issue 30, twenty-first round (a): catalogue wording (docs/explain.md, "Twenty-first
round (a)").

- an asked ℜ is a radius of curvature, not a curvature (the notes: "el seu radi de
  curvatura", ℜ_T(P));
- the drag is defined once, in the composition section's intro: the later lines say
  "Drag:" alone;
- a rolling body's contact point is its CIR in the plain word order ("su punto de contacto
  K1", ca "el punt de contacte K1 n'és el CIR");
- Catalan "díade" (DIEC, TERMCAT), "perpendicularment a la recta que l'uneix amb"; Basque
  "Coriolis terminoak", as "termino" everywhere else on the pages;
- the M/D legend names only the letters that are a point of the page (C5-1.1 D, C5-2.1 M,
  C5-E.5 D), never a body (001's guide M).
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, explained, over, rendered

# the answers' label of an asked ℜ, per language
RADIUS = {"en": "radius of curvature of the path", "es": "radio de curvatura de la trayectoria",
          "ca": "radi de curvatura de la trajectòria", "eu": "ibilbidearen kurbadura-erradioa"}
BARE = {"en": r"(?<!radius of )curvature of the path", "es": r"(?<!radio de )curvatura de la trayectoria",
        "ca": r"(?<!radi de )curvatura de la trajectòria", "eu": r"ibilbidearen kurbadura(?!-)"}
DRAG = {"en": "Drag:", "es": "Arrastre:", "ca": "Arrossegament:", "eu": "Arrastrea:"}
CONTACT = {"en": "its contact point", "es": "su punto de contacto", "ca": "el punt de contacte", "eu": "kontaktuko"}
# the sentence after the legend (twenty-fourth round (e): its own sentence, not an aside)
LEGEND = {"en": ("it is not the point", "they are not the points M and D"),
          "es": ("no es el punto", "no son los puntos M y D"),
          "ca": ("no és el punt", "no són els punts M i D"),
          "eu": ("ez da [MD] puntua", "ez dira M eta D puntuak")}


@over(name=SEEDS, lang=LANGS)
def test_an_asked_radius_is_called_a_radius(name, lang):
    """ℜ_P is the radius of curvature: every answer line giving ℜ says so, none says bare
    "curvature" (C5-1.7, 1.8, E.1, E.6 read "curvature of the path of P … ℜ_P = 8·R")."""
    md = rendered(name, lang)
    for line in md.splitlines():
        if "ℜ_" in line and re.match(r"^(\||- )", line):
            assert RADIUS[lang] in line, line
            assert not re.search(BARE[lang], line), line


@over(name=SEEDS, lang=LANGS)
def test_the_drag_is_defined_once(name, lang):
    """The composition intro defines the drag (the motion of the coinciding point of the
    moving frame); the drag lines before v and a say only "Drag:"."""
    md = rendered(name, lang)
    coincide = {"en": "moving frame that coincides with it", "es": "referencia móvil que coincide con él",
                "ca": "referència mòbil que coincideix amb ell",
                "eu": "erreferentzia mugikorrean puntuarekin bat datorren"}[lang]
    for line in md.splitlines():
        if line.endswith(DRAG[lang]):        # "Velocities. Drag:" (twenty-fourth round (c))
            assert re.fullmatch(r"\w+\. " + DRAG[lang], line.strip()), line
    assert md.count(coincide) <= 1, md.count(coincide)         # one composition section, one intro


@over(name=SEEDS, lang=LANGS)
def test_a_rolling_contact_is_its_centre_in_plain_words(name, lang):
    """C5-1.2's K1/K2 and C5-E.6's J: "su punto de contacto K1 es su CIR" (not "su punto K1
    del contacto"), ca "el punt de contacte K1 n'és el CIR" (not "el seu … el seu")."""
    md = rendered(name, lang)
    assert "del contacto es su CIR" not in md
    assert not re.search(r"el seu punt de contacte \w+ és el seu CIR", md)
    assert not re.search(r"its point \w+ at the contact", md)
    for line in md.splitlines():
        if re.search(r"(CIR|instant centre|biraketa-zentro instantaneoa da), (de modo que|de manera que|so|beraz):?$", line):
            assert CONTACT[lang] in line, line


@over(name=SEEDS, lang=("ca", "eu"))
def test_catalan_and_basque_words(name, lang):
    """ca: "díade" (singular; "díades" plural), "perpendicularment a la recta que l'uneix amb";
    eu: "Coriolis terminoak", never "gaiak"."""
    md = rendered(name, lang)
    if lang == "ca":
        assert not re.search(r"\bdíada\b", md)
        assert "perpendicular a la seva recta" not in md
    else:
        assert "Coriolis gaiak" not in md


def test_the_catalan_vehicle_centre_sentence():
    """C5-2.1 (ca): every point of the chassis moves perpendicular to the line joining it to
    the centre."""
    assert "es mou perpendicularment a la recta que l’uneix amb I_" in rendered("seed_c5_2_1_tricycle", "ca")


def test_the_catalan_title_says_diade():
    assert "díade moguda pels dos extrems" in rendered("seed_001_r_pairs", "ca")


@over(name=SEEDS, lang=LANGS)
def test_the_marks_legend_names_only_its_points(name, lang):
    """The legend's "it is not the point(s) …" names exactly the model's points (or contacts)
    called M or D (C5-1.1's and C5-E.5's D, C5-2.1's M until the twenty-eighth round (b): no
    seed names one now); 001's guide M is a body, so no clause."""
    sol, doc = explained(name)
    md = rendered(name, lang)
    points = set(sol.model.points) | set(doc.joints.values())
    points |= set(re.findall(r"^\| ([A-Z][A-Za-z0-9]*) \|", md, flags=re.M))       # the points tables
    clash = [m for m in ("M", "D") if m in points]
    one, both = LEGEND[lang]
    if len(clash) == 2:
        assert both in md
    elif len(clash) == 1:
        assert re.search(rf"{one} ?{clash[0]}\b" if lang != "eu" else rf"ez da {clash[0]} puntua", md), clash
        assert both not in md
    else:
        assert not re.search(one, md) and both not in md


def test_the_guide_m_is_no_point_in_the_legend():
    """001's prismatic pair: M is the guide (a body); the legend names no point."""
    for lang in LANGS:
        md = rendered("seed_001_p_pair_coriolis", lang)
        assert not re.search(LEGEND[lang][0], md) and LEGEND[lang][1] not in md
