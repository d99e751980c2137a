"""Names and labels as the notes write them (issue 30, third round), over the notes' 19
examples in the four languages, text and figures: a joint is never named by its id, the
instant centres are written by the bodies' names where the model names them (I_biela, as
ω_biela), a contact at a model point is that point, and a figure never repeats a tag its
body's name already reads (`roda 1 (1)`)."""
from __future__ import annotations

import base64
import re

import pytest

import kinematika
from kinematika.draw.names import centre_subscript, coincident_point, shows_tag

from .helpers import EXAMPLES, LANGS, SEEDS, body_of, explained, rendered

SVG = re.compile(r"data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)")
JOINT_ID = re.compile(r"\bj\d+\b")


def _text_and_figures(name: str, lang: str) -> tuple[str, str]:
    """A page's Markdown without its images, and the words its figures set."""
    page = rendered(name, lang)
    figures = []
    for b64 in SVG.findall(page):
        svg = base64.b64decode(b64).decode()
        figures += re.findall(r"<text[^>]*>([^<]*)<", svg) + re.findall(r"<!-- (.*?) -->", svg)
    return body_of(page), "\n".join(figures)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_no_joint_is_named_by_its_id(name, lang):
    """`wheel j4`, `∥ j3 guide`, `I_12: the pin of joint j1`, the polygon's `j10∈ring`: a
    joint is said by what it is, its bodies and its point or contact."""
    text, figures = _text_and_figures(name, lang)
    assert not JOINT_ID.findall(text), JOINT_ID.findall(text)[:5]
    assert not JOINT_ID.findall(figures), JOINT_ID.findall(figures)[:5]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_centres_are_written_by_the_bodies_names(name, lang):
    """Every seed names its bodies in every language: no centre by numbers (I_13, I_01 in the
    text, $I_{13}$ in a figure), no caption saying the bodies are numbered."""
    sol, _ = explained(name)
    assert sol.model.wording.bodies.get(lang)
    text, figures = _text_and_figures(name, lang)
    for where in (text, figures):          # a pair of numbers: I_13, I_{2,11}, $I_{\mathrm{13}}$
        hits = re.findall(r"I_\{?\d\d|I_\{?\d+,|I_\{\\mathrm\{\d\d", where)
        assert not hits, hits[:5]
    assert not re.search(r"numbered|numerad|numerat|zenbakitu|zenbakiekin|números de dos|nombres de dos", text)


def test_a_centre_by_names_reads_like_omega():
    """The rule on hand-made labels: the frame is numbered 1; a body's centre relative to it is
    its label alone, another pair the later body REL the earlier; numbers when unnamed."""
    numbers = {"ground": 1, "arm": 2, "pulley": 3}
    labels = {"ground": "terra", "arm": "braç", "pulley": "politja mòbil"}
    assert centre_subscript("ground", "arm", numbers, labels, True, "REL") == "braç"
    assert centre_subscript("pulley", "arm", numbers, labels, True, "REL") == "politja mòbil REL braç"
    assert centre_subscript("arm", "ground", numbers, {"ground": "1", "arm": "2", "pulley": "3"}, False, "rel") == "12"
    assert centre_subscript("pulley", "arm", numbers, {"ground": "1", "arm": "2", "pulley": "N"}, False, "rel") == "2N"


@pytest.mark.parametrize("name", SEEDS)
def test_a_contact_at_a_model_point_is_that_point(name):
    """C5-E.3 names its contacts J and K: the text writes J, never J and J′ for one point.
    Checked on the model's own positions: wherever a body of the joint carries a point at the
    contact, the contact's name is that point's, in every language."""
    sol, _ = explained(name)
    for j in sol.model.joints:
        if not j.kind.touches or sol.geometry(j.id).contact is None:
            continue
        there = coincident_point(sol, j.id)
        if there is None:
            continue
        contact = sol.geometry(j.id).contact.point
        assert all(abs(float(sol.inst.num(a)) - float(sol.inst.num(b))) < 1e-9
                   for a, b in zip(sol.inst.points[there], contact))
        for lang in LANGS:
            text, _ = _text_and_figures(name, lang)
            assert f"{there}'" not in text and f"{there}′" not in text, (name, lang, there)


def test_e3_contacts_are_j_and_k():
    """By hand: C5-E.3's points J (0, 0) and K (4R, 0) are the ground's, where the wheels touch."""
    sol = kinematika.solve(EXAMPLES / "seed_c5_e3_wheels_with_rod.yaml")
    assert [coincident_point(sol, j.id) for j in sol.model.joints[:2]] == ["J", "K"]


def test_a_figure_tag_is_not_its_name_again():
    """`roda 1 (1)`, `R erradioko gurpila (R)`: the tag repeats the name; `txasisa (t)` does not."""
    assert not shows_tag("1", "1. gurpila") and not shows_tag("R", "R erradioko gurpila")
    assert not shows_tag("politja1", "politja 1") and not shows_tag("satelitea1", "1. satelitea")
    assert not shows_tag("biela", "biela") and not shows_tag("roda esquerra", "roda esquerra")
    assert shows_tag("t", "txasisa") and shows_tag("3", "roda")


@pytest.mark.parametrize("lang", LANGS)
def test_e5_figures_repeat_no_tag(lang):
    """C5-E.5 indexes its wheels 1, 2 and R (the notes' roda 1, roda 2, rodaR): the figure
    writes each wheel's name alone."""
    _, figures = _text_and_figures("seed_c5_e5_unequal_wheels", lang)
    assert not re.search(r"\b(\d+)\.? \w+ \(\1\)|\b\w+ (\d+) \(\2\)|\bR\b[^()\n]* \(R\)", figures), figures
