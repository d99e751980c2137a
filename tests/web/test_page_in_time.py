"""The page plays a motion followed in time (`kinematika simulate`): the notes' articulated
vehicle (C5-2.2), whose second chassis trails behind the first as a tractrix. By hand (see
tests/simulate/test_closed_forms.py): with V = r w, tan(φ/2) = tan(22.5°) e^(−V t/a), and
ω_S2 = −(V/a) sin φ; the hinge O moves at V along x."""
from __future__ import annotations

import math
import os

import pytest

from kinematika.web.strings import page_strings

from .test_page import cell, edited, page, ready, set_row  # noqa: F401  (the page fixture)

pytestmark = pytest.mark.browser
SHOT = os.environ.get("KINEMATIKA_SHOT")      # a path: the page is saved there as PNG, to look at


def test_the_slider_moves_a_vehicle_through_time(page, server):   # noqa: F811
    gen = page.evaluate("window.kinematika.state.gen")
    page.get_by_test_id("example").select_option("seed_c5_2_2_articulated.yaml")
    # the simulation is the server's CPU time, which a loaded machine stretches: waited on by it
    server.wait(page, "(gen) => window.kinematika.state.gen > gen && window.kinematika.state.sweep"
                      " && document.getElementById('busy').hidden", gen)
    ready(page)
    slider = page.get_by_test_id("input-slider")
    assert slider.is_enabled() and slider.get_attribute("max") == "200"      # 10 s in 200 steps
    a, r, w = 1.0, 0.3, 5.0
    speed = r * w
    for k in (0, 20, 70, 200):
        set_row(page, k)
        t = k * 0.05
        assert page.get_by_test_id("coordinate").inner_text() == f"t = {t:g} s"
        phi = 2 * math.atan(math.tan(math.radians(22.5)) * math.exp(-speed * t / a))
        assert cell(page, "bodies.S2.omega") == pytest.approx(-(speed / a) * math.sin(phi), abs=1e-8)
        hinge = page.evaluate("""() => { const c = document.querySelector('#figure [data-point=O]');
            const m = c.getCTM(), s = document.querySelector('[data-testid=figure]').getCTM().inverse();
            const p = new DOMPoint(+c.getAttribute('cx'), +c.getAttribute('cy')).matrixTransform(m).matrixTransform(s);
            return [p.x, -p.y]; }""")
        assert hinge == pytest.approx([speed * t, 0.0], abs=1e-9)
    assert "t (s)" in page.locator("#plot").text_content()
    page.screenshot(path=str(SHOT)) if SHOT else None


def test_a_model_placed_by_symbols_says_what_it_lacks(page, server):   # noqa: F811
    """The vehicle's points are placed by symbols, so its sketch has bodies but no points:
    with its two drivers taken away it is not a page not begun (which says nothing) but a
    mechanism of two degrees of freedom that lacks its inputs, and the page says so (it
    once said nothing at all, and a failed solve of such a model left a silent page)."""
    gen = page.evaluate("window.kinematika.state.gen")
    page.get_by_test_id("example").select_option("seed_c5_2_2_articulated.yaml")
    server.wait(page, "(gen) => window.kinematika.state.gen > gen && window.kinematika.state.sweep"
                      " && document.getElementById('busy').hidden", gen)
    drivers = ('  - {velocity: C1, along: [1, 0], value: "r*w"}\n'
               '  - {velocity: C2, along: [1, 0], value: "r*w"}\n')
    with edited(page, drivers, "  []\n", "missing") as (_, _, missing):
        assert missing.inner_text() == page_strings("en")["messages"]["missing-input"]
        assert page.get_by_test_id("dof").inner_text() == "DOF 2"      # 3 × 2 − 2 − 4·1 (no side slip)
        assert page.get_by_test_id("error").is_hidden()
