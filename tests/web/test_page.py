"""The page in a real browser (Debian's Chromium driven by Playwright): what a new user
does with `kinematika app examples/four_bar.yaml` — sees the linkage, drags the slider
through a full turn with the numbers following, edits a length and sees it re-solve, drags
a point, reads the Basque explanation, downloads the CSV, copies a link.

Skipped only when Chromium is not installed (`bash scripts/browser.sh` installs it); under
CI it must be there. The figures for the four-bar are derived by hand: the crank O2A has
length 1, is drawn at 90° and turns at ω = 10 rad/s, so at an input of k degrees
A = (cos(90°+k), sin(90°+k)) and v_A = 10·(−sin(90°+k), cos(90°+k)).
"""
from __future__ import annotations

import json
import math
import re
import statistics
from contextlib import contextmanager
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from kinematika.cli import app as cli       # the typer application, every command registered
from tests.core.models import jansen
from tests.conftest import BROWSER_WAIT, DEEP, EXAMPLES

from .conftest import CHROMIUM, FLAGS, _chromium_or_skip  # noqa: F401 - used by other modules too

pytestmark = [pytest.mark.browser,
              pytest.mark.early]     # minutes of work: handed to a worker before the shorter files (tests/conftest.py)
FOUR_BAR = EXAMPLES / "four_bar.yaml"
EXPLAINED = "() => { const s = window.kinematika.state; return s.explained === `${s.gen}|${s.lang}|${s.row}`; }"


@pytest.fixture
def page(browser, server):
    context = browser.new_context(viewport={"width": 1400, "height": 1000}, bypass_csp=True,
                                  accept_downloads=True)
    pg = context.new_page()
    pg.set_default_timeout(BROWSER_WAIT)          # a hang detector: a loaded machine is slow, not wrong
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.on("console", lambda m: errors.append(m.text) if m.type == "error" and "attribute" in m.text
          else None)                                   # an SVG attribute set to NaN, say
    pg.on("dialog", lambda d: (errors.append(f"dialog: {d.message}"), d.dismiss()))
    pg.goto(server.url)
    ready(pg)
    yield pg
    context.close()
    assert not errors, errors


def ready(pg) -> None:
    """Wait for the model to be solved, drawn and swept."""
    pg.wait_for_function("() => window.kinematika && window.kinematika.state.solution"
                         " && document.getElementById('busy').hidden", timeout=BROWSER_WAIT)


def cell(pg, key: str):
    return json.loads(pg.get_by_test_id("answers").locator(f'td[data-key="{key}"]')
                      .get_attribute("data-value"))


def sweep_rows(path: Path = FOUR_BAR, *args: str) -> dict:
    result = CliRunner().invoke(cli, ["sweep", str(path), "--json", "--skip-bad", *args])
    assert result.exit_code == 0
    return json.loads(result.stdout)


def set_row(pg, k: int) -> float:
    """Move the slider to row k as an input event does; the milliseconds until the next
    frame is painted with the figure and table updated."""
    return pg.evaluate("""async (k) => {
        const s = document.querySelector('[data-testid=input-slider]');
        const t0 = performance.now();
        s.value = String(k);
        s.dispatchEvent(new Event('input', {bubbles: true}));
        await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
        return performance.now() - t0;
    }""", k)


def v_a(k: float) -> list[float]:
    t = math.radians(90 + k)
    return [-10 * math.sin(t), 10 * math.cos(t)]


def test_loads_the_linkage_with_its_answers(page):
    figure = page.get_by_test_id("figure")
    assert sorted(figure.locator("g.body").evaluate_all("gs => gs.map(g => g.dataset.body)")) == \
        ["coupler", "crank", "rocker"]
    assert page.get_by_test_id("dof").inner_text() == "DOF 1"
    assert page.get_by_test_id("error").is_hidden()
    assert cell(page, "points.A@crank.velocity") == pytest.approx([-10.0, 0.0], abs=1e-9)
    assert cell(page, "bodies.crank.omega") == 10.0
    # the asked velocity of B, answered as the CLI answers it
    cli_json = json.loads(CliRunner().invoke(cli, ["solve", str(FOUR_BAR), "--json"]).stdout)
    assert cell(page, "answers.0") == cli_json["answers"][0]["value"]
    assert figure.locator("[data-mark]").count() == 6            # every instant centre
    assert figure.locator("[data-kennedy]").count() > 0
    # I13 is far above, labelled with its place without round-off: on the crank's line
    # x = 0 (O2A is vertical) and on the rocker's line O4B. B by hand: |AB| = 4 from
    # A = (0, 1), |O4B| = 3 from O4 = (4, 0), the upper of the two points.
    ax, ay, ox, b, c = 0.0, 1.0, 4.0, 4.0, 3.0
    d = math.hypot(ox - ax, ay)
    along = (b * b - c * c + d * d) / (2 * d)
    h = math.sqrt(b * b - along * along)
    ux, uy = (ox - ax) / d, (0 - ay) / d
    bx, by = max(((ax + along * ux - s * h * uy, ay + along * uy + s * h * ux) for s in (1, -1)),
                 key=lambda p: p[1])
    i13 = ox / (ox - bx) * by                      # O4 + t (B - O4) where x = 0
    label = figure.locator("[data-mark='centre:ground-coupler'] text")
    assert label.text_content() == f"I13 far off at (0, {i13:.3g})"     # as the figure writes it
    # the rocker's line is measured from its fixed pivot, as the sweep plots measure it:
    # O4 → B, not B → O4 as its points are listed
    assert cell(page, "bodies.rocker.angle") == pytest.approx(math.degrees(math.atan2(by, bx - ox)), abs=1e-9)


# what the slider test reads at each row: the table's cells it checks (as `cell` reads them)
# and the crank's end A where the figure draws it, in model coordinates
ROW_SHOWN = """() => {
    const value = (key) => JSON.parse(document.querySelector(
        `[data-testid=answers] td[data-key="${key}"]`).getAttribute('data-value'));
    const out = {};
    for (const key of ['bodies.crank.rotation', 'bodies.crank.angle', 'points.A@crank.velocity',
                       'points.B@coupler.acceleration', 'bodies.rocker.omega']) out[key] = value(key);
    const c = document.querySelector('[data-point=A]');
    const m = c.getCTM(), s = document.querySelector('[data-testid=figure]').getCTM().inverse();
    const p = new DOMPoint(+c.getAttribute('cx'), +c.getAttribute('cy')).matrixTransform(m).matrixTransform(s);
    out.A = [p.x, -p.y];
    return out; }"""


def test_the_slider_drives_figure_and_table_through_a_full_turn(page, capsys):
    rows = sweep_rows()
    slider = page.get_by_test_id("input-slider")
    assert slider.get_attribute("max") == "360"
    # drag the slider's thumb with the mouse from one end to the other
    box = slider.bounding_box()
    y = box["y"] + box["height"] / 2
    page.mouse.move(box["x"] + 2, y)
    page.mouse.down()
    page.mouse.move(box["x"] + box["width"] / 2, y, steps=12)
    k = int(slider.input_value())
    assert 150 < k < 210
    assert cell(page, "points.A@crank.velocity") == pytest.approx(v_a(k), abs=1e-9)
    assert cell(page, "points.B@coupler.velocity") == rows["points"]["B@rocker"]["velocity"][k]
    page.mouse.move(box["x"] + box["width"] - 1, y, steps=12)
    page.mouse.up()
    assert slider.input_value() == "360"
    times = []
    for k in range(0, 361, 15):              # a full turn, every 15th row
        times.append(set_row(page, k))
        shown = page.evaluate(ROW_SHOWN)      # the row's cells and where A is drawn, in one look
        # the rotation since the drawn position, and the textbook angle of O2A (drawn at 90°)
        assert shown["bodies.crank.rotation"] == rows["bodies"]["crank"]["angle"][k] == pytest.approx(k)
        assert shown["bodies.crank.angle"] == pytest.approx(90 + k, abs=1e-9)
        assert shown["points.A@crank.velocity"] == pytest.approx(v_a(k), abs=1e-9)
        for key in ("B@coupler", "B@rocker"):      # one motion, one row (B@coupler)
            assert shown["points.B@coupler.acceleration"] == rows["points"][key]["acceleration"][k]
        assert shown["bodies.rocker.omega"] == rows["bodies"]["rocker"]["omega"][k]
        # the crank's bar is drawn where the sweep puts A
        assert shown["A"] == pytest.approx(rows["points"]["A@crank"]["position"][k], abs=1e-9)
    with capsys.disabled():
        print(f"\n[page] slider to painted frame: median {statistics.median(times):.1f} ms, "
              f"max {max(times):.1f} ms over {len(times)} positions")


def test_editing_a_length_solves_again(page):
    editor = page.get_by_test_id("model-editor")
    text = editor.input_value()
    assert "  a: 1 " in text                                      # the crank O2A, by construction
    editor.fill(text.replace("  a: 1 ", "  a: 1.5 "))             # the crank 1.5 long
    page.wait_for_function("() => JSON.parse(document.querySelector("
                           "'td[data-key=\"points.A@crank.velocity\"]').dataset.value)[0] < -14")
    assert cell(page, "points.A@crank.velocity") == pytest.approx([-15.0, 0.0], abs=1e-9)
    assert cell(page, "points.A@crank.position") == [0.0, 1.5]
    assert page.get_by_test_id("error").is_hidden()


@contextmanager
def edited(page, old: str, new: str, box: str):
    """The editor's text with `old` replaced by `new` until the block ends (then the text as
    it was, and the box `box` hidden again); yields the editor, the text as it was and the
    box, once the box is shown."""
    editor = page.get_by_test_id("model-editor")
    good = editor.input_value()
    editor.fill(good.replace(old, new))
    shown = page.get_by_test_id(box)
    shown.wait_for(state="visible")
    yield editor, good, shown
    editor.fill(good)
    shown.wait_for(state="hidden")


def test_errors_appear_as_you_type_at_their_place(page):
    with edited(page, "at: O4}", "at: Q4}", "error") as (editor, good, error):
        assert error.get_attribute("data-kind") == "schema" and "'Q4'" in error.inner_text()
        bad_line = good.splitlines().index(next(l for l in good.splitlines() if "at: O4}" in l)) + 1
        assert page.locator("#gutter .bad").inner_text() == str(bad_line)
        editor.fill(good.replace("drivers:", "drivers: ["))
        page.wait_for_function("() => document.querySelector('[data-testid=error]').dataset.kind === 'syntax'")
    assert page.get_by_test_id("dof").inner_text() == "DOF 1"


@pytest.mark.filterwarnings("ignore::kinematika.errors.KinematikaWarning")   # the server's, in its threads
def test_an_angle_in_radians_meant_as_degrees_is_answered_with_a_warning(page):
    with edited(page, "theta2: deg(90)", "theta2: 90", "warnings") as (_, _, warning):
        assert "points.A.angle" in warning.inner_text() and "deg(90)" in warning.inner_text()
        # answered as written: A at 90 rad on the crank circle, its speed a·ω = 10 across O2A
        t = 90.0
        assert cell(page, "points.A@crank.position") == pytest.approx([math.cos(t), math.sin(t)], abs=1e-9)
        assert cell(page, "points.A@crank.velocity") == pytest.approx([-10 * math.sin(t), 10 * math.cos(t)],
                                                                      abs=1e-9)


def handle_centre(page, point: str) -> tuple[float, float]:
    """Where the figure draws the drag handle of `point`: its box's centre on the screen."""
    box = page.locator(f'[data-testid=figure] [data-handle="{point}"]').bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def grab(page, point: str) -> tuple[float, float]:
    """At the sweep's first row, the pointer pressed on the handle of `point` (where it is)."""
    set_row(page, 0)
    x, y = handle_centre(page, point)
    page.mouse.move(x, y)
    page.mouse.down()
    return x, y


def test_dragging_a_point_changes_the_text(page):
    x, y = grab(page, "A")
    page.mouse.move(x + 20, y - 30, steps=6)
    page.mouse.up()
    page.wait_for_function("() => !document.querySelector('[data-testid=model-editor]').value.includes('theta2: deg(90)')")
    page.wait_for_function("() => !window.kinematika.figure.drag && document.getElementById('busy').hidden")
    ready(page)                                      # the drag's last edit solved (no edit under way)
    text = page.get_by_test_id("model-editor").input_value()
    # A is the crank's end by construction (a from O2 at theta2): the drag edits those two
    params = yaml.safe_load(text)["parameters"]
    theta = math.radians(float(params["theta2"].removeprefix("deg(").removesuffix(")")))
    x_new, y_new = params["a"] * math.cos(theta), params["a"] * math.sin(theta)
    assert x_new > 0 and y_new > 1                       # right of and above where it was
    assert cell(page, "points.A@crank.position") == pytest.approx([x_new, y_new])
    # the crank turning at 10 rad/s about O2 = (0, 0): v_A = 10·(−y, x)
    assert cell(page, "points.A@crank.velocity") == pytest.approx([-10 * y_new, 10 * x_new])


def test_basque_explanation_of_the_current_position(page):
    set_row(page, 90)
    page.get_by_test_id("language").select_option("eu")
    frame = page.frame_locator("[data-testid=explanation]")
    frame.locator("html[lang=eu]").wait_for()     # an explanation with figures (the page's default wait)
    # one choice: the page speaks Basque too ("at j1 +90°" is "j1 +90° posizioan")
    page.wait_for_function("() => document.getElementById('explanation-where').textContent === 'j1 +90° posizioan'", timeout=BROWSER_WAIT)
    body = frame.locator("body").inner_text()
    assert "Abiadurak" in body and "Azelerazioak" in body
    assert "Velocities" not in body
    printed = CliRunner().invoke(cli, ["explain", str(FOUR_BAR), "--move", "j1=90", "--lang", "eu",
                                       "--format", "html"]).stdout
    assert page.get_by_test_id("explanation").get_attribute("srcdoc") == printed


def test_at_rest_the_slider_position_is_solved_exactly(page):
    set_row(page, 90)
    answers = page.get_by_test_id("answers")
    page.wait_for_function("() => !document.querySelector('[data-testid=answers] td.held')")
    moved = json.loads(CliRunner().invoke(cli, ["solve", str(FOUR_BAR), "--move", "j1=90", "--json"]).stdout)
    for i, a in enumerate(moved["answers"]):
        assert cell(page, f"answers.{i}") == a["value"]
    # the crank at 180°: A = (−1, 0) lies on the ground line O2O4, so the coupler's centre
    # (where the lines O2A and O4B meet) is O4
    assert moved["answers"][6]["value"] == {"point": [4.0, 0.0]}
    assert answers.locator("td.held").count() == 0
    assert page.get_by_test_id("figure").locator("[data-mark]").count() >= 5


def test_the_other_assembly_can_be_picked(page):
    pick = page.get_by_test_id("assembly")
    page.wait_for_function("() => document.querySelector('[data-testid=assembly]').options.length === 3")
    pick.select_option("2")
    crossed = json.loads(CliRunner().invoke(cli, ["solve", str(FOUR_BAR), "--assembly", "2", "--json"]).stdout)
    b = crossed["points"]["B@rocker"]["position"]
    page.wait_for_function(f"() => JSON.parse(document.querySelector("
                           f"'td[data-key=\"points.B@coupler.position\"]').dataset.value)[1] < {b[1] + 1e-6}")
    assert cell(page, "points.B@coupler.position") == b
    assert b[1] < 0                          # the crossed four-bar: B below the ground line


def test_downloads_the_sweep_as_csv(page, tmp_path):
    page.locator("#downloads summary").click()
    with page.expect_download() as info:
        page.get_by_test_id("download-csv").click()
    download = info.value
    assert download.suggested_filename == "four_bar.csv"
    saved = tmp_path / "rows.csv"
    download.save_as(saved)
    expected = tmp_path / "cli.csv"
    assert CliRunner().invoke(cli, ["sweep", str(FOUR_BAR), "--skip-bad", "--csv", str(expected)]).exit_code == 0
    assert saved.read_bytes() == expected.read_bytes()
    lines = saved.read_text().splitlines()
    assert lines[0].startswith("coordinate_deg,") and len(lines) == 362
    page.locator("#downloads summary").click()
    with page.expect_download() as info:
        page.get_by_test_id("download-model").click()
    model = tmp_path / "model.yaml"
    info.value.save_as(model)
    assert info.value.suggested_filename == "four_bar.yaml"
    assert model.read_text() == FOUR_BAR.read_text()


def test_the_link_holds_the_model(page, browser, server):
    editor = page.get_by_test_id("model-editor")
    edited = editor.input_value().replace("w2: 10", "w2: 7")
    editor.fill(edited)
    page.wait_for_function("() => window.kinematika.state.solution.bodies.crank.omega === 7")
    page.get_by_test_id("copy-link").click()
    page.wait_for_function("() => location.hash.includes('model=')")
    url = page.url
    other = browser.new_context(bypass_csp=True).new_page()
    other.goto(url)
    ready(other)
    assert other.get_by_test_id("model-editor").input_value() == edited
    assert cell(other, "bodies.crank.omega") == 7.0
    other.context.close()


def test_play_moves_the_input(page):
    play = page.get_by_test_id("play")
    play.click()
    page.wait_for_function("() => +document.querySelector('[data-testid=input-slider]').value > 10")
    play.click()
    k = int(page.get_by_test_id("input-slider").input_value())
    page.wait_for_timeout(200)
    assert int(page.get_by_test_id("input-slider").input_value()) == k     # stopped
    assert cell(page, "points.A@crank.velocity") == pytest.approx(v_a(k), abs=1e-9)


@pytest.mark.parametrize("name", ["slider_crank.yaml", "quick_return.yaml", "planetary_gears.yaml",
                                  "robot_arm_3d.yaml", "fan_symbolic.yaml"])
def test_every_kind_of_model_is_shown(page, server, name):
    """A prismatic joint, a slot, gears, a 3D model, a symbolic one: drawn, with
    the slider over the sweep when there is one (and off, saying why, when there is none).
    Their explanations are not read here (the gears' is seconds of the server's work; the
    page's explanation is test_basque_explanation_of_the_current_position's matter, the
    API's each kind's in test_api.py): the page's requests for them are refused, which it
    takes as any such failure."""
    page.route(re.compile(r".*/api/explain$"), lambda route: route.abort())
    gen = page.evaluate("window.kinematika.state.gen")
    page.get_by_test_id("example").select_option(name)
    server.wait(page, "(gen) => window.kinematika.state.gen > gen && document.getElementById('busy').hidden", gen)
    assert page.get_by_test_id("error").is_hidden()
    cli_json = json.loads(CliRunner().invoke(cli, ["solve", str(EXAMPLES / name), "--json"]).stdout)
    assert page.get_by_test_id("dof").inner_text() == f"DOF {cli_json['dof']}"
    assert cell(page, "answers.0") == cli_json["answers"][0]["value"]
    answers = page.get_by_test_id("answers")        # long answers (a decomposition) wrap
    assert answers.evaluate("a => a.scrollWidth <= a.clientWidth")
    figure = page.get_by_test_id("figure")
    names = {key.split("@")[0] for key in cli_json["points"]}
    assert figure.locator("[data-point]").count() == len(names)
    # a point is dragged in the plane; a 3D model's points are moved in its text
    assert figure.locator("[data-handle]").count() == (len(names) if cli_json["dimension"] == 2 else 0)
    sweep = CliRunner().invoke(cli, ["sweep", str(EXAMPLES / name), "--json", "--skip-bad"])
    slider = page.get_by_test_id("input-slider")
    if sweep.exit_code != 0:
        assert slider.is_disabled() and "the slider is off" in page.locator("#notes").inner_text()
        return
    rows = json.loads(sweep.stdout)
    last = len(rows["coordinate"]) - 1
    assert slider.get_attribute("max") == str(last)
    # the plot opens on quantities that change over the motion (a piston's speed, not its angle)
    shown = page.locator("[data-testid=plot-pick] button[aria-pressed=true]").evaluate_all(
        "bs => bs.map(b => b.dataset.quantity)")
    key, what = shown[0].rsplit(".", 1)
    series = rows["bodies"][key][what] if key in rows["bodies"] else \
        rows["points"][key]["velocity" if what == "speed" else "acceleration"]
    assert len({json.dumps(x) for x in series if x is not None}) > 1, shown
    set_row(page, last)
    body = next(b for b in rows["bodies"] if b != "ground")
    assert cell(page, f"bodies.{body}.omega") == rows["bodies"][body]["omega"][last]


def test_names_are_shown_as_text_never_as_markup(page):
    """Markup, control characters and bidirectional overrides in names: shown escaped, as
    the command line shows them; nothing is interpreted."""
    text = FOUR_BAR.read_text().replace("name: Four-bar linkage",
                                        'name: "<img src=x onerror=alert(1)>\\x1b[31m"')
    text = text.replace("crank", '"<b>cr\\u202eank</b>"')
    editor = page.get_by_test_id("model-editor")
    editor.fill(text)
    page.wait_for_function("() => window.kinematika.state.solution && "
                           "window.kinematika.state.solution.name.startsWith('<img')")
    ready(page)
    assert page.get_by_test_id("error").is_hidden()
    assert page.locator("#model-name").inner_text() == "<img src=x onerror=alert(1)>\\x1b[31m"
    assert page.locator("body img, #answers b b, #figure b").count() == 0
    body = r"<b>cr\u202eank</b>"
    assert body in page.get_by_test_id("answers").inner_text()
    assert f"2 {body}" in page.locator("#notes").inner_text()
    assert any(body in c for c in page.locator("[data-testid=plot-pick] button").all_inner_texts())


def test_a_phone_sees_the_whole_page_width_under_the_pages_own_security_policy(browser, server):
    """A phone's width: every part of the page within it. The page as a user gets it (no
    CSP bypass): it runs under its own security policy, with nothing refused."""
    context = browser.new_context(viewport={"width": 390, "height": 844})
    pg = context.new_page()
    problems: list[str] = []
    pg.on("console", lambda m: problems.append(m.text) if m.type == "error" else None)
    pg.on("pageerror", lambda e: problems.append(str(e)))
    pg.goto(server.url)
    ready(pg)
    pg.get_by_test_id("figure").locator("g.body").first.wait_for()
    pg.get_by_test_id("dof").filter(has_text="DOF 1").wait_for()
    assert pg.evaluate("document.documentElement.scrollWidth") <= 390
    for part in ("copy-link", "example", "assembly", "figure", "input-slider", "model-editor"):
        box = pg.get_by_test_id(part).bounding_box()
        assert box["x"] >= 0 and box["x"] + box["width"] <= 390, part
    assert not problems, problems
    context.close()


def test_a_3d_figure_follows_the_slider(page, capsys):
    """The spherical four-bar moves with the slider, not only where it settles. By hand:
    A turns about z on its cone, at an input of k° A = (−sin 30° sin k, sin 30° cos k,
    cos 30°); B stays 70° from A and 50° from D = (sin 60°, 0, cos 60°)."""
    path = EXAMPLES / "spherical_four_bar.yaml"
    page.get_by_test_id("example").select_option(path.name)
    page.wait_for_function("() => window.kinematika.state.solution.name === 'Spherical four-bar'")
    ready(page)
    P = page.evaluate("window.kinematika.state.scene.projection")
    on_page = lambda x: [sum(r * c for r, c in zip(row, x)) for row in P]
    rows = sweep_rows(path)
    d = [math.sin(math.radians(60)), 0, math.cos(math.radians(60))]
    angle = lambda u, v: math.degrees(math.acos(sum(a * b for a, b in zip(u, v))))
    times = []
    for k in (7, 24, 50, 67):
        times.append(set_row(page, k))                 # at once: not waiting for it to settle
        dots = page.evaluate("""() => Object.fromEntries(['A', 'B'].map((p) => {
            const c = document.querySelector(`#figure [data-point=${p}]`);
            return [p, [+c.getAttribute('cx'), -c.getAttribute('cy')]]; }))""")
        t = math.radians(rows["coordinate"][k])
        a = [-0.5 * math.sin(t), 0.5 * math.cos(t), math.cos(math.radians(30))]
        assert rows["coordinate"][k] == 5 * k
        assert dots["A"] == pytest.approx(on_page(a), abs=1e-9)
        b = rows["points"]["B@coupler"]["position"][k]
        assert (angle(a, b), angle(b, d)) == pytest.approx((70, 50), abs=1e-6)
        assert dots["B"] == pytest.approx(on_page(b), abs=1e-9)
    with capsys.disabled():
        print(f"\n[page] 3D slider to painted frame: median {statistics.median(times):.1f} ms, "
              f"max {max(times):.1f} ms over {len(times)} positions")


def _jansen_top() -> str:
    """Jansen's leg cut to its first loop and top triangle (its crank, A-B and the triangle
    Z-B-E): two circle intersections in a chain, the second drawn from the first's roots of
    its decimal lengths, enough for named coordinates at a quarter of the whole leg's work;
    asked E's velocity alone (its acceleration, asked too, is half as much work again for
    the same named coordinates)."""
    tree = jansen()                                      # its crank angle a symbol
    tree["ask"] = [{"velocity": "E"}]
    return yaml.safe_dump(tree, sort_keys=False)


JANSEN_TOP = _jansen_top()


def _left_of(p: tuple, r: float, q: tuple, s: float) -> tuple[float, float]:
    """The point r from p and s from q, left of the line p → q (a model's `circles: [[p, r],
    [q, s]], side: left`), by hand: along = (r² − s² + |pq|²) / 2|pq| on the line, then
    √(r² − along²) across it."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    dist = math.hypot(dx, dy)
    ux, uy = dx / dist, dy / dist
    along = (r * r - s * s + dist * dist) / (2 * dist)
    h = math.sqrt(r * r - along * along)
    return p[0] + along * ux - h * uy, p[1] + along * uy + h * ux


def test_named_quantities_of_long_formulas_are_listed(page, server, tmp_path):
    """Jansen's leg's top (crank, A-B, the triangle Z-B-E) with its crank angle a symbol:
    its points' exact coordinates are named (x_B, y_B, x_E, y_E) and the table lists each
    name's formula, the later ones written in the earlier names (the whole leg shows the
    same, at four times the server's work). The formulas the page shows are checked by hand
    over a full turn of the crank: A = O + m (cos θ, sin θ), B the point b from Z and j from
    A left of Z → A, E the point d from Z and e from B left of Z → B. That they are the CLI's
    answer, byte for byte, seconds more of exact work: a deep run.

    The exact solve takes the server seconds of CPU time, which a loaded machine stretches:
    the page is waited on by the server's CPU time, not by the clock (`PageServer.wait`).
    Its figure (exact centres: as long again), explanation and assemblies are not asked for
    here, each test's matter of its own: the page's requests for them are refused, which it
    takes as any such failure."""
    import sympy

    page.route(re.compile(r".*/api/(draw|explain|assemblies)$"), lambda route: route.abort())
    page.get_by_test_id("model-editor").fill(JANSEN_TOP)
    server.wait(page, "() => !!document.querySelector('td[data-key=\"where.x_E\"]')"
                      " && document.getElementById('busy').hidden")
    shown = page.locator("[data-testid=answers] td[data-key^='where.']").evaluate_all(
        "tds => tds.map((td) => [td.dataset.key.slice(6), JSON.parse(td.dataset.value)])")
    assert [name for name, _ in shown] == ["x_B", "y_B", "x_E", "y_E"]
    p = yaml.safe_load(JANSEN_TOP)["parameters"]
    symbols = {name: sympy.Symbol(name) for name in ("theta", "x_B", "y_B", "x_E", "y_E")}
    formulas = {symbols[name]: sympy.sympify(formula, locals=symbols) for name, formula in shown}
    assert formulas[symbols["x_B"]].free_symbols == {symbols["theta"]}          # in the parameters
    assert formulas[symbols["x_E"]].free_symbols == {symbols["x_B"], symbols["y_B"]}   # in B's names
    for theta in (0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0):
        a = (p["a"] + p["m"] * math.cos(theta), p["l"] + p["m"] * math.sin(theta))
        b = _left_of((0, 0), p["b"], a, p["j"])
        e = _left_of((0, 0), p["d"], b, p["e"])
        values = {symbols["theta"]: theta}
        for name, formula in formulas.items():                 # in order: B's names, then E's
            values[name] = float(formula.subs(values))
        assert [values[symbols[n]] for n in ("x_B", "y_B", "x_E", "y_E")] == pytest.approx([*b, *e], abs=1e-9)
    if DEEP:
        path = tmp_path / "jansen_top.yaml"
        path.write_text(JANSEN_TOP)
        cli_json = json.loads(CliRunner().invoke(cli, ["solve", str(path), "--json"]).stdout)
        assert [list(pair) for pair in cli_json["where"].items()] == shown
    server.idle()                       # before the next test shares the server


def test_a_slow_drag_ends_under_the_pointer(page):
    """A hand drags the crank's end A slowly, hesitating: six small moves, each followed
    by a pause long enough for the page to edit, solve and redraw (most of a second). The
    drag holds the pointer through every redraw, and at the end A is drawn under the
    pointer (the view is kept while dragging), its text changed through the crank's
    parameters (a, theta2), never replaced by numbers."""
    x, y = grab(page, "A")
    for i in range(1, 7):
        page.mouse.move(x + 10 * i, y - 7.5 * i)
        page.wait_for_timeout(500)                 # the hand hesitates; the page re-solves
    page.mouse.up()
    page.wait_for_function("() => !window.kinematika.figure.drag && document.getElementById('busy').hidden",
                           timeout=BROWSER_WAIT)
    ready(page)
    cx, cy = handle_centre(page, "A")
    assert math.hypot(cx - (x + 60), cy - (y - 45)) < 3, (cx, cy, x + 60, y - 45)
    text = page.get_by_test_id("model-editor").input_value()
    assert "A: {from: O2, distance: a, angle: theta2}" in text
    assert "theta2: deg(90)" not in text
