"""The page as a student meets it (issue 35): one drag is one step of Undo; a second kind of
drag turns the mechanism by hand along its motion, leaving the model as it is; names in the
page's language, and renaming; no alarm while building, and New forgets the last model;
words that agree; one angle convention; a phone that shows everything.

One server and one browser for the session (conftest), one page for the module (a student
goes on using it). Expected numbers are derived here by hand, never read from the tool.
"""
from __future__ import annotations

import json
import math
import re

import pytest

from kinematika.web.strings import page_strings
from tests.conftest import BROWSER_WAIT

from .test_build import blank, click_at, open_page, click_body, click_point, example, selected, step, text, tool

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def shared_page(browser, server):
    yield from open_page(browser, server, 900)


# the page's requests a test refuses unless it reads their answers: the explanation (seconds
# of the server's work after each edit) and the assemblies to pick from
UNREAD = re.compile(r".*/api/(explain|assemblies)$")


@pytest.fixture
def page(shared_page, request):
    pg, errors = shared_page
    if pg.get_by_test_id("ui-language").input_value() != "en":
        pg.get_by_test_id("ui-language").select_option("en")
        pg.wait_for_function("() => document.documentElement.lang === 'en'")
    pg.get_by_test_id("tool-select").click()
    refusing = "explanation" not in request.node.name           # the page takes it as any failure
    if refusing:
        pg.route(UNREAD, lambda route: route.abort())
    yield pg
    if refusing:
        pg.unroute(UNREAD)
    assert not errors, errors


def words(lang: str = "en") -> dict[str, str]:
    return page_strings(lang)["messages"]


def editor(pg) -> str:
    return pg.get_by_test_id("model-editor").input_value()


def handle(pg, name: str) -> tuple[float, float]:
    """The centre of a point's handle on the screen (CSS pixels)."""
    box = pg.locator(f'#figure [data-handle="{name}"]').first.bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def idle(pg) -> None:
    """Wait until no drag is under way and the last analysis is shown."""
    pg.wait_for_function("() => !window.kinematika.figure.drag && document.getElementById('busy').hidden")


def analysed_after(pg, gen: int) -> None:
    pg.wait_for_function(f"() => window.kinematika.state.gen > {gen} && document.getElementById('busy').hidden")


# 1. one drag, one step of Undo ---------------------------------------------------------------
def test_one_drag_is_one_step_of_undo(page):
    """The crank's end dragged in three moves, each edited and solved before the next (three
    edits of the text): one press of Undo brings the text from before the drag back, one
    of Redo the text after it."""
    example(page, "four_bar.yaml")
    before = editor(page)
    x, y = handle(page, "A")
    page.mouse.move(x, y)
    page.mouse.down()
    edits = 0
    for i in range(1, 4):
        gen = page.evaluate("window.kinematika.state.gen")
        page.mouse.move(x + 10 * i, y - 8 * i)
        analysed_after(page, gen)                   # this place edited into the text, solved
        edits += 1
    gen = page.evaluate("window.kinematika.state.gen")
    page.mouse.up()
    idle(page)
    after = editor(page)
    assert after != before and edits == 3
    step(page, lambda: page.get_by_test_id("undo").click())
    assert editor(page) == before
    step(page, lambda: page.get_by_test_id("redo").click())
    assert editor(page) == after
    assert gen > 0


# 4. no alarm while building; New forgets the last model ---------------------------------------
def test_what_is_missing_while_building_is_a_hint_not_an_error(page):
    """A pivot alone: nothing moves yet; a crank on it: an input is missing. Both said as a
    hint (no red error box, the degrees of freedom not marked bad); once the crank is the
    input, the hint goes and the model is solved."""
    blank(page)
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    missing = page.get_by_test_id("missing")
    assert missing.is_visible() and missing.inner_text() == words()["missing-body"]
    assert page.get_by_test_id("error").is_hidden()
    tool(page, "link", lambda: click_point(page, "O1"), lambda: click_at(page, (0.04, 0.02)))
    assert missing.inner_text() == words()["missing-input"]
    assert page.get_by_test_id("error").is_hidden()
    assert "bad" not in page.get_by_test_id("dof").get_attribute("class")
    assert page.get_by_test_id("dof").inner_text() == words()["dof"].replace("{$n}", "1")
    page.get_by_test_id("tool-select").click()
    assert page.get_by_test_id("build-hint").inner_text() == words()["missing-input"]
    selected(page, lambda: click_body(page, "O1", "A"), "link1")
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("10")
    step(page, lambda: page.get_by_test_id("set-input").click())
    assert missing.is_hidden() and page.get_by_test_id("error").is_hidden()
    assert page.evaluate("window.kinematika.state.solution.dof") == 1


def test_a_real_error_while_building_is_still_an_error(page):
    """Two inputs on a one-degree-of-freedom crank conflict: that is an error, in red."""
    blank(page)
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    tool(page, "link", lambda: click_point(page, "O1"), lambda: click_at(page, (0.04, 0.02)))
    page.get_by_test_id("tool-select").click()
    selected(page, lambda: click_body(page, "O1", "A"), "link1")
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("10")
    step(page, lambda: page.get_by_test_id("set-input").click())
    selected(page, lambda: click_point(page, "O1"), "O1")
    page.get_by_test_id("properties").get_by_test_id("input-rate-j1").fill("5")
    step(page, lambda: page.get_by_test_id("set-input-j1").click())
    assert page.get_by_test_id("error").is_visible()
    assert page.get_by_test_id("missing").is_hidden()


def test_new_forgets_the_last_models_answers_and_explanation(page):
    example(page, "four_bar.yaml")
    page.wait_for_function("() => document.getElementById('explanation').srcdoc.length > 0")
    assert page.get_by_test_id("answers").locator("td").count() > 0
    blank(page)
    assert page.get_by_test_id("answers").locator("td").count() == 0
    assert page.evaluate("document.getElementById('explanation').srcdoc") == ""
    assert page.locator("#answers-stale").is_hidden() and page.locator("#plot-box").is_hidden()
    assert page.get_by_test_id("error").is_hidden()


# 5. words that agree ---------------------------------------------------------------------------
def field_words(pg, testid: str) -> list[str]:
    """The words before each field `testid` of the properties panel."""
    return pg.get_by_test_id("properties").locator(f"input[data-testid='{testid}']").evaluate_all(
        "fields => fields.map((f) => f.previousElementSibling.textContent)")


def template(pg, name: str) -> None:
    pg.locator("#new-menu summary").click()
    step(pg, lambda: pg.get_by_test_id(f"new-{name}").click())


def test_one_quantity_has_one_word_and_one_place(page):
    """The offset slider-crank stated by its dimensions: the rod's length AB is the same words
    and the same value on the rod and on its end B; the guide's height is typed on the
    slider only (B says where); the crank's length and angle read the same on the crank and
    on A."""
    template(page, "slider-crank")
    selected(page, lambda: click_body(page, "A", "B"), "rod")
    rod = field_words(page, "prop-length")
    value = page.get_by_test_id("properties").locator("input[data-testid='prop-length']").input_value()
    assert rod == [words()["prop-length"].replace("{$about}", "AB") + " (l)"]      # the parameter it sets
    selected(page, lambda: click_point(page, "B"), "B")
    assert field_words(page, "prop-length") == rod
    assert page.get_by_test_id("properties").locator("input[data-testid='prop-length']").input_value() == value == "0.15"
    assert field_words(page, "prop-line-y") == [] and field_words(page, "prop-direction") == []
    assert page.get_by_test_id("properties").get_by_test_id("prop-guide-on").inner_text() == \
        words()["prop-guide-on"].replace("{$about}", "slider")
    selected(page, lambda: click_point(page, "A"), "A")
    at_a = field_words(page, "prop-length") + field_words(page, "prop-angle")
    selected(page, lambda: click_body(page, "O", "A"), "crank")
    assert field_words(page, "prop-length") + field_words(page, "prop-angle") == at_a == \
        [words()["prop-length"].replace("{$about}", "OA") + " (r)", words()["prop-angle"].replace("{$about}", "OA") + " (theta)"]


def test_the_slider_body_has_its_guide(page):
    template(page, "slider-crank")
    page.get_by_test_id("tool-select").click()
    block = page.locator("#figure g.body[data-body=slider]").bounding_box()     # beside the pin's handle
    selected(page, lambda: page.mouse.click(block["x"] + 4, block["y"] + block["height"] / 2), "slider")
    assert field_words(page, "prop-line-y") == [words()["prop-line-y"]]


def test_each_click_of_a_tool_has_its_own_hint(page):
    """The Link tool asks for its first end, then for its second."""
    blank(page)
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    page.get_by_test_id("tool-link").click()
    hint = page.get_by_test_id("build-hint")
    first = hint.inner_text()
    click_point(page, "O1")
    second = hint.inner_text()
    name = words()["tool-link"]
    assert (first, second) == (f"{name}: {words()['pick-link-1']}", f"{name}: {words()['pick-link-2']}")
    page.keyboard.press("Escape")


# 3. names ---------------------------------------------------------------------------------------
def test_a_new_model_speaks_the_pages_language(page):
    """On the Basque page a new model is `Mekanismo berria` and its fixed body `lurra`; a
    blank model made on the English page and not begun becomes the Basque one when the
    page turns Basque."""
    blank(page)
    assert "name: New mechanism" in editor(page)
    step(page, lambda: page.get_by_test_id("ui-language").select_option("eu"))
    page.wait_for_function("() => document.querySelector('[data-testid=model-editor]').value.includes('Mekanismo berria')")
    tool(page, "pivot", lambda: click_at(page, (0, 0)))
    tool(page, "link", lambda: click_point(page, "O1"), lambda: click_at(page, (0.04, 0.02)))
    model = text(page)
    assert (model["name"], model["frame"]) == ("Mekanismo berria", "lurra")
    assert model["bodies"] == {"lurra": ["O1"], "barra1": ["O1", "A"]}
    assert model["joints"][0]["bodies"] == ["lurra", "barra1"]


def rename_field(pg):
    return pg.get_by_test_id("properties").locator("input[data-testid=rename]")


def test_a_body_and_a_point_are_renamed_from_the_properties(page):
    """The slider-crank's rod becomes `biela` and its end B becomes `C`: everywhere the model
    names them (bodies, joints, questions, the pin's construction), and the answers say so;
    the rod's name in Spanish is typed into the model's `names:`."""
    template(page, "slider-crank")
    selected(page, lambda: click_body(page, "A", "B"), "rod")
    field = rename_field(page)
    assert field.input_value() == "rod"
    step(page, lambda: (field.fill("biela"), field.press("Enter")))
    page.get_by_test_id("properties").get_by_test_id("selected").filter(has_text="biela").wait_for()
    model = text(page)
    assert "rod" not in model["bodies"] and model["bodies"]["biela"] == ["A", "B"]
    assert [j["bodies"] for j in model["joints"]][1:3] == [["crank", "biela"], ["biela", "slider"]]
    assert model["ask"][2] == {"omega": "biela"}
    assert "biela" in page.get_by_test_id("answers").locator("td.q").all_inner_texts()[2]
    page.get_by_test_id("properties").get_by_test_id("names-per-language").locator("summary").click()
    spanish = page.get_by_test_id("properties").locator("input[data-testid=name-es]")
    step(page, lambda: (spanish.fill("la biela"), spanish.press("Enter")))
    assert text(page)["names"] == {"es": {"bodies": {"biela": "la biela"}}}
    selected(page, lambda: click_point(page, "B"), "B")
    step(page, lambda: (rename_field(page).fill("C"), rename_field(page).press("Enter")))
    model = text(page)
    assert "B" not in model["points"] and model["points"]["C"]["circle"] == ["A", "l"]
    assert model["bodies"]["biela"] == ["A", "C"] and model["bodies"]["slider"] == ["C"]
    assert model["joints"][2]["at"] == "C" and model["ask"][:2] == [{"velocity": "C"}, {"acceleration": "C"}]
    assert page.get_by_test_id("error").is_hidden()


# 2. turning the mechanism by hand ---------------------------------------------------------------
def screen(pg, xy) -> tuple[float, float]:
    return tuple(pg.evaluate(f"window.kinematika.toScreen({json.dumps(list(xy))})"))


def row(pg) -> int:
    return int(pg.get_by_test_id("input-slider").input_value())


def test_the_crank_is_turned_by_hand_and_the_model_stays(page):
    """The four-bar's crank pin A (O2A = 1, drawn at 90°) dragged by hand along a quarter
    turn to (−1, 0): the mechanism follows, A under the pointer, the slider at +90° (row
    90 of the 360 one-degree steps: A = (cos(90° + k), sin(90° + k)) is (−1, 0) at k = 90),
    and the model's text is what it was."""
    example(page, "four_bar.yaml")
    before = editor(page)
    page.get_by_test_id("by-hand").click()
    assert page.get_by_test_id("build-hint").inner_text() == words()["hint-by-hand"]
    x, y = handle(page, "A")
    assert (x, y) == pytest.approx(screen(page, (0, 1)), abs=1)
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 11):                             # along the crank's circle, 9° at a time
        t = math.radians(90 + 9 * i)
        page.mouse.move(*screen(page, (math.cos(t), math.sin(t))))
    page.mouse.up()
    assert row(page) == 90
    assert handle(page, "A") == pytest.approx(screen(page, (-1, 0)), abs=1.5)
    page.get_by_test_id("by-hand").click()
    idle(page)
    assert editor(page) == before


def test_shift_drag_stops_the_rocker_at_its_limit_position(page):
    """The rocker's end B dragged with Shift far beyond where it can go: it stops at the
    limit position, crank and coupler in line. By hand: B on the circle of radius 3 about
    O4 = (4, 0) with |O2B| = a + b = 5 is (4, 3) (the upper branch); the crank is then at
    atan2(3, 4) = 36.87°, 53.13° before its drawn 90°: row 307 of 360 (a full turn,
    307° ahead)."""
    example(page, "four_bar.yaml")
    before = editor(page)
    x, y = handle(page, "B")
    page.keyboard.down("Shift")
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 9):                              # towards (6, 1), past the limit
        page.mouse.move(*screen(page, (3.489 + 2.511 * i / 8, 2.956 - 1.956 * i / 8)))
    page.mouse.up()
    page.keyboard.up("Shift")
    assert abs(row(page) - (360 - math.degrees(math.atan2(4, 3)))) <= 1
    b = json.loads(page.get_by_test_id("answers").locator('td[data-key="points.B@coupler.position"]')
                   .get_attribute("data-value"))
    assert b == pytest.approx([4, 3], abs=2e-3)        # within a degree of crank of the limit
    idle(page)
    assert editor(page) == before


def test_a_fixed_point_does_not_turn(page):
    example(page, "four_bar.yaml")
    page.get_by_test_id("by-hand").click()
    x, y = handle(page, "O4")
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + 30, y + 30)
    page.mouse.up()
    assert row(page) == 0
    page.locator("#toast").filter(has_text="O4").wait_for()
    page.get_by_test_id("by-hand").click()


# 7. a phone ------------------------------------------------------------------------------------
@pytest.fixture
def phone(browser, server):
    context = browser.new_context(viewport={"width": 390, "height": 844})
    pg = context.new_page()
    pg.set_default_timeout(BROWSER_WAIT)
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(server.url)
    pg.wait_for_function("() => window.kinematika && window.kinematika.state.solution && document.getElementById('busy').hidden")
    yield pg
    context.close()
    assert not errors, errors


def test_a_phone_shows_every_answer_and_every_line(phone):
    """At 390 × 844 the four-bar's answers fit the panel (θ, rotation, ω, α of every body,
    position, velocity and acceleration of every point, none cut off), every line of the
    model's text is seen whole, and no label of the figure sticks out of it."""
    outside = phone.evaluate("""() => {
        const panel = document.getElementById('answers').getBoundingClientRect();
        return [...document.querySelectorAll('#answers td.v')].filter((td) => {
            const r = td.getBoundingClientRect();
            return r.left < panel.left - 0.5 || r.right > panel.right + 0.5; }).map((td) => td.dataset.key); }""")
    assert not outside, outside
    keys = phone.evaluate("[...document.querySelectorAll('#answers td.v')].map((td) => td.dataset.key)")
    assert {"bodies.rocker.alpha", "points.B@coupler.acceleration"} <= set(keys)
    area = phone.get_by_test_id("model-editor")
    assert area.evaluate("(t) => t.scrollWidth <= t.clientWidth")          # no line runs out of sight
    gutter = phone.evaluate("document.getElementById('gutter').textContent.split('\\n')")
    lines = area.input_value().split("\n")
    assert [x for x in gutter if x] == [str(i) for i in range(1, len(lines) + 1)]
    assert len(gutter) - 1 > len(lines)                # long lines wrap, and their rows are numbered once
    cut = phone.evaluate("""() => {
        const box = document.getElementById('figure').getBoundingClientRect();
        return [...document.querySelectorAll('#figure .content text')].filter((t) => {
            if (t.closest('[style*="display: none"]') || t.getAttribute('visibility') === 'hidden') return false;
            const r = t.getBoundingClientRect();
            return r.width && (r.left < box.left - 0.5 || r.right > box.right + 0.5 ||
                               r.top < box.top - 0.5 || r.bottom > box.bottom + 0.5); }).map((t) => t.textContent); }""")
    assert not cut, cut


def test_a_phone_shows_the_selected_elements_properties_by_the_figure(phone):
    """A point tapped in the figure: its properties come up by the figure, both in sight,
    without scrolling; tapping the grid puts them away."""
    x, y = (lambda b: (b["x"] + b["width"] / 2, b["y"] + b["height"] / 2))(
        phone.locator('#figure [data-handle="A"]').bounding_box())
    phone.mouse.click(x, y)
    phone.get_by_test_id("properties").get_by_test_id("selected").filter(has_text="A").wait_for()
    seen = phone.evaluate("""() => {
        const field = document.querySelector('[data-testid=properties] input[data-testid=prop-length]');
        const r = field.getBoundingClientRect(), f = document.getElementById('figure').getBoundingClientRect();
        const cx = r.left + r.width / 2, cy = r.top + r.height / 2;
        const handle = document.querySelector('#figure [data-handle="A"]').getBoundingClientRect();
        const hx = handle.left + handle.width / 2, hy = handle.top + handle.height / 2;
        return {field: document.elementFromPoint(cx, cy) === field && cy < innerHeight,
                figure: f.top >= -1 && f.bottom <= document.getElementById('properties').getBoundingClientRect().top + 1,
                point: document.getElementById('figure').contains(document.elementFromPoint(hx, hy))}; }""")
    assert seen == {"field": True, "figure": True, "point": True}
    phone.get_by_test_id("close-properties").click()
    assert phone.evaluate("getComputedStyle(document.getElementById('properties')).position") != "fixed"


# 6. one angle convention -------------------------------------------------------------------------
def rocker_theta(crank_deg: float) -> float:
    """The four-bar's rocker angle θ (O4 → B from the x axis) by hand: A = (cos c, sin c),
    B where the circles |AB| = 4 and |O4B| = 3 (O4 = (4, 0)) meet, left of A → O4."""
    c = math.radians(crank_deg)
    a, o4 = (math.cos(c), math.sin(c)), (4.0, 0.0)
    dx, dy = o4[0] - a[0], o4[1] - a[1]
    d = math.hypot(dx, dy)
    along = (16 - 9 + d * d) / (2 * d)
    h = math.sqrt(16 - along * along)
    b = (a[0] + along * dx / d - h * dy / d, a[1] + along * dy / d + h * dx / d)
    return math.degrees(math.atan2(b[1], b[0] - 4))


def test_the_plot_gives_the_tables_angle_against_the_cranks_angle(page):
    """The four-bar's plot shows the rocker's angle θ (as the table's θ column and the
    command line's plot), against the crank's angle θ (90° as drawn, 180° at the slider's
    row 90), both said so."""
    example(page, "four_bar.yaml")
    assert round(rocker_theta(90), 2) == 99.81
    chips = page.get_by_test_id("plot-pick").locator("button[aria-pressed=true]").all_inner_texts()
    assert chips[0] == words()["plot-angle"].replace("{$body}", "rocker") + " (°)"
    assert words()["plot-input-angle"].replace("{$body}", "crank") in page.get_by_test_id("plot").text_content()
    import yaml

    from kinematika.draw.plots import read_sweep
    from kinematika.sweep import run_sweep
    from tests.conftest import EXAMPLES

    reading = read_sweep(run_sweep(yaml.safe_load((EXAMPLES / "four_bar.yaml").read_text())))   # the twin
    rocker = next(x for p in reading.panels if p.quantity == "angle" for x in p.series if x.name == "rocker")
    for k, crank in ((0, 90), (90, 180)):
        assert (reading.x[k], rocker.values[k]) == pytest.approx((crank, rocker_theta(crank)), abs=1e-6)
        page.get_by_test_id("input-slider").fill(str(k))
        shown = page.locator("#plot text[font-family=monospace]").first.text_content()
        cell = json.loads(page.get_by_test_id("answers").locator('td[data-key="bodies.rocker.angle"]')
                          .get_attribute("data-value"))
        assert float(shown.replace("−", "-")) == pytest.approx(rocker_theta(crank), abs=0.05)   # 4 digits
        assert cell == pytest.approx(rocker_theta(crank), abs=1e-6)
    page.get_by_test_id("input-slider").fill("0")
