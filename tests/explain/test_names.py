"""A model's names are set as names in every format, and a hostile name (markup, TeX
specials, control characters, a bidirectional override) is shown, never obeyed."""
from __future__ import annotations

import re

import pytest

import kinematika
from kinematika.explain import build, render

BODY = "<img src=x onerror=alert(1)>&$\\{}_^%#~*[x](y)|`\x1b[2J\u202e"
POINT = "P<b>\x07"
JOINT = "j$&\x1b"
MODEL = {
    "name": "Evil <script>alert(1)</script> $x$ \x1b]0;t\x07",
    "points": {"O2": [0, 0], "A": [0, 1], POINT: [3, 2], "O4": [4, 0]},
    "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], BODY: ["A", POINT], "rocker": [POINT, "O4"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
               {"id": JOINT, "type": "revolute", "bodies": ["crank", BODY], "at": "A"},
               {"type": "revolute", "bodies": [BODY, "rocker"], "at": POINT},
               {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}],
    "drivers": [{"omega": "crank", "value": 10}],
    "ask": [{"omega": BODY}, {"velocity": POINT}, {"icr": BODY}],
}
CONTROLS = re.compile("[\x00-\x08\x0b-\x1f\x7f\u202a-\u202e\u2066-\u2069]")


@pytest.fixture(scope="module")
def doc():
    return build(kinematika.solve(MODEL))


@pytest.mark.filterwarnings("ignore::UserWarning")      # matplotlib: no glyph for ESC in a label
def test_html_shows_hostile_names(doc):
    page = render(doc, "ca", "html")
    assert not CONTROLS.search(page)
    assert "<script" not in page and "<img" not in page and "<b>" not in page
    assert "&lt;img src=x onerror=alert(1)&gt;" in page and "\\x1b[2J" in page
    assert page.count("<svg") == page.count("</svg>") >= 3


def test_markdown_escapes_its_markup(doc):
    text = render(doc, "es", "md", drawings=False)
    assert not CONTROLS.search(text)
    prose = re.sub(r"```.*?```", "", text, flags=re.S)          # equations are code: nothing is markup there
    assert not re.search(r"(?<!\\)<(script|img|b>)", prose)
    assert "\\[x\\](y)" in prose and "\\*\\[x" in prose


def test_latex_escapes_its_specials(doc):
    tex = render(doc, "eu", "tex")
    assert not CONTROLS.search(tex)
    assert "\\textbackslash{}\\{\\}\\_\\textasciicircum{}\\%\\#\\textasciitilde{}" in tex
    assert "\\$x\\$" in tex                                      # the title's dollars are not math


def test_names_styled_per_format():
    """Points upright sans serif, bodies in italics (as the figures set them); bodies by
    their numbers in subscripts, as the notes write them: ω_3, v_B∈3, I_13."""
    from .helpers import explained

    _, fb = explained("four_bar")
    page = render(fb, "en", "html", drawings=False)
    assert '<i class="bd">coupler</i>' in page and '<span class="pt">O4</span>' in page
    assert "<i>ω</i><sub>3</sub>" in page and "<i>I</i><sub>13</sub>" in page
    assert "\\emph{coupler}" in render(fb, "en", "tex")
    assert "*coupler*" in render(fb, "en", "md", drawings=False)


FOUR = {"points": {"O2": [0, 0], "A": [0, 1], "B": [3, 2], "O4": [4, 0]},
        "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"], "rocker": ["B", "O4"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                   {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                   {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                   {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}],
        "drivers": [{"omega": "crank", "value": 10}],
        "ask": [{"omega": "coupler"}, {"velocity": "B", "relative_to": "crank"}, {"icr": "coupler"}]}


def test_a_bodys_index_is_written_everywhere():
    """notation index(coupler): N — ω_N, v_{B∈N rel 2} (relative to body 2: no slash, which
    reads as a fraction), I_{1N} in the text (a centre's subscript in braces: twenty-seventh
    round (g)); (N) in the figure's numbering; the other bodies keep their numbers (the model
    names none)."""
    sol = kinematika.solve({**FOUR, "notation": {"index(coupler)": "N"}})
    doc = build(sol)
    text = render(doc, "en", "md", drawings=False)
    assert "ω_N" in text and "v_{B∈N rel 2}" in text and "I_{1N}" in text and "ω_3" not in text
    from kinematika.draw.build import build_scene
    from kinematika.draw.scene import numbering
    from kinematika.draw.options import DrawOptions

    scene = build_scene(sol.inst, sol, DrawOptions(lang="en", bare=True, centres=True))
    assert ("N", "coupler") in numbering(scene) and (2, "crank") in numbering(scene)


@pytest.mark.parametrize("notation, place", [
    ({"index(coupler)": "2"}, "notation.index(coupler)"),                 # the crank is 2
    ({"index(coupler)": "N!"}, "notation.index(coupler)"),
    ({"index(nobody)": "N"}, "notation.index(nobody)"),
    ({"spin(j1)": {"symbol": "phidot", "radius": "r"}}, "notation.spin(j1)"),     # not a wheel
    ({"spin(j9)": {"symbol": "phidot", "radius": "r"}}, "notation.spin(j9)"),
    ({"contact(j1)": "F"}, "notation.contact(j1)"),            # a pin has no contact to name
    ({"contact(j9)": "F"}, "notation.contact(j9)"),
])
def test_a_wrong_index_or_spin_is_an_error_naming_its_place(notation, place):
    from kinematika.errors import KinematikaError

    with pytest.raises(KinematikaError) as err:
        kinematika.solve({**FOUR, "parameters": {"r": 1}, "notation": notation})
    assert err.value.where == place or place in str(err.value), (str(err.value), notation)


def test_a_contact_is_named_as_the_notes_name_it():
    """notation contact(j4): F — the slides' rolling pair writes its contact F (F_R, F_N):
    the explanation's equations and sentences write F∈R and F∈N, never J; a contact name
    that is not one to four letters or digits is an error naming its place."""
    from kinematika.errors import KinematikaError

    from .helpers import EXAMPLES

    doc = build(kinematika.solve(EXAMPLES / "seed_001_rolling_pair.yaml"))
    text = render(doc, "eu", "md", drawings=False)
    assert "v_{F∈R}" in text and "v_{F∈N}" in text
    assert "J∈" not in text and "J^{geom}" not in text
    text = (EXAMPLES / "seed_001_rolling_pair.yaml").read_text().replace("contact(j4): F ", "contact(j4): F! ")
    with pytest.raises(KinematikaError) as err:
        kinematika.solve(text)
    assert err.value.where == "notation.contact(j4)"
