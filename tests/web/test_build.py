"""Building a mechanism by hand on the page, as a student who has never seen the model
format would: a blank model, the palette, the grid and typed dimensions only — no typing in
the editor — then the answers read from the page. One server and one browser for the session (conftest).

Every expected number is derived here by hand (closed-form loop equations), not taken from
the tool.
"""
from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
import yaml

from tests.conftest import BROWSER_WAIT, sampled

pytestmark = pytest.mark.browser


def open_page(browser, server, height: int):
    """A page 1400 px wide, loaded and settled, with the script errors it meets: (page, errors),
    closed when the caller is done."""
    context = browser.new_context(viewport={"width": 1400, "height": height})
    pg = context.new_page()
    pg.set_default_timeout(BROWSER_WAIT)          # a hang detector
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(server.url)
    settled(pg, 0)
    yield pg, errors
    context.close()


@pytest.fixture(scope="module")
def shared_page(browser, server):
    """One page for the module (a student goes on using it): each test starts from a blank
    model or an example it opens itself."""
    yield from open_page(browser, server, 1000)


@pytest.fixture
def page(shared_page):
    pg, errors = shared_page
    pg.get_by_test_id("tool-select").click()
    yield pg
    assert not errors, errors


@pytest.fixture
def unexplained(page):
    """`page`'s requests for explanations (and for the assemblies to pick from) refused
    while the test builds: a build step's explanation is seconds of the server's work that
    nothing here reads (the page's explanation is tests/web/test_page.py's matter); the
    page takes a refusal as any such failure."""
    refused = re.compile(r".*/api/(explain|assemblies)$")
    page.route(refused, lambda route: route.abort())
    yield
    page.unroute(refused)


def example(pg, name: str) -> None:
    """Open a bundled example, in English."""
    if pg.get_by_test_id("ui-language").input_value() != "en":
        step(pg, lambda: pg.get_by_test_id("ui-language").select_option("en"))
    step(pg, lambda: pg.get_by_test_id("example").select_option(name))


def settled(pg, gen: int) -> None:
    """Wait until the page has analysed the text after generation `gen`."""
    pg.wait_for_function(f"() => window.kinematika && window.kinematika.state.gen > {gen} && "
                         "document.getElementById('busy').hidden && "
                         "document.getElementById('properties-body').childElementCount > 0")


def step(pg, action) -> None:
    """Do `action` (a build step) and wait until its edit has been analysed."""
    gen = pg.evaluate("window.kinematika.state.gen")
    action()
    settled(pg, gen)


def click_at(pg, xy) -> None:
    x, y = pg.evaluate(f"window.kinematika.toScreen({json.dumps(list(xy))})")
    pg.mouse.click(x, y)


def where(pg, name: str) -> list:
    """A point's place in the builder's sketch (waiting for the sketch that has it)."""
    js = f"window.kinematika.builder.sketch.points[{json.dumps(name)}]"
    pg.wait_for_function(f"() => !!{js}")
    return pg.evaluate(js)


def click_point(pg, name: str) -> None:
    click_at(pg, where(pg, name))


def click_body(pg, a: str, b: str) -> None:
    """Click halfway along the bar between points a and b."""
    p, q = (np.array(where(pg, n)) for n in (a, b))
    click_at(pg, (p + q) / 2)


def selected(pg, click, name: str) -> None:
    """Select an element by clicking it (no edit: the properties panel shows it)."""
    click()
    pg.get_by_test_id("properties").get_by_test_id("selected").filter(has_text=name).wait_for()


def tool(pg, kind: str, *picks) -> None:
    pg.get_by_test_id(f"tool-{kind}").click()
    *first, last = picks
    for pick in first:
        pick()
    step(pg, last)


def typed(pg, testid: str, text: str) -> None:
    """Type a dimension into the properties panel and press Enter."""
    field = pg.get_by_test_id("properties").get_by_test_id(testid)
    step(pg, lambda: (field.fill(text), field.press("Enter")))


def blank(pg) -> None:
    step(pg, lambda: pg.get_by_test_id("new-model").click())
    assert "points" not in pg.get_by_test_id("model-editor").input_value()


def answer(pg, i: int):
    return json.loads(pg.get_by_test_id("answers").locator(f'td[data-key="answers.{i}"]')
                      .get_attribute("data-value"))


def text(pg) -> dict:
    return yaml.safe_load(pg.get_by_test_id("model-editor").input_value())


@pytest.mark.usefixtures("unexplained")
def test_an_offset_slider_crank_built_by_hand(page):
    """Crank OA = 50 mm at 30°, rod AB = 150 mm, the slider's line 20 mm below O, the crank
    at 10 rad/s ccw, steady.

    By hand: A = r(cos 30°, sin 30°) = (0.043301, 0.025); B on y = −0.02, so the rod's
    vertical drop is 0.045 and its horizontal run √(0.15² − 0.045²) = 0.143091 (x_B =
    0.186392). Velocities: v_A = ω × OA = (−0.25, 0.433013); v_B = v_A + ω₃ × AB with
    v_By = 0 gives ω₃ = −0.433013 / 0.143091 = −3.0261 rad/s and v_B = −0.25 − ω₃·0.045 =
    −0.3862 m/s. Accelerations: a_A = −ω²·OA = (−4.3301, −2.5); a_By = 0 = −2.5 +
    α₃·0.143091 + ω₃²·0.045 gives α₃ = 14.59 rad/s², and a_B = −4.3301 + α₃·0.045 −
    ω₃²·0.143091 = −4.984 m/s².
    """
    blank(page)
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    tool(page, "link", lambda: click_point(page, "O1"), lambda: click_at(page, (0.04, 0.02)))
    typed(page, "prop-length", "50 mm")
    typed(page, "prop-angle", "30")
    tool(page, "link", lambda: click_point(page, "A"), lambda: click_at(page, (0.18, 0.0)))
    typed(page, "prop-length", "150 mm")
    tool(page, "slider", lambda: click_point(page, "B"))
    typed(page, "prop-line-y", "-20 mm")
    page.get_by_test_id("tool-select").click()
    selected(page, lambda: click_body(page, "O1", "A"), "link1")        # the crank: the input
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("10")
    step(page, lambda: page.get_by_test_id("set-input").click())
    selected(page, lambda: click_point(page, "B"), "B")
    step(page, lambda: page.get_by_test_id("ask-velocity").click())
    step(page, lambda: page.get_by_test_id("ask-acceleration").click())
    selected(page, lambda: click_body(page, "A", "B"), "link2")
    step(page, lambda: page.get_by_test_id("ask-omega").click())

    model = text(page)
    assert model["points"]["A"] == {"from": "O1", "distance": 0.05, "angle": "deg(30)"}
    assert model["points"]["B"]["circle"] == ["A", 0.15]          # by construction, as stated
    assert model["points"]["B"]["line"]["through"][1] == -0.02
    r, th, rod, e, w = 0.05, math.radians(30), 0.15, 0.02, 10.0
    ax, ay = r * math.cos(th), r * math.sin(th)
    drop = ay + e
    run = math.sqrt(rod ** 2 - drop ** 2)
    w3 = -(w * ax) / run
    vb = -w * ay - w3 * (-drop)            # v_Bx = v_Ax − ω₃·(y_B − y_A)
    a3 = (w ** 2 * ay - w3 ** 2 * drop) / run
    ab = -w ** 2 * ax - a3 * (-drop) - w3 ** 2 * run
    assert (round(vb, 4), round(ab, 3), round(w3, 3)) == (-0.3862, -4.984, -3.026)
    assert answer(page, 0) == pytest.approx([vb, 0], abs=1e-9)
    assert answer(page, 1) == pytest.approx([ab, 0], abs=1e-8)
    assert answer(page, 2) == pytest.approx(w3, abs=1e-9)
    assert page.get_by_test_id("error").is_hidden()


@pytest.mark.usefixtures("unexplained")
def test_a_four_bar_built_by_its_lengths(page):
    """Ground O2O4 = 0.4, crank O2A = 0.1 at 60°, coupler AB = 0.4, rocker O4B = 0.3, B
    above the ground line; the crank at 10 rad/s ccw.

    By hand: B where the circles about A (0.4) and O4 (0.3) meet, the upper point; then
    v_A + ω₃ k × AB = ω₄ k × O4B, two equations for ω₃ and ω₄ (solved below by Cramer)."""
    blank(page)
    for _ in range(2):
        page.get_by_test_id("zoom-out").click()             # room for the ground link
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    tool(page, "pivot", lambda: click_at(page, (0.4, 0)))
    tool(page, "link", lambda: click_point(page, "O1"), lambda: click_at(page, (0.06, 0.08)))
    typed(page, "prop-length", "0.1")
    typed(page, "prop-angle", "60")
    tool(page, "link", lambda: click_point(page, "O2"), lambda: click_at(page, (0.3, 0.26)))
    typed(page, "prop-length", "300 mm")
    tool(page, "link", lambda: click_point(page, "A"), lambda: click_point(page, "B"))
    typed(page, "prop-length", "0,4")                    # a decimal comma is a decimal mark
    page.get_by_test_id("tool-select").click()
    selected(page, lambda: click_point(page, "O1"), "O1")        # the crank's pivot: its joint
    page.get_by_test_id("properties").get_by_test_id("input-rate-j1").fill("10")
    step(page, lambda: page.get_by_test_id("set-input-j1").click())
    for body, pts in (("link3", ("A", "B")), ("link2", ("O2", "B"))):
        selected(page, lambda pts=pts: click_body(page, *pts), body)
        step(page, lambda: page.get_by_test_id("ask-omega").click())

    model = text(page)
    assert model["points"]["B"] == {"circles": [["O2", 0.3], ["A", 0.4]], "side": "right"}
    assert model["drivers"] == [{"joint": "j1", "rate": 10, "accel": 0}]
    a = np.array([0.1 * math.cos(math.radians(60)), 0.1 * math.sin(math.radians(60))])
    o4 = np.array([0.4, 0.0])
    d = np.linalg.norm(o4 - a)
    along = (0.4 ** 2 - 0.3 ** 2 + d ** 2) / (2 * d)
    u = (o4 - a) / d
    b = a + along * u + math.sqrt(0.4 ** 2 - along ** 2) * np.array([-u[1], u[0]])
    assert b[1] > 0
    va = 10 * np.array([-a[1], a[0]])
    ab, ob = b - a, b - o4
    # va + w3 (−ab_y, ab_x) = w4 (−ob_y, ob_x)
    m = np.array([[-ab[1], ob[1]], [ab[0], -ob[0]]])
    w3, w4 = np.linalg.solve(m, -va)
    assert answer(page, 0) == pytest.approx(w3, abs=1e-9)
    assert answer(page, 1) == pytest.approx(w4, abs=1e-9)
    assert (round(w3, 3), round(w4, 3)) == (-1.538, 1.795)


@pytest.mark.usefixtures("unexplained")
def test_a_wheel_rolling_on_a_line(page):
    """A wheel of radius 0.1 rolling on the ground line at ω = −5 rad/s (clockwise),
    steady. By hand (no slip): v_C = −ω R (1, 0) = (0.5, 0); the top point P = C + (0, R)
    moves at 2 v_C = (1, 0) and accelerates towards the centre, −ω² (P − C) = (0, −2.5)."""
    blank(page)
    for _ in range(2):
        page.get_by_test_id("zoom-out").click()
    tool(page, "wheel", lambda: click_at(page, (0, 0)), lambda: click_at(page, (0, 0.06)))
    typed(page, "prop-radius", "100 mm")
    click_body_of_wheel = lambda: click_at(page, (0.05, 0.1))          # inside the wheel's disc
    tool(page, "plate", click_body_of_wheel, lambda: click_at(page, (0, 0.2)))
    page.get_by_test_id("tool-select").click()
    selected(page, click_body_of_wheel, "wheel1")
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("-5")
    step(page, lambda: page.get_by_test_id("set-input").click())
    selected(page, lambda: click_point(page, "B"), "B")
    step(page, lambda: page.get_by_test_id("ask-velocity").click())
    step(page, lambda: page.get_by_test_id("ask-acceleration").click())
    model = text(page)
    assert model["parameters"] == {"R1": 0.1}
    assert list(model) == ["name", "parameters", "points", "bodies", "joints", "drivers", "ask"]
    assert model["bodies"]["wheel1"]["circle"] == {"center": "A", "radius": "R1"}
    assert answer(page, 0) == pytest.approx([1.0, 0.0], abs=1e-9)
    assert answer(page, 1) == pytest.approx([0.0, -2.5], abs=1e-9)


def _words(text: str) -> set[str]:
    import re

    return {w.lower() for w in re.findall(r"[A-Za-z]{4,}", text)}


@pytest.mark.parametrize("lang", sampled(["eu", "es", "ca"], {"eu"}))    # es, ca: a deep run
def test_no_english_word_of_the_page_in_another_language(page, lang):
    """With the page's language chosen (one choice: the page, the explanation, the figure's
    numbers; remembered), no English word of the page's own catalogue is left on the page:
    buttons, headings, tooltips, the palette, the properties, the answers' headings, the
    legend, the plot's chips. The model's own names (crank, coupler, the example's title)
    are the model's, not the page's, and are left out."""
    from kinematika.web.strings import page_strings

    english = _words(" ".join(page_strings("en")["messages"].values()))
    own = _words(" ".join(page_strings(lang)["messages"].values()))
    foreign = english - own - {"yaml", "toml", "json", "kennedy", "coriolis", "kinematika"}
    example(page, "four_bar.yaml")
    gen = page.evaluate("window.kinematika.state.gen")
    page.get_by_test_id("ui-language").select_option(lang)
    settled(page, gen)
    assert page.get_by_test_id("language").input_value() == lang      # the explanation's too
    selected(page, lambda: click_body(page, "O2", "A"), "crank")      # a full properties panel
    model = {"crank", "coupler", "rocker", "ground", "linkage", "four"}      # the model's names
    model |= _words(" ".join(page.locator("#example option").all_inner_texts()))   # file names
    shown = page.evaluate("""() => {
        const parts = [...document.querySelectorAll('header, .panel-head, .build-bar, #build-hint, #legend,'
            + ' #properties, #answers tr.section, #answers td.q, #plot-pick, #notes, #answers-where')];
        const text = parts.map((n) => n.innerText).join(' ');
        const tips = [...document.querySelectorAll('[title]')].map((n) => n.title).join(' ');
        const labels = [...document.querySelectorAll('[aria-label]')].map((n) => n.getAttribute('aria-label')).join(' ');
        return text + ' ' + tips + ' ' + labels; }""")
    left = (_words(shown) & foreign) - model
    assert not left, left
    assert page.evaluate("localStorage.getItem('kinematika.lang')") == lang
    page.reload()
    settled(page, 0)
    assert page.get_by_test_id("ui-language").input_value() == lang       # remembered
    # a decimal comma, as the explanations in es, ca, eu write numbers (the rocker's ω)
    omega = page.get_by_test_id("answers").locator('td[data-key="bodies.rocker.omega"]').inner_text()
    assert "," in omega and "." not in omega
    step(page, lambda: page.get_by_test_id("ui-language").select_option("en"))


@pytest.mark.usefixtures("unexplained")
def test_the_format_menu_converts_and_undo_goes_back(page):
    """The Format menu writes the same model in TOML (the same answers); Undo brings the
    YAML text back with its format, Redo the TOML again. After a model error the answers and
    the plot are greyed and said to be the last model's."""
    example(page, "four_bar.yaml")
    editor = page.get_by_test_id("model-editor")
    yaml_text = editor.input_value()
    omega = answer(page, 2)
    step(page, lambda: page.get_by_test_id("format").select_option("toml"))
    toml = editor.input_value()
    assert "[points]" in toml and "[bodies]" in toml
    assert answer(page, 2) == omega
    step(page, lambda: page.get_by_test_id("undo").click())
    assert editor.input_value() == yaml_text and page.get_by_test_id("format").input_value() == "yaml"
    step(page, lambda: page.get_by_test_id("redo").click())
    assert editor.input_value() == toml and page.get_by_test_id("format").input_value() == "toml"
    gen = page.evaluate("window.kinematika.state.gen")
    editor.fill(toml.replace('at = "O4"', 'at = "Q4"'))
    page.get_by_test_id("error").wait_for(state="visible")
    settled(page, gen)
    assert "stale" in page.get_by_test_id("answers").get_attribute("class")
    assert "stale" in page.locator("#plot-box").get_attribute("class")
    assert page.locator("#answers-stale").is_visible()
    assert page.locator("#plot .series-value, #plot text[font-family=monospace]").evaluate_all(
        "ts => ts.every(t => t.textContent === '')")


def test_help_is_one_click_away(page):
    """The format reference and the walk-through open from the page's bar, served by the
    page's own server as HTML."""
    with page.context.expect_page() as opened:
        page.get_by_test_id("help-format").click()
    doc = opened.value
    doc.wait_for_load_state()
    assert doc.url.endswith("/docs/model-format.md")
    assert doc.locator("h1").first.inner_text().startswith("Model format")
    assert doc.locator("table").count() >= 3           # its tables rendered, not left as text
    walk = page.request.get(page.url.rstrip("/") + page.get_by_test_id("help-problem").get_attribute("href"))
    assert walk.status == 200 and "<h1>" in walk.text()
    doc.close()
