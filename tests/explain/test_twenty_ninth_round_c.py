"""Issue 30, twenty-ninth round (c): equations and derivations as the notes write them, as the
sixth reading's four teachers read them (/work/audit_s_{en,es,ca,eu}/report.md).

1. A rolling wheel's centre alone on a straight path is written term by term, a_A = a_A^t (its
   marks per term: ? over it, ⊥ AG under it), never with a product α × GA as an equation's term.
2. A rolling contact's reversed relative acceleration says only why: no slip, v_rel = 0, no
   Coriolis term; never the general 2 (ω_R − ω_N) × v_rel, beyond the course.
3. A symbolic centre of curvature whose coordinates are past reading is said from its point
   ("ℜ_P above P"); a radius a length the page found shortens is written with it (C5-E.6:
   d = CI_chainring = R·R_wheel/r, ℜ_P = (d − L)²/L, the notes' form).
4. Every arrow of a velocity polygon that is a term of its equation is labelled, the blue ones
   from the pole too (001 p_pair: o→b∈M and o→b∈N).
5. C5-1.8's α_OC = 0: C runs on the circle of radius OC = 3r about O at the constant speed rω₀.
6. A belt's or chain's run gets no rate (the notes give it none); C5-1.6's fixed pulley is
   listed with its 0.
7. The joints table gives a guide's direction in words ("J slides along a horizontal line",
   "… at 45° to the horizontal", "along PO"), never "J ∥ (1, 0)".
"""
from __future__ import annotations

import math
import re

import sympy

from .helpers import LANGS, SEEDS, explained, over, plain_page


def _blocks(page: str) -> list[list[str]]:
    """The fenced equation blocks of a page, each as its lines."""
    return [b.strip("\n").splitlines() for b in re.findall(r"```\n(.*?)```", page, flags=re.S)]


# ---- 1. a_A = a_A^t, term by term --------------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_c1_no_equation_has_a_product_as_a_term(name: str, lang: str) -> None:
    """The symbol row of every M/D/? equation (its middle line) writes symbols only: a cross
    product stands in the term's list, never as a term (C5-E.4–E.6 wrote a_A = α_wheelR × GA)."""
    for block in _blocks(plain_page(name, lang)):
        if len(block) == 3 and "=" in block[1]:
            assert "×" not in block[1], (name, block)


ALONE = {"seed_c5_e5_unequal_wheels": ("A", "G"), "seed_c5_e6_bicycle": ("H", "G"), "seed_c5_e4_upper_wheel": ("A1", "J")}


@over(name=tuple(ALONE), lang=LANGS)
def test_c1_the_centre_is_its_tangential_part(name: str, lang: str) -> None:
    """The centre C of a wheel rolling on the fixed ground moves on a straight line: a_C = a_C^t,
    perpendicular to the radius to the contact J (so ⊥ CJ under it), its magnitude unknown (α is
    what the step finds: ?)."""
    centre, contact = ALONE[name]
    sup = "T" if lang == "eu" else "t"
    page = plain_page(name, lang)
    found = [b for b in _blocks(page) if len(b) == 3 and re.fullmatch(rf"a_{centre}\s+=\s+a_{centre}\^{sup}", b[1].strip())]
    assert found, name
    marks, under = found[0][0].split(), found[0][2].split()
    assert marks[-1] == "?" and under[-2:] == ["⊥", f"{centre}{contact}"], found[0]
    assert f"a_{centre} = a_{centre}^{sup} = α_" in page      # its sentence: tangential alone


# ---- 2. no slip: no Coriolis term, the reverse -------------------------------------------------------------
WHY = {"en": "No slip: v_{F∈R rel N} = 0, so there is no Coriolis term and a_{F∈R rel N} = −a_{F∈N rel R} = ",
       "es": "Sin deslizamiento: v_{F∈R rel N} = 0, así que no hay término de Coriolis y a_{F∈R rel N} = −a_{F∈N rel R} = ",
       "ca": "Sense lliscament: v_{F∈R rel N} = 0, de manera que no hi ha terme de Coriolis i a_{F∈R rel N} = "
             "−a_{F∈N rel R} = ",
       "eu": "Irristadurarik ez: v_{F∈R rel N} = 0; beraz, ez dago Coriolisen terminorik, eta a_{F∈R rel N} = "
             "−a_{F∈N rel R} = "}


@over(lang=LANGS)
def test_c2_the_reverse_says_only_why(lang: str) -> None:
    page = plain_page("seed_001_rolling_pair", lang)
    assert WHY[lang] in page
    assert "(ω_R − ω_N) ×" not in page


# ---- 3. the centre of curvature from its point; ℜ with d -------------------------------------------------
ABOVE = {"en": "is ℜ_P above P.", "es": "está a ℜ_P por encima de P.", "ca": "és a ℜ_P per sobre de P.",
         "eu": "kurbadura-zentroa P puntuaren gainetik ℜ_P distantziara dago."}
WHEEL = {"en": "R_wheel", "es": "R_rueda", "ca": "R_roda", "eu": "R_gurpila"}
CHAINRING = {"en": "chainring", "es": "plato", "ca": "plat", "eu": "platera"}


def test_c3_the_notes_form_of_the_radius_is_the_radius() -> None:
    """Independently: v_P = (r/R)(v/R_w)(d − L) with d = R_w·R/r and aⁿ = L((r/R)v/R_w)² give
    ℜ = v_P²/aⁿ = (d − L)²/L, which is the (R·R_w − L·r)²/(L·r²) the page derives."""
    R, r, Rw, L, v = sympy.symbols("R r R_w L v", positive=True)
    d = Rw * R / r
    vp, an = (r / R) * (v / Rw) * (d - L), L * ((r / R) * v / Rw) ** 2
    assert sympy.simplify(vp ** 2 / an - (d - L) ** 2 / L) == 0
    assert sympy.simplify((R * Rw - L * r) ** 2 / (L * r ** 2) - (d - L) ** 2 / L) == 0


@over(lang=LANGS)
def test_c3_the_bicycle_curvature_as_the_notes_write_it(lang: str) -> None:
    """C5-E.6: P is below C moving forward, its normal acceleration (the crank's L·ω²) points up
    to C: the centre of curvature is ℜ_P above P — never its long coordinates; and ℜ_P is also
    written with d, the chainring's instant-centre depth the page found."""
    page = plain_page("seed_c5_e6_bicycle", lang)
    assert ABOVE[lang] in page
    assert f"(b, {WHEEL[lang]} + r +" not in page and f"(b; {WHEEL[lang]} + r +" not in page
    assert f"*d* = CI_{{{CHAINRING[lang]}}} = R·{WHEEL[lang]}/r" in page      # d a parameter (italic)
    assert "ℜ_P = (d − L)²/L." in page


@over(name=("seed_c5_e5_unequal_wheels", "seed_c5_1_7_semicylinder"), lang=("en",))
def test_c3_short_coordinates_stay(name: str, lang: str) -> None:
    """A centre whose coordinates read easily keeps them (C5-E.5's (L, r₂·(r₂ − r₁)/r₁))."""
    assert "The centre of curvature of the path of P is at (" in plain_page(name, lang)


# ---- 4. every polygon term labelled -----------------------------------------------------------------------
def test_c4_the_p_pair_velocity_polygon_labels_its_blue_terms() -> None:
    """001 p_pair: v_{B∈N} = v_E + v_BE = v_{B∈M} + v_{B∈N rel M}, with E and A fixed: the arrows
    o→b∈N (v_BE) and o→b∈M (v_{B∈M}) are terms the student reads; each carries a label, and the
    one to b∈N is ω_rocker × EB = 14.11 × |EB| long (the rocker's rate the text finds)."""
    from kinematika.explain.document import Figure

    sol, doc = explained("seed_001_p_pair_coriolis")
    polygons = [b for b in doc.blocks() if isinstance(b, Figure) and b.arrows]
    velocity = polygons[0]
    from_pole = [a for a in velocity.arrows if math.dist(a.start, (0.0, 0.0)) < 1e-12]
    assert len(from_pole) == 2
    assert all(a.label is not None for a in velocity.arrows), [(a.start, a.end, a.label) for a in velocity.arrows]
    subs = sorted(str(a.label.sub) for a in from_pole)
    assert any(s == "BE" for s in subs), subs


# ---- 5. α_OC = 0 as the notes say it ----------------------------------------------------------------------
CONSTANT = {"en": "α_OC = 0 (C runs on the circle of radius OC = 3·r about O at the constant speed v_C = r·ω₀, so "
                  "ω_OC = −ω₀/3 is constant)",
            "es": "α_OC = 0 (C recorre la circunferencia de radio OC = 3·r centrada en O con la celeridad constante "
                  "v_C = r·ω₀, así que ω_OC = −ω₀/3 es constante)",
            "ca": "α_OC = 0 (C recorre la circumferència de radi OC = 3·r centrada a O amb la celeritat constant "
                  "v_C = r·ω₀, de manera que ω_OC = −ω₀/3 és constant)",
            "eu": "α_OC = 0 (C puntuak O zentroko eta OC = 3·r erradioko zirkunferentzia deskribatzen du v_C = r·ω₀ "
                  "abiadura konstantez; beraz, ω_OC = −ω₀/3 konstantea da)"}


@over(lang=LANGS)
def test_c5_the_arm_turns_at_a_constant_rate(lang: str) -> None:
    """C5-1.8: the wheel (radius r) rolls at ω₀ on the fixed cylinder of radius 2r, so its centre
    C is 3r from O and moves at rω₀ (about the contact); Ω = rω₀/3r = ω₀/3, constant."""
    assert CONSTANT[lang] in plain_page("seed_c5_1_8_contact_points", lang)


# ---- 6. no rate for a belt or a chain ---------------------------------------------------------------------
BELT = {"en": ("belt", "fixed pulley"), "es": ("correa", "polea fija"), "ca": ("corretja", "politja fixa"),
        "eu": ("uhala", "polea finkoa")}
CHAIN = {"en": "chain", "es": "cadena", "ca": "cadena", "eu": "katea"}


def _rates(page: str, lang: str) -> str:
    """The page's section of angular velocities (its table of rates)."""
    from kinematika.explain.catalogue import catalogue

    titles = [catalogue(lang).format(k) for k in ("sec-rates_summary", "sec-rates_summary_v")]
    start = max(page.find(f"## {t}\n") for t in titles)
    assert start >= 0
    end = page.find("\n## ", start + 3)
    return page[start:end if end >= 0 else None]


@over(lang=LANGS)
def test_c6_the_belt_has_no_rate(lang: str) -> None:
    belt, fixed = BELT[lang]
    page = plain_page("seed_c5_1_6_belt", lang)
    rates = _rates(page, lang)
    assert f"| *{belt}* |" not in rates
    assert not re.search(r"^ω_\w+ = ω_\w+ \(", page, flags=re.M)          # no ω_belt = ω_arm (…)
    assert re.search(r"^\| \*" + fixed + r"\* \| 0 \|$", rates, flags=re.M), fixed
    assert f"| *{CHAIN[lang]}* |" not in _rates(plain_page("seed_c5_e6_bicycle", lang), lang)


# ---- 7. a guide's direction in words ----------------------------------------------------------------------
GUIDES = {("seed_c5_1_2_bar_on_inclined_wheels", "en"): "| J slides along a horizontal line |",
          ("seed_c5_2_1_tricycle", "en"): "| the wheel at F rolls along (1, 1), at 45° to the horizontal |",
          ("seed_c5_2_2_articulated", "en"): "| the wheel at C3 rolls along PO |",
          ("seed_c5_1_2_bar_on_inclined_wheels", "es"): "| J desliza a lo largo de una recta horizontal |",
          ("seed_c5_2_1_tricycle", "ca"): "| la roda a F rodola segons (1; 1), a 45° de l’horitzontal |",
          ("seed_c5_2_2_articulated", "eu"): "| C3 puntuko gurpila errodatu egiten da; norabidea: PO |"}


@over(name=SEEDS, lang=LANGS)
def test_c7_no_parallel_sign_in_the_joints_table(name: str, lang: str) -> None:
    """A row of the joints table (bodies joined by "–") gives no "∥ (1, 0)": words instead; the
    tricycle's front wheel, along (1, 1), is at atan2(1, 1) = 45° to the horizontal."""
    page = plain_page(name, lang)
    for row in (r for r in page.splitlines() if r.startswith("| ") and " – " in r):
        assert "∥" not in row, row
    if (name, lang) in GUIDES:
        assert GUIDES[(name, lang)] in page
    assert "(a point on a fixed line)" not in page


@over(lang=LANGS)
def test_c7_a_guides_angle_is_its_directions_own(lang: str) -> None:
    """C5-1.3's sleeve guides the bar along (3, −1): its angle to the horizontal is
    atan(−1/3) = −18.43°, the direction's own, never the line's 161.6° (180° − 18.43°) written
    beside the vector (the seventh reading: "(3; −1), a 161,6°" contradicts itself)."""
    page = plain_page("seed_c5_1_3_bar_in_sleeve", lang)
    assert "161" not in page
    assert ("−18.4°" if lang == "en" else "−18,4°") in page

