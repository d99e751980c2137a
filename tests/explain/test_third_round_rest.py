"""Issue 30, third round, the remaining defects of the second audit (docs/explain.md,
"Method (third round)"), each a rule checked over the four languages:

- C5-1.8: the notes' final list gives each of the three coincident points its own line: the
  answers table gives each point's v and a a row of its own, labelled by its symbol; the
  bar OC's angular velocity is ω_OC beside its α_OC (one letter for one kind of quantity).
- C5-2.1: a driven pin's rate is given by its symbol, ω_{b rel a} = value, the one the
  composition uses; a centre the velocity steps placed and found velocities from is not
  "checked" against them again.
- Every contact point the page names is defined in the Data section (C5-E.4: J6).
- C5-E.6: the note on the notes' slip writes ℜ_P (a radius of curvature), not ρ (a circle's radius).
- Lengths with their unit in the model's data sentences (C5-1.2); a position by a symbolic
  distance said as a distance (C5-2.2's C1); a polygon's o′ explained in its caption (C5-E.1).
- Catalan: "relative to" in a subscript is rel. (relatiu a); REL stays the moving frame's name.
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, explained, rendered, over


def _answers(page: str) -> list[str]:
    """The rows of the answers table (the last table of the page's last sections)."""
    head = re.search(r"^## (Answers|Respuestas|Respostes|Erantzunak)$", page, re.M)
    assert head, "no answers section"
    return [line for line in page[head.end():].splitlines() if line.startswith("| ")]


@pytest.mark.parametrize("lang", LANGS)
def test_contact_points_one_row_each(lang):
    """C5-1.8: six rows v/a of J∈ground, J∈wheel and J^geom, each with its value alone."""
    rows = _answers(rendered("seed_c5_1_8_contact_points", lang, drawings=False))
    firsts = [row.split("|")[1].strip() for row in rows]
    for sym in ("v_{J^{geom}}", "a_{J^{geom}}"):
        assert sym in firsts, (lang, firsts)
    wheel = {"en": "wheel", "es": "rueda", "ca": "roda", "eu": "gurpila"}[lang]
    assert f"a_{{J∈{wheel}}}" in firsts, (lang, firsts)
    row = rows[firsts.index("a_{J^{geom}}")]
    assert row.split("|")[2].strip() == "(0, −2·r·ω₀²/9)".replace(",", "," if lang == "en" else ";"), row


@pytest.mark.parametrize("lang", LANGS)
def test_bar_rate_one_letter(lang):
    """C5-1.8: the bar OC turns at ω_OC = −ω₀/3, with α_OC; no Ω_OC beside them."""
    page = rendered("seed_c5_1_8_contact_points", lang, drawings=False)
    assert "Ω_OC" not in page
    # read off the term's x component on a symbolic page (twenty-fifth round d)
    # the arm OC = (0, 3r) written first (twenty-eighth round d)
    assert re.search(r"^OC = \(0[,;] 3·r\); .*: v_CO = −ω_OC·\(3·r\) ⇒ ω_OC = −ω₀/3$", page, re.M) and "α_OC" in page


@pytest.mark.parametrize("lang", LANGS)
def test_held_pin_by_its_symbol(lang):
    """C5-2.1: the steering held is said by the rate the composition uses, the notes' δ̇ = 0
    (since the eighth round; ω_{front wheel rel chassis} = 0 before; no α since the seventh
    round: the notes ask no acceleration), not as "the relative angular velocity at the pin F" — and,
    since the fifth round, as a condition of the pin F, not a datum (test_fifth_round_words); and
    the chassis' centre, placed in the velocity step and giving its velocities, is not
    checked again against them at the end."""
    page = rendered("seed_c5_2_1_tricycle", lang, drawings=False)
    given = [line for line in page.splitlines() if re.match(r"(Given|Dato|Dada|Datua): ", line)]
    rel = re.compile(r"(δ̇|(ω|α)_\{[^}]+\}) = 0\.$")
    held = [line for line in page.splitlines() if rel.search(line) and line not in given]
    assert held and all(line.endswith("δ̇ = 0.") for line in held), held
    assert not any(rel.search(line) for line in given), given
    check = {"en": "Check with the velocities", "es": "Comprobación con las velocidades",
             "ca": "Comprovació amb les velocitats", "eu": "Egiaztapena aurkitutako abiadurekin"}[lang]
    assert check not in page


@over(name=SEEDS)
def test_every_contact_named_is_in_data(name):
    """Every contact point the page names (J6 in C5-E.4's structure table and centres, in no
    equation) is a row of the Data section's points."""
    from kinematika.draw.names import contact_names

    sol, _ = explained(name)
    page = rendered(name, "en", drawings=False)
    data, rest = page.split("\n## Structure", 1)
    rows = {line.split("|")[1].strip() for line in data.splitlines() if line.startswith("| ")}
    kept, in_code = [], False                 # not the M / D / ? marks ("M": magnitude known)
    for line in rest.splitlines():
        if line.startswith("```"):
            in_code = not in_code
        elif not (in_code and "=" not in line) and not re.search(r"(?<!\S)\?(?!\S)", line):
            kept.append(line)
    rest = "\n".join(kept)
    named = {c for c in contact_names(sol.model, sol).values() if re.search(rf"(?<![\w']){re.escape(c)}(?![\w'′])", rest)}
    assert named <= rows, sorted(named - rows)


@pytest.mark.parametrize("lang", LANGS)
def test_bicycle_curvature_radius_is_a_length(lang):
    """C5-E.6: the note correcting the notes writes P's radius of curvature with the page's
    ℜ (ρ is a circle's radius) and defines the d it uses: ℜ_P = (d − L)²/L with d = R_roda R/r,
    a length; the same formula as the curvature section's (R R_roda − L r)²/(L r²), the
    square written as the note's (d − L)² (d > L at the figure's numbers: sixth round)."""
    page = rendered("seed_c5_e6_bicycle", lang, drawings=False)
    w = {"ca": "R_roda", "en": "R_wheel", "es": "R_rueda", "eu": "R_gurpila"}[lang]   # the model's notation
    note = page[page.rindex(f"ℜ = (R/r)² {w}"):]
    assert "ρ" not in note
    normal = "N" if lang == "eu" else "n"        # the Basque slides' a^N (twenty-seventh round (g))
    assert f"ℜ_P = v_P²/a_P^{normal} = (d − L)²/L" in note and f"d = {w} R/r" in note   # v_P: twenty-fourth round (e)
    assert f"ℜ_P = |v_P|² / |a_P^{normal}| = (R·{w} − L·r)²/(L·r²)" in page


@pytest.mark.parametrize("lang", LANGS)
def test_data_sentences_and_captions_read(lang):
    """C5-1.2's chosen geometry gives its lengths in the page's unit (s = 3 m, not "s = 3 from
    K0"); a position by a symbolic distance reads as one (C5-2.2: "C1 is at a distance a
    from O", not "C1 is a from O"); a polygon that labels a point O's image o′ says why."""
    page = rendered("seed_c5_1_2_bar_on_inclined_wheels", lang, drawings=False)
    assert "s = 3 m" in page and "(y = 2 m)" in page and "x = −5 m" in page
    page = rendered("seed_c5_2_2_articulated", lang, drawings=False)
    line = next(x for x in page.splitlines() if x.startswith("C1 "))
    assert {"en": "at a distance a from O", "es": "a una distancia a de O", "ca": "a una distància a d’O",
            "eu": "O puntutik a distantziara"}[lang] in line, line
    page = rendered("seed_c5_e1_cavity", lang)
    said = {"en": "o′, the image of the fixed point O of the arm OC, is at the pole o",     # round 21e, 25d
            "es": "o′, la imagen del punto fijo O del brazo OC, está en el polo o",
            "ca": "o′, la imatge del punt fix O del braç OC, és al pol o",
            "eu": "o′, OC besoaren O puntu finkoaren irudia, o poloan dago"}[lang]
    assert said in page


@over(name=SEEDS)
def test_catalan_rel_names_the_frame_only(name):
    """The Catalan notes keep REL as the name of the moving frame (v_REL, Ω_REL); "relative
    to" joins two names with rel. (relatiu a): ω_{politja fixa rel. braç}, never
    ω_{politja fixa REL braç}, where REL would read as a third body (C5-1.6)."""
    for fmt in ("md", "html"):
        text = rendered(name, "ca", fmt, drawings=False)
        joined = re.search(r"[_>{][^}<\n]*\w REL \w[^}<\n]*[}<]", text)
        assert joined is None, text[joined.start() - 40:joined.end() + 20]
    if name == "seed_c5_1_6_belt":
        assert "ω_{politja1 rel braç}" in rendered(name, "ca", "md", drawings=False)
