"""The page plays a motion through limit positions back and forth (Chromium, Playwright).

The pin in a circular slot (`examples/pin_in_circular_slot.yaml`) is a four-bar whose crank
swings: its default sweep runs 62.8° up to a limit position, 245.7° down to the other and
51.5° up again, 360 rows that do not come back to the drawing. The slider runs over them
as over any sweep; played, it goes to the last row and comes back (it does not jump to the
first); at rest past a limit position the page solves that row on the branch it is on
(the API's `row`), not the drawn branch `move` would give at the same coordinate.

Both tests share one page with the pin loaded and one CLI sweep (a module's fixtures): the
row solved at rest first, then the playing, whose clock of the test's own stays installed.
"""
from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from kinematika.cli import app as cli
from tests.conftest import BROWSER_WAIT, EXAMPLES

from .test_page import cell, ready, set_row

pytestmark = pytest.mark.browser
PIN = "pin_in_circular_slot.yaml"


def _open(pg, name: str) -> None:
    gen = pg.evaluate("window.kinematika.state.gen")
    pg.get_by_test_id("example").select_option(name)
    pg.wait_for_function(f"() => window.kinematika.state.gen > {gen} && document.getElementById('busy').hidden"
                         " && window.kinematika.state.sweep")


@pytest.fixture(scope="module")
def rows() -> dict:
    """The pin's sweep as the CLI answers it, once for the module."""
    return json.loads(CliRunner().invoke(cli, ["sweep", str(EXAMPLES / PIN), "--json", "--skip-bad"]).stdout)


@pytest.fixture(scope="module")
def pin(browser, server):
    """One page with the pin loaded, for both tests (the page fixture's checks of errors)."""
    context = browser.new_context(viewport={"width": 1400, "height": 1000})
    pg = context.new_page()
    pg.set_default_timeout(BROWSER_WAIT)
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(server.url)
    ready(pg)
    _open(pg, PIN)
    yield pg
    context.close()
    assert not errors, errors


def test_at_rest_past_a_limit_the_row_is_solved_on_its_branch(pin, rows):
    k = 200                                         # on the way down, past the limit at 62.8°
    set_row(pin, k)
    pin.wait_for_function("() => !document.querySelector('[data-testid=answers] td.held')")
    assert cell(pin, "bodies.rocker.omega") == pytest.approx(rows["bodies"]["rocker"]["omega"][k], rel=1e-8)
    assert cell(pin, "points.C@rocker.position") == pytest.approx(
        rows["points"]["C@rocker"]["position"][k], abs=1e-9)


def test_a_swinging_input_is_played_back_and_forth(pin, rows):
    """After the test above (the same page): its clock is the test's own from here on."""
    page = pin
    last = len(rows["coordinate"]) - 1
    slider = page.get_by_test_id("input-slider")
    assert slider.get_attribute("max") == str(last)
    assert page.evaluate("window.kinematika.state.sweep.limits") == pytest.approx(rows["limits"])
    # the plot marks where the input runs back
    assert page.get_by_test_id("plot").locator("g.input-limit").count() == 2
    page.evaluate("""(k) => {
        const s = document.querySelector('[data-testid=input-slider]');
        s.value = String(k);
        s.dispatchEvent(new Event('input', {bubbles: true}));
    }""", last - 20)
    page.clock.install()                  # frames on a clock of the test's own: no speed in it
    page.clock.pause_at(page.evaluate("Date.now()") + 1000)
    page.get_by_test_id("play").click()   # 1×: 60 rows a second
    seen = []
    for _ in range(40):
        page.clock.run_for(50)
        seen.append(page.evaluate("window.kinematika.state.row"))
    page.get_by_test_id("play").click()                     # stop
    top = seen.index(max(seen))
    assert max(seen) >= last - 3                            # it went to the end (a sample a 50 ms)
    assert seen[:top] == sorted(seen[:top]) and seen[0] >= last - 20
    assert seen[top:] == sorted(seen[top:], reverse=True)   # then back, row by row
    assert seen[-1] < last - 60                             # never jumped to the first rows

