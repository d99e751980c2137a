"""Issue 30, twenty-third round (a): a reader's items on main's pages.

- a witness of the proportional construction that is a rolling contact says why it moves
  with the other body: the no-slip condition (C5-1.4: "… and Q with the *ring* about O
  (*planet 1* does not slip on the *ring*, so its point Q has the velocity of the *ring*
  there)"), as `centre.line.rolls` says it;
"""

from __future__ import annotations

import re


from kinematika.explain.document import CentreNote
from kinematika.explain.kinds import rolls

from .helpers import LANGS, SEEDS, explained, over, rendered, model_tree

# the no-slip clause each catalogue writes, by its opening words
SLIP = {"en": "does not slip on", "es": "no desliza sobre", "ca": "no llisca sobre",
        "eu": "ez da irristatzen"}


def _notes(doc) -> list[CentreNote]:
    """Every proportional centre note said with its pivots (`centre.carried.*`)."""
    return [b for s in doc.sections for b in s.leaves()
            if isinstance(b, CentreNote) and b.how == "proportional" and b.pivots and len(b.witnesses) == 2]


@over(name=SEEDS, lang=LANGS)
def test_a_rolling_witness_says_it_does_not_slip(name: str, lang: str) -> None:
    """Each witness of "P moves with k1 about c1, and Q with k2 about c2" that is the contact
    of a rolling joint between k and the body says the no-slip reason (the model decides, not
    the note: a rolling joint between the witness's body and the centre's body); a pin says none."""
    sol, doc = explained(name)
    md = rendered(name, lang)
    for note in _notes(doc):
        b = note.pair[1]
        rolling = [k for k in note.via if any(rolls(j) and {j.a, j.b} == {k, b} for j in sol.model.joints)]
        line = next((x for x in md.splitlines() if x.startswith("I_") and f" {note.witnesses[0][0]} " in x
                     and f" {note.witnesses[1][0]} " in x and ("(" in x or not rolling)), None)
        if line is None or re.search(r"^I_\S+: (as for|como para|com per a|\S+ \S+ bezala,)", line):
            # a construction done for a symmetric body, referred to (29 b)
            assert any(re.search(r"^I_\S+: (as for|como para|com per a|\S+ \S+ bezala,)", x) for x in md.splitlines())
            continue
        assert line.count(SLIP[lang]) == len(rolling), line


def test_the_epicyclic_planet_rolls_on_the_ring() -> None:
    """C5-1.4, the reader's words, four languages (the old page gave no reason)."""
    want = {"en": "and Q with the *ring* about O (*planet 1* does not slip on the *ring*, so its point Q has the velocity of the *ring* there): both",
            "es": "y Q con la *corona* alrededor de O (el *satélite 1* no desliza sobre la *corona*, así que su punto Q tiene la velocidad de la *corona* en ese punto): ambas",
            "ca": "i Q amb la *corona* al voltant d’O (la *rodeta 1* no llisca sobre la *corona*, de manera que el seu punt Q té la velocitat de la *corona* en aquest punt): totes",
            "eu": "eta Q puntua *koroarekin* O puntuaren inguruan (*1. satelitea* ez da irristatzen *koroaren* gainean: bere Q puntuak *koroaren* abiadura du bertan): bi"}
    for lang in LANGS:
        assert want[lang] in rendered("seed_c5_1_4_epicyclic", lang), lang
    assert "A1 moves with the *carrier* about O, and" in rendered("seed_c5_1_4_epicyclic", "en")


@over(name=SEEDS, lang=LANGS)
def test_the_unit_tangent_is_the_velocitys_unit_vector(name: str, lang: str) -> None:
    """Every answer "unit tangent t = …" writes it as the velocity's unit vector, t = v_P/|v_P|
    = (1, 0), with the point the speed |v_P| just before it names (C5-1.7: "t = (1, 0)" had
    no working)."""
    md = rendered(name, lang)
    # the working stands before the answers since the twenty-fourth round (d): "|v_P| = …; t = …"
    # the derivation before the split since the twenty-fifth round (a): "With |v_P| = …, the
    # unit tangent is t = …;" (each language's words between the speed and t)
    for m in re.finditer(r"\|(v_\S+?)\| = [^;,]*,[^;]*?\bt = ([^;]*?)(?: da)?;", md):
        v = m.group(1)
        assert m.group(2).startswith(f"{v}/|{v}| = ("), m.group(0)


def test_the_unit_tangent_is_written_on_the_semicylinders_page() -> None:
    """The rule above reads C5-1.7's working in every language (it would pass on a page that
    lost it): there, |v_P| = 2·r·ω and t = v_P/|v_P| = (1, 0)."""
    for lang in LANGS:
        md = rendered("seed_c5_1_7_semicylinder", lang)
        assert "|v_P| = 2·r·ω" in md and " t = v_P/|v_P| = (1" in md, lang
        assert len(re.findall(r"\|(v_\S+?)\| = [^;,]*,[^;]*?\bt = ([^;]*?)(?: da)?;", md)) == 1, lang


# each catalogue's word for a contact point in the fixed body's row
CONTACT = {"en": "contact", "es": "contacto", "ca": "contacte", "eu": "kontaktu-punt"}


@over(name=SEEDS, lang=LANGS)
def test_the_fixed_row_says_a_wheels_point_is_a_contact(name: str, lang: str) -> None:
    """A point the fixed body carries only for a wheel or rolling joint (`at:` in the model,
    no pin of the frame there) is listed in its row as the contact it is, never bare beside
    its own points (C5-2.1: "C1, C2, F" was read as the wheels' centres)."""
    model = model_tree(name)
    frame = next(iter(model["bodies"]))
    kinds = {"wheel", "rolling"}
    at = [j for j in model.get("joints", []) if frame in j.get("bodies", []) and j.get("at")]
    pins = {j["at"] for j in at if j["type"] not in kinds}
    own = model["bodies"][frame]
    own = own.get("points", []) if isinstance(own, dict) else own       # the points the frame carries
    contacts = [j["at"] for j in at if j["type"] in kinds and j["at"] not in pins and j["at"] in own]
    if not contacts:
        return
    row = next(x for x in rendered(name, lang).splitlines() if x.startswith("| 1 |"))
    cell = row.rstrip(" |").rsplit("|", 1)[1]
    assert CONTACT[lang] in cell, row
    bare = [p.strip() for p in re.split(r",| and | y | i | eta ", cell.split("(")[0] if lang == "eu" else cell.split(CONTACT[lang])[0])]
    if lang == "eu":       # "G, J eta K (kontaktu-puntuak)", "C1 eta F puntuen azpiko …": the contacts are filtered out
        bare = [p for p in bare if p not in contacts]
    assert not set(bare) & set(contacts), row


def test_the_tricycle_ground_row() -> None:
    """C5-2.1, the reader's item in four languages."""
    want = {"en": "| contact points under C1, C2, and F |", "es": "| puntos de contacto bajo C1, C2 y F |",
            "ca": "| punts de contacte sota C1, C2 i F |", "eu": "| C1, C2 eta F puntuen azpiko kontaktu-puntuak |"}
    for lang in LANGS:
        row = next(x for x in rendered("seed_c5_2_1_tricycle", lang).splitlines() if x.startswith("| 1 |"))
        assert row.endswith(want[lang]), row


def test_the_articulated_vehicles_ground_row_names_its_wheels_contacts() -> None:
    """C5-2.2: the ground lists no point (`ground: []`), yet its four knife-edge wheels touch it
    at C1–C4; its row was empty (two readers marked it). The contacts are listed as on 2.1."""
    want = {"en": "| contact points under C1, C2, C3, and C4 |", "es": "| puntos de contacto bajo C1, C2, C3 y C4 |",
            "ca": "| punts de contacte sota C1, C2, C3 i C4 |", "eu": "| C1, C2, C3 eta C4 puntuen azpiko kontaktu-puntuak |"}
    for lang in LANGS:
        row = next(x for x in rendered("seed_c5_2_2_articulated", lang).splitlines() if x.startswith("| 1 |"))
        assert row.endswith(want[lang]), row
