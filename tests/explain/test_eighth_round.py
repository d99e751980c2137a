"""Issue 30, eighth round: what the sixth reader still edited on the five B pages, each a rule
(or the model's names where the notes' symbol was missing from the model), checked on the
notes' nineteen examples in the four languages where the rule applies."""
from __future__ import annotations

import re

import pytest
import sympy

from kinematika.explain.document import Equation, Msg, Section

from .helpers import EXAMPLES, LANGS, SEEDS, explained, rendered, section, words_of, over, model_tree


def _ask(name: str) -> list[dict]:
    return model_tree(name)["ask"]


def _asks_accelerations(name: str) -> bool:
    kinds = {k for q in _ask(name) for k in q}
    return bool(kinds & {"acceleration", "alpha", "intrinsic", "curvature", "decompose", "contact"})


# -- (a) the polygon's example letter is no symbol of the page -----------------------------------------------------
# C5-2.2's length a: "(a, A-rentzat)" beside it reads as the length's name. The caption's
# example is then one of the polygon's own images (P, the axle's midpoint: "p for P").
EXAMPLE = {"en": "({} for {})", "es": "({} para {})", "ca": "({} per a {})", "eu": "({1}-rentzat {0})"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_polygons_example_letter_is_no_symbol(lang):
    page = rendered("seed_c5_2_2_articulated", lang, drawings=False)
    assert EXAMPLE[lang].format("a", "A") not in page
    assert EXAMPLE[lang].format("p", "P") in page
    assert EXAMPLE[lang].format("a", "A") in rendered("seed_001_r_pairs", lang, drawings=False)


@over(name=SEEDS)
def test_no_caption_letters_a_parameter(name):
    parameters = model_tree(name).get("parameters") or {}
    page = rendered(name, "en", drawings=False)
    for used in re.findall(r"lettered as the point \((\w+) for (\w+)\)", page):
        assert used[0] not in parameters and used[0].upper() == used[1], (name, used)


# -- (b) the sign convention names only the rates the page uses --------------------------------------------------
ACCELERATIONS = {"en": "and accelerations are signed", "es": "y aceleraciones angulares llevan signo",
                 "ca": "i acceleracions angulars tenen signe", "eu": "abiadura eta azelerazio angeluarrek"}
VELOCITIES = {"en": "angular velocities are signed", "es": "las velocidades angulares llevan signo",
              "ca": "les velocitats angulars tenen signe", "eu": "Mugimendu laua: abiadura angeluarrek zeinua"}


@over(name=SEEDS, lang=LANGS)
def test_the_sign_convention_says_what_the_page_uses(name, lang):
    page = rendered(name, lang, drawings=False)
    _, doc = explained(name)
    accelerations = any(s.title.key == "sec.accelerations" for s in doc.sections)
    assert (ACCELERATIONS[lang] in page) == accelerations, name
    assert (VELOCITIES[lang] in page) == (not accelerations), name


# -- (c) a figure's magnitude is written as the text writes it -----------------------------------------------------
def test_a_magnitude_is_signed_as_drawn():
    """|L − s| at L = 1.2, s = 0.4 is L − s; |L − s| at L = 0.4, s = 1.2 is s − L (−(L − s));
    a factor that vanishes at the values keeps its bars."""
    from kinematika.draw.results import signed_bars

    big_l, s, v = sympy.symbols("L s v0", positive=True)
    expr = sympy.sqrt(2) * v * sympy.Abs(big_l - s) / (2 * big_l)
    assert signed_bars(expr, {big_l: 1.2, s: 0.4}) == sympy.sqrt(2) * v * (big_l - s) / (2 * big_l)
    assert sympy.simplify(signed_bars(expr, {big_l: 0.4, s: 1.2}) - sympy.sqrt(2) * v * (s - big_l) / (2 * big_l)) == 0
    assert signed_bars(expr, {big_l: 1.0, s: 1.0}).has(sympy.Abs)


@pytest.mark.parametrize("lang", LANGS)
def test_the_tricycles_figure_writes_the_texts_factor(lang):
    labels = words_of(rendered("seed_c5_2_1_tricycle", lang))
    assert r"|{L - s}|" not in labels
    assert r"\left(L - s\right)" in labels


# -- (d) C5-2.1: the notes' questions, the steering's δ̇, the front fork ----------------------------------------------
def test_the_tricycle_asks_what_the_notes_ask():
    """The notes: the chassis' centre, the precession ψ̇, the rear left wheel's centre velocity
    and its spin φ̇ — not the right wheel's velocity."""
    assert _ask("seed_c5_2_1_tricycle") == [{"icr": "chassis"}, {"omega": "chassis"}, {"velocity": "C1@chassis"}]
    for lang in LANGS:
        assert "v_{C2" not in rendered("seed_c5_2_1_tricycle", lang, drawings=False)


@over(name=SEEDS)
def test_a_seed_names_no_acceleration_it_does_not_ask(name):
    """A seed's notation spells an α (C5-2.1's ψ̈) only where the page has accelerations."""
    notation = model_tree(name).get("notation") or {}
    if any(str(k).startswith("alpha(") for k in notation):
        assert _asks_accelerations(name), name


FORK = {"en": ("*front fork*", "δ̇ = 0"), "es": ("*horquilla delantera*", "δ̇ = 0"),
        "ca": ("*forquilla davantera*", "δ̇ = 0"), "eu": ("*aurreko furka*", "δ̇ = 0")}


@pytest.mark.parametrize("lang", LANGS)
def test_the_steering_held_is_the_notes_delta_dot(lang):
    """The planar body at F is the front wheel's plane, turned by the steering: it is held,
    δ̇ = 0 (the notes' δ̇), and its rate in the table is the fork's, ψ̇ + δ̇, not the wheel's."""
    page = rendered("seed_c5_2_1_tricycle", lang, drawings=False)
    fork, held = FORK[lang]
    assert held in page and fork in page
    assert not re.search(r"ω_\{\w+ (rel|resp\.|erl|resp) \w+\} = 0", page)
    rows = re.findall(r"^\| (\*[^*]+\*) \| √2·v₀/\(2·L\) \|$", page, re.M)
    assert fork.lower() in [r.lower() for r in rows], rows
    assert "ψ̇ + δ̇ = ψ̇ + 0" in page


# -- (e) a circle rolls on a line ------------------------------------------------------------------------------------
STRAIGHT = ("Line", "Plane")


def _straight(model, body: str) -> bool:
    shapes = model.bodies[body].shapes
    return bool(shapes) and all(type(s).__name__ in STRAIGHT for s in shapes)


def _round(model, body: str) -> bool:
    return any(type(s).__name__ in ("Circle", "Disc") for s in model.bodies[body].shapes)


@over(name=SEEDS)
def test_a_circle_rolls_on_a_line(name):
    """"Les politges no llisquen al damunt del cable": the subject of a rolling sentence is
    the body with the circle, never a strand rolling on a pulley."""
    sol, doc = explained(name)
    model = sol.model
    said = [b for s in doc.sections for b in _all(s) if isinstance(b, Msg)
            and b.key in ("rolling.noslip", "rolling.same", "rolling.kept")]
    for m in said:
        rolling, on = m.args["b"].text, m.args["a"].text
        assert not (_straight(model, rolling) and _round(model, on)), (name, rolling, on)


def _all(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += _all(b) if isinstance(b, Section) else [b]
    return out


ROLLS = {"en": "*Pulley 4* rolls on *strand 5* without slipping",
         "es": "La *polea 4* rueda sin deslizar sobre el *tramo 5*",
         "ca": "La *politja 4* rodola sense lliscar sobre el *tram 5*",
         "eu": "*4. polea* *5. kable-zatiaren* gainean errodatzen da irristatu gabe"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_pulley_rolls_on_the_blocks_strand(lang):
    """C5-1.5: the block hangs on the cable's last strand, strand 5, which pulley 4 rolls on;
    the point K is the block."""
    page = rendered("seed_c5_1_5_pulley_block", lang, drawings=False)
    assert ROLLS[lang] in page, [line for line in page.splitlines() if "4" in line and "5" in line][:5]
    assert re.search(r"^\| K \| (block|bloque|bloc|blokea) \|", page, re.M)


# -- (f) a centre found from the velocities: no talk of what the joints do not do ----------------------------------
LEAD_INS = ("do not place it", "no lo sitúan", "no el situen", "ez dute kokatzen")


@over(name=SEEDS, lang=LANGS)
def test_no_centre_says_what_the_joints_do_not_do(name, lang):
    page = rendered(name, lang, drawings=False)
    assert not any(w in page for w in LEAD_INS), name


@pytest.mark.parametrize("lang,said", [("en", "I_{pulley3}: the points T4 and C3 of *pulley 3* move, relative to the *ceiling*, "
                                              "at v_{T4∈pulley3} = (0, 2·v)"),
                                       ("eu", "I_{polea3}: *3. polearen* T4 eta C3 puntuek, *sabaiarekiko*, v_{T4∈polea3} = (0; 2·v)")])
def test_the_third_pulleys_centre_from_its_two_velocities(lang, said):
    assert said in rendered("seed_c5_1_5_pulley_block", lang, drawings=False)


# -- (g) radii written as the notes write them ----------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_radius_is_renamed_rho(name, lang):
    """The radii have the model's symbols (r, R, 3·r): a relation or Willis' check writes them,
    never ρ_sprocket … "(with ρ_sprocket = r)"."""
    page = rendered(name, lang, drawings=False)
    assert not re.search(r"ρ_", page), name


@pytest.mark.parametrize("name,willis", [("seed_c5_1_4_epicyclic", "(ω_sun − ω_carrier) / (ω_ring − ω_carrier) = −3·r / r = −3."),
                                         ("seed_c5_e2_gear_change", "(ω_central − ω_arm) / (ω_ring − ω_arm) = −3·r / r = −3.")])
def test_willis_writes_the_radii(name, willis):
    """C5-1.4: ring 3r, sun r, both meshing the planet from outside and inside: (ω_s − ω_c)/
    (ω_ring − ω_c) = −3r/r = −3 (C5-E.2 likewise)."""
    assert willis in rendered(name, "en", drawings=False)


@pytest.mark.parametrize("lang,rel", [("en", "r ω_{sprocket rel frame} = R ω_{chainring rel frame}:"),
                                      ("eu", "r ω_{pinoia rel koadroa} = R ω_{platera rel koadroa}:")])
def test_the_chain_relation_is_the_notes(lang, rel):
    """C5-E.6: "r Ω_pinyó = R Ω_plat" seen from the frame."""
    assert rel in rendered("seed_c5_e6_bicycle", lang, drawings=False)


def test_a_numeric_train_keeps_its_radii_named():
    """A numeric model's radii are numbers: the relation keeps ρ and says their values."""
    page = rendered("pulley_train", "en", drawings=False)
    assert "ρ_2 ω_2 = ρ_4 ω_4 (with ρ_2 = 0.05 m, ρ_4 = 0.2 m)" in page


# -- (h) the order of the notes' questions ---------------------------------------------------------------------------
@pytest.mark.parametrize("lang", LANGS)
def test_the_pedals_centre_comes_before_the_accelerations(lang):
    """C5-E.6's first question is the pedals' centre (and rate), the second the curvature of
    P's path: the centres are said right after the velocities."""
    _, doc = explained("seed_c5_e6_bicycle")
    keys = [s.title.key for s in doc.sections]
    assert keys.index("sec.centres") == keys.index("sec.velocities") + 1 < keys.index("sec.accelerations")
    assert _ask("seed_c5_e6_bicycle")[0] == {"icr": "chainring"}


def test_a_centre_asked_after_the_accelerations_comes_after_them(tmp_path):
    import kinematika
    from kinematika.explain import build

    text = (EXAMPLES / "seed_c5_e6_bicycle.yaml").read_text(encoding="utf-8")
    text = text.replace("  - {icr: chainring}\n", "").replace("  - {curvature: P}\n",
                                                               "  - {curvature: P}\n  - {icr: chainring}\n")
    path = tmp_path / "later.yaml"
    path.write_text(text, encoding="utf-8")
    keys = [s.title.key for s in build(kinematika.solve(path)).sections]
    assert keys.index("sec.centres") > keys.index("sec.accelerations")


@pytest.mark.parametrize("lang", LANGS)
def test_the_pedals_centre_is_the_notes_c(lang):
    """The notes call the pedals' centre (the crank axle) C: "a partir de les del centre dels
    pedals (C)"."""
    page = rendered("seed_c5_e6_bicycle", lang, drawings=False)
    assert re.search(r"^\| C \| ", page, re.M) and not re.search(r"^\| K \| ", page, re.M)
    assert "v_K" not in page and "v_C" in page


# -- (i) a repeated planet is worked with its own equations ----------------------------------------------------------
SAME_WAY = ("in the same way", "de la misma manera", "de la mateixa manera", "modu berean", "era berean")


@over(name=SEEDS, lang=LANGS)
def test_no_step_is_done_in_the_same_way(name, lang):
    page = rendered(name, lang, drawings=False)
    assert not any(w in page for w in SAME_WAY), name


@pytest.mark.parametrize("name,planet", [("seed_c5_1_4_epicyclic", "planet2"), ("seed_c5_e2_gear_change", "planet2")])
def test_an_asked_planet_has_its_own_equation(name, planet):
    """C5-1.4's planet 2 (ω asked: −5ω) and C5-E.2's lower planet (2Ω): an equation with a
    term ω_planet × … gives each, as for the first planet."""
    _, doc = explained(name)
    eqs = [b for b in _all(section(doc, "sec.velocities")) if isinstance(b, Equation)]
    turning = {t.how[0].sub for eq in eqs for side in eq.sides for t in side
               if t.kind == "rotation" and t.how and getattr(t.how[0], "base", "") == "ω"}
    assert planet in turning, turning


@over(name=SEEDS)
def test_the_order_lists_the_steps_written(name):
    """Every item of the order of solution is a step the velocities write (C5-1.4's third
    planet, which nothing asks, is neither)."""
    page = rendered(name, "en", drawings=False)
    order = page.split("### Order of solution", 1)[1].split("\n## ", 1)[0] if "### Order of solution" in page else ""
    items = re.findall(r"^(\d+)\. ", order, re.M)
    velocities = page.split("## Velocities", 1)[1].split("\n## ", 1)[0]
    steps = re.findall(r"^### Step (\d+)", velocities, re.M)
    assert items == [str(i) for i in range(1, len(items) + 1)]
    assert len(items) == len(steps), (name, items, steps)


def test_a_marked_symbol_is_set_in_the_sans_font():
    """HTML: the serif italic sets δ̇'s dot into the δ's curl (read as δ = 0): a notation's
    letter with a combining mark is set as a marked parameter is, in the sans font."""
    html = rendered("seed_c5_2_1_tricycle", "ca", "html", drawings=False)
    assert '<i><span class="mk dt tl">δ</span></i> = 0.' in html     # the dot drawn over it (round 29a)
    assert "<i>δ̇</i>" not in html
