"""Issue 30, fifth round (words): what the third audit still read oddly in the slides' examples
and in C5-1.7, C5-2.x and C5-E.x, each fixed as a rule (docs/explain.md, "Fifth round: words").
Every test here failed on the code before the round."""
from __future__ import annotations

import re

import pytest

from .helpers import SEEDS, rendered

P_PAIR = "seed_001_p_pair_coriolis"
ROLLING = "seed_001_rolling_pair"


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


@pytest.mark.parametrize("lang,words,absent", [
    ("eu", "Mekanismoak bi askatasun-gradu ditu.", "baldintza independente"),
    ("ca", "El mecanisme té dos graus de llibertat.", "condicions independents"),
])
def test_structure_says_the_mobility_and_no_count_of_conditions(lang, words, absent):
    """The notes write no count of unknowns or independent conditions: the structure section
    keeps the mobility (two cranks drive 001's R pairs: 2 degrees of freedom, by hand: 4 moving
    bars, 5 pins, 3·4 − 2·5 = 2) and drops the rest."""
    text = rendered("seed_001_r_pairs", lang, "md", False)
    assert words in text
    assert absent not in text and "Ezezagunak:" not in text and "Incògnites:" not in text


def test_a_guide_is_said_once_by_its_line():
    """The slides write a slide's direction "∥ XX", the guide's line; the page wrote "∥ M gida
    solidoaren gida" (the guide's name twice). The guide is the line AB (the model's `along`)."""
    text = rendered(P_PAIR, "eu", "md", False)
    assert "gida solidoaren gida" not in text
    velocities = text.split("## Abiadurak", 1)[1].split("## Azelerazioak", 1)[0]
    assert re.search(r"\+\s+v_\{B∈N rel M\}\n.*∥ AB", velocities)


@pytest.mark.parametrize("lang,held,datum", [
    ("eu", "F giltzaduran: δ̇ = 0", "Datua: ω_{gurpila rel txasisa}"),
    ("ca", "a l’articulació F: δ̇ = 0", "Dada: ω_{roda rel xassís}"),
])
def test_a_held_pin_is_a_condition_not_a_datum(lang, held, datum):
    """C5-2.1's steering is held at this instant (the notes give its angle, not a rate): the
    pin's rate 0 is said as a condition of the pin F, never as a given value."""
    text = rendered("seed_c5_2_1_tricycle", lang, "md", False)
    assert held in text
    assert datum not in text


def test_a_relative_rate_is_worked_out_before_a_term_uses_it():
    """001 rolling pair: the composition writes v_A-F = ω_R/N × FA. The page says ω_R/N first,
    composed the notes' way (ω_R = ω_R/N + ω_N), with its value: ω_R − ω_N from the answers'
    ω_R and ω_N (α likewise)."""
    text = rendered(ROLLING, "eu", "md", False)
    answers = text.split("## Erantzunak", 1)[1]

    def answer(sym: str) -> float:
        return _number(re.search(rf"\| {re.escape(sym)} \| ([−\d,]+) rad/s", answers).group(1))

    for w, unit in (("ω", "rad/s"), ("α", "rad/s²")):
        said = re.search(rf"{w}_R = {w}_{{R rel N}} \+ {w}_N ⇒ {w}_{{R rel N}} = {w}_R − {w}_N = ([−\d,]+) {unit}",
                         text)
        assert said, w
        assert abs(_number(said.group(1)) - (answer(f"{w}_R") - answer(f"{w}_N"))) < 2e-3
        used = re.search(rf"\|?{w}_\{{R rel N\}}\|?·AF", text).start()     # the term's own segment
        # (twenty-fourth round (c)); |ω|, a magnitude's factor, where the rate is negative (round 29a)
        assert said.start() < used, w


@pytest.mark.parametrize("name,lang,cor", [
    (P_PAIR, "eu", "cor"), (ROLLING, "eu", "cor"), (ROLLING, "ca", "Cor"),
])
def test_the_coriolis_term_has_one_name_a_page(name, lang, cor):
    """The step's Coriolis term, the composition's and the answers' are one quantity (2 ω × v_rel
    at one point, one relative motion): one name, the notes' a_cor at the point (the Basque
    slides' lower-case cor)."""
    text = rendered(name, lang, "md", False)
    names = set(re.findall(r"a_\{(?:Cor|cor),([^}]*)\}", text))
    assert len(names) == 1 and "∈" not in next(iter(names)), names
    assert f"a_{{{cor}," in text


def _steps(text: str, order: str, velocities: str, step: str) -> tuple[int, int]:
    listed = text.split(f"### {order}", 1)[1].split("\n## ", 1)[0]
    done = text.split(f"## {velocities}", 1)[1].split("\n## ", 1)[0]
    return (len(re.findall(r"^\d+\. ", listed, re.M)), len(re.findall(rf"^### {step} \d+", done, re.M)))


@pytest.mark.parametrize("name", [n for n in SEEDS if n.startswith(("seed_c5_2", "seed_c5_e"))])
def test_the_order_lists_the_steps_the_text_does(name):
    """C5-2.2: the order listed two steps (S1, then S2) where the text does one (a vehicle's
    wheels at once): the list and the velocity steps are the same steps."""
    text = rendered(name, "en", "md", False)
    if "### Order of solution" not in text:
        pytest.skip("no order of solution")
    listed, done = _steps(text, "Order of solution", "Velocities", "Step")
    assert listed == done, (listed, done)


def test_a_centre_on_its_path_is_written_in_one_style():
    """C5-1.7: a_C = a_C^n + a_CJ^t in the step and a_C = a_C^t + a_C^n in the curvature
    section. The notes write the intrinsic components, tangential then normal (→ r ω̇) +
    (↓ r ω²/3): one style, a_C^t + a_C^n (written once since the twentieth round (d): the
    curvature section reads ℜ_C = OC off the circle C keeps to, not off a_C again)."""
    text = rendered("seed_c5_1_7_semicylinder", "eu", "md", False)     # Basque: ^T, ^N (27th round (g))
    assert "a_CJ^T" not in text
    assert len(re.findall(r"^a_C  =\s+a_C\^T\s+\+\s+a_C\^N$", text, re.M)) == 1
    assert len(re.findall(r"^a_C  =", text, re.M)) == 1


def test_a_contact_sentence_stands_next_to_the_equation_that_uses_it():
    """C5-E.3: the right wheel's rolling sentence came between the rod's two equations; it
    comes after them, before the wheel's equation v_B = v_K∈wheel + v_B-K (its contact K)."""
    text = rendered("seed_c5_e3_wheels_with_rod", "eu", "md", False)
    rod = text.index("v_B  =  v_{I_{biela}}  +")
    sentence = text.index("K puntua *eskuineko gurpilaren* biraketa-zentro")   # the CIR section's centre (17a)
    wheel = text.index("v_B  =  v_{K∈gurpila2}")
    assert rod < sentence < wheel


def test_a_caption_names_each_arrow_by_its_point_on_the_page():
    """001's P pair draws v_B and the drag of B (the guide M's point there): the caption said
    "the velocities of B and B". Each arrow is named as its label on the figure writes it:
    the drag by its symbol v_arr,B (ninth round: "B∈M" sat under an arrow labelled v_arr,B)."""
    caption = next(line for line in rendered(P_PAIR, "eu", "md").splitlines()
                   if line.startswith("*Mekanismoa une honetan"))
    assert "B eta B puntuen" not in caption
    assert "B∈N puntuaren abiadura, arrastre-abiadura (v_{arr,B}) eta abiadura erlatiboa" in caption
