"""The position step: every point placed by construction is told how it was found (the
construction, the lengths, the branch, the assembly), with where it is, in every language."""
from __future__ import annotations

import math

import pytest

import kinematika
from kinematika.explain import build, render
from kinematika.explain.catalogue import LANGS
from kinematika.explain.document import Msg, Section

from tests.conftest import KINDS, sampled

from .helpers import ALL, EXAMPLES, explained


def position_section(doc) -> Section | None:
    return next((s for s in doc.sections if s.title.key == "sec.position"), None)


def sentences(doc) -> dict[str, Msg]:
    sec = position_section(doc)
    return {} if sec is None else {b.args["point"].text: b for b in sec.blocks if "point" in b.args}


def constructed(sol) -> list[str]:
    return [n for n, spec in sol.model.points.items() if not isinstance(spec, tuple)]


# one example of each kind, with Jansen's leg (a point on the right of its circles) and the
# articulated vehicle (a point placed in a frame): every sentence of the section; every
# example in a deep run
@pytest.mark.parametrize("name", sampled(ALL, KINDS | {"jansen_leg", "seed_c5_2_2_articulated"}))
def test_every_constructed_point_is_told(name):
    sol, doc = explained(name)
    if sol.space.dim != 2:
        assert position_section(doc) is None
        return
    told = sentences(doc)
    assert sorted(told) == sorted(constructed(sol))
    for point, m in told.items():
        at = sol.inst.num(m.args["at"].value[0]), sol.inst.num(m.args["at"].value[1])
        want = tuple(sol.inst.num(c) for c in sol.inst.points[point])
        assert all(math.isclose(a, b, abs_tol=1e-9 * sol.inst.scale) for a, b in zip(at, want)), point


def test_four_bar_by_hand():
    """B at 4 from A(0, 1) and 3 from O4(4, 0): y = 4x − 11 and 17x² − 96x + 128 = 0, so
    x = (96 ± √512)/34; on the left of A→O4 (above the ground), the open assembly."""
    sol, doc = explained("four_bar")
    told = sentences(doc)
    a = told["A"]
    assert a.key == "pos.polar" and a.args["angle"].value == pytest.approx(90.0)
    b = told["B"]
    assert b.key == "pos.circles"
    x = (96 + math.sqrt(512)) / 34
    assert b.args["at"].value == pytest.approx((x, 4 * x - 11))
    assert b.args["which"].key == "pos.assembly"
    assert b.args["which"].args["which"].key == "pos.left"
    assert b.args["which"].args["assembly"].key == "pos.open"
    text = render(doc, "en", "md")
    assert "is at distance b = 4 m from A and c = 3 m from O4" in text
    assert "the open assembly" in text


def test_crossed_assembly(tmp_path):
    """The same four-bar on the other side of A→O4: B = (2.158, −2.368), the links cross."""
    src = (EXAMPLES / "four_bar.yaml").read_text(encoding="utf-8").replace("side: left", "side: right")
    path = tmp_path / "crossed.yaml"
    path.write_text(src, encoding="utf-8")
    doc = build(kinematika.solve(path))
    b = sentences(doc)["B"]
    x = (96 - math.sqrt(512)) / 34
    assert b.args["at"].value == pytest.approx((x, 4 * x - 11))
    assert b.args["which"].args["assembly"].key == "pos.crossed"


def test_slider_and_coupler_point():
    """Slider-crank: B on the line of stroke at l from A, ahead along +x; G on AB."""
    sol, doc = explained("slider_crank")
    told = sentences(doc)
    assert told["B"].key == "pos.circle_line" and told["B"].args["which"].key == "pos.ahead"
    r, l, th = 0.05, 0.2, math.radians(60)
    assert told["B"].args["at"].value == pytest.approx((r * math.cos(th) + math.sqrt(l**2 - (r * math.sin(th))**2), 0))
    assert told["G"].key == "pos.frame_on"


def test_symbolic_angles_in_degrees():
    """The epicyclic's planets at −90°, 30° and 150° about O (exact multiples of π)."""
    _, doc = explained("seed_c5_1_4_epicyclic")
    angles = {p: m.args["angle"].value for p, m in sentences(doc).items()}
    assert angles == {"A1": pytest.approx(-90.0), "A2": pytest.approx(30.0), "A3": pytest.approx(150.0)}


@pytest.mark.parametrize("lang", LANGS)
def test_told_in_every_language(lang):
    _, doc = explained("four_bar")
    text = render(doc, lang, "md")
    heading = {"en": "## Position", "es": "## Posición", "ca": "## Posició", "eu": "## Posizioa"}[lang]
    assert heading in text
    closing = {"en": "open assembly", "es": "configuración abierta", "ca": "configuració oberta",
               "eu": "konfigurazio irekia"}[lang]
    assert closing in text
    if lang == "ca":
        assert "d’A cap a O4" in text and "d’O2" in text


def test_named_coordinates_are_defined_where_the_point_is_placed(monkeypatch):
    """A constructed point too long to write out is named (x_B, y_B); the explanation gives
    each name's formula right after the point's sentence, and that formula is the point's
    coordinate by hand (the four-bar in all its lengths, with the naming threshold lowered
    so that its coupler pin is named: B where the circles (A, b) and (O4, c) meet, left of
    A→O4), and the acceleration section says that angular velocities may be written by
    name."""
    import sympy

    from kinematika.engine import positions

    monkeypatch.setattr(positions, "NAME_OPS", 10)
    sol = kinematika.solve(EXAMPLES / "four_bar.yaml", symbolic=True)
    doc = build(sol)
    blocks = position_section(doc).blocks
    defined = {str(b.args["name"].value): b.args["formula"].value for b in blocks if b.key == "pos.named"}
    assert {"x_B", "y_B"} <= set(defined)
    names = {str(k): v for k, v in sol.inst.names.items()}
    at = {"a": 1.3, "b": 4.2, "c": 3.1, "d": 4.4, "theta2": 1.2}          # a general place
    ax, ay = at["a"] * math.cos(at["theta2"]), at["a"] * math.sin(at["theta2"])
    f2 = (at["d"] - ax) ** 2 + ay ** 2                 # |A O4|²
    along = (at["b"] ** 2 - at["c"] ** 2 + f2) / (2 * f2)
    height = math.sqrt(at["b"] ** 2 / f2 - along ** 2)
    by_hand = (ax + along * (at["d"] - ax) + height * ay, ay - along * ay + height * (at["d"] - ax))
    for axis, want in zip("xy", by_hand):
        formula = sympy.sympify(defined[f"{axis}_B"])
        formula = formula.subs({s: names[str(s)] for s in formula.free_symbols if str(s) in names})
        value = formula.subs({s: at[str(s)] for s in formula.free_symbols})
        assert float(sympy.N(value)) == pytest.approx(want, abs=1e-9)
    order = [b.args.get("point").text if "point" in b.args else str(b.args["name"].value) for b in blocks[1:]]
    assert order.index("x_B") == order.index("B") + 1          # right after B's sentence
    accelerations = next(s for s in doc.sections if s.title.key == "sec.accelerations")
    assert any(getattr(b, "key", "") == "a.named" for b in accelerations.blocks)


def test_an_offset_to_the_right_is_said_so():
    """C5-2.2 places each wheel a/2 to one side of its axle's midpoint (`at: [a, -a/2]` is
    to the right of O→P): the text says "a/2 … to its right", never "−a/2 … to its left".
    S2 moves from P towards O, so its wheels' sides are said looking that way (seventeenth
    round (a)): C3 on the left looking from P towards O, C4 on the right."""
    import sympy

    _, doc = explained("seed_c5_2_2_articulated")
    told = sentences(doc)
    sides = {p: told[p].key for p in ("C1", "C2", "C3", "C4")}
    assert sides == {"C1": "pos.frame", "C2": "pos.frame_right", "C3": "pos.frame", "C4": "pos.frame_right"}
    assert [told[p].args["from"].text for p in ("C1", "C3")] == ["O", "P"]
    a = sympy.Symbol("a", positive=True)
    for p in sides:
        y = sympy.sympify(told[p].args["y"].value)
        assert sympy.simplify(y.subs(dict.fromkeys(y.free_symbols, a)) - a / 2) == 0, p
    text = render(doc, "ca", "md", drawings=False)
    assert "a −a/2 en perpendicular" not in text and "a a/2 en perpendicular, a la dreta mirant d’O cap a P1: C2" in text
