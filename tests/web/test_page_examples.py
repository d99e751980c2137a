"""The page animates every bundled example (issue 31): one page, each example chosen from its
menu in turn as a user would, and the slider moved — the figure's points leave their drawn
places (a sweep's row, or an instant in time for a model followed in time, as
tests/simulate/test_every_example.py lists them). The explanations are not asked for here
(each is its own test's matter): the page's request for one is refused, which the page says
in the explanation's place, so that the test costs the server the motions alone."""
from __future__ import annotations

import math

import pytest

from tests.simulate.test_every_example import MOVES, TIME

from .test_page import page, ready, set_row  # noqa: F401  (the page fixture)

pytestmark = pytest.mark.browser

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


def test_every_example_moves_on_the_page(page, server):     # noqa: F811
    page.route("**/api/explain", lambda route: route.abort())
    menu = page.get_by_test_id("example")
    names = [n for n in menu.locator("option").evaluate_all("os => os.map(o => o.value)") if n]
    assert sorted(n.removesuffix(".yaml") for n in names) == sorted(MOVES)
    still = []
    for name in names:
        gen = page.evaluate("window.kinematika.state.gen")
        menu.select_option(name)
        server.wait(page, "(gen) => window.kinematika.state.gen > gen && window.kinematika.state.sweep"
                          " && document.getElementById('busy').hidden", gen)
        ready(page)
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
