"""Issue 30, seventeenth round (a): what two teachers read on main (98eae38), each a rule
over the 19 seeds in the languages where it applies, failing on that output:

1. a vehicle's instant centre in a subscript without its body ("v_FI = ψ̇ × I_{chassis}F",
   v_C1I, v_PI, v_C4I) and a one-term equation v_F∈chassis = v_FI;
2. something derived twice: C5-1.3's support "… so it is the instant centre of the support"
   after the centres section placed it; C5-1.5's "I_pulley3 = (9r/2, −4r): placed in Step
   3"; 001's composition sections writing again the sum a step wrote;
3. C5-1.8's "α_OC = |a_CO^t| / OC = 0" where ω_OC is constant;
4. C5-2.2's left wheel C3 placed "on the right as one looks from O towards P";
5. bodies in the structure table that no step works out and the table of rates leaves out
   (C5-1.2's wheels, C5-1.4's third planet, C5-E.6's front wheel)."""
from __future__ import annotations

import re

import pytest
import sympy

from kinematika.explain.document import Derived, Equation, Msg, Table

from .helpers import LANGS, SEEDS, explained, rendered, over

SUB = re.compile(r"v_(\{[^{}]*(?:\{[^{}]*\}[^{}]*)*\}|[A-Za-z0-9]+)")


def _page(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


# -- 1. the centre's full symbol, the composition about it ------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_velocity_subscript_ends_in_a_bare_centre(name: str, lang: str) -> None:
    """No v_FI, v_C1I, v_PI, v_C4I: a subscript ending in a bare I that is no point of the
    model reads as a point I; the centre is written in full, v_{FI_{chassis}}."""
    sol, _ = explained(name)
    points = set(sol.model.points) if hasattr(sol.model, "points") else set()
    for m in SUB.finditer(_page(name, lang)):
        sub = m.group(1).strip("{}")
        if sub.endswith("I") and len(sub) > 1 and "I" not in points and sub not in points:
            pytest.fail(f"{name} {lang}: v_{m.group(1)}")


@over(name=["seed_c5_2_1_tricycle", "seed_c5_2_2_articulated"], lang=LANGS)
def test_a_velocity_about_the_centre_is_the_notes_composition(name: str, lang: str) -> None:
    """Each equation about the chassis' centre is v_P = v_{I_b} + v_{P I_b} (v_{I_b} = 0),
    never the one-term v_P = v_PI."""
    page = _page(name, lang)
    # Markdown writes the velocity about a centre as the segment to it, v_{FI_{b}}, the centre
    # braced as everywhere on the page (twenty-seventh round (g); sixteenth round: v_{F,I_b})
    lines = [ln for ln in page.splitlines() if re.search(r"v_\{\w+I_\{", ln) and "  =  " in ln]
    assert lines, (name, lang)
    for ln in lines:
        assert re.search(r"=\s+v_\{I_\{\w+\}\}\s+\+\s+v_\{\w+I_\{", ln), (name, lang, ln)
    assert re.search(r"v_\{I_\{\w+\}\} = 0", page), (name, lang)


# -- 2. a result derived once ------------------------------------------------------------------
def _placed_first(doc) -> set[str]:
    """Bodies whose centre the centres section before the velocities puts at a joint."""
    titles = [s.title.key for s in doc.sections]
    if "sec.centres" not in titles or "sec.velocities" not in titles:
        return set()
    if titles.index("sec.centres") > titles.index("sec.velocities"):
        return set()
    sec = doc.sections[titles.index("sec.centres")]
    return {b for n in sec.blocks if getattr(n, "how", None) == "joint" for b in n.pair}


@over(name=SEEDS)
def test_a_contact_the_centres_section_placed_is_referred_to(name: str) -> None:
    """C5-1.3: "I_support: the contact point J" in the centres section, then a step saying
    again "the support rolls … so it is the instant centre of the support": the step refers
    to the section (centre.site) instead."""
    _, doc = explained(name)
    placed = _placed_first(doc)
    for b in doc.blocks():
        if isinstance(b, Msg) and b.key == "rolling.centre":
            assert b.args["b"].text not in placed, (name, b.args["b"].text)


STEP_AGAIN = {"en": r"I_\S+ = \([^)]*\): placed in Step", "es": r"I_\S+ = \([^)]*\): hallado en el paso",
              "ca": r"I_\S+ = \([^)]*\): trobat al pas", "eu": r"I_\S+ = \([^)]*\): \d+\. urratsean aurkitua"}


@over(name=SEEDS, lang=LANGS)
def test_a_centre_a_step_found_is_not_written_again(name: str, lang: str) -> None:
    """C5-1.5 "I_pulley3 = (9r/2, −4r): placed in Step 3" after Step 3 wrote it: the closing
    section names it and its step, without the value again."""
    assert not re.search(STEP_AGAIN[lang], _page(name, lang)), (name, lang)


def test_the_reader_s_centres_name_their_step() -> None:
    for name, lang, line in (("seed_c5_1_5_pulley_block", "ca", "I_{politja3}: trobat al pas 3"),
                             ("seed_c5_2_1_tricycle", "en", "I_{chassis}: placed in Step 1")):
        assert line in _page(name, lang), (name, lang)


@over(name=SEEDS)
def test_the_composition_does_not_sum_again_what_a_step_summed(name: str) -> None:
    """001's v_B = v_arr,B + v_rel,B where Step 2 wrote v_{B∈rocker} = v_{B∈M} + v_{B∈N rel M}:
    no equation of the composition section has a drag term and a point a step's equation
    reached by sliding along the same guide."""
    _, doc = explained(name)
    slid = {(eq.level, eq.point.point) for sec in doc.sections if sec.title.key in ("sec.velocities", "sec.accelerations")
            for eq in sec.leaves() if isinstance(eq, Equation) and eq.point is not None
            for side in eq.sides for t in side if t.kind == "slide" and t.sym.sub.startswith(f"{eq.point.point}∈")}
    for sec in doc.sections:
        if sec.title.key != "sec.composition":
            continue
        for eq in (b for b in sec.blocks if isinstance(b, Equation)):
            if eq.point is not None and any(t.kind == "drag" for side in eq.sides for t in side):
                assert (eq.level, eq.point.point) not in slid, (name, eq.level, eq.point.point)


@pytest.mark.parametrize("lang", LANGS)
def test_001_composition_refers_to_step_2(lang: str) -> None:
    # (twenty-seventh round (e): the equation with which the step found it, never one "which found")
    words = {"en": "is the equation with which Step 2 found", "es": "es la ecuación del paso 2", "ca": "és l’equació del pas 2",
             "eu": "aurkitzeko erabilitako ekuazioa"}[lang]
    for name in ("seed_001_p_pair_coriolis", "seed_001_rolling_pair"):
        assert _page(name, lang).count(words) == 2, (name, lang)


# -- 3. an angular acceleration from a constant rate -------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_zero_alpha_read_off_a_bar_of_centres(name: str, lang: str) -> None:
    """No "α_OC = |a_CO^t| / OC = 0": a line of centres turning at a constant rate has α = 0
    by its constancy."""
    assert not re.search(r"α_[A-Z]\w* = −?\|a_\w+\^t\| / \w+ = 0(?![\d.,])", _page(name, lang)), (name, lang)


def test_c5_1_8_alpha_oc_from_constancy() -> None:
    """By hand: J^geom's bar OC (length 3r) turns at ω_OC = v_C / 3r = −ω₀/3 (C at r ω₀
    clockwise about O), fixed by the radii and the wheel's constant ω₀: α_OC = 0."""
    _, doc = explained("seed_c5_1_8_contact_points")
    d = next(b for b in doc.blocks() if isinstance(b, Derived) and b.sym.base == "α" and b.sym.sub == "OC")
    assert d.how == [] and d.remark is not None and d.remark.key == "how.constant_speed"   # round 29 c
    assert sympy.simplify(sympy.sympify(d.value.value)) == 0
    w0 = sympy.Symbol("w0", positive=True)
    assert sympy.simplify(sympy.sympify(d.remark.args["value"].value) + w0 / 3) == 0
    for lang, word in (("en", "is constant"), ("es", "es constante"), ("ca", "és constant"), ("eu", "konstantea da")):
        assert re.search(r"α_OC = 0 \(C .*ω_OC = −ω₀/3 " + word, _page("seed_c5_1_8_contact_points", lang)), lang


# -- 4. a vehicle's sides looking the way it moves ---------------------------------------------
SIDES = {"en": ("on the left as one looks from P towards O", "on the right as one looks from P towards O"),
         "es": ("a la izquierda mirando desde P hacia O", "a la derecha mirando desde P hacia O"),
         "ca": ("a l’esquerra mirant de P cap a O", "a la dreta mirant de P cap a O"),
         "eu": ("P puntutik O puntura begiratuta ezkerretara", "P puntutik O puntura begiratuta eskuinetara")}


@pytest.mark.parametrize("lang", LANGS)
def test_c5_2_2_left_wheel_on_the_left(lang: str) -> None:
    """By hand: S2's axle midpoint P = a(−√2/2, −√2/2); S2 moves from P towards O (v_P =
    (rω/2, rω/2)); C3 = P + (a/2)(−√2/2, √2/2) is to the left of P→O, the notes' left wheel."""
    page = _page("seed_c5_2_2_articulated", lang)
    c3 = next(ln for ln in page.splitlines() if ln.startswith("C3 "))
    c4 = next(ln for ln in page.splitlines() if ln.startswith("C4 "))
    assert SIDES[lang][0] in c3 and SIDES[lang][1] in c4, (lang, c3, c4)


@over(name=SEEDS)
def test_a_named_side_matches_the_words(name: str) -> None:
    """Every English point named a left (right) wheel is placed on the left (right)."""
    sol, _ = explained(name)
    names = sol.model.wording.points.get("en", {}) if hasattr(sol.model.wording, "points") else {}
    page = _page(name, "en")
    for p, words in names.items():
        line = next((ln for ln in page.splitlines() if ln.startswith(f"{p} is at a distance")), None)
        if line is None or "as one looks" not in line:
            continue
        if re.search(r"\bleft\b", words) and not re.search(r"\bright\b", words):
            assert "on the left" in line, (name, p, line)
        if re.search(r"\bright\b", words) and not re.search(r"\bleft\b", words):
            assert "on the right" in line, (name, p, line)


# -- 5. every listed body's rate ---------------------------------------------------------------
def _rates_table(doc) -> set[str]:
    sec = next(s for s in doc.sections if s.title.key in ("sec.rates_summary", "sec.rates_summary_v"))
    table = next(b for b in sec.blocks if isinstance(b, Table))
    return {r[0].text for r in table.rows}


@over(name=SEEDS)
def test_every_listed_body_has_its_rate_or_is_said_unused(name: str) -> None:
    """A moving body of the structure table is in the table of rates, or a sentence says it
    does not enter the question; no α cell is left "—" for a body given its rate."""
    from kinematika.explain.context import Ctx

    sol, doc = explained(name)
    if sol.model.default_questions:
        return
    ctx = Ctx(sol)
    from kinematika.explain.drives import drives

    runs = {d.line for d in drives(ctx)}       # a belt's run: no rate (round 29 c)
    listed = [b for b in sol.model.moving_bodies if not ctx.fixed(b) and b not in runs]
    unused = {n.text for b in doc.blocks() if isinstance(b, Msg) and b.key == "idle.unused"
              for n in b.args["bodies"].items}
    rows = _rates_table(doc)
    for b in listed:
        assert b in rows or b in unused, (name, b)


def _value(doc, base: str, body: str):
    d = next(b for b in doc.blocks() if isinstance(b, Derived) and b.sym.base == base and b.body == body)
    return sympy.sympify(d.value.value)


def _free(expr, name: str):
    return next(s for s in expr.free_symbols if s.name == name)


def test_the_reader_s_idle_bodies_by_hand() -> None:
    """C5-1.4's third planet: its centre A3 at 2r on the carrier (ω), its contact with the
    ring (−ω, radius 3r): ω_3 = (−3rω − 2rω)/r = −5ω, the first planet's.
    C5-E.6's front wheel rolls on the ground, its centre at the frame's speed v: ω = −v/R_roda,
    α = −v̇/R_roda. C5-1.2's two wheels each roll on a fixed plane. Since round 27b each is
    worked out by the equations of its own kind (its centre, its contact), never by the
    shortcut lines "by symmetry" or "its contact point is its instant centre, so" (`idle`)."""
    _, doc = explained("seed_c5_1_4_epicyclic")
    w3 = _value(doc, "ω", "planet3")
    assert sympy.simplify(w3 + 5 * _free(w3, "w")) == 0
    _, doc = explained("seed_c5_e6_bicycle")
    w, a = _value(doc, "ω", "front"), _value(doc, "α", "front")
    assert sympy.simplify(w + _free(w, "v") / _free(w, "R_roda")) == 0
    vdot = next(s for s in a.free_symbols if s.name != "R_roda")
    assert sympy.simplify(a + vdot / _free(a, "R_roda")) == 0
    for name in ("seed_c5_1_4_epicyclic", "seed_c5_e6_bicycle", "seed_c5_1_2_bar_on_inclined_wheels"):
        _, doc = explained(name)
        assert not [b for b in doc.blocks() if isinstance(b, Msg) and b.key.startswith("idle.")], name
