"""Figures write numbers as the explanation beside them does: a decimal comma in Spanish,
Catalan and Basque, with the text's minus sign and powers of ten (`DrawOptions.lang`); a
figure asked in no language writes them as it always has (Python's 2.5, -0.3, 1e-05).

The expected values are derived here by hand (the four-bar's loop closure) or read from
the contract's JSON (`centres --json`), never from the figure code."""
from __future__ import annotations

import json
import re

import numpy as np
import pytest
from typer.testing import CliRunner

from kinematika import solve
from kinematika.cli import app as cli
from kinematika.draw import svg
from kinematika.draw.names import value_text
from kinematika.errors import KinematikaError
from kinematika.explain import build, render
from kinematika.explain.catalogue import catalogue
from kinematika.explain.document import Drawing, Section
from kinematika.explain.render.html import HtmlRenderer
from kinematika.explain.render.svg import embedded
from tests.conftest import EXAMPLES, sampled

FOUR_BAR = EXAMPLES / "four_bar.yaml"


def texts(svg_text: str) -> list[str]:
    """The texts a matplotlib SVG draws (it writes each as a comment before its glyphs)."""
    return re.findall(r"<!-- (.*?) -->", svg_text)


def four_bar_by_hand() -> dict[str, float]:
    """The example's four-bar (O2 (0, 0), O4 (4, 0), crank 1 at 90° turning at 10 rad/s,
    coupler 4, rocker 3, B left of A→O4): |v_B|, |v_B relative to the crank| and the
    coupler's centre I13 on the line O2A (x = 0), from the loop closure."""
    o4, a = np.array([4.0, 0.0]), np.array([0.0, 1.0])
    d = np.linalg.norm(o4 - a)
    along = (4.0**2 - 3.0**2 + d**2) / (2 * d)              # from A towards O4
    u = (o4 - a) / d
    left = np.array([-u[1], u[0]])
    b = a + along * u + np.sqrt(4.0**2 - along**2) * left
    perp = lambda r: np.array([-r[1], r[0]])
    v_a = 10 * perp(a)
    # v_A + ω3 k×(B−A) = ω4 k×(B−O4)
    w3, w4 = np.linalg.solve(np.column_stack([perp(b - a), -perp(b - o4)]), -v_a)
    v_b = w4 * perp(b - o4)
    i13_y = b[1] + (0 - b[0]) * (b[1] - o4[1]) / (b[0] - o4[0])   # line O4B at x = 0
    return {"v_B": float(np.linalg.norm(v_b)), "v_B/2": float(np.linalg.norm(v_b - 10 * perp(b))),
            "I13": float(i13_y)}


def test_the_four_bar_by_hand_is_what_the_figures_round():
    """The derivation gives 9.252, 41.80 and 23.14: three digits 9.25, 41.8, 23.1."""
    hand = four_bar_by_hand()
    assert round(hand["v_B"], 2) == 9.25 and round(hand["v_B/2"], 1) == 41.8
    assert round(hand["I13"], 1) == 23.1


# one comma language (every one in a deep run): the figures in Basque and Catalan are the
# command line's and the animation's below
@pytest.mark.parametrize("lang", sampled(["es", "ca", "eu"], {"es"}))
def test_a_figure_in_a_comma_language_writes_decimal_commas(lang):
    sol = solve(FOUR_BAR)
    shown = texts(svg(sol, centres=True, lang=lang))
    assert r"$v_{\mathrm{B}}$ = 9,25" in shown and r"$v_{\mathrm{B}{\in}\mathrm{3}\ \mathrm{rel}\ \mathrm{2}}$ = 41,8" in shown     # B∈3 seen from 2
    far_off = {"es": r"$I_{\mathrm{13}}$ en (0; 23,1)", "ca": r"$I_{\mathrm{13}}$ a (0; 23,1)",
               "eu": r"$I_{\mathrm{13}}$ (0; 23,1) puntuan"}[lang]
    assert far_off in shown        # components parted as in the text, said in the figure's language
    assert not [t for t in shown if re.search(r"\d\.\d", t)]


@pytest.mark.parametrize("lang", [None, "en"])
def test_a_figure_in_english_or_no_language_keeps_the_point(lang):
    shown = texts(svg(solve(FOUR_BAR), centres=True, lang=lang))
    assert r"$v_{\mathrm{B}}$ = 9.25" in shown and r"$I_{\mathrm{13}}$ at (0, 23.1)" in shown


def test_minus_signs_and_powers_of_ten_as_the_text_writes_them():
    """The Jansen leg's I67 (rocker 6, knee 7) lies far off, at (−1197.5, −177.3) by the
    contract's JSON: three digits are −1.20×10³ and −177. The figure in no language writes
    Python's `-1.2e+03`; in Spanish the text's minus sign and power of ten, `−1,2×10³`."""
    out = CliRunner().invoke(cli, ["centres", str(EXAMPLES / "jansen_leg.yaml"), "--json"])
    x, y = next(c["point"] for c in json.loads(out.stdout)["centres"] if c["bodies"] == ["rocker", "knee"])
    assert round(x, -1) == -1200 and round(y) == -177
    sol = solve(EXAMPLES / "jansen_leg.yaml")
    plain, es = (texts(svg(sol, centres=True, bare=True, lang=lang)) for lang in (None, "es"))
    assert r"$I_{\mathrm{67}}$ = (-1.2e+03, -177)" in plain
    assert r"$I_{\mathrm{67}}$ = (−1,2×10³; −177)" in es


def test_the_figure_writer_is_the_text_writer():
    """Where three digits are all there is, a figure's number and the HTML text's are the
    same characters (the text's ×10<sup>−5</sup> as ×10⁻⁵)."""
    doc = build(solve(FOUR_BAR))
    for lang in ("en", "es", "ca", "eu"):
        text = HtmlRenderer(doc, catalogue(lang))
        for x in (2.5, -0.3, 1.5e-05, -2.25e-07, 123000.0, 0.0):
            html = text.number(x)
            html = re.sub(r"<sup>(.*?)</sup>", lambda m: m.group(1).translate(str.maketrans("−0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")),
                          html)
            assert value_text(x, lang) == html
    assert value_text(-1.5e-05, "es") == "−1,5×10⁻⁵" and value_text(-1.5e-05) == "-1.5e-05"


def drawings(blocks) -> list[Drawing]:
    out = []
    for b in blocks:
        if isinstance(b, Section):
            out += drawings(b.blocks)
        elif isinstance(b, Drawing):
            out.append(b)
    return out


def test_an_explanation_embeds_its_language_figures():
    """The Spanish page holds the figures drawn in Spanish (9,25 beside the text's 9,252),
    not the English ones; each language's figure is drawn once."""
    doc = build(solve(FOUR_BAR))
    page = render(doc, "es", "html")
    first = drawings(doc.sections)[0]
    assert r"$v_{\mathrm{B}}$ = 9,25" in texts(first.svg("es"))
    assert r"$v_{\mathrm{B}}$ = 9.25" in texts(first.svg("en"))
    assert embedded(first.svg("es"), "d1") in page and embedded(first.svg("en"), "d1") not in page
    assert first.svg("es") is first.svg("es")


def test_an_unknown_language_is_a_usage_error(tmp_path):
    with pytest.raises(KinematikaError, match="unknown language 'fr'"):
        svg(solve(FOUR_BAR), lang="fr")
    out = CliRunner().invoke(cli, ["draw", str(FOUR_BAR), "-o", str(tmp_path / "f.svg"), "--lang", "fr"])
    assert out.exit_code == 2 and "error (usage): --lang: unknown language 'fr'" in out.stderr


def test_draw_lang_on_the_command_line(tmp_path):
    path = tmp_path / "f.svg"
    out = CliRunner().invoke(cli, ["draw", str(FOUR_BAR), "-o", str(path), "--lang", "eu"])
    assert out.exit_code == 0
    assert r"$v_{\mathrm{B}}$ = 9,25" in texts(path.read_text(encoding="utf-8"))


def test_a_formula_in_a_figure_takes_the_decimal_comma():
    """A symbolic label keeps its formula; a decimal inside it (an exponent sympy keeps as a
    float) is written as the language writes it, in mathtext's unspaced comma."""
    import sympy

    from kinematika.draw.names import formula, settable

    r = sympy.Symbol("r")
    assert formula(r ** sympy.Float(0.3), 1.0) == "$r^{0.3}$"
    assert formula(r ** sympy.Float(0.3), 1.0, "eu") == "$r^{0{,}3}$"
    assert settable("$r^{0{,}3}$")


def test_an_animation_labels_its_live_vectors_in_the_language():
    """Row 0 of the sweep is the drawn position: |v_B| = 9.252 by hand, 9,25 in Catalan."""
    from kinematika.draw import DrawOptions
    from kinematika.draw.animation import Film

    film = Film.of(FOUR_BAR, by=90, steps=1, frames=2, options=DrawOptions(lang="ca"))
    film.show(0)
    labels = {v.kind: text.get_text() for v, _, text in film.motion.arrows}
    assert labels["velocity"] == r"$v_{\mathrm{B}}$ = 9,25"


# the words a figure writes itself, per language, as a teacher of the course writes them
LEGEND = {"en": ("velocity", "instant centre", "Kennedy line"),
          "es": ("velocidad", "CIR (centro instantáneo de rotación)", "recta de Aronhold–Kennedy"),
          "ca": ("velocitat", "CIR (centre instantani de rotació)", "recta d’Aronhold–Kennedy"),
          "eu": ("abiadura", "biraketa-zentro instantaneoa", "Aronhold–Kennedyren zuzena")}
TITLE = {"en": "Epicyclic transmission (example C5-1.4)", "es": "Transmisión epicicloidal (ejemplo C5-1.4)",
         "ca": "Transmissió epicicloidal (exemple C5-1.4)", "eu": "Transmisio epizikloidala (C5-1.4 adibidea)"}
AT_INFINITY = {"en": "at infinity, direction", "es": "en el infinito, dirección", "ca": "a l’infinit, direcció",
               "eu": "infinituan, norabidea"}


@pytest.mark.parametrize("lang", ["en", "es", "ca", "eu"])
def test_a_figure_says_its_own_words_in_its_language(lang):
    """`draw --lang`: the title (the model's in that language), the legend and the notes
    (a centre at infinity, the values a symbolic model is drawn at) are in the figure's
    language, never English beside Catalan labels; the epicyclic train has centres at
    infinity (satellites translating relative to each other) and is drawn at its draw_at."""
    sol = solve(EXAMPLES / "seed_c5_1_4_epicyclic.yaml")
    shown = texts(svg(sol, centres=True, lang=lang))
    assert TITLE[lang] in shown
    assert all(word in shown for word in LEGEND[lang]), [t for t in shown if not t.startswith("$")][:20]
    assert any(AT_INFINITY[lang] in t for t in shown)
    english = {"velocity", "instant centre", "Kennedy line", "symbolic model"}
    if lang != "en":
        assert not [t for t in shown if any(w in t for w in english)]


def test_the_figures_catalogues_have_the_same_words():
    """Every word a figure writes exists in the four languages (none falls back to a key)."""
    from kinematika.draw.words import catalogue as words

    keys = {lang: words(lang).keys() for lang in ("en", "es", "ca", "eu")}
    assert keys["en"] and all(k == keys["en"] for k in keys.values())
