"""Issue 30, twenty-eighth round (d): the solution's sentences, as the fifth reading's four
teachers read them (/work/audit_r_{en,es,ca,eu}/report.md).

1. The sentence that finds an instant centre from two velocities says "the instant centre"
   (es/ca: el CIR, eu: BZIa), never "the centre": the wheels' own centres lie on the same line.
2. A translating body is said to translate with ω = 0, as the notes do; a velocity step says no
   more, a centres' entry puts the centre "at infinity, in the direction perpendicular to v".
3. A rate read off one component of its term ("along x: v_BK = −ω·R ⇒") prints the arm with its
   components first, and the factor is one of them: never a length (I_{planet1}Q, 2r, 6R)
   printed nowhere.
4. The Answers table has no row that answers nothing: the contact's "three coincident points
   | position = (0, 2·r)" goes (the position is the Data's); the points' own rows stay.
5. An asked planar ω or α says its sense in the Answers table when its sign is known (C5-2.1:
   "el valor i sentit de la precessió"); a relative rate the notation writes by a letter of its
   own (C5-2.1's δ̇) is defined in the Notation line, before "δ̇ = 0".
6. C5-2.2's Data say whose spin ω′ is (the wheel C4's) where they first write it, and the
   chassis, not the wheels, are hinged at O.
7. A rolling contact's two relative accelerations: their SUM is the Coriolis expression, as the
   equation writes it (never "they differ by" / "aldea"); the step whose equation has no
   Coriolis term at the contact says why there: v_{F∈N rel R} = 0.
8. C5-1.4: a three-armed carrier is hinged at its centre O, not at a "midpoint".
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


# ---- 3. the length used is printed with its value ------------------------------------------------------------
ALONG = {"en": "along", "es": "según", "ca": "segons", "eu": None}
READ_OFF = {lang: re.compile(r"(?:^|; )(?P<seg>[^\s;]+) = \((?P<x>[^;,]+)[;,] (?P<y>[^)]+)\); "
                             + (rf"{word} (?P<axis>[xy]):" if word else r"(?P<axis>[xy]) norabidean:")
                             + r" [^=]+ = (?P<sign>−?)(?P<rate>[^·\s]+)·(?P<factor>\([^)]+\)|\S+) ⇒")
            for lang, word in ALONG.items()}
ANY_ALONG = {lang: re.compile(rf"{word} [xy]:" if word else r"\b[xy] norabidean:") for lang, word in ALONG.items()}


def _bare(part: str) -> str:
    """A coordinate or a factor without its sign and brackets: −3·r/5 → 3·r/5, (6·R) → 6·R."""
    return part.strip().lstrip("−").removeprefix("(").removesuffix(")")


@over(name=SEEDS, lang=LANGS)
def test_d3_a_component_line_shows_its_length(name: str, lang: str) -> None:
    """Every "along x:" line is read off an arm printed on it: SEG = (x, y); along x: the term =
    ∓rate·|y| (the term rate k × (x, y) has the x component −rate·y and the y component rate·x)."""
    for line in plain_page(name, lang).splitlines():
        if not ANY_ALONG[lang].search(line):
            continue
        m = READ_OFF[lang].search(line)
        assert m, line
        used = m["y"] if m["axis"] == "x" else m["x"]
        assert _bare(m["factor"]) == _bare(used), line
        # the sign: along x, −rate·y; along y, +rate·x
        negative = (m["axis"] == "x") != used.strip().startswith("−")
        assert (m["sign"] == "−") == negative, line


EXPECTED_ALONG = {   # (seed, the line in English), each derived from the arm of the notes' figure
    # C5-1.4: A1 = (0, −2r) moves at 2rω, Q = (0, −3r) at −3rω: the centre is 2r/5 below A1, Q 3r/5 below it
    ("seed_c5_1_4_epicyclic", "I_{planet1}Q = (0, −3·r/5); along x: v_{QI_{planet1}} = ω_planet1·(3·r/5) ⇒ ω_planet1 = −5·ω"),
    # C5-1.1: the pulley's centre C is 2r above its instant centre (the rope's fixed strand)
    ("seed_c5_1_1_pulley_on_cable", "I_{pulley}C = (0, 2·r); along x: v_{CI_{pulley}} = −ω_pulley·(2·r) ⇒ ω_pulley = −v/(2·r)"),
    # C5-E.3: A is 6R above the rod's instant centre (0, −4R): A at (0, 2R)
    ("seed_c5_e3_wheels_with_rod", "I_{rod}A = (0, 6·R); along x: v_{AI_{rod}} = −ω_rod·(6·R) ⇒ ω_rod = −ω/3"),
}


def test_d3_the_three_lines_the_spanish_reader_quoted() -> None:
    """C5-1.1, C5-1.4, C5-E.3: the lengths 2r, 3r/5, 6R are printed where they are used."""
    for name, line in EXPECTED_ALONG:
        assert line in plain_page(name, "en"), (name, line)


# ---- 4. no row that answers nothing --------------------------------------------------------------------------
POSITION = {"en": "position", "es": "posición", "ca": "posició", "eu": "posizioa"}


def _answers(page: str) -> list[str]:
    """The rows of a page's Answers table (the last table of the page)."""
    tail = page[page.rindex("| --- | --- |"):]
    return [ln for ln in tail.splitlines()[1:] if ln.startswith("|")]


CONTACT = {"en": "three coincident points", "es": "tres puntos coincidentes", "ca": "tres punts coincidents",
           "eu": "bat datozen hiru puntuak"}


@over(name=SEEDS, lang=LANGS)
def test_d4_no_answer_is_only_a_position_of_the_data(name: str, lang: str) -> None:
    """No row of the Answers table answers the contact's question with its position alone (an
    instant centre's position is an answer: those rows stay)."""
    rows = [r for r in _answers(plain_page(name, lang))
            if CONTACT[lang] in r.split("|")[1] and re.search(rf"\| {POSITION[lang]} = \([^|]*\) \|$", r)]
    assert not rows, rows


def test_d4_the_contact_points_rows_of_c5_1_8() -> None:
    """C5-1.8 by hand (the notes, corrected: /work/shared/seeds/README.md): the wheel (radius r)
    rolls on the fixed cylinder (radius 2r, centre O) at ω₀ clockwise, J = (0, 2r), C = (0, 3r):
    the cylinder's point is at rest; the wheel's point has v = 0 and a = (2/3)·r·ω₀² towards C
    (up); the geometric point runs on the circle of radius 2r at ω₀/3: v = (2/3)·r·ω₀ and
    a = 2r(ω₀/3)² = (2/9)·r·ω₀² towards O (down). The first six rows, with no row before them."""
    rows = _answers(plain_page("seed_c5_1_8_contact_points", "en"))
    assert rows[:6] == ["| v_{J∈cylinder} | (0, 0) |", "| a_{J∈cylinder} | (0, 0) |", "| v_{J∈wheel} | (0, 0) |",
                        "| a_{J∈wheel} | (0, 2·r·ω₀²/3) |", "| v_{J^{geom}} | (2·r·ω₀/3, 0) |",
                        "| a_{J^{geom}} | (0, −2·r·ω₀²/9) |"], rows


# ---- 5. the precession's sense; δ̇ defined ---------------------------------------------------------------------
CCW = {"en": "counter-clockwise", "es": "antihorario", "ca": "antihorari", "eu": "erlojuaren orratzen aurkako noranzkoan"}
DELTA = {"en": "δ̇ is the angular velocity of the *front fork* relative to the *chassis*",
         "es": "δ̇ es la velocidad angular de la *horquilla delantera* respecto del *chasis*",
         "ca": "δ̇ és la velocitat angular de la *forquilla davantera* respecte del *xassís*",
         "eu": "δ̇ *aurreko furkaren* abiadura angeluarra da *txasisarekiko*"}


@over(name=("seed_c5_2_1_tricycle",), lang=LANGS)
def test_d5_the_precession_with_its_sense(name: str, lang: str) -> None:
    """C5-2.1 by hand: the rear axle's line (x = 0) and the normal to v_F at F = (L, 0), v_F along
    (1, 1), meet at I = (0, L); F is √2·L from I and moves at v₀, so ψ̇ = v₀/(√2·L) = √2·v₀/(2·L),
    positive: counter-clockwise (the tricycle turns to the left). δ̇, the fork's rate relative to
    the chassis, is defined before the line that says it is zero."""
    page = plain_page(name, lang)
    assert f"| ψ̇ | √2·v₀/(2·L) ({CCW[lang]}) |" in page
    assert DELTA[lang] in page
    assert page.index(DELTA[lang]) < page.index("δ̇ = 0")


def test_d5_numeric_rates_with_their_sense() -> None:
    """001_r_pairs (the fifth reading's numbers, by hand): ω_N = −5.5 rad/s turns clockwise,
    ω_P = 2 rad/s counter-clockwise; α_N = 12.25 and α_P = 35 rad/s² are counter-clockwise."""
    rows = _answers(plain_page("seed_001_r_pairs", "en"))
    for row in ("| ω_N | −5.5 rad/s (clockwise) |", "| ω_P | 2 rad/s (counter-clockwise) |",
                "| α_N | 12.25 rad/s² (counter-clockwise) |", "| α_P | 35 rad/s² (counter-clockwise) |"):
        assert row in rows, (row, rows)


@over(name=SEEDS, lang=("en",))
def test_d5_a_rate_of_unknown_sign_says_none(name: str, lang: str) -> None:
    """A formula with a parameter of either sign (C5-E.1's θ̈) has no sense to say; one whose
    parameters are all positive has: never a sense word on a row whose value has no sign."""
    for row in _answers(plain_page(name, lang)):
        m = re.fullmatch(r"\| [ωα]\S* \| (?P<value>[^|(]+?)(?: rad/s²?)? \((?P<sense>(counter-)?clockwise)\) \|", row)
        if m:
            assert m["value"].startswith("−") == (m["sense"] == "clockwise"), row


# ---- 6. C5-2.2: ω′ is C4's spin; the chassis are hinged at O ---------------------------------------------------
WHOSE = {"en": "the wheel C4 of S2", "es": "la rueda C4 de S2", "ca": "la roda C4 de S2", "eu": "S2-ren C4 gurpila"}
HINGED = {"en": "its two chassis, S1 and S2, hinged at O, are identical, and so are its four wheels.",
          "es": "sus dos chasis, S1 y S2, articulados en O, son idénticos, y sus cuatro ruedas también son iguales.",
          "ca": "els dos xassissos, S1 i S2, són idèntics i estan articulats a O, i les quatre rodes són iguals.",
          "eu": "bi txasisak, S1 eta S2, berdinak dira eta O puntuan giltzatuta daude"}


@over(name=("seed_c5_2_2_articulated",), lang=LANGS)
def test_d6_omega_prime_is_said_whose_where_first_written(name: str, lang: str) -> None:
    """C5-2.2 by hand: S2 turns about I_S2 = (0, −√2·a) at rω/(√2·a); C4 is a/2 from it and
    C3 3a/2, so C4 spins at ω/(2√2) (the notes' ω′) and C3 at 3ω/(2√2): the first sentence
    writing ω′ names C4, so no student takes ω′ for both wheels. Since the twenty-ninth round
    (b) that sentence is the Data's, which give no asked value (ω′ = ω/(2√2) is derived in
    Step 1 and recalled in the Note; C3's spin, derived nowhere, is not printed)."""
    page = plain_page(name, lang)
    first = next(ln for ln in page.splitlines() if "ω′" in ln)
    assert WHOSE[lang] in first and "ω′ = ω/(2√2)" not in first and "3ω/(2√2)" not in page, first
    assert HINGED[lang] in page


# ---- 7. the two relative accelerations' sum; no Coriolis term at a rolling contact ----------------------------
# a_{F∈R} = a_{F∈N} + a_{F∈R rel N} + 2 ω_N × v_{F∈R rel N} and a_{F∈N} = a_{F∈R} + a_{F∈N rel R}
# + 2 ω_R × v_{F∈N rel R}, with v_{F∈N rel R} = −v_{F∈R rel N}: adding, the relative accelerations'
# sum is −(the two Coriolis terms) = 2 (ω_R − ω_N) × v_{F∈R rel N}
SUM = {"en": "In general the two relative accelerations are not opposite: their sum is the opposite of the sum of the "
             "two Coriolis terms, a_{F∈R rel N} + a_{F∈N rel R} = ",
       "es": "En general las dos aceleraciones relativas no son opuestas: su suma es la opuesta de la suma de los dos "
             "términos de Coriolis, a_{F∈R rel N} + a_{F∈N rel R} = ",
       "ca": "En general les dues acceleracions relatives no són oposades: la seva suma és l’oposada de la suma dels dos "
             "termes de Coriolis, a_{F∈R rel N} + a_{F∈N rel R} = ",
       "eu": "Oro har, bi azelerazio erlatiboak ez dira aurkakoak: haien batura bi Coriolisen terminoen baturaren "
             "aurkakoa da, a_{F∈R rel N} + a_{F∈N rel R} = "}
DIFFER = ("differ by the Coriolis", "difieren en los términos de Coriolis", "difereixen en els termes de Coriolis",
          "arteko aldea Coriolis")
NO_CORIOLIS = {"en": "there is no Coriolis term, since at a rolling contact the two points have no relative velocity: ",
               "es": "no hay término de Coriolis, porque en un contacto de rodadura los dos puntos no tienen velocidad "
                     "relativa: ",
               "ca": "no hi ha terme de Coriolis, perquè en un contacte de rodolament els dos punts no tenen velocitat "
                     "relativa: ",
               "eu": "ez dago Coriolisen terminorik, errodadura-kontaktu batean bi puntuek ez baitute abiadura "
                     "erlatiborik: "}


@over(name=SEEDS, lang=LANGS)
def test_d7_the_relative_accelerations_sum(name: str, lang: str) -> None:
    """The relative accelerations are never said to "differ by" the Coriolis terms (001_rolling_pair;
    since round 29 c their general sum is not written at a rolling contact at all); and wherever a rolling contact's sentence stands, it gives v_rel = 0."""
    page = plain_page(name, lang)
    assert not [w for w in DIFFER if w in page]
    for line in page.splitlines():
        if NO_CORIOLIS[lang] in line:
            assert re.search(re.escape(NO_CORIOLIS[lang]) + r"v_\{\w+∈\w+ rel \w+\} = 0\.", line), line
    if name == "seed_001_rolling_pair":     # round 29 c: the general sum is beyond the course when v_rel = 0
        assert SUM[lang] not in page and "2 (ω_R − ω_N) × v_{F∈R rel N}" not in page


@over(name=("seed_001_rolling_pair",), lang=LANGS)
def test_d7_step_3_says_why_no_coriolis(name: str, lang: str) -> None:
    """001_rolling_pair, accelerations, Step 3: a_{F∈N} = a_A + a_FA^n + a_FA^t + a_{F∈N rel R} has
    no Coriolis term because the roller rolls on the lever (v_{F∈N rel R} = 0): said in that step,
    before the equation, with the relative velocity written as the equation writes its term."""
    page = plain_page(name, lang)
    equation = page.index("+  a_{F∈N rel R}")
    step = page.rindex("\n### ", 0, equation)          # the step the equation stands in
    assert NO_CORIOLIS[lang] + "v_{F∈N rel R} = 0." in page[step:equation]


# ---- 8. C5-1.4: the carrier's centre ---------------------------------------------------------------------------
CENTRE_O = {"en": "at its centre O", "es": "en su centro O", "ca": "el centre O articulat", "eu": "bere O zentroan"}
MIDPOINT = {"en": "midpoint O", "es": "punto medio O", "ca": "punt mig O", "eu": "O erdiko puntuan"}


@over(name=("seed_c5_1_4_epicyclic",), lang=LANGS)
def test_d8_the_carrier_is_hinged_at_its_centre(name: str, lang: str) -> None:
    """A carrier with three arms has a centre, where the three meet, not a midpoint."""
    page = plain_page(name, lang)
    assert CENTRE_O[lang] in page and MIDPOINT[lang] not in page


def test_d5_a_relative_rate_defined_once() -> None:
    """The fan's ω₂ (the blades relative to the motor block, the model's notation): the Data's
    sentence on relative quantities defines it, so the Notation line does not again."""
    page = plain_page("fan_composition", "en")
    assert page.count("the angular velocity of the *blades* relative to the *motor block*") == 1
