"""Names as a teacher writes them in the explanations (θ₂, ω with the subscript link5, x
with the subscript B), in formulas, prose, definitions and captions, while the answers keep
sympy's syntax; the expected texts are written by hand."""
from __future__ import annotations

import json
import re

import pytest
import sympy
from typer.testing import CliRunner

import kinematika
from kinematika.cli import app as cli
from kinematika.explain import build, render
from kinematika.explain.render.names import html_name, latex_name, unicode_name

from tests.conftest import sampled
from tests.core.models import jansen as jansen_model

from .helpers import model_tree

def crank(parameters: dict, distance: str, angle: str, body: str, omega: str) -> str:
    """A crank O–A turned by a driver, placed polar: the smallest model with formulas."""
    given = "".join(f"\n  {k}: {v}" for k, v in parameters.items())
    return f"""name: Names
parameters:{given}
points:
  O: [0, 0]
  A: {{from: O, distance: {distance}, angle: {angle}}}
bodies:
  ground: [O]
  {body}: [O, A]
joints:
  - {{type: revolute, bodies: [ground, {body}], at: O}}
drivers:
  - {{omega: {body}, value: {omega}, alpha: 0}}
ask:
  - {{velocity: A}}
"""


LINK = crank({"atheta": 2, "theta": "deg(30)", "theta2": "deg(20)", "omega_link5": 3},
             "atheta", "theta + theta2", "link5", "omega_link5")
# parameters spelt as sympy's constants and a Python keyword; deg(90) brings in the constant π
CONSTANTS = crank({"pi": "deg(30)", "E": 3, "I": 2, "lambda": 5}, "lambda*I", "pi + deg(90)", "crank", "E")


@pytest.mark.parametrize("name, text, html", [
    ("theta", "θ", "θ"), ("theta2", "θ₂", "θ<sub>2</sub>"), ("alpha3", "α₃", "α<sub>3</sub>"),
    ("Omega", "Ω", "Ω"), ("lambda", "λ", "λ"), ("phi12", "φ₁₂", "φ<sub>12</sub>"),
    ("omega_link5", "ω_link5", "ω<sub>link5</sub>"), ("x_B", "x_B", "x<sub>B</sub>"),
    ("v0x_link", "v0x_link", "v0x<sub>link</sub>"), ("omega_left_arm", "ω_left_arm", "ω<sub>left_arm</sub>"),
    ("x_theta", "x_θ", "x<sub>θ</sub>"), ("x__2", "x²", "x<sup>2</sup>"), ("w2", "w₂", "w<sub>2</sub>"),
    ("atheta", "atheta", "atheta"), ("thetas", "thetas", "thetas"), ("d", "d", "d"),
    ("pi", "pi", "pi"), ("pi2", "pi₂", "pi<sub>2</sub>"), ("E", "E", "E"), ("I", "I", "I"),
    ("x_", "x_", "x_"), ("θ2", "θ₂", "θ<sub>2</sub>"),
])
def test_names_by_hand(name, text, html):
    assert unicode_name(name) == text
    assert html_name(name) == html


def test_latex_names_are_sympys_but_pi_and_words():
    """LaTeX as sympy writes the symbol in a formula (so text and formulas agree), but a
    subscript that is a word upright (ω_link5 a word under ω, not l·i·n·k in italics,
    as HTML and Markdown show it); a parameter named pi is the word, the constant stays \\pi."""
    for name, tex in [("theta2", r"\theta_{2}"), ("x_B", "x_{B}"), ("B2_x", "B_{2 x}"), ("lambda", r"\lambda"), ("E", "E")]:
        assert latex_name(name) == tex == sympy.latex(sympy.Symbol(name))
    for name, tex in [("omega_link5", r"\omega_{\mathrm{link5}}"), ("R_roda", r"R_{\mathrm{roda}}"),
                      ("omega_left_arm", r"\omega_{\text{\normalfont left arm}}"),
                      ("omega_besoa__2", r"\omega^{2}_{\mathrm{besoa}}")]:
        assert latex_name(name) == tex
    assert latex_name("pi") == r"\mathit{pi}" and latex_name("pi_B") == r"\mathit{pi}_{B}"


def test_html_name_escapes():
    assert html_name("a&b_<c>") == "a&amp;b<sub>&lt;c&gt;</sub>"


@pytest.fixture(scope="module")
def four_bar():
    """The four-bar asked its rocker's ω alone (its explanation a third of the whole ask's
    work), every parameter a symbol."""
    tree = model_tree("four_bar")
    tree["ask"] = [{"omega": "rocker"}]
    sol = kinematika.solve(tree, symbolic=True)
    return build(sol)


def test_four_bar_symbolic(four_bar):
    """The crank angle theta2 and speed w2 of the four-bar read θ₂ and w₂ in the prose,
    the formulas and the caption of the drawing, in every format."""
    page = render(four_bar, "en", "html", drawings=False)
    # a parameter in italics wherever it is written, prose, formula or caption (one letter, one face)
    assert "at <i>θ<sub>2</sub></i> from the x axis: <span class=\"pt\">A</span> = (<i>a</i>·cos(<i>θ<sub>2</sub></i>), " \
           "<i>a</i>·sin(<i>θ<sub>2</sub></i>))" in page
    assert "(−<i>a</i>·<i>w<sub>2</sub></i>·sin(<i>θ<sub>2</sub></i>), <i>a</i>·<i>w<sub>2</sub></i>·cos(<i>θ<sub>2</sub></i>))" in page
    assert "theta" not in page and not re.search(r"\bw2\b", page)
    text = render(four_bar, "es", "md", drawings=False)
    assert "A = (a·cos(θ₂); a·sen(θ₂))" in text and "theta" not in text     # Spanish separates by ; and writes sen
    tex = render(four_bar, "eu", "tex", drawings=False)
    assert r"a \cos{\left(\theta_{2} \right)}" in tex and "theta2" not in tex
    drawn = render(four_bar, "en", "html")                    # the drawing's caption names the values
    assert "<i>θ<sub>2</sub></i> = 1.571" in drawn and "<i>w<sub>2</sub></i> = 10" in drawn


def test_answers_keep_sympys_names(tmp_path):
    """The JSON answer is the contract: its formulas stay in sympy's syntax (the crank of
    `LINK`, the smallest model with formulas)."""
    path = tmp_path / "link.yaml"
    path.write_text(LINK)
    out = CliRunner().invoke(cli, ["solve", str(path), "--symbolic", "--json"])
    text = json.dumps(json.loads(out.stdout), ensure_ascii=False)
    assert "theta2" in text and "omega_link5" in text and "atheta" in text
    assert "θ" not in text and "ω" not in text


def _explained(tmp_path, source: str):
    path = tmp_path / "model.yaml"
    path.write_text(source)
    return build(kinematika.solve(path, symbolic=True))


def test_a_name_inside_another_is_left_whole(tmp_path):
    """theta, theta2 and atheta are three names: θ, θ₂ and atheta; omega_link5 is ω_link5
    (the body link5 as its subscript) and the word "the" of the prose is untouched."""
    doc = _explained(tmp_path, LINK)
    page = render(doc, "en", "html", drawings=False)
    assert "at distance <i>atheta</i> from <span class=\"pt\">O</span>, at <i>θ</i> + <i>θ<sub>2</sub></i> from the x axis" in page
    assert ("(−<i>atheta</i>·<i>ω<sub>link5</sub></i>·sin(<i>θ</i> + <i>θ<sub>2</sub></i>), "
            "<i>atheta</i>·<i>ω<sub>link5</sub></i>·cos(<i>θ</i> + <i>θ<sub>2</sub></i>))") in page
    assert set(re.findall(r"\w*theta\w*", page)) == {"atheta"} and "omega" not in page
    text = render(doc, "ca", "md", drawings=False)
    assert "(−atheta·ω_link5·sin(θ + θ₂); atheta·ω_link5·cos(θ + θ₂))" in text


def test_names_spelt_as_constants(tmp_path):
    """Parameters named pi, E, I and lambda: pi stays the word (π is the constant, which
    deg(90) brings in), E and I stay letters, lambda is λ; sin(pi) is not taken for 0."""
    doc = _explained(tmp_path, CONSTANTS)
    text = render(doc, "en", "md", drawings=False)
    assert "A is at distance I·λ from O, at (2·pi + π)/2 from the x axis: A = (−I·λ·sin(pi), I·λ·cos(pi))" in text
    assert "(−E·I·λ·cos(pi), −E·I·λ·sin(pi))" in text and "lambda" not in text
    tex = render(doc, "en", "tex", drawings=False)
    assert r"\frac{2 \mathit{pi} + \pi}{2}" in tex and r"\sin{\left(\mathit{pi} \right)}" in tex


# Jansen's leg's points whose coordinates are named: its top (the crank, A-B and the
# triangle Z-B-E: two circle intersections in a chain), and the whole leg, where the
# accelerations are also written in named angular velocities (8 times the work: a deep run)
PARTS = {"top": ("B", "E"), "whole": ("B", "E", "D", "F", "P")}


@pytest.fixture(scope="module", params=sampled(list(PARTS), {"top"}))
def jansen(request):
    """Jansen's leg (or its top) with its crank angle a symbol: its points' coordinates are
    named."""
    tree = jansen_model(top=request.param == "top")
    return request.param, build(kinematika.solve(tree))


@pytest.mark.parametrize("lang, here", [("en", "Here"), ("eu", "Hemen,")])
def test_named_coordinates_as_subscripts(jansen, lang, here):
    """'Here x_B = …' defines x with the subscript B, and the formulas use it so."""
    part, doc = jansen
    page = render(doc, lang, "html", drawings=False)
    for name in PARTS[part]:
        assert f"{here} <i>x<sub>{name}</sub></i> = " in page and f"{here} <i>y<sub>{name}</sub></i> = " in page
    assert "x_B" not in page and "·sin(<i>θ</i>)" in page and "theta" not in page
    if part == "whole":
        assert "ω<sub>crank</sub>" in page                    # the named angular velocities, by name
