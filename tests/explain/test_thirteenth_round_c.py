"""Issue 30, thirteenth round (c): what a Catalan and Basque teacher still edited on main's
pages, each a rule checked over the seeds and the four languages where it applies:

1. each side of a rigid-body relation v_B = v_A + v_BA is one body's: both points carry that
   body (or none, a body's own centre or a fixed pivot), the rolling contact's equality said
   apart (v_F∈R = v_F∈N, then each point from its own body, as the slides write it);
2. a placed centre said plainly, never "I_politja ≡ I";
3. no sentence said twice on a page (two rules writing one thing);
4. a centre's step reads ω at the point the centres section placed it by;
5. the geometric contact point's place on the line of centres as a fraction (OJ/OC = 2/3);
6. a symbolic page's figures label vectors by name, never by a number;
7. a body named by the model's name (Basque "arrabola", not "gurpil");
8. the drag's witness on a guide said as the notes say it (the foot J′ of the perpendicular).
"""
from __future__ import annotations

import re

import pytest

from kinematika.explain.document import Equation

from .helpers import LANGS, SEEDS, explained, rendered, words_of, over


def _body(sym_sub: str) -> str:
    return sym_sub.split("∈")[1] if "∈" in sym_sub else ""


# ---- 1. one body per side ---------------------------------------------------------------

def _rigid_sides(eq: Equation):
    """The sides of an equation that are one rigid-body relation: a point term, then the
    rotation (normal and tangential) terms of one body, nothing else."""
    for side in eq.sides:
        points = [t for t in side if t.kind == "point"]
        turns = [t for t in side if t.kind in ("rotation", "normal", "tangential") and t.how]
        if len(points) == 1 and turns and len(points) + len(turns) == len(side):
            bodies = {x.sub for t in turns for x in t.how if getattr(x, "base", "") in ("ω", "α")}
            if len(bodies) == 1:
                yield [eq.target] + points, bodies.pop()


@over(name=SEEDS)
def test_each_side_of_a_rigid_relation_is_one_bodys(name):
    """v_B = v_A + ω_b × AB: a point written with a body (B∈x) is a point of b itself. By
    hand from the notes (slides 4.4, C5-1.4): v_F∈R = v_F∈N at the contact, then v_F∈R =
    v_A + v_FA — never v_Q∈ring = v_K∈sun + v_QK, whose terms belong to three bodies."""
    sol, doc = explained(name)
    # bodies pinned together at a point share it for good: the twenty-first round (e) writes
    # one label there (v_{B∈N} in the rocker's relation, "v_{B∈N} is the velocity of both")
    pinned = {(j.at, frozenset((j.a, j.b))) for j in sol.model.joints if j.type == "revolute"}
    for eq in doc.equations():
        for points, body in _rigid_sides(eq):
            for t in points:
                owner = _body(t.sym.sub)
                point = t.sym.sub.split("∈")[0]
                assert owner in ("", body) or (point, frozenset((owner, body))) in pinned, (name, t.sym.sub, body)


def test_the_epicyclic_planet_by_hand():
    """C5-1.4, step 5: the planet 2 touches the sun at K and the ring at S (the contacts J, K,
    N, Q, S, U: M is the equations' mark, fourteenth round (b)); since round 27b it is found as
    planet 1 is, from the carrier and the ring: its centre between A2 and S, then its ω at S,
    each term a point of the planet: v_S∈rodeta2 = v_I_rodeta2 + v_S,I_rodeta2, with the
    contact equality said in the contact's sentence; never v_S∈corona = v_K∈central + …."""
    ca = rendered("seed_c5_1_4_epicyclic", "ca", "md", drawings=False)
    assert "v_{S∈rodeta2}  =  v_{I_{rodeta2}}  +  v_{SI_{rodeta2}}" in ca
    assert "v_{S∈rodeta2} = v_{S∈corona}." in ca
    assert "v_{S∈corona}  =  v_{K∈central}" not in ca


@pytest.mark.parametrize("name, lang, equation", [
    ("seed_c5_e2_gear_change", "ca", "v_{N∈corona}  =  v_O  +  v_NO"),
    ("seed_c5_1_1_pulley_on_cable", "ca", "v_{J∈tram1}  =  v_G1  +  v_JG1"),
    ("seed_001_rolling_pair", "en", "v_{F∈R}  =  v_A  +  v_FA"),
    ("seed_c5_e1_cavity", "ca", "v_C  =  v_O  +    v_CO"),
    ("seed_c5_e1_cavity", "ca", "a_C  =  a_O  +   a_CO^n   +    a_CO^t"),     # |α_OC|·OC above it (round 29a)
])
def test_the_teachers_equations_by_hand(name, lang, equation):
    """The equations the teacher rewrote: C5-E.2's ring from M (ω_ring × OM: M of the ring),
    C5-1.1's strand from G1, 001's roller from A, C5-E.1's bar about its fixed pivot O (v_O,
    not v_O∈OC: the wheels' point at O keeps its body)."""
    assert equation in rendered(name, lang, "md", drawings=False)


# ---- 2. a placed centre said plainly ----------------------------------------------------

@over(name=SEEDS, lang=LANGS)
def test_no_centre_is_said_with_an_equivalence_sign(name, lang):
    """"El CIR I_politja ≡ I" read as notation to decode: the centre's symbol and the point's
    name are said in words (… és el punt I)."""
    assert "≡" not in rendered(name, lang, "md", drawings=False)


def test_the_pulleys_centre_sentence():
    ca = rendered("seed_c5_1_1_pulley_on_cable", "ca", "md", drawings=False)
    assert "I_{politja}, trobat a «Centres instantanis de rotació (CIR)», no té velocitat: v_{I_{politja}} = 0." in ca   # one symbol (round 15a)


# ---- 3. said once -----------------------------------------------------------------------

LEVELS = {"v": ("## Velocities", "## Velocidades", "## Velocitats", "## Abiadurak"),
          "a": ("## Accelerations", "## Aceleraciones", "## Acceleracions", "## Azelerazioak")}
COMPOSITION = ("## Composition of motions", "## Composición de movimientos", "## Composició de moviments",
               "## Mugimenduen konposizioa")
GIVEN = ("Given:", "Dato:", "Dada:", "Datua:")
RUN = 16


def _sentences(page: str) -> list[tuple[str, str]]:
    """(section heading, sentence) of the page's prose: not its equations, tables, lists,
    captions or figure definitions."""
    page = re.sub(r"^\[fig-\d+\]: .*$", "", page, flags=re.M)
    page = re.sub(r"```.*?```", "", page, flags=re.S)
    out, heading = [], ""
    for para in re.split(r"\n\s*\n", page):
        para = para.strip()
        if para.startswith("## "):
            heading = para
        if not para or para[0] in "|#!-" or (para.startswith("*") and para.endswith("*")):
            continue                    # tables, headings, figures, lists, captions
        # a datum's lead ("Datua: *gurpila* …", "Given: A moves …") stays with its sentence (round 29a)
        out += [(heading, s) for s in re.split(r"(?<=[.:;])(?<!Given:)(?<!Dato:)(?<!Dada:)(?<!Datua:)\s+(?=[A-ZÀ-Ý*])", para)]
    return out


def _level(heading: str) -> str:
    return next((k for k, titles in LEVELS.items() if heading in titles), "")


def _names(s: str) -> set:
    """The names a sentence speaks of: bodies (*…*) and points (C1, F)."""
    return set(re.findall(r"\*[^*]+\*|\b[A-Z][A-Z0-9′]*\b", s))


def _same_thing(a: str, b: str) -> bool:
    """Whether a and b say one thing: the same words, or a run of `RUN` words about the
    same names (one's names among the other's) — not two sentences of one pattern about two
    points (C1 is at a from O …, C2 is at a from O …)."""
    if a == b:
        return True
    na, nb = _names(a), _names(b)
    if not (na <= nb or nb <= na):
        return False
    wa, wb = a.split(), b.split()
    runs = {tuple(wa[i:i + RUN]) for i in range(len(wa) - RUN + 1)}
    return any(tuple(wb[i:i + RUN]) in runs for i in range(len(wb) - RUN + 1))


def repeats(page: str) -> list[tuple[str, str]]:
    """The sentences of ≥ 8 words said twice on a page (the same words, or half a sentence
    about the same things), but for what a reader expects twice: each level said on its own,
    as the notes work them (a step of the accelerations saying again what its body does, the
    composition's relative motion for v then a); a datum recalled in the step that uses it
    ("Given: …"), never a sentence of the Data said again (a pin held at this instant)."""
    found = []
    units = [(h, s) for h, s in _sentences(page) if len(s.split()) >= 8]
    for i, (h1, s1) in enumerate(units):
        for h2, s2 in units[i + 1:]:
            if not _same_thing(s1, s2):
                continue
            if {_level(h1), _level(h2)} == {"v", "a"} or (h1 == h2 and h1 in COMPOSITION):
                continue                # each level on its own
            if s1.startswith(GIVEN):
                continue                # the datum recalled where it is used, by its symbol
            # (a datum's sentence in the Data and again in a step is a repeat: fourteenth round c,
            # C5-2.1's held steering)
            found.append((s1, s2))
    return found


@over(name=SEEDS, lang=LANGS)
def test_no_sentence_is_said_twice(name, lang):
    """C5-2.1 placed the chassis' centre in step 1 and again, word for word, in the centres
    section; the check fails on that page as main wrote it (`test_the_check_finds_the_old_repeat`)."""
    assert repeats(rendered(name, lang, "md", drawings=False)) == [], name


def test_the_check_finds_the_old_repeat():
    """The tricycle's paragraph as main printed it twice (the teacher's copy, ca)."""
    old = ("## Velocitats\n\nEl CIR del *xassís* és a la perpendicular al pla de la roda C1 pel punt C1 (el "
           "seu eix: la roda no llisca lateralment) i a la perpendicular a v_F pel punt F; es tallen a "
           "I_xassís = (0; L).\n\n## Centres instantanis de rotació (CIR)\n\nI_xassís: és a la perpendicular "
           "al pla de la roda C1 pel punt C1 (el seu eix: la roda no llisca lateralment) i a la perpendicular "
           "a v_F pel punt F; aquestes rectes es tallen a (0; L).\n")
    assert repeats(old)


@pytest.mark.parametrize("lang", LANGS)
def test_the_fixed_strand_is_said_fixed_once(lang):
    """C5-1.5: the statement gives strand 1 tied to the ceiling (a datum); that it is welded
    to the ceiling, part of the fixed body, is the structure's rule, said once."""
    text = rendered("seed_c5_1_5_pulley_block", lang, "md", drawings=False)
    welded = {"en": "is fixed to the", "es": "está fijado al", "ca": "és fix al", "eu": "zurrunki lotuta"}[lang]   # round a: no weld words
    prose = "\n".join(s for _, s in _sentences(text))
    assert prose.count(welded) == 1, prose.count(welded)


# ---- 4. the centre's point is the step's point ------------------------------------------

@pytest.mark.parametrize("lang", LANGS)
def test_the_upper_wheels_step_uses_the_centres_point(lang):
    """C5-E.4: I_upper is placed by U and by N (on the left wheel: the contacts J, K, N, Q, M
    being the equations' mark), not by its mirror Q. Since round 27b the step finds ω_upper as
    the accelerations do, seen from the chassis, and P's velocity follows from U's,
    v_P = v_U + v_PU = 0: neither v_NP nor v_QP is written."""
    text = rendered("seed_c5_e4_upper_wheel", lang, "md", drawings=False)
    centres = text.split("\n## ")[[s.split("\n")[0] for s in text.split("\n## ")].index(
        {"en": "Instant centres", "es": "Centros instantáneos de rotación (CIR)",
         "ca": "Centres instantanis de rotació (CIR)", "eu": "Biraketa-zentro instantaneoak"}[lang])]
    assert " N " in centres and " Q " not in centres
    assert re.search(r"v_P  =  v_U  \+ +v_PU", text)
    assert "v_QP" not in text and "v_NP" not in text


# ---- 5. the fraction ----------------------------------------------------------------------

@pytest.mark.parametrize("lang", LANGS)
def test_the_geometric_points_fraction(lang):
    """C5-1.8 by hand from the model: the wheel (radius r, centre C at (0, 3r)) touches the
    cylinder (radius 2r, centre O) at J = (0, 2r): OJ = 2r, OC = 3r, so J^geom stays at
    OJ/OC = 2/3 (the notes' "a 2/3 d'OC des d'O"), the radii's ratio at every instant."""
    text = rendered("seed_c5_1_8_contact_points", lang, "md", drawings=False)
    assert "OJ/OC = 2/3" in text
    assert not any(w in text for w in ("same fraction", "misma fracción", "mateixa fracció", "zati berean"))


# ---- 6. symbolic figures name their vectors -----------------------------------------------

# a vector's label set to a number (v_P = 4,03, v_P ≈ 4,03); a point at rest's "v_I = 0" is exact
NUMBER_LABEL = re.compile(r"\b[va]_?[A-Z]\w* (?:=|≈) −?(?:[1-9]\d*(?:[.,]\d+)?|0[.,]\d+)")


@over(name=SEEDS, lang=LANGS)
def test_symbolic_figures_label_no_vector_by_a_number(name, lang):
    """C5-E.6: "vP = 4,03" on a page whose data are symbols; the figures' labels are the
    vectors' names (their values are formulas the text gives)."""
    sol, doc = explained(name)
    if not doc.symbolic:
        return
    figures = words_of(rendered(name, lang, "md"))
    labels = "\n".join(re.findall(r"<!--(.*?)-->", figures, flags=re.S)) + figures
    assert not NUMBER_LABEL.search(labels.replace("\u2009", " ")), NUMBER_LABEL.search(labels)


# ---- 7. the model's names ----------------------------------------------------------------

@over(name=SEEDS)
def test_basque_names_the_rolling_body_by_its_name(name):
    """001: the roller R (arrabola) rolls on the lever's edge: "ardatzak *R arrabolaren* A
    zentroan", never "gurpilaren" for a body the model does not call gurpil."""
    text = rendered(name, "eu", "md", drawings=False)
    assert "ardatzak gurpilaren" not in text
    if name == "seed_001_rolling_pair":
        assert "ardatzak *R arrabolaren* A zentroan definituz" in text


# ---- 8. the foot of the perpendicular ----------------------------------------------------

@pytest.mark.parametrize("lang", LANGS)
def test_the_sleeves_drag_is_said_at_the_foot(lang):
    """C5-1.3: the notes' statement: at the foot J′ of the perpendicular from the pivot to
    the guide, v_REL ∥ guide and the drag ⊥ JJ′; no long bracket of the bar's point."""
    text = rendered("seed_c5_1_3_bar_in_sleeve", lang, "md", drawings=False)
    assert "J′" in text
    long_bracket = {"en": "its foot on the guide is a point of the bar",
                    "es": "su pie sobre la guía es un punto de la barra",
                    "ca": "el seu peu sobre la guia és un punt de la barra",
                    "eu": "oina gidan"}[lang]
    assert long_bracket not in text

