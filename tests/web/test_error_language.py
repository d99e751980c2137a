"""The page's errors and warnings in the page's language (issue 30, item 12): the API says
them in the request's `lang` (the contract's error JSON, its kind the English word, its place
the same), and the page, in Basque or Catalan, shows a mobility error and the radians warning
in that language. The expected words are the course's, written here by hand."""
from __future__ import annotations

import copy
import re

import pytest
import yaml

from tests.conftest import BROWSER_WAIT, DEEP, sampled
from tests.core.models import four_bar

FREE = yaml.safe_dump(four_bar(drivers=[]))                 # no driver: one degree of freedom left free
# two drivers for one degree of freedom whose values disagree: a real mobility error
CONFLICT = yaml.safe_dump(four_bar(drivers=[{"omega": "crank", "value": "w2", "alpha": 0},
                                            {"omega": "rocker", "value": 1, "alpha": 0}]))


def _radians() -> str:
    tree = four_bar()
    tree["points"]["A"] = {"from": "O2", "distance": 1, "angle": 30}       # 30 rad where 30° was meant
    return yaml.safe_dump(tree)


def _apart() -> str:
    tree = copy.deepcopy(four_bar())
    tree["points"]["A"] = [0, 5]
    tree["points"]["B"] = {"circles": [["A", 1], ["O4", 1]], "side": "left"}        # 6.4 apart, radii 1 and 1
    return yaml.safe_dump(tree)


@pytest.mark.parametrize("lang, word", [("eu", "askatasun-gradu"), ("ca", "grau de llibertat"),
                                        ("es", "grado de libertad"), ("en", "degree of freedom")])
def test_the_api_says_a_mobility_error_in_the_requests_language(client, lang, word):
    answer = client.post("/api/solve", json={"model": FREE, "lang": lang})
    assert answer.status_code == 400
    error = answer.json()["error"]
    assert (error["kind"], error["where"]) == ("mobility", "drivers") and word in error["message"]


def test_the_api_says_warnings_and_the_sketchs_problem_in_the_requests_language(client):
    answer = client.post("/api/solve", json={"model": _radians(), "lang": "ca"})
    warned = answer.json()["warnings"][0]
    assert warned["where"] == "points.A.angle"
    assert "radiants" in warned["message"] and "4,8 voltes" in warned["message"] and "deg(30)" in warned["message"]
    problem = client.post("/api/sketch", json={"model": _apart(), "lang": "eu"}).json()["problem"]
    assert (problem["kind"], problem["where"]) == ("geometry", "points.B")
    assert "zirkunferentziak ez dira ebakitzen" in problem["message"] and "6,40312" in problem["message"]


def test_the_api_says_a_refused_request_in_its_language(client):
    refused = client.post("/api/solve", json={"model": "", "lang": "eu", "nonsense": 1})
    assert refused.status_code == 400
    assert refused.json()["error"] == {"kind": "usage", "where": "nonsense", "message":
                                       "gako ezezaguna 'nonsense' /api/solve helbiderako (onartuak: model, format, "
                                       "set, move, assembly, lang, symbolic, row)"}
    plain = client.post("/api/solve?lang=ca", content=b"{}", headers={"content-type": "text/plain"})
    assert plain.status_code == 415
    assert plain.json()["error"]["message"] == "envia la petició com a JSON (Content-Type: application/json)"
    from kinematika.errors import speak

    speak("eu")                  # a server started under a Basque locale (`kinematika app` in eu_ES)
    try:
        english = client.post("/api/solve", json={"model": FREE, "format": "yaml"})
    finally:
        speak("en")
    assert "degree of freedom" in english.json()["error"]["message"]      # the request says nothing: English


@pytest.mark.browser
@pytest.mark.filterwarnings("ignore::kinematika.errors.KinematikaWarning")   # the server's, in its threads
@pytest.mark.parametrize("lang, words", sampled([
    ("eu", {"kind": "mugikortasuna", "error": "eragileek elkarren kontra egiten dute", "warning": "abisua",
            "radians": "30 angelua radianetan dago", "missing": "aukeratu sarrera bat", "dof": "ag 1"}),
    ("ca", {"kind": "mobilitat", "error": "les dades de moviment es contradiuen", "warning": "avís",
            "radians": "l’angle 30 és en radiants", "missing": "tria una entrada", "dof": "gdl 1"})],
    lambda case: case[0] == "eu"))          # the same page in Catalan: a deep run
def test_the_page_shows_a_mobility_error_and_the_radians_warning_in_its_language(browser, server, lang, words,
                                                                                 tmp_path):
    context = browser.new_context(viewport={"width": 1400, "height": 1000})
    page = context.new_page()
    page.set_default_timeout(BROWSER_WAIT)
    try:
        page.goto(server.url)
        page.wait_for_function("() => window.kinematika && window.kinematika.state.solution", timeout=BROWSER_WAIT)
        # the boxes are read, not the explanation (nor the assemblies): those requests are
        # refused, which the page takes as any such failure
        page.route(re.compile(r".*/api/(explain|assemblies)$"), lambda route: route.abort())
        page.get_by_test_id("ui-language").select_option(lang)
        editor = page.get_by_test_id("model-editor")
        editor.fill(FREE)                 # a model still being built: a hint of what to add, not an error
        hint = page.get_by_test_id("missing")
        server.wait(page, "() => !document.querySelector('[data-testid=missing]').hidden")
        assert words["missing"] in hint.inner_text().lower()
        assert page.get_by_test_id("dof").inner_text().lower() == words["dof"]
        assert page.get_by_test_id("error").is_hidden()
        editor.fill(CONFLICT)
        error = page.get_by_test_id("error")
        server.wait(page, "(w) => document.querySelector('[data-testid=error]').innerText.includes(w)",
                    words["error"])
        text = error.inner_text().lower()       # the kind is written in capitals (CSS)
        assert error.get_attribute("data-kind") == "mobility"
        assert words["kind"] in text and "drivers" in text and "degree" not in text and hint.is_hidden()
        error.scroll_into_view_if_needed()
        if DEEP:                                  # a picture to look at, not a check
            page.screenshot(path=str(tmp_path / f"error-{lang}.png"))
        editor.fill(_radians())
        warning = page.get_by_test_id("warnings")
        server.wait(page, "(w) => { const box = document.querySelector('[data-testid=warnings]');"
                          " return !box.hidden && box.innerText.includes(w); }", words["radians"])
        shown = warning.inner_text().lower()
        assert words["warning"] in shown and "points.a.angle" in shown and "deg(30)" in shown
        assert "radians" not in shown and "turns" not in shown
        assert error.is_hidden()
        warning.scroll_into_view_if_needed()
        if DEEP:                                  # a picture to look at, not a check
            page.screenshot(path=str(tmp_path / f"warning-{lang}.png"))
    finally:
        context.close()
