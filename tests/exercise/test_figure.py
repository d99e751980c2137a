"""A statement's figure marks every datum of the statement once, as the statement writes it
(the model's notation and the statement's units), and nothing that follows from the data."""
from __future__ import annotations

from decimal import Decimal

import pytest

from kinematika.exercise import make_exercise
from kinematika.exercise.figure import dimensions_of, rates_of, statement_figure
from kinematika.model.files import load_model

from tests.conftest import EXAMPLES


def marks(name, vary, lang):
    path = EXAMPLES / "exercises" / f"{name}.yaml"
    ex = make_exercise(load_model(path), vary, 1, 11, lang, source=path)
    v = ex.variants[0]
    stated = v.all_stated(ex)
    dims = dimensions_of(ex, v.solution, stated, lang)
    return ex, v, stated, dims, rates_of(ex, v.solution, stated, lang, dims)


def test_the_quick_returns_figure_marks_every_datum_in_mm_and_theta():
    ex, v, stated, dims, rates = marks("quick_return", ["th=20:160:5", "w=5:15:1"], "eu")
    texts = [d.text for d in dims]
    lengths = {n: f"{n} = {stated[n].normalize():f}\u00a0mm" for n in ("r", "c", "L", "l", "h")}
    assert sorted(t for t in texts if "mm" in t) == sorted(lengths.values())     # each once, in mm
    assert [t for t in texts if "°" in t] == [f"θ = {stated['th'].normalize():f}°"]   # θ, not th; no 0°
    assert [r.text for r in rates] == [f"ω = {stated['w'].normalize():f}\u00a0rad/s"]
    assert rates[0].sweep > 0                                   # the crank turns counter-clockwise
    # h is the guide's height above O4: from O4 (0, 0) to the ram's point C, along y
    h = next(d for d in dims if d.text.startswith("h ="))
    assert h.along == "y" and h.start == (0.0, 0.0) and h.end[1] == pytest.approx(float(stated["h"]) / 1000)


def test_the_epicyclic_trains_figure_marks_r_once_and_the_two_given_rates():
    ex, v, stated, dims, rates = marks("epicyclic", ["r=30:80:5", "w=2:20:1"], "ca")
    assert [d.text for d in dims] == [f"r = {stated['r'].normalize():f}\u00a0mm"]   # not 2r, no layout angles
    r = dims[0]
    assert abs(((r.end[0] - r.start[0]) ** 2 + (r.end[1] - r.start[1]) ** 2) ** 0.5
               - float(stated["r"]) / 1000) < 1e-12                            # a radius of a planet or the sun
    # the carrier at +ω, the ring at −ω: two arrows of opposite senses, the datum ω as stated
    assert sorted(r.sweep > 0 for r in rates) == [False, True]
    assert {r.text for r in rates} == {f"ω = {stated['w'].normalize():f}\u00a0rad/s"}


def test_a_figure_is_a_palette_png_of_print_resolution():
    ex, v, *_ = marks("quick_return", ["th=20:160:5", "w=5:15:1"], "eu")
    png = statement_figure(ex, v, "eu")
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and png[25] == 3             # colour type 3: a palette
    width = int.from_bytes(png[16:20], "big")
    assert 450 <= width <= 4.6 * 150 + 60 and len(png) < 60_000


@pytest.mark.parametrize("angle", [Decimal(0), Decimal(90)])
def test_a_zero_angle_is_no_datum_but_a_stated_zero_is(angle):
    # the quick-return's B lies on the line O4→A at angle 0 from it: never marked; the crank's
    # θ is a datum, marked even when it is 0
    path = EXAMPLES / "exercises" / "quick_return.yaml"
    ex = make_exercise(load_model(path), ["th=20:160:5"], 1, 1, "en", source=path)
    v = ex.solve({"th": angle})
    dims = dimensions_of(ex, v.solution, v.all_stated(ex), "en")
    assert [d.text for d in dims if d.kind == "angle"] == [f"θ = {angle}°"]
