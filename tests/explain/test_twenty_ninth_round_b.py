"""Issue 30, twenty-ninth round (b): the Data and Structure sections say what the problem
states (docs/explain.md, "Twenty-ninth round (b)").

The sixth reading's teachers (en, es, ca, eu) found Data that gave away the asked answer
(C5-2.2's ω′ = ω/(2√2) and an underived 3ω/(2√2) for C3) or the model-maker's reason
(C5-1.2's "centres 3.54 m apart, more than 2r"); a Structure that listed the inclined planes as
bodies 2 and 3 "fixed to the ground" and J, the bar's sliding end, among the ground's points;
a ground row "contacts of the wheels at C1, C2 and F" where C1, C2, F are the wheels' centres;
C5-E.6's notation line among the statement's paragraphs; an opaque reason for a strand's
ω = 0; C5-E.6's "P | pedal axle" (it is the pedal's end), C5-E.1's "horizontal" track and
"circle of radius R, circle of radius 2R". Each is checked as a rule over the pages it
applies to.
"""
from __future__ import annotations

import re

import yaml

from .helpers import EXAMPLES, LANGS, SEEDS, over, rendered

HEAD = {"en": ("Data", "Structure", "Answers"), "es": ("Datos", "Estructura", "Respuestas"),
        "ca": ("Dades", "Estructura", "Respostes"), "eu": ("Datuak", "Egitura", "Erantzunak")}
NOTATION = {"en": "Notation:", "es": "Notación:", "ca": "Notació:", "eu": "Notazioa:"}


def section(page: str, title: str) -> str:
    """The text of the section `## title` up to the next `## ` heading."""
    start = page.index(f"\n## {title}\n")
    end = page.find("\n## ", start + 1)
    return page[start:end if end >= 0 else len(page)]


def model(name: str) -> dict:
    return yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8"))


def squeeze(text: str) -> str:
    return re.sub(r"[\s·*]", "", text)


def answer_values(page: str, lang: str) -> list[str]:
    """The values of the Answers table: the last side of each "a = b" in its answer cells."""
    out = []
    for row in section(page, HEAD[lang][2]).splitlines():
        cells = [c.strip() for c in row.strip().strip("|").split("|")]
        if len(cells) != 2 or set(cells[1]) <= set("- "):
            continue
        for part in cells[1].split(";"):
            value = part.split("=")[-1].split("(")[0] if "=" in part else part
            out.append(squeeze(value))
    # a formula's value (ω/(2√2)), not a number with its unit (0) m/s²)
    return [v for v in out if len(v) >= 6 and re.search(r"[/√]", v) and not re.search(r"m/s|rad/s", v)]


@over(name=SEEDS, lang=LANGS)
def test_the_data_print_no_asked_answer(name: str, lang: str) -> None:
    """The Data say what is given; an asked quantity's value is derived and stated by the Answers
    (and the closing Note), never announced in the statement (C5-2.2, C5-2.1)."""
    page = rendered(name, lang)
    data = squeeze(section(page, HEAD[lang][0]))
    given = [v for v in answer_values(page, lang) if v in data]
    assert not given, given


@over(lang=LANGS)
def test_the_articulated_vehicle_prints_no_underived_spin(lang: str) -> None:
    """C5-2.2: the wheel C3's 3ω/(2√2) is derived nowhere: not printed; the notes' ω′ = ω/(2√2)
    is in the Note, not the Data."""
    page = rendered("seed_c5_2_2_articulated", lang)
    assert "3ω/(2√2)" not in page
    assert "ω/(2√2)" not in section(page, HEAD[lang][0])
    assert "ω/(2√2)" in page.split("\n## ")[-1]


@over(lang=LANGS)
def test_the_data_give_no_model_makers_reason(lang: str) -> None:
    """C5-1.2: the distance of the wheel centres (3.54 m, "more than 2r") was the model-maker's
    reason for s = 3 m: a datum is given, not justified."""
    data = section(rendered("seed_c5_1_2_bar_on_inclined_wheels", lang), HEAD[lang][0])
    assert not re.search(r"3[.,]54|2r", data), data


def _welded(m: dict) -> set[str]:
    frame = "ground"
    fixed, grew = {frame}, True
    while grew:
        grew = False
        for j in m["joints"]:
            if j["type"] == "weld" and len(set(j["bodies"]) & fixed) == 1:
                fixed |= set(j["bodies"])
                grew = True
    return fixed - {frame}


@over(name=SEEDS, lang=LANGS)
def test_a_body_welded_to_the_frame_is_the_frames_row(name: str, lang: str) -> None:
    """A body welded to the frame (C5-1.2's planes, C5-1.5's strand 1) is the frame: no row of
    its own, named in the frame's row, and the table numbered 1, 2, … without a gap."""
    m = model(name)
    structure = section(rendered(name, lang), HEAD[lang][1])
    rows = [r for r in structure.splitlines() if re.match(r"\| \d+ \|", r)]
    numbers = [int(r.split("|")[1]) for r in rows]
    assert numbers == list(range(1, len(numbers) + 1)), numbers
    assert len(rows) == len(m["bodies"]) - len(_welded(m)), rows
    spelt = ((m.get("names") or {}).get(lang) or {}).get("bodies") or {}
    for b in _welded(m):
        word = re.sub(r"^(el|la|les|els|los|las) ", "", spelt.get(b, b))
        assert word.casefold() in rows[0].casefold(), (b, rows[0])
        assert not any(word.casefold() in r.casefold() for r in rows[1:]), (b, rows)


@over(name=SEEDS, lang=LANGS)
def test_a_sliding_point_is_not_the_lines_bodys_point(name: str, lang: str) -> None:
    """A point sliding along a fixed line (C5-1.2's J, the bar's end on the floor) is the sliding
    body's point: the ground's row does not list it."""
    m = model(name)
    slid = [j["at"] for j in m["joints"] if j["type"] == "slot" and j["bodies"][0] == "ground" and "at" in j]
    if not slid:
        return
    row = next(r for r in rendered(name, lang).splitlines() if r.startswith("| 1 |"))
    cell = row.rstrip(" |").rsplit("|", 1)[1]
    assert not set(re.split(r"[ ,]+", cell)) & set(slid), row


UNDER = {"en": "contact points under ", "es": "puntos de contacto bajo ", "ca": "punts de contacte sota ",
         "eu": " puntuen azpiko kontaktu-puntuak"}


@over(name=SEEDS, lang=LANGS)
def test_the_ground_row_says_the_contacts_are_under_the_wheels_centres(name: str, lang: str) -> None:
    """Knife-edge wheels (C5-2.1, C5-2.2): C1, C2, F … are the wheels' centres; the ground's row
    names the contact points under them, never "contacts of the wheels at C1"."""
    wheels = [j["at"] for j in model(name)["joints"] if j["type"] == "wheel"]
    if len(wheels) < 2:
        return
    row = next(r for r in rendered(name, lang).splitlines() if r.startswith("| 1 |"))
    assert UNDER[lang] in row, row
    assert all(p in row for p in wheels), row


@over(name=SEEDS, lang=LANGS)
def test_the_notation_line_follows_the_data_tables(name: str, lang: str) -> None:
    """The notation line (ω_wheel1 …) is said after the statement and the Data's tables, never
    among the statement's paragraphs before any table (C5-E.6's statement wrote r ω_sprocket =
    R ω_chainring; it now says it in words, and its notation goes under the Structure's table)."""
    page = rendered(name, lang)
    at = page.find("\n" + NOTATION[lang])
    if at < 0:
        return
    assert "\n| " in page[:at], page[:at][-400:]


@over(lang=LANGS)
def test_a_strand_tangent_to_two_pulleys_stays_vertical(lang: str) -> None:
    """C5-1.5: the strands between the pulleys stay vertical and translate (the notes'
    reason); strand 1 does not move because its top is tied; no "pendular", no "swing"."""
    page = rendered("seed_c5_1_5_pulley_block", lang)
    word = {"en": "it stays vertical", "es": "se mantiene vertical", "ca": "es manté vertical",
            "eu": "bertikal mantentzen da"}[lang]
    rates = [x for x in page.splitlines() if re.match(r"ω_\S+ = 0 \(", x)]
    assert len(rates) >= 3 and all(word in x for x in rates), rates
    assert not re.search(r"pendular|swing|component across", page, re.I)


@over(lang=LANGS)
def test_the_bicycles_pedal_end_and_the_unused_distances(lang: str) -> None:
    """C5-E.6: P is the pedal's end, L below C; b and e are given and said to place points only."""
    page = rendered("seed_c5_e6_bicycle", lang)
    row = next(x for x in page.splitlines() if x.startswith("| P |"))
    assert re.search(r"\bL\b", row.split("|")[2]) and re.search(r"\bC\b", row.split("|")[2]), row
    data = section(page, HEAD[lang][0])
    assert re.search(r"\bb\b.*\be\b", data.split("\n| ")[0]), data[:600]


@over(lang=LANGS)
def test_welded_wheels_are_said_once(lang: str) -> None:
    """C5-E.1: the wheels' row says "two welded wheels of radii R and 2R", not a list of circles;
    the track's axis, not the track, is horizontal."""
    page = rendered("seed_c5_e1_cavity", lang)
    row = next(x for x in page.splitlines() if x.startswith("| 3 |"))
    assert re.search(r"R (and|y|i|eta) 2·R", row) and row.count("R") == 2, row
    word = {"en": "in one piece", "es": "solidarias", "ca": "solidàries", "eu": "solidario"}[lang]
    assert word in row, row
    assert not re.search(r"(track|pista cilíndrica|zilindrikoaren barruan biratzen dira \(), horizont", page)


GROUND = {"en": "ground", "es": "suelo", "ca": "terra", "eu": "lurra"}


@over(name=SEEDS, lang=LANGS)
def test_a_fixed_body_is_the_reference_by_its_own_name(name: str, lang: str) -> None:
    """A fixed body with its own name (C5-1.6's fixed pulley, C5-E.1's track) is the reference of
    the motions by that name ("relative to the *fixed pulley*"): no "(*ground*)" beside it and
    no *ground* the problem does not have."""
    m = model(name)
    spelt = (((m.get("names") or {}).get(lang) or {}).get("bodies") or {}).get("ground", "ground")
    if GROUND[lang] in spelt.split():
        return
    page = rendered(name, lang)
    assert f"*{GROUND[lang]}*" not in page and f"*el {GROUND[lang]}*" not in page, spelt


PERMANENT = {"en": "a permanent centre", "es": "un centro permanente", "ca": "un centre permanent",
             "eu": "zentro iraunkorra"}


OLD_PIN = re.compile(r"^I_\{?[^ ]*\}?: (the pin |el eje de la articulación \S+,|l’eix de l’articulació \S+,|"
                     r"\S+ giltzaduraren ardatza)")


@over(name=SEEDS, lang=LANGS)
def test_a_fixed_pivot_is_said_a_permanent_centre(name: str, lang: str) -> None:
    """A body pinned to the fixed body has its pin for instant centre at every instant: the
    centre's line says so (the notes' point in C5-E.2), never the bare "the pin O" of a
    relative centre."""
    page = rendered(name, lang)
    lines = [x for x in page.splitlines() if x.startswith("I_") and " rel " not in x.split(":")[0]]
    assert not [x for x in lines if OLD_PIN.match(x)], [x for x in lines if OLD_PIN.match(x)]


@over(lang=LANGS)
def test_the_gear_changes_arm_and_ring_turn_about_permanent_centres(lang: str) -> None:
    """C5-E.2 (eu's item): I_arm and I_ring, both at the fixed axis O, are permanent centres."""
    page = rendered("seed_c5_e2_gear_change", lang)
    said = [x for x in page.splitlines() if x.startswith("I_") and PERMANENT[lang] in x]
    assert len(said) == 2, said


TIED_AT = {"en": "where the *left strand* is tied to the *ceiling*", "es": "donde el *tramo izquierdo* está atado al *techo*",
           "ca": "on el *tram esquerre* és lligat al *sostre*", "eu": "*ezkerreko kable-zatia* *sabaiari* lotuta dagoen lekua"}


@over(lang=LANGS)
def test_a_strands_centre_is_where_it_is_tied(lang: str) -> None:
    """C5-1.1: a strand's instant centre is the point G1 where it is tied to the ceiling (the
    notes), never "the axis of the hinge G1"; both strands' centres are asked and answered."""
    page = rendered("seed_c5_1_1_pulley_on_cable", lang)
    assert TIED_AT[lang] in page
    assert not re.search(r"articulació G1|articulación G1|G1 giltzaduraren|pin G1", page)
    answers = section(page, HEAD[lang][2])
    assert answers.count("(−2·√3·r") == 1 and answers.count("(2·√3·r") == 1, answers


@over(lang=LANGS)
def test_a_body_sliding_without_turning_carries_every_point(lang: str) -> None:
    """C5-1.3: E is the bar's free end, not in the sleeve: the bar slides without turning, so every
    point of it, E too, has the relative velocity (acceleration) found before."""
    page = rendered("seed_c5_1_3_bar_in_sleeve", lang)
    too = {"en": "E too", "es": "también E", "ca": "també E", "eu": "E puntuak ere"}[lang]
    assert page.count(too) == 2, page.count(too)
    assert not re.search(r"E (slides along its guide|desliza a lo largo de su guía|llisca al llarg de la seva guia)|"
                         r"E puntua bere gidan", page)


def test_the_basque_shared_unknown_and_guide_sentences() -> None:
    """C5-1.3 (eu): "haien bi ? ikurrek ezezagun bakar bat adierazten dute, α_euskarria"; the
    guide's perpendicular said in two sentences."""
    page = rendered("seed_c5_1_3_bar_in_sleeve", "eu")
    assert "haien bi ? ikurrek ezezagun bakar bat adierazten dute, α_euskarria." in page
    assert "ikurrak ezezagun bakarra dira" not in page
    assert "J′ da J puntutik gidara doan perpendikularraren oina. Han," in page


@over(lang=LANGS)
def test_a_repeated_construction_is_referred_to(lang: str) -> None:
    """C5-1.4: planets 2 and 3 are found as planet 1 was: their centres' lines refer to planet 1
    and give the distance, 2r/5 from A2 (A3), instead of repeating the paragraph."""
    page = rendered("seed_c5_1_4_epicyclic", lang)
    carried = [x for x in page.splitlines() if re.match(r"I_\S+[123]\}: ", x) and "2·r/5" in x]
    assert len(carried) == 3, carried
    full, *short = carried
    assert all(len(x) < len(full) / 2 for x in short), short
    assert all(("A2" in x or "A3" in x) for x in short), short
