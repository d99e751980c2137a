"""Issue 30, twenty-ninth round (a): notation sentences, catalogue wording, rates' senses
(docs/explain.md, "Twenty-ninth round (a)").

The sixth reading (four teachers, one a language) quoted: a notation line that glossed a
relative point velocity as an angular velocity, of a symbol the page never wrote again; the
Basque order list "aurkitzen dira" and its fragment "RRR loturak dituzten bi elementu"; C5-2.1's
ψ̇ never called the precession; a dotted letter whose dot stood off the italic δ in HTML; C5-E.6's
note writing aᴺ for the page's a_P^N; data rates without their sense ("ω_O2E = −5 rad/s.");
magnitudes written as signed products ("ω_wheel·CJ" with ω_wheel = −ω); 001's acceleration
polygon naming "Steps 2 and 3" over Step 1's a_AO1^n, drawn from o to a. One rule an item.
"""
from __future__ import annotations

import re

import yaml

from kinematika.explain.catalogue import catalogue
from kinematika.explain.render.base import Slot

from .helpers import EXAMPLES, LANGS, SEEDS, over, rendered

NOTATION = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
# the words of an angular velocity, which a point's velocity is not
ANGULAR = {"en": "angular velocity", "es": "velocidad angular", "ca": "velocitat angular",
           "eu": "abiadura angeluarra"}
# a symbol at the head of a notation item: ψ̇, ω_N, v_{J∈pulley rel strand1}, a_J∈3
HEAD = re.compile(r"^([^\W\d_][\u0307\u0308]?(?:_(?:\{[^}]*\}|[^\s;(]+))?)")


def _notation(md: str) -> tuple[str, str] | None:
    """The page's notation line and the text after it, or None."""
    for lead in NOTATION.values():
        at = md.find("\n" + lead)
        if at >= 0:
            end = md.index("\n", at + 1)
            return md[at + 1 + len(lead):end], md[end:]
    return None


# ---- 1. the notation line glosses only what the page writes, as what it is -----------------
@over(name=SEEDS, lang=LANGS)
def test_the_notation_line_glosses_only_symbols_the_page_writes_after_it(name, lang):
    """C5-1.1's "v_{J∈pulley rel strand1} is the angular velocity of the pulley relative to the
    left strand": a velocity glossed as a rate, and a symbol written nowhere else. Every symbol
    the line glosses is written after it, and a velocity's gloss is never a rate's."""
    found = _notation(rendered(name, lang, drawings=False))
    if found is None:
        return
    line, after = found
    for item in line.rstrip(".").split("; "):
        head = HEAD.match(item)
        assert head, item
        sym = head[1]
        assert sym in after, (sym, "glossed, never written after")
        if sym[0] in "va":
            assert ANGULAR[lang] not in item, item


@over(lang=LANGS)
def test_a_relative_point_velocity_is_glossed_as_a_velocity(lang):
    """The catalogue's gloss of a symbol with "rel" chooses its words by the quantity: a point's
    velocity v_{P∈A rel B} is the velocity of A's point P (the select read `$kind` bare, which no
    key matched, and fell to the rate)."""
    cat = catalogue(lang)
    args = {"sym": "SYM", "point": "J", "body": "BODY", "other": "OTHER"}

    def kind(word: str) -> Slot:          # as the renderer hands a word to Fluent: a token
        slot = Slot(f"\ue000{word}\ue001")
        slot.plain = word
        return slot
    speed = cat.format("structure-subscript_rel", {**args, "kind": kind("speed")})
    rate = cat.format("structure-subscript_rel", {**args, "kind": kind("rate")})
    assert ANGULAR[lang] in rate and ANGULAR[lang] not in speed, speed
    assert "J" in speed


# ---- 2. the Basque order list: the bodies are solved; a dyad is a group of two ------------
@over(name=SEEDS)
def test_the_basque_order_solves_the_bodies(name):
    md = rendered(name, "eu", drawings=False)
    assert "aurkitzen dira" not in md
    assert "loturak dituzten bi elementu" not in md
    if "Ebazpen-ordena" in md and "Solidoak ordena honetan" in md:
        assert "Solidoak ordena honetan ebazten dira, bakoitza jadanik ezagunak diren solidoetatik:" in md


# the step title and the order list of 001's revolute pairs, per language (a dyad as a noun phrase)
DYAD = {"en": "RRR dyad", "es": "díada RRR", "ca": "díade RRR", "eu": "RRR loturak dituen bi elementuko taldea"}


@over(lang=LANGS)
def test_a_dyad_is_named_as_a_whole_phrase(lang):
    md = rendered("seed_001_r_pairs", lang, drawings=False)
    title = next(line for line in md.splitlines() if line.startswith("### ") and "RRR" in line)
    assert DYAD[lang] + " — " in title, title
    assert re.search(rf"^3\. {re.escape(DYAD[lang])}: ", md, re.M | re.I)     # the list capitalises it


# ---- 3. ψ̇ is the precession ---------------------------------------------------------------
PRECESSION = {"en": "the precession", "es": "la precesión", "ca": "la precessió", "eu": "prezesioa"}


def _psidot_bodies(name: str) -> list[str]:
    notation = yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text()).get("notation") or {}
    return [k for k, v in notation.items() if v == "psidot" and re.fullmatch(r"omega\(\w+\)", k)]


@over(name=SEEDS, lang=LANGS)
def test_a_rate_written_psidot_is_glossed_as_the_precession(name, lang):
    """C5-2.1's model writes the chassis' ω as ψ̇ (the notes: "la precessió ψ̇"); the gloss
    says so: "ψ̇ (la precessió) és la velocitat angular del xassís"."""
    if not _psidot_bodies(name):
        return
    line, _ = _notation(rendered(name, lang, drawings=False))
    assert f"ψ̇ ({PRECESSION[lang]})" in line, line


def test_the_tricycle_has_a_precession():
    assert _psidot_bodies("seed_c5_2_1_tricycle") == ["omega(chassis)"]


# ---- 4. a dotted letter in HTML: the dot drawn over the italic letter ----------------------
@over(name=SEEDS, lang=("ca", "en"))
def test_a_dotted_letter_is_drawn_with_its_dot_over_it(name, lang):
    """HTML: "δ̇" set with the font's combining dot put the dot right of the italic δ (read as
    δ́): the letter is written alone, in italics, and the CSS draws the dot centred over it."""
    html = rendered(name, lang, "html", drawings=False)
    text = re.sub(r"<style>.*?</style>", "", html, flags=re.S)
    assert not re.search("[\u0307\u0308]", text)
    md = rendered(name, lang, drawings=False)
    dotted = len(re.findall("[^\\W\\d_]\u0307", md))
    assert len(re.findall(r'<span class="mk dt( tl)?">[^<]</span>', html)) >= dotted > 0 or dotted == 0
    if dotted:
        assert 'span.dt::after{content:"\\02D9"}' in html


def test_the_tricycles_steering_rate_is_drawn_dotted():
    html = rendered("seed_c5_2_1_tricycle", "ca", "html", drawings=False)
    assert '<i><span class="mk dt tl">δ</span></i> = 0.' in html
    assert '<i><span class="mk dt tl">ψ</span></i> (la precessió)' in html


# ---- 5. a note's formula writes the page's symbols -----------------------------------------
def _model_texts(name: str, lang: str) -> list[str]:
    names = (yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text()).get("names") or {}).get(lang, {})
    return [t for key in ("data", "notes") for t in (names.get(key) or []) if isinstance(t, str)]


@over(name=SEEDS, lang=LANGS)
def test_a_models_words_write_a_component_as_the_page_does(name, lang):
    """C5-E.6 (eu): "aᴺ = L ((r/R) v/R_roda)²" beside the page's a_P^N: a component is
    written with its point, a_P^N, never the bare aⁿ or the small capital aᴺ."""
    for text in _model_texts(name, lang):
        assert not re.search("[aα][ⁿᴺᵗᵀ]", text), text


COMPONENT = {"en": "a_P^n", "es": "a_P^n", "ca": "a_P^n", "eu": "a_P^N"}


@over(lang=LANGS)
def test_the_bicycles_note_writes_the_normal_component_of_the_page(lang):
    md = rendered("seed_c5_e6_bicycle", lang, drawings=False)
    sym = COMPONENT[lang]
    assert f"- {sym} = " in md                       # the page's own symbol …
    assert f"{sym} = L ((r/R) v/R_" in md and f"v_P²/{sym} = (d − L)²/L" in md     # … in the note
    html = rendered("seed_c5_e6_bicycle", lang, "html", drawings=False)
    assert f"<i>a</i><sub>P</sub><sup>{sym[-1]}</sup> = L" in html


# ---- 6. a given rate with its sense; a given zero acceleration in words --------------------
GIVEN = {"en": "Given", "es": "Dato", "ca": "Dada", "eu": "Datua"}
CCW = {"en": "(counter-clockwise)", "es": "(antihorario)", "ca": "(antihorari)",
       "eu": "(erlojuaren orratzen aurkako noranzkoan)"}
CW = {"en": "(clockwise)", "es": "(horario)", "ca": "(horari)", "eu": "(erlojuaren orratzen noranzkoan)"}


@over(name=SEEDS, lang=LANGS)
def test_a_given_rate_says_its_sense(name, lang):
    """"Dato: ω_O2E = −5 rad/s." said the sign only: a given ω or α that is a nonzero number
    says its sense in words, as the answers do; a zero α says the body turns at a constant
    rate, and a zero acceleration of a point that it moves at constant velocity."""
    md = rendered(name, lang, drawings=False)
    for m in re.finditer(rf"^{GIVEN[lang]}: [ωα]\S* = (−?[\d.,]+) rad/s²?( \([^)]*\))?", md, re.M):
        number = float(m[1].replace("−", "-").replace(",", "."))
        assert number != 0, m[0]
        assert m[2] == " " + (CCW if number > 0 else CW)[lang], m[0]
    assert not re.search(rf"^{GIVEN[lang]}: a_\S+ = \(0[,;] 0\)", md, re.M)


# by hand from the models' data: 001's O2E turns at −5 rad/s (clockwise), O1A at 10 rad/s
# (counter-clockwise); the P pair's guide M at 4 rad/s (counter-clockwise), slowing at −2 rad/s²
SENSES = [("seed_001_r_pairs", "ω_O2E = −5 rad/s", CW), ("seed_001_r_pairs", "ω_O1A = 10 rad/s", CCW),
          ("seed_001_p_pair_coriolis", "ω_M = 4 rad/s", CCW), ("seed_001_p_pair_coriolis", "α_M = −2 rad/s²", CW)]


@over(lang=LANGS)
def test_the_seeds_rates_are_given_with_their_senses(lang):
    for name, given, sense in SENSES:
        md = rendered(name, lang, drawings=False)
        assert f"{GIVEN[lang]}: {given} {sense[lang]}" in md, (name, given)


STEADY = {"en": "Given: A moves at constant velocity (a_A = 0).",
          "es": "Dato: A se mueve con velocidad constante (a_A = 0).",
          "ca": "Dada: A es mou amb velocitat constant (a_A = 0).",
          "eu": "Datua: A puntua abiadura konstantez mugitzen da (a_A = 0)."}
TURNS = {"en": "Given: the *crank O1A* turns at a constant rate (α_O1A = 0).",
         "es": "Dato: la *manivela O1A* gira con velocidad angular constante (α_O1A = 0).",
         "ca": "Dada: la *manovella O1A* gira amb velocitat angular constant (α_O1A = 0).",
         "eu": "Datua: *O1A biradera* abiadura angeluar konstantez biratzen da (α_O1A = 0)."}


@over(lang=LANGS)
def test_a_zero_acceleration_given_is_said_in_words(lang):
    """001's rolling pair drives the slider A at 0.5 m/s, a_A = 0 (the model's data); 001's
    revolute pairs turn O1A at a constant 10 rad/s."""
    assert STEADY[lang] in rendered("seed_001_rolling_pair", lang, drawings=False)
    assert TURNS[lang] in rendered("seed_001_r_pairs", lang, drawings=False)


# ---- 7. a magnitude is never a signed product ------------------------------------------------
ROW = re.compile(r"^ +(?:[?M]|\S+·\S+)(?: {2,}\S+)+ *$")
FACTOR = re.compile(r"(?<![|\w])([ωα]_(?:\{[^}]*\}|[^\s·²|]+))(?=·)")


@over(name=SEEDS, lang=LANGS)
def test_a_magnitude_row_writes_no_negative_rate_bare(name, lang):
    """C5-1.7's M row "ω_wheel·CJ" with ω_wheel = −ω: a rate the page finds or is given
    negative (written "ω_X = −…") is |ω_X| in a magnitude."""
    md = rendered(name, lang, drawings=False)
    for line in md.splitlines():
        if not ROW.match(line):
            continue
        for sym in FACTOR.findall(line):
            assert not re.search(rf"(?:^|⇒ |: |; |- ){re.escape(sym)} = −", md, re.M), (sym, line)


# by hand: C5-1.7's semicylinder rolls with ω_wheel = −ω (the model's clockwise ω), C5-E.3's
# wheel 1 is given ω_wheel1 = −ω, 001's crank O2E −5 rad/s
BARRED = [("seed_c5_1_7_semicylinder", "|ω_wheel|·CJ"), ("seed_c5_e3_wheels_with_rod", "|ω_wheel1|·AJ"),
          ("seed_001_r_pairs", "|ω_O2E|·EO2"), ("seed_001_r_pairs", " ω_O1A·AO1")]


def test_the_readers_magnitudes_are_unsigned():
    for name, factor in BARRED:
        assert factor in rendered(name, "en", drawings=False), (name, factor)


# ---- 8. a polygon's caption names the steps whose terms it draws -----------------------------
STEPS = {"en": "of the equations of Steps 1 to 3", "es": "de las ecuaciones de los pasos 1 a 3",
         "ca": "de les equacions dels passos 1 a 3", "eu": "1.–3. urratsetako ekuazioen"}


@over(lang=LANGS)
def test_the_acceleration_polygon_names_step_one(lang):
    """001's revolute pairs: a_A = a_O1 + a_AO1^n + a_AO1^t with a_O1 = 0 and α_O1A = 0 (the
    data), so Step 1's one term a_AO1^n is the arrow from o1 = o to a; Step 2's a_EO2^n is drawn
    beside a_E, Step 3's four terms between the images: the caption names Steps 1 to 3."""
    md = rendered("seed_001_r_pairs", lang, drawings=False)
    caption = [line for line in md.splitlines() if line.startswith("*") and "a_O1 = a_O2 = 0" in line]
    assert len(caption) == 1 and STEPS[lang] in caption[0], caption
