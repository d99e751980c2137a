"""The page animates every bundled example (issue 31): one page, each example chosen from its
menu in turn as a user would, and the slider moved — the figure's points leave their drawn
places (a sweep's row, or an instant in time for a model followed in time, as
tests/simulate/test_every_example.py lists them). The explanations, and the exact solves at
the row where the slider rests, are not asked for here (each is its own test's matter): the
page's requests for them are refused, which it takes as it does any such failure, so that
the test costs the server the motions alone.

Even so the 46 examples cost the server about 140 s of CPU time (a 3D car simulated over
200 rows, a cam's profile prepared for each request), too much for the suite's budget: the
suite shows one example of each way of moving — through limit positions, a sliding
contact, a 3D ω along a revolute's axis, symbols at their draw_at numbers, a wheel round a
cylinder in time, a section's time in symbols, a vehicle — and KINEMATIKA_DEEP=1 every
example. That every example has the slider's input at all (a joint or a time) is checked
for each, cheaply, in tests/web/test_simulate_api.py."""
from __future__ import annotations

import math

import pytest

from tests.conftest import BROWSER_WAIT, DEEP
from tests.simulate.test_every_example import MOVES, TIME

from .test_page import page, ready, set_row  # noqa: F401  (the page fixture)

pytestmark = pytest.mark.browser
SHOWN = ("pin_in_circular_slot", "eccentric_cam", "fan_symbolic", "seed_c5_1_8_contact_points",
         "seed_c5_e3_wheels_with_rod", "tractor_trailer")          # every example when deep

POINTS = """() => {
    const s = document.querySelector('[data-testid=figure]').getCTM().inverse();
    const out = {};
    for (const c of document.querySelectorAll('#figure circle[data-point]')) {
        if (c.closest('[visibility=hidden]') || c.closest('[display=none]')) continue;
        const p = new DOMPoint(+c.getAttribute('cx'), +c.getAttribute('cy')).matrixTransform(c.getCTM())
            .matrixTransform(s);
        out[c.dataset.point] = [p.x, p.y];
    }
    return out;
}"""


def _motions_only(route) -> None:
    """Let the page's requests for the model and its motion through; refuse its explanations
    and its exact solves at a row where the slider rests (the page keeps the drawn
    position's answers then, as it does when moving is not available)."""
    body = route.request.post_data_json or {}
    if route.request.url.endswith("/api/explain") or "row" in body or "move" in body:
        route.abort()
    else:
        route.continue_()


def test_every_example_moves_on_the_page(page, server):     # noqa: F811
    page.route("**/api/*", _motions_only)
    menu = page.get_by_test_id("example")
    names = [n for n in menu.locator("option").evaluate_all("os => os.map(o => o.value)") if n]
    assert sorted(n.removesuffix(".yaml") for n in names) == sorted(MOVES)
    still = []
    for name in names if DEEP else [f"{n}.yaml" for n in SHOWN]:
        gen = page.evaluate("window.kinematika.state.gen")
        menu.select_option(name)
        server.wait(page, "(gen) => window.kinematika.state.gen > gen && window.kinematika.state.sweep"
                          " && document.getElementById('busy').hidden", gen)
        ready(page)
        # the figure is painted after the answers arrive: on a busy machine it can be still empty
        page.wait_for_function("() => document.querySelectorAll('#figure circle[data-point]').length > 0",
                               timeout=BROWSER_WAIT)
        slider = page.get_by_test_id("input-slider")
        last = int(slider.get_attribute("max"))
        assert slider.is_enabled() and last > 0, name
        before = page.evaluate(POINTS)
        set_row(page, last // 3)
        text = page.get_by_test_id("coordinate").inner_text()
        assert text.startswith("t = ") == (MOVES[name.removesuffix(".yaml")] == TIME), (name, text)
        after = page.evaluate(POINTS)
        size = max(max(abs(a - b) for a, b in zip(p, q)) for p in before.values() for q in before.values()) or 1.0
        moved = max(math.dist(before[p], after[p]) for p in before if p in after)
        if not moved > 1e-3 * size:
            still.append(name)
        set_row(page, 0)
    assert not still, still
