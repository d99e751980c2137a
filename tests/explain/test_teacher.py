"""Explanations a teacher hands out as they are (issue 30): the notes' worked examples, in
every language, speak of mechanics and not of the program, name no colour where the text
is plain (Markdown), state every datum in their Data section and derive every asked
quantity by an equation before the answers."""
from __future__ import annotations

import re

import pytest

from kinematika.explain import render
from kinematika.explain.catalogue import LANGS

from tests.conftest import KINDS, sampled

from .helpers import WORKED, explained, render_of, model_tree
from .test_text import plain_text

# the notes' examples of each kind (every one in a deep run)
NOTES = sampled(WORKED, KINDS)

# the program, as a student must never read it: the solver, its method (the velocity
# equations' block-triangular form) and the rank that counts the degrees of freedom, in the
# four languages
SOLVER = re.compile(r"(?i)\b(solver|resolutor|resolvedor|solucionador|ebazle\w*|programa|program|"
                    r"\w*triang\w*|rank|rango|rang|heina\w*)\b")
# colours, which plain text (Markdown) does not show
COLOURS = re.compile(r"(?i)\b(red|blue|black|green|grey|gray|rojo|roja|azul|azules|negro|verde|vermell|"
                     r"blau|blava|blaves|blaus|negre|verd|gorri\w*|urdin\w*|beltz\w*|berde\w*)\b")


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", NOTES)
def test_no_explanation_mentions_the_solver(name, lang):
    _, doc = explained(name)
    for fmt in ("md", "html"):
        text = plain_text(render_of(doc, lang, fmt, drawings=False), fmt)
        found = SOLVER.search(text)
        assert found is None, (name, lang, fmt, text[max(0, found.start() - 80):found.end() + 40])


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", NOTES)
def test_no_markdown_mentions_colours(name, lang, monkeypatch):
    from kinematika.explain.document import Drawing

    monkeypatch.setattr(Drawing, "svg", lambda self, lang: "<svg/>")     # the captions, not the drawings
    _, doc = explained(name)
    text = plain_text(render(doc, lang, "md", drawings=True), "md")
    found = COLOURS.search(text)
    assert found is None, (name, lang, text[max(0, found.start() - 80):found.end() + 40])


@pytest.mark.parametrize("name,lang,wrong,right", [
    # a plural body's name (les rodes, las ruedas) takes a plural verb
    ("seed_c5_e1_cavity", "ca", "*rodes* rodola", "*rodes* rodolen"),
    ("seed_c5_e1_cavity", "es", "*ruedas* gira ", "*ruedas* giran"),
    # two wheels (les rodes, feminine) do not slip "l'un sobre l'altre": between themselves
    ("seed_c5_e4_upper_wheel", "ca", "no llisquen l’un sobre l’altre", "no llisquen entre si"),
    # a belt's two pulleys: their rims have one speed (not "both move with the same speed")
    ("seed_c5_1_6_belt", "eu", "biek abiadura berarekin mugitzen dute", "bien periferiek abiadura bera dute"),
    ("seed_c5_1_6_belt", "ca", "tots dos la mouen", "les seves perifèries tenen la mateixa velocitat"),
    # the normal to the floor's line through the point that slides on it
    ("seed_c5_1_2_bar_on_inclined_wheels", "ca", "a la normal a J a la recta", "a la normal a la recta del *terra* per J"),
    # a body's name stripped of its article keeps no stray article of its own
    # (round 20f: the sources in the order the step reads them, pulley 1 before the ceiling)
    ("seed_c5_1_5_pulley_block", "ca", "i el *sostre*", "a partir de la *politja 1* i del *sostre*"),
    # the fourth audit's words: the drag's terms are those of the equation that found the point
    ("seed_001_rolling_pair", "eu", "puntu hau aurkitu zuen goiko urratseko lehen terminoak",
     "2. urratseko ekuazioaren lehen terminoak dira"),
    # a body whose two points run on one line translates along it (points move, the body translates)
    ("seed_c5_e4_upper_wheel", "eu", "zuzena ibiltzen dute",
     "zuzenean zehar mugitzen dira une oro: solidoa zuzen horretan zehar traslatzen da, biratu gabe"),
    ("seed_c5_e6_bicycle", "eu", "irristatzen da eta ez da biratzen", "solidoa zuzen horretan zehar traslatzen da"),
    ("seed_c5_e4_upper_wheel", "ca", "llisca al llarg d’ella", "el sòlid es trasllada al llarg d’aquesta recta, sense girar"),
    ("seed_c5_e4_upper_wheel", "es", "desliza a lo largo de ella y no gira", "el sólido se traslada a lo largo de ella, sin girar"),
    # the symbol I is named as a symbol: a sentence opening "I amb" reads as the word "and"
    ("seed_c5_1_4_epicyclic", "ca", "I amb el nom d’un sòlid", "El símbol I, amb el nom d’un sòlid (I_{portador}), designa el CIR"),
    ("seed_c5_1_4_epicyclic", "es", "I con el nombre", "El símbolo I, con el nombre de un sólido"),
    ("seed_c5_1_4_epicyclic", "en", "\nI with a body's name", "The symbol I with a body's name"),
    # the notes' own word for the planets (seed 002: "el CIR de cada rodeta")
    ("seed_c5_1_4_epicyclic", "ca", "satèl·lit", "la *rodeta 1*"),
    ("seed_c5_e2_gear_change", "ca", "satèl·lit", "amb les rodetes a sobre i a sota del centre"),
    # a hub is not "buje" (Spanish) in Basque: the wheel's axle
    ("seed_c5_e6_bicycle", "eu", "bujetik", "*atzeko gurpilaren* ardatzetik pedalen ardatzerainoko"),
    # fourteenth round (c): E.1's OC is a body, the notes' arm; E.5 the notes' "terra pla"; E.6's
    # wheelbase is e, so the crank axle C's image is plain c with no note; "plater pedalduna" declines
    ("seed_c5_e1_cavity", "ca", "recta OC", "*braç OC*"),
    ("seed_c5_e1_cavity", "eu", "OC zuzena", "*OC besoa*"),
    ("seed_c5_e5_unequal_wheels", "ca", "terra recte", "sobre el terra pla"),
    ("seed_c5_e6_bicycle", "eu", "pedalekin", "*plater pedaldunaren*"),
    ("seed_c5_e6_bicycle", "ca", "c′", "| *e* | batalla |"),
])
def test_the_notes_grammar(name, lang, wrong, right):
    """Catalan, Spanish and Basque as the notes write them (issue 30's audit, its grammar points)."""
    _, doc = explained(name)
    text = render_of(doc, lang, "md", drawings=False)
    assert wrong not in text and right in text

# how a page may speak of its source: what it takes, not what became of the notes' figure
HISTORY = re.compile(r"(?i)galdu da|s[’']ha perdut|se ha perdido|se perdió|is lost|\blost\b")


@pytest.mark.parametrize("lang", LANGS)
def test_no_page_tells_the_history_of_the_notes(lang):
    """The Data's statements say which geometry the page takes ("Aquí es pren aquesta
    geometria: …"), never that the notes' figure was lost (the fourth audit: a student holding
    the notes finds it odd). Every notes' example, read from its model."""
    from kinematika.api import as_model

    from .helpers import EXAMPLES

    said = {name: " ".join(as_model(EXAMPLES / f"{name}.yaml").wording.data.get(lang, []))
            for name in WORKED}
    assert {name: HISTORY.search(text).group(0) for name, text in said.items() if HISTORY.search(text)} == {}


@pytest.mark.parametrize("lang", LANGS)
def test_the_centres_symbol_is_named_as_a_symbol(lang):
    """The CIR section's first sentence names I as a symbol ("El símbol I, amb …", "I ikurrak"):
    a sentence that opens with a bare "I" reads as the Catalan "and" or the English "I"."""
    from kinematika.explain.catalogue import catalogue

    opening = {"ca": "El símbol I,", "es": "El símbolo I,", "en": "The symbol I ", "eu": "I ikurrak,"}[lang]
    cat = catalogue(lang)
    for key in ("centres.intro", "centres.intro_named"):
        text = cat.format(key, {"example": "I_13", "pair": "I_a", "body": "a", "frame": "b"})
        assert text.startswith(opening), (lang, key, text)


def test_count_reads_plural_names():
    from kinematika.explain.catalogue import count

    assert [count(n) for n in ("les rodes", "el plat i els pedals", "la roda", "el portador", "los dientes",
                               "las aspas", "el bloc")] == ["many", "many", "one", "one", "many", "many", "one"]


def _data_text(doc, lang: str = "en") -> str:
    """The Data section as a reader reads it (Markdown), up to the next section."""
    text = render_of(doc, lang, "md", drawings=False)
    start = text.index("\n## ")
    return text[start:text.index("\n## ", start + 1)]


def _number(x: float) -> str:
    """A number as the explanation writes it in English: at most four significant digits."""
    return f"{float(x):.4g}".replace("-", "−")


@pytest.mark.parametrize("name", NOTES)
def test_every_datum_is_stated_in_the_data_section(name):
    """Read off the model file itself (not the explanation's code): every numeric parameter's
    value, every point given by plain numbers, every driver's value and every circle's
    radius appears in the Data section, with its unit where it has one; a parameter left a
    symbol appears as its symbol."""

    from kinematika.explain.render.names import unicode_name


    raw = model_tree(name)
    sol, doc = explained(name)
    data = _data_text(doc)
    notation = raw.get("notation") or {}
    for pname, value in (raw.get("parameters") or {}).items():
        if value is None:
            spelt = notation.get(pname, pname)
            spelt = spelt if isinstance(spelt, str) else spelt.get("en", pname)
            assert unicode_name(spelt) in data, (name, pname)
        elif isinstance(value, (int, float)):
            assert _number(value) in data, (name, pname, value)
        elif isinstance(value, str) and value.startswith("deg("):
            assert _number(float(value[4:-1])) + "°" in data, (name, pname, value)
    for pname, where in raw["points"].items():
        if isinstance(where, list) and all(isinstance(c, (int, float)) for c in where):
            written = "(" + ", ".join(_number(c) for c in where) + ")"
            assert f"| {pname} |" in data and written in data, (name, pname, written)
    for d in raw.get("drivers") or []:
        for key in ("value", "alpha", "acceleration"):
            given = d.get(key)
            if isinstance(given, (int, float)):
                assert _number(given) in data, (name, d, key)
    for body, spec in raw["bodies"].items():
        circle = spec.get("circle") if isinstance(spec, dict) else None
        if circle is not None:
            radius = circle["radius"]
            if isinstance(radius, (int, float)):
                shown = _number(radius) + " m"
            elif radius in (raw.get("parameters") or {}):
                spelt = notation.get(radius, radius)
                shown = unicode_name(spelt if isinstance(spelt, str) else spelt.get("en", radius))
            else:
                shown = str(radius).replace("*", "·")
            assert shown in data, (name, body, shown)


def test_the_tricycles_spin_is_derived_as_the_notes_give_it():
    """C5-2.1: with the steering at 45°, the chassis turns about I on the rear axle line, L to
    the left of M, at ω = v₀/(√2 L); the left rear wheel's centre, L − s from I, moves at
    ω (L − s) = r φ̇, so φ̇ = v₀ (L − s)/(√2 L r) (worked here by hand)."""
    import sympy


    sol, doc = explained("seed_c5_2_1_tricycle")
    L, s, v0, r = (sympy.Symbol(n, positive=True) for n in ("L", "s", "v0", "r"))
    by_hand = v0 * (L - s) / (sympy.sqrt(2) * L * r)
    spins = [d for d in doc.derived() if d.kind == "spin"]
    assert len(spins) == 1
    env = {str(k): k for k in getattr(spins[0].value.value, "free_symbols", set())}
    got = spins[0].value.value.subs({env[n]: sym for n, sym in zip(("L", "s", "v0", "r"), (L, s, v0, r)) if n in env})
    assert sympy.simplify(got - by_hand) == 0
    answers = render_of(doc, "en", "md", drawings=False).split("## Answers")[1]
    assert "φ̇" in answers and "φ̇ = v_RL / *r*" not in answers


def test_the_articulated_vehicles_wheel_spin_is_the_notes():
    """C5-2.2: S1 translates at rω, so O does; S2 (at 45°) turns about I on its axle line at
    ω_S2 = rω/(√2 a) (|OI| = √2 a); its inner wheel's centre C4, a/2 from the axle's midpoint
    towards I, is a/2 from I and moves at ω_S2 a/2 = rω/(2√2) = r ω′: ω′ = ω/(2√2)."""
    import sympy

    _, doc = explained("seed_c5_2_2_articulated")
    spins = [d for d in doc.derived() if d.kind == "spin"]
    assert len(spins) == 1
    w = next(s for s in spins[0].value.value.free_symbols if s.name == "w")
    assert sympy.simplify(spins[0].value.value - w / (2 * sympy.sqrt(2))) == 0


def test_a_chassis_on_one_axle_translates_because_its_wheels_share_a_velocity():
    """C5-2.2: S1's two wheels lie on one axle line (their lines coincide, they do not run
    parallel), so the lines cannot place its centre; C1 and C2 are both given (rω; 0), and
    two points with one velocity (v_W2 = v_W1 + ω × W1W2, W1W2 ≠ 0) give ω = 0: it translates."""
    _, doc = explained("seed_c5_2_2_articulated")
    said = [b for s in doc.sections for b in _walk(s) if getattr(b, "key", "").startswith("vehicle.translation")]
    assert [m.key for m in said] == ["vehicle.translation_equal"]
    assert {said[0].args["p"].text, said[0].args["q"].text} == {"C1", "C2"}
    for lang, words in (("ca", "tenen la mateixa velocitat"), ("eu", "abiadura bera dute")):
        text = render_of(doc, lang, "md", drawings=False)
        assert words in text and "paral·leles: el seu CIR" not in text and "zuzenak paraleloak dira" not in text


def _walk(section):
    """Every block of a section and of its subsections."""
    for b in section.blocks:
        if hasattr(b, "blocks") and hasattr(b, "title"):
            yield from _walk(b)
        else:
            yield b


@pytest.mark.parametrize("name,lines", [
    # J slides on the floor: no slot; and the lines through O and K1, Q and K2 the text meets at
    # I_OQ (nineteenth round (d): a centre the text places where lines meet is drawn with them)
    ("seed_c5_1_2_bar_on_inclined_wheels", ["fig.normal.slot_fixed", "fig.normal.radius"]),
    # knife-edge wheels: their axles; and the line from I_chassis to the pin F, perpendicular
    # to F's velocity (fourteenth round (d): drawn, so named)
    ("seed_c5_2_2_articulated", ["fig.normal.wheel", "fig.normal.radius"]),
    ("four_bar", ["fig.normal.radius"]),     # pins only: the crank's and the rocker's lines meet at I
])
def test_the_centres_caption_names_the_contacts_the_mechanism_has(name, lines):
    """What the centres' figure says its lines are comes from the joints: C5-1.2's bar end J
    on the floor is a point sliding on a fixed line, and its caption says so, never "slots"."""
    from kinematika.explain.document import Drawing

    _, doc = explained(name)
    captions = [b.caption for s in doc.sections for b in _walk(s)
                if isinstance(b, Drawing) and b.caption.key == "fig.centres"]
    assert captions and all([m.key for m in c.args["normals"].items] == lines for c in captions)
    if name.startswith("seed_c5_1_2"):
        for lang, slot in (("ca", "ranures"), ("eu", "arteken")):
            assert slot not in render(doc, lang, "md", drawings=True)


def _points_table(text: str, header: str) -> dict[str, str]:
    """The Data section's table of points (Markdown): point -> what it is."""
    lines = text.split(f"| {header} |", 1)[1].split("\n\n", 1)[0].splitlines()[2:]
    return {cells[1].strip(): cells[2].strip() for cells in (line.split("|") for line in lines)}


@pytest.mark.parametrize("name", sampled(sorted(p for p in WORKED if p.startswith("seed_")),
                                         KINDS | {"seed_001_r_pairs", "seed_c5_1_2_bar_on_inclined_wheels"}))
def test_every_point_says_what_it_is(name):
    """The Data section's "what it is" column is never empty for a point a body holds: where
    the model's `names` do not say, its structure does (a circle's centre, a joint's point,
    a point of its bodies)."""
    _, doc = explained(name)
    for lang, header in (("ca", "punt"), ("eu", "puntua")):
        table = _points_table(render_of(doc, lang, "md", drawings=False), header)
        assert table and all(table.values()), (name, lang, [p for p, w in table.items() if not w])


def test_what_a_point_is_comes_from_the_joints_and_shapes():
    """C5-1.2: O is the left wheel's centre (its circle's), J the bar's end sliding on the
    floor; the slides' r_pairs: B is the pin between N and P (a joint
    is said by what it is, never by its id)."""
    _, doc = explained("seed_c5_1_2_bar_on_inclined_wheels")
    table = _points_table(render_of(doc, "ca", "md", drawings=False), "punt")
    assert table["O"] == "centre de la *roda esquerra*"
    assert table["J"].startswith("contacte amb lliscament") and "*barra OJ*" in table["J"]
    _, doc = explained("seed_001_r_pairs")
    table = _points_table(render_of(doc, "eu", "md", drawings=False), "puntua")
    assert table["B"].startswith("giltzadura (R), *N elementua* eta *P elementua*")


# -- the notes' reasoning (issue 30, the audit's S2, S6 and C5-E.4) ---------------------------------------------------
SEEDS = sorted(p for p in WORKED if p.startswith("seed_"))


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_no_seed_names_aronhold_kennedy(name, lang, monkeypatch):
    """The notes never name Aronhold–Kennedy: they find a centre where the perpendiculars to
    two known velocities meet (C5-1.2's OQ from its wheels' centres, C5-E.3's rod), on the
    perpendicular to a guide (C5-1.3), or from speeds along one line (C5-1.4). No seed
    explanation names the theorem, in its text or its figures' captions."""
    from kinematika.explain.document import Drawing

    monkeypatch.setattr(Drawing, "svg", lambda self, lang: "<svg/>")
    _, doc = explained(name)
    text = render(doc, lang, "md", drawings=True)
    assert "Aronhold" not in text and "Kennedy" not in text, (name, lang)


@pytest.mark.parametrize("name,lang,line", [
    # C5-1.2: the centres of the wheels move parallel to the inclined planes; OQ's centre is
    # where the perpendiculars to those velocities through the centres meet
    ("seed_c5_1_2_bar_on_inclined_wheels", "en", "I_{OQ}: it lies on the perpendicular to v_O through O (O moves with "
                                                 "the *left wheel*, which turns about K1) and on the perpendicular to v_Q "
                                                 "through Q (Q moves with the *right wheel*, which turns about K2)"),
    # C5-1.3: on OQ (the perpendicular to v_Q) and on the perpendicular to the bar through J
    ("seed_c5_1_3_bar_in_sleeve", "ca", "I_{barra}: és a la perpendicular a v_Q per Q (Q es mou amb l’*element OQ*, que gira "
                                        "al voltant d’O) i a la perpendicular a la guia per J"),
    # C5-E.3: the rod's pins move with the wheels about their contacts
    ("seed_c5_e3_wheels_with_rod", "eu", "I_{biela}: bi zuzen hauetan dago: A puntuan v_A abiadurarekiko perpendikularra"),
    # C5-1.4: the planet's centre and its contact with the ring, carried about O
    ("seed_c5_1_4_epicyclic", "en", "I_{planet1}: A1 moves with the *carrier* about O, and Q with the *ring* about O"),
])
def test_a_centre_is_found_as_the_notes_find_it(name, lang, line):
    _, doc = explained(name)
    assert line in render_of(doc, lang, "md", drawings=False)


# velocity drivers whose component is the point's whole motion (the notes' v_U = (←v)), by
# hand from each statement: a wheel's centre on flat ground, a slider on its guide, a pulley's
# centre on a vertical strand; and the one that truly is a component (the car's rear-axle
# midpoint M, driven at a steady v along MK, turns with the chassis about the centre on the
# rear axle line: its acceleration has the normal part v·v tan δ/L across MK)
WHOLE = {
    "seed_c5_e4_upper_wheel": ["Given: v_U = (−v, 0), to the left.", "Given: a_U = (−v̇, 0), to the left."],
    "seed_c5_e6_bicycle": ["Given: v_H = (v, 0), to the right.", "Given: a_H = (v̇, 0), to the right."],
    "seed_c5_e5_unequal_wheels": ["Given: v_A = (v, 0), to the right."],
    "seed_c5_1_5_pulley_block": ["Given: v_C1 = (0, −v), downwards.", "Given: v_C3 = (0, −2·v), downwards."],
    "seed_001_rolling_pair": ["Given: v_A = (0.5, 0) m/s, to the right."],
    "seed_c5_2_1_tricycle": ["Given: v_{F∈fork} = (√2·v₀/2, √2·v₀/2), along (1, 1)."],
    "car_wheel_steering": ["Given: the component of a_M along MK is 0 m/s²."],
}


@pytest.mark.parametrize("name", sorted(WHOLE))
def test_a_drivers_whole_velocity_is_stated_as_the_vector(name):
    """S6: "the component of v_U along (1; 0) is −v" where the notes write v_U = (←v): a
    datum that is the point's whole velocity is the vector, with its direction in words —
    in the Data section and where the step states it; a true component stays one."""
    _, doc = explained(name)
    text = render_of(doc, "en", "md", drawings=False)
    data = _data_text(doc)
    for line in WHOLE[name]:
        assert line in data, (name, line)
    assert not re.search(r"component of v_", text), name
    if name == "seed_c5_e4_upper_wheel":
        eu = render_of(doc, "eu", "md", drawings=False)
        assert "Datua: v_U = (−v; 0), ezkerrerantz." in eu


def _chain_ends(eq) -> list[tuple[str, str]]:
    """For each side of a velocity equation: (the point its sum is the velocity of, the
    target's point). A side starts at a point Q (v_Q) and each rotation term ω × QP moves it to
    P (v_PQ, written P-Q); components (v_P^∥, v_P^⊥) are of their own point."""
    def point_of(sub: str) -> str:
        return str(sub).split("∈")[0]

    target = point_of(eq.target.sym.sub)
    out = []
    for side in eq.sides:
        at = None
        for t in side:
            if t.kind == "point":
                at = point_of(t.sym.sub) if at is None else at
            elif t.kind == "rotation":          # v_PQ or v_{P-Q}: the velocity of P about Q
                seg = str(t.sym.sub).split(",")[0]
                at = target if seg.startswith(target) else point_of(seg.split("-")[0] if "-" in seg else seg[0])
        if at is not None:
            out.append((at, target))
    return out


@pytest.mark.parametrize("name", SEEDS)
def test_no_velocity_equation_mixes_two_points(name):
    """C5-E.4 wrote v_U = v_U^∥ + v_U^⊥ = v_{J4∈3} + v_{A1-J4}: the right side is the velocity
    of A1, not of U. Every side of a velocity equation is the velocity of the equation's own
    point: from a known point along relative terms that end there (v_A1 = v_J4∈3 + v_{A1-J4}),
    or the velocity of a point of a body said to translate (v_A1 = v_U)."""
    from kinematika.explain.document import Equation, Msg

    _, doc = explained(name)
    translating = False
    for sec in doc.sections:
        if sec.title.key != "sec.velocities":
            continue
        for b in _walk(sec):
            if isinstance(b, Msg) and b.key in ("translation.same", "translation.points", "vehicle.translation", "vehicle.translation_equal",
                                                "rolling.same"):
                translating = True
            if not isinstance(b, Equation) or b.target.kind != "point":
                continue
            for side, (at, target) in zip(b.sides, _chain_ends(b)):
                single = len(side) == 1 and side[0].kind == "point"
                assert at == target or (single and translating), (name, b.target.sym.sub, [t.sym.sub for t in side])
