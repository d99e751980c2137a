"""Issue 30, twenty-seventh round (e): the explanations' wording, after three teachers read
every seed page in es, ca and eu (docs/explain.md, "Twenty-seventh round (e)").

Each rule is general and checked over the notes' 19 seeds in the four languages where it can
be; the pages the readers quoted are checked by hand beside it.
"""
from __future__ import annotations

import re

import yaml

from .helpers import EXAMPLES, LANGS, SEEDS, over, plain_page, rendered

# the ground's word as the page writes it in italics (Basque declines it: *lurrarekiko*)
GROUND = {"en": r"\*ground\*", "es": r"\*suelo\*", "ca": r"\*terra\*", "eu": r"\*lurr\w*\*"}
FIXED = {"en": "fixed", "es": "fijo", "ca": "fix", "eu": "finkoa"}


def _frame_row(page: str) -> str:
    row = re.search(r"^\| 1 \| .*$", page, flags=re.M)
    assert row, "no structure table"
    return row.group(0)


# -- 1. the fixed body has one name on the page ----------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_a_shapeless_fixed_body_keeps_its_own_name(name: str, lang: str) -> None:
    """A fixed body with no shape of its own (001's *bastidor*, C5-1.1's and C5-1.5's
    ceiling) is "*bastidor* (fijo)" in the structure table and the reference of every
    motion after it ("CIR … respecto del *bastidor*"): never "(fijo: el *suelo*)", which
    reads as two bodies, nor "respecto del *suelo*" on a page with no floor. A fixed body
    named after a part of the ground that carries a shape (C5-1.6's fixed pulley) keeps the
    notes' "respecte al terra" (`structure.ground_part`)."""
    page = plain_page(name, lang)
    row = _frame_row(page)
    ground = (yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text()).get("bodies") or {}).get("ground")
    if isinstance(ground, dict) and any(k in ground for k in ("circle", "line")):
        return                                                   # "*polea fija* (*suelo*)": the ground's part
    assert row.startswith("| 1 | *") and row.split("* ", 1)[1].startswith(f"({FIXED[lang]})"), row
    own = re.match(r"\| 1 \| \*([^*]+)\*", row).group(1)
    if re.fullmatch(GROUND[lang], f"*{own}*"):
        return                                                   # the model calls it the ground
    assert not re.search(GROUND[lang], page), (own, re.findall(GROUND[lang], page)[:3])


def test_the_frame_is_named_as_the_model_names_it_by_hand() -> None:
    """es 001 and C5-1.4 call the frame *bastidor*; C5-1.1's ceiling in four languages."""
    for name in ("seed_001_r_pairs", "seed_001_p_pair_coriolis", "seed_001_rolling_pair", "seed_c5_1_4_epicyclic"):
        assert "| 1 | *bastidor* (fijo) |" in plain_page(name, "es"), name
    assert "CIR del *portasatélites* respecto del *bastidor*" in plain_page("seed_c5_1_4_epicyclic", "es")
    pulley = {"en": ("| 1 | *ceiling* (fixed) |", "instant centre of the *pulley* relative to the *ceiling*"),
              "es": ("| 1 | *techo* (fijo) |", "CIR de la *polea* respecto del *techo*"),
              "ca": ("| 1 | *sostre* (fix) |", "CIR de la *politja* respecte del *sostre*"),
              "eu": ("| 1 | *sabaia* (finkoa) |", "*polearen* biraketa-zentro instantaneoa *sabaiarekiko*")}
    for lang, (row, centre) in pulley.items():
        page = plain_page("seed_c5_1_1_pulley_on_cable", lang)
        assert row in page and centre in page, lang


# -- 2. a point with no velocity at this instant is not at rest ------------------------------------------------------
AT_REST = {"en": "is at rest", "es": "está en reposo", "ca": "és en repòs", "eu": "geldi dago"}


@over(name=SEEDS, lang=LANGS)
def test_no_point_is_said_at_rest(name: str, lang: str) -> None:
    """A point of a moving body whose velocity is zero at this instant is its instant centre,
    not a point at rest: C5-E.4's P has a_P = v²/R (the page's own answer)."""
    assert AT_REST[lang] not in rendered(name, lang)


def test_the_upper_wheels_p_is_its_instant_centre() -> None:
    """C5-E.4 by hand: P = U + (0, R) is the top of the upper wheel; the wheel turns at v/R
    clockwise about it (the chassis carries U at v to the left, P at rest relative to the
    ground), so the figure's only drawn velocity is v_P = 0 and P is the wheel's centre."""
    said = {"en": "P has zero velocity at this instant (it is the instant centre of the upper wheel), written beside it",
            "es": "P tiene velocidad nula en este instante (es el CIR de la rueda superior), escrita a su lado",
            "ca": "P té velocitat nul·la en aquest instant (és el CIR de la roda superior), escrita al costat",
            "eu": "P puntuaren abiadura nulua da une honetan (goiko gurpilaren biraketa-zentro instantaneoa da)"}
    for lang, text in said.items():
        assert text in rendered("seed_c5_e4_upper_wheel", lang), lang


# -- 3. the composition names the quantity, and an equation finds nothing -----------------------------------------------
OLD_DRAG = {"en": "the motion of that point", "es": "el movimiento de ese punto", "ca": "el moviment d’aquest punt",
            "eu": "puntu horren mugimendua"}
OLD_FOUND = {"en": ", which found ", "es": ", que halló ", "ca": ", que va trobar ", "eu": " aurkitu zuena"}


@over(name=SEEDS, lang=LANGS)
def test_the_composition_says_what_it_refers_to(name: str, lang: str) -> None:
    """A drag velocity and a drag acceleration are each named (never "the motion of that
    point" for both); an equation is the one with which a step found something (never an
    equation "which found"); a rolling contact's reverse relative acceleration is derived from
    the relation a_{P∈b rel a} + a_{P∈a rel b} = 2 (ω_b − ω_a) × v_{P∈b rel a}, never from
    itself ("…so the two relative accelerations are opposite")."""
    page = plain_page(name, lang)
    assert OLD_DRAG[lang] not in page and OLD_FOUND[lang] not in page
    assert "relative accelerations are opposite" not in page and "aceleraciones relativas son opuestas" not in page


def test_the_p_pairs_drag_and_the_rolling_pairs_reverse_by_hand() -> None:
    """001's P pair: B's drag is the motion of the guide M's point at B, found in step 1
    (v_{B∈M} = v_A + v_BA there); its rolling pair: F is the contact, v_{F∈R rel N} = 0."""
    drag = {"en": ("the velocity of the point of the *guide M* that coincides with B, found in Step 1.",
                   "the acceleration of the point of the *guide M* that coincides with B, found in Step 1.",
                   "is the equation with which Step 2 found v_{B∈N}."),
            "es": ("la velocidad del punto de la *guía M* que coincide con B, hallada en el paso 1.",
                   "la aceleración del punto de la *guía M* que coincide con B, hallada en el paso 1.",
                   "es la ecuación del paso 2, con la que se halló v_{B∈N}."),
            "ca": ("la velocitat del punt de la *guia M* que coincideix amb B, trobada al pas 1.",
                   "l’acceleració del punt de la *guia M* que coincideix amb B, trobada al pas 1.",
                   "és l’equació del pas 2, amb la qual s’ha trobat v_{B∈N}."),
            "eu": ("*M gidaren* B puntuarekin bat datorren puntuaren abiadura, 1. urratsean aurkitua.",
                   "*M gidaren* B puntuarekin bat datorren puntuaren azelerazioa, 1. urratsean aurkitua.",
                   "Beraz, 2. urratsean v_{B∈N} aurkitzeko erabilitako ekuazioa v_{B∈N} = ")}   # verb last (28 e)
    for lang, texts in drag.items():
        page = plain_page("seed_001_p_pair_coriolis", lang)
        for text in texts:
            assert text in page, (lang, text)
        rolling = plain_page("seed_001_rolling_pair", lang)
        # round 29 c: at a rolling contact only the reason, v_{F∈R rel N} = 0, never the general sum
        assert "a_{F∈R rel N} + a_{F∈N rel R} = 2 (ω_R − ω_N) × v_{F∈R rel N}" not in rolling, lang
        assert "v_{F∈R rel N} = 0" in rolling and "a_{F∈R rel N} = −a_{F∈N rel R} = " in rolling, lang
    assert "con la que se hallaron ω_N y v_{A∈R rel N}" in plain_page("seed_001_rolling_pair", "es")
    assert "amb la qual s’han trobat ω_N i v_{A∈R rel N}" in plain_page("seed_001_rolling_pair", "ca")


# -- 4. a single equation's polygon caption is a sentence ------------------------------------------------------------
OLD_POLYGON = {"en": "its vertices the images of the points", "es": "con los vértices imágenes de los puntos",
               "ca": "amb els vèrtexs imatges dels punts", "eu": "erpinak puntuen irudiak direlarik"}
VERTEX = {"en": "Each vertex is the image of a point.", "es": "Cada vértice es la imagen de un punto.",
          "ca": "Cada vèrtex és la imatge d’un punt.", "eu": "Erpin bakoitza puntu baten irudia da."}


@over(name=SEEDS, lang=LANGS)
def test_a_polygon_caption_is_a_sentence(name: str, lang: str) -> None:
    page = rendered(name, lang)
    assert OLD_POLYGON[lang] not in page
    html = rendered(name, lang, "html", drawings=False)
    assert OLD_POLYGON[lang] not in html


def test_the_sleeves_composition_polygons_by_hand() -> None:
    """C5-1.3's composition of E: v_E = v_{drag,E} + v_{E∈bar rel support}, a_E = a_{drag,E}
    + a_{E∈bar rel support} + a_{Cor,E}; each polygon closes on the sum."""
    sums = {"en": ("and their sum v_E closes it", "and their sum a_E closes it"),
            "es": ("y su suma, v_E, lo cierra", "y su suma, a_E, lo cierra"),
            "ca": ("i la seva suma, v_E, el tanca", "i la seva suma, a_E, el tanca"),
            "eu": ("haien baturak, v_E bektoreak, poligonoa ixten du", "haien baturak, a_E bektoreak, poligonoa ixten du")}
    for lang, (v, a) in sums.items():
        page = rendered("seed_c5_1_3_bar_in_sleeve", lang)
        assert v in page and a in page and page.count(VERTEX[lang]) == 2, lang


# -- 5. a segment is spelt one way; C5-2.2's points are given, not drawn ------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_the_position_section_spells_segments_as_the_page_does(name: str, lang: str) -> None:
    """"C1 is at a distance a from O along OP1": a segment between two labels is the labels
    run together, as in every equation (`context.segment`), never "O–P1" beside "OP"."""
    page = plain_page(name, lang)
    parts = re.split(r"^## ", page, flags=re.M)
    heads = {"en": "Position", "es": "Posición", "ca": "Posició", "eu": "Posizio"}
    for part in parts:
        if part.startswith(heads[lang]):
            assert not re.search(r"\b[A-Z][A-Za-z0-9]*–[A-Z][A-Za-z0-9]*\b", part), part[:300]


def test_the_articulated_vehicles_points_are_given_in_each_chassis_frame() -> None:
    said = {"en": ("the points of each chassis are given in its own frame", "along OP1", "along OP "),
            "es": ("los puntos de cada chasis se dan en su propia referencia", "según OP1", "según OP "),
            "ca": ("els punts de cada xassís es donen en la seva pròpia referència", "OP1", "OP "),
            "eu": ("txasis bakoitzaren puntuak bere erreferentzian ematen dira", "OP1 zuzenean", "OP zuzenean")}
    for lang, texts in said.items():
        page = plain_page("seed_c5_2_2_articulated", lang)
        assert all(t in page for t in texts) and "O–P1" not in page, lang


# -- 6. every page says its degrees of freedom ----------------------------------------------------------------------
DOF = {"en": r"The mechanism has \w+ degrees? of freedom", "es": r"El mecanismo tiene \w+ grados? de libertad",
       "ca": r"El mecanisme té \w+ graus? de llibertat", "eu": r"Mekanismoak .*askatasun-gradu"}


@over(name=SEEDS, lang=LANGS)
def test_every_planar_page_says_its_degrees_of_freedom(name: str, lang: str) -> None:
    assert re.search(DOF[lang], plain_page(name, lang))


def test_the_pulley_blocks_freedoms_by_hand() -> None:
    """C5-1.5: the statement gives v_C1 (down, along the vertical) and v_C3 = (0; −2v) whole,
    its direction the notes' "no pendulum motion"; with that direction the mechanism has two
    degrees of freedom, one a datum (the joints alone leave three: the sixth round)."""
    said = {"en": "The mechanism has two degrees of freedom, one for each datum (v_C1 and v_C3).",
            "es": "El mecanismo tiene dos grados de libertad, uno por cada dato (v_C1 y v_C3)",
            "ca": "El mecanisme té dos graus de llibertat, un per cada dada (v_C1 i v_C3)",
            "eu": "Mekanismoak bi askatasun-gradu ditu, datu bakoitzeko bat (v_C1 eta v_C3)"}
    model = yaml.safe_load((EXAMPLES / "seed_c5_1_5_pulley_block.yaml").read_text())
    assert len(model["drivers"]) == 2
    for lang, text in said.items():
        assert text in plain_page("seed_c5_1_5_pulley_block", lang), lang


# -- 7. wordings: the notation of a relative quantity, distances between centres, units --------------------------------
def test_the_readers_wordings() -> None:
    relative = {"en": "The notation of a relative quantity names both bodies:",
                "es": "La notación de una magnitud relativa indica los dos sólidos:",
                "ca": "La notació d’una magnitud relativa indica els dos sòlids:",
                "eu": "Magnitude erlatibo baten notazioak bi solidoak adierazten ditu:"}
    for lang, text in relative.items():
        assert text in plain_page("seed_001_p_pair_coriolis", lang), lang
    assert "els centres de les rodes són a 4R l’un de l’altre" in plain_page("seed_c5_e3_wheels_with_rod", "ca")
    assert "són a 2√2 R l’un de l’altre" in plain_page("seed_c5_e4_upper_wheel", "ca")   # round 29 (d)
    assert "elkarrengandik 4R-ra" in plain_page("seed_c5_e3_wheels_with_rod", "eu")
    assert "elkarrengandik 2√2 R-ra" in plain_page("seed_c5_e4_upper_wheel", "eu")   # round 29 (d)
    assert "(vegeu la Nota)" in plain_page("seed_c5_2_1_tricycle", "ca")     # the answer in the Note (29 b)
    for lang, text in {"en": "radius 1 m", "es": "radio 1 m", "ca": "radi 1 m", "eu": "1 m-ko erradioko"}.items():
        assert text in plain_page("seed_c5_1_3_bar_in_sleeve", lang), lang
    assert "pren R per al radi del *plat amb els pedals* i r per al del *pinyó*" in plain_page("seed_c5_e6_bicycle", "ca")
    assert "té el *plat amb els pedals* R" not in plain_page("seed_c5_e6_bicycle", "ca")


# -- 8. an order item names the bodies its step went through ---------------------------------------------------------
def test_the_bar_oq_is_found_through_the_wheels() -> None:
    """C5-1.2: I_OQ is where the normals to the planes through the wheels' centres O and Q
    meet (each wheel turns about its contact with its plane), so the bar is found from the
    planes through the wheels, and the order of solution must not skip them (a Catalan
    reader: "a partir del pla esquerre i del pla dret" alone). Since the twenty-seventh round
    (b) the wheels are solved in the bar's own step, so its line names them beside the bar."""
    said = {"en": "1. The *bar OQ*, the *left wheel*, and the *right wheel*, from the *left plane* and the *right plane*.",
            "es": "1. La *barra OQ*, la *rueda izquierda* y la *rueda derecha*, a partir del *plano izquierdo* y del "
                  "*plano derecho*.",
            "ca": "1. La *barra OQ*, la *roda esquerra* i la *roda dreta*, a partir del *pla esquerre* i del *pla dret*.",
            "eu": "1. *OQ barra*, *ezkerreko gurpila* eta *eskuineko gurpila*, *ezkerreko planoa* eta *eskuineko planoa* "
                  "solidoetatik."}
    for lang, text in said.items():
        assert text in plain_page("seed_c5_1_2_bar_on_inclined_wheels", lang), lang


# -- 9. a body's several circles in one row; C5-E.5's wheel R ----------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_body_has_two_rows_of_one_shape(name: str, lang: str) -> None:
    """The Data's shapes table gives a body one row per shape kind (C5-E.1's wheels: "two
    concentric circles | centre C, radii R and 2·R"), never two rows of one name."""
    page = plain_page(name, lang)
    rows = [r for r in page.splitlines() if re.match(r"^\| \*[^*]+\* \| [^|]+ \| ", r)]
    keys = [tuple(c.strip() for c in r.split("|")[1:3]) for r in rows]
    assert len(keys) == len(set(keys)), [k for k in keys if keys.count(k) > 1]


def test_the_cavitys_wheels_and_arm_by_hand() -> None:
    said = {"en": ("| *wheels* | two concentric circles | centre C, radii R and 2·R |", "in a parallel plane, off the *cylindrical track*",
                   "that line is taken here as an *arm OC* hinged at O and C"),
            "es": ("| *ruedas* | dos circunferencias concéntricas | centro C, radios R y 2·R |", "en un plano paralelo",
                   "esa recta se modela aquí como un *brazo OC*"),
            "ca": ("| *rodes* | dues circumferències concèntriques | centre C, radis R i 2·R |", "en un pla paral·lel",
                   "aquí aquesta recta es modela com un *braç OC*"),
            "eu": ("| *gurpilak* | bi zirkunferentzia zentrokide | zentroa C, erradioak R eta 2·R |",
                   "plano paralelo batean", "giltzatutako *OC beso* gisa hartzen da")}
    for lang, texts in said.items():
        page = plain_page("seed_c5_e1_cavity", lang)
        assert all(t in page for t in texts), lang
    # twenty-ninth round (d): the wheel of radius R is the *rear wheel* (R was a radius, a
    # wheel's name and the hinges' letter on one page)
    for lang, name in {"en": "*rear wheel*", "es": "*rueda trasera*", "ca": "*roda del darrere*",
                       "eu": "*atzeko gurpila*"}.items():
        page = plain_page("seed_c5_e5_unequal_wheels", lang)
        assert name in page and "of radius R*" not in page and "de radio R*" not in page and "de radi R*" not in page


# -- 10. the Data state the mechanism ---------------------------------------------------------------------------------
# a word of how the bodies are joined (hinged, sliding, rolling without slip, meshing), per language
JOINED = {"en": r"hinged|pivoted|pinned|slid|slip|mesh|rests on|tied",
          "es": r"articulad|desliz|engran|atad|se apoya",
          "ca": r"articula|llisc|llisq|engran|lligat|rodol|recolza|reposa",
          "eu": r"giltzatu|irristat|engranatzen|lotuta|errodatzen|gainean dago"}


@over(name=SEEDS, lang=LANGS)
def test_the_data_state_the_mechanism(name: str, lang: str) -> None:
    """The model's own statements (`names.LANG.data`) say how the bodies are joined, in the
    notes' words: the statement of the problem, before its geometry (C5-1.6, C5-E.4 and
    C5-E.5 gave only their geometry; a reader met "the arm" and "the belt" first in a
    table)."""
    model = yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text())
    said = " ".join(((model.get("names") or {}).get(lang) or {}).get("data") or [])
    assert re.search(JOINED[lang], said), said[:200]
