"""Issue 30, sixteenth round (g): words and notation an English and Spanish teacher quoted on
main's pages (en 6 A / 13 B, es 5 A / 14 B) — Spanish calques of English prepositions ("a s a
lo largo de la guía", "por B a β", "a r φ̇", "a la distancia del radio de su rueda del suelo",
said twice), a spin read off a vector over a length (φ̇ = v_C1 / r), "its centre is at
infinity", nested subscripts in Markdown (v_{CI_{pulley}}), two bar characters (∣v_P∣ beside
|v_P|), a body's name upright in a model's words ("centre of pulley 1" beside "*pulley 2*")
and the centres' intro naming a centre the page never places (C5-E.1's I_OC). Each test is a
rule over the 19 seeds in the languages where it applies and fails on main at 158f758."""
from __future__ import annotations

import re


from .helpers import LANGS, SEEDS, SVG, body_of, rendered, over

CODE = re.compile(r"```.*?```", re.S)
SPIN_SEEDS = ("seed_c5_2_1_tricycle", "seed_c5_2_2_articulated")


def _text(name: str, lang: str) -> str:
    return SVG.sub("", body_of(rendered(name, lang)))


# 1. prepositions --------------------------------------------------------------------------
CALQUES = {
    "es": (r"\ba s a lo largo\b", r"\bpor B a β", r"en el plano de la rueda a r\b", r"a la distancia del radio"),
    "ca": (r"\ba s al llarg\b", r"\bper B a β", r"en el pla de la roda a r\b", r"a la distància del radi"),
}


@over(name=SEEDS, lang=sorted(CALQUES))
def test_no_calques_of_english_prepositions(name, lang):
    """'a s a lo largo de la guía' is 'a una distancia s de A a lo largo de la guía'; 'por B a
    β' is 'que pasa por B y forma un ángulo β con la horizontal'; a speed is 'con celeridad
    r φ̇'; a wheel's centre 'se mantiene a una altura igual al radio de su rueda'."""
    text = _text(name, lang)
    bad = [c for c in CALQUES[lang] if re.search(c, text)]
    assert not bad, (name, lang, bad)


def test_the_calques_replaced_by_hand():
    """The Spanish sentences the teacher asked for, word for word."""
    assert "a una distancia s de A a lo largo de la *guía M*" in _text("seed_001_p_pair_coriolis", "es")
    assert "que pasa por B y forma un ángulo β con la horizontal" in _text("seed_001_rolling_pair", "es")
    assert "se mueve en el plano de la rueda con celeridad r φ̇" in _text("seed_c5_2_1_tricycle", "es")
    assert "con celeridad r ω′" in _text("seed_c5_2_2_articulated", "es")
    e5 = _text("seed_c5_e5_unequal_wheels", "es")
    assert "A y B se mantienen siempre a una altura igual al radio de su rueda sobre el suelo plano" in e5


@over(name=SEEDS, lang=LANGS)
def test_a_reason_for_translating_is_said_once(name, lang):
    """The reason a body does not turn (its wheels' centres on one line or on parallel lines)
    is said at velocities; α = 0 refers to it instead of saying it again (C5-E.5)."""
    text = _text(name, lang)
    remarks = re.findall(r"^[ωα]_\S+ = 0 (\(.{40,}\))$", text, re.M)
    assert len(remarks) == len(set(remarks)), (name, lang, remarks)


# 2. a magnitude over a length --------------------------------------------------------------
@over(name=SPIN_SEEDS, lang=LANGS)
def test_a_spin_is_a_magnitude_over_a_length(name, lang):
    """C5-2.1 by hand: C1 rolls, so r φ̇ = |v_C1|, φ̇ = |v_{C1∈chassis}| / r = v₀ (L − s)/(√2 L r);
    never the vector v_C1 over the length r."""
    text = _text(name, lang)
    assert not re.search(r"= [va]_\S+ / r\b", text), (name, lang)
    assert re.search(r"= \|v_\S+\| / r = ", text), (name, lang)


def test_tricycle_spin_by_hand():
    """φ̇ = |v_{C1∈chassis}| / r = √2·v₀·(L − s)/(2·L·r) (the notes: v₀ (L − s)/(√2 L r))."""
    assert "φ̇ = |v_{C1∈chassis}| / r = √2·v₀·(L − s)/(2·L·r)" in _text("seed_c5_2_1_tricycle", "en")


# 3. the instant centre at infinity ---------------------------------------------------------
@over(name=SEEDS)
def test_a_centre_at_infinity_is_the_instant_centre(name):
    """'(its instant centre is at infinity)', never 'its centre is at infinity' (a wheel's
    centre is a point of the page); Basque 'biraketa-zentro instantaneoa', not 'zentroa'."""
    assert not re.search(r"\b(its|their) centre is at infinity", _text(name, "en")), name
    assert not re.search(r"(?<!instantaneoa )\bzentroa infinituan", _text(name, "eu")), name


def test_articulated_translates_by_hand():
    """C5-2.2: C1 and C2 have one velocity, so S1 translates, ω_S1 = 0 (twenty-eighth round (d):
    the velocity step says the translation and ω = 0, as the notes do, not where the centre is)."""
    page = _text("seed_c5_2_2_articulated", "en")
    assert "so the *chassis S1* translates: every point has the velocity (r·ω, 0)." in page
    assert "ω_S1 = 0 (it translates)" in page


# 4. a centre written one way in Markdown ------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_nested_subscript_in_markdown(name, lang):
    """A velocity to a centre was written v_{C,I_pulley} here (the notes' v_C,I), so that no
    subscript stood inside a subscript; the twenty-seventh round (g) writes the centre one
    way on the page, I_{pulley} everywhere, and the velocity to it as the segment to it,
    v_{CI_{pulley}} as v_CJ is the segment CJ (a Basque teacher read I_polea, I_{polea} and
    v_{C,I_polea} on one page): no comma before a centre, no centre with an open subscript."""
    text = _text(name, lang)
    assert not re.search(r",I_", text), (name, lang)
    assert not re.search(r"I_(?!\{)\w", text), (name, lang)


def test_pulley_on_cable_by_hand():
    """C5-1.1: v_C = v_{I_{pulley}} + v_{CI_{pulley}}, v_{CI_{pulley}} = ω_pulley × I_{pulley}C."""
    text = _text("seed_c5_1_1_pulley_on_cable", "en")
    assert "v_{CI_{pulley}} = ω_pulley × I_{pulley}C" in text
    html = rendered("seed_c5_1_1_pulley_on_cable", "en", "html")
    assert "CI_{" not in html


# 5. one bar character -------------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_one_bar_character(name, lang):
    """A magnitude's bars are '|' on every page, in every format: no '∣' (U+2223)."""
    for fmt in ("md", "html"):
        assert "\u2223" not in SVG.sub("", rendered(name, lang, fmt)), (name, lang, fmt)


def test_semicylinder_answers_keep_the_bars():
    """C5-1.7's answer to the tangential and normal accelerations writes |v_P| = 2·r·ω."""
    assert "|v_P| = 2·r·ω" in _text("seed_c5_1_7_semicylinder", "en")


# 6. a body's name marked the same way ---------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_a_body_name_is_always_in_italics(name, lang):
    """Where a body's name is written in italics anywhere on the page, it is never written
    upright as a whole word in the model's own words (the Data section: its statements and
    the tables of what each symbol, point and body is), outside a symbol."""
    text = CODE.sub("", _text(name, lang))
    marked = set(re.findall(r"(?<![\w*])\*([^*\n]+)\*(?![\w*])", text))
    data = re.search(r"^## .*?\n(.*?)^## ", text, re.S | re.M)
    prose = re.sub(r"\*[^*\n]+\*", " ", data.group(1) if data else "")
    prose = re.sub(r"\S*_\{[^{}]*\}\S*", " ", prose)     # symbols: ω_{moving pulley rel arm}
    prose = re.sub(r"\S*[_^∈]\S*", " ", prose)           # I_pulley1, O∈wheels (a figure's label)
    prose = re.sub(r"^#.*$", " ", prose, flags=re.M)      # the title
    bare = [m for m in marked if sum(c.isalpha() for c in m) >= 3 and not m.startswith(("Notation", "Nota"))
            and re.search(rf"(?<![\w.]){re.escape(m)}(?![\w])", prose)]
    assert not bare, (name, lang, bare[:4])


def test_pulley_block_points_by_hand():
    """C5-1.5's point table: 'centre of *pulley 1*', as the bodies' table writes *pulley 1*."""
    assert "| C1 | centre of *pulley 1* |" in _text("seed_c5_1_5_pulley_block", "en")


# 7. the centres' intro names a centre the page places ----------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_the_centres_intro_names_a_centre_the_page_uses(name, lang):
    """The symbol the first sentence of 'Instant centres' takes as its example is used again."""
    text = CODE.sub("", _text(name, lang))
    lines = text.split("\n")
    for k, line in enumerate(lines):
        m = re.search(r"\((I_\S+?)\)", line)
        if m and ("rel" in line or "erl" in line) and re.search(r"\bI\b", line):
            rest = "\n".join(lines[k + 1:])
            assert m.group(1) in rest, (name, lang, m.group(1))
