"""The Python builder's constructions, `move` and assemblies: the same answers as the
textbook position analysis (Freudenstein's equation as Norton solves it)."""
from __future__ import annotations

import math

import pytest

from kinematika import Mechanism
from kinematika.report.json_answer import solution_json

from .test_constructions import freudenstein, norton_rates


def four_bar(side: str = "left") -> Mechanism:
    m = Mechanism("four-bar", parameters={"theta": "deg(52)"})
    m.points(O2=(0, 0), O4=(5.2, 0))
    m.polar("A", "O2", 2.25, "theta")
    m.circles("B", ("A", 6.1), ("O4", 4.35), side=side)
    m.in_frame("P", ("A", "B"), (3.4, -1.15))
    m.body("ground", "O2", "O4"); m.body("crank", "O2", "A"); m.body("coupler", "A", "B", "P")
    m.body("rocker", "O4", "B")
    m.revolute("ground", "crank", at="O2"); m.revolute("crank", "coupler", at="A")
    m.revolute("coupler", "rocker", at="B"); m.revolute("ground", "rocker", at="O4")
    m.drive_omega("crank", 9.5, alpha=-21)
    m.ask(omega="coupler").ask(omega="rocker").ask(alpha="coupler").ask(alpha="rocker")
    return m


def answers(sol) -> list:
    return [a["value"] for a in solution_json(sol)["answers"]]


@pytest.mark.parametrize("delta", [0, 40])
def test_builder_four_bar_by_construction_and_moved(delta):
    m = four_bar()
    if delta:
        m.move(j1=delta)
    t2 = math.radians(52 + delta)
    t3, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, t2)
    assert answers(m.solve()) == pytest.approx(list(norton_rates(2.25, 6.1, 4.35, t2, t3, t4, 9.5, -21)),
                                               rel=1e-9, abs=1e-9)
    p = solution_json(m.solve())["points"]["P@coupler"]["position"]
    ax, ay = 2.25 * math.cos(t2), 2.25 * math.sin(t2)
    assert p == pytest.approx([ax + 3.4 * math.cos(t3) + 1.15 * math.sin(t3),
                               ay + 3.4 * math.sin(t3) - 1.15 * math.cos(t3)], abs=1e-9)


def test_builder_assemblies_and_the_crossed_one():
    m = four_bar()
    found = m.assemblies()
    assert [a.closures for a in found] == [["B left of A→O4"], ["B right of A→O4"]]
    t2 = math.radians(52)
    t3, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, t2, open_circuit=False)
    assert answers(m.solve(assembly=2)) == pytest.approx(
        list(norton_rates(2.25, 6.1, 4.35, t2, t3, t4, 9.5, -21)), rel=1e-9, abs=1e-9)


def test_builder_circle_line_and_lines():
    m = Mechanism("slider-crank", parameters={"theta": "deg(40)"})
    m.points(O2=(0, 0), G=(0, -2), H=(5, -2))
    m.polar("A", "O2", 3, "theta")
    m.circle_line("C", ("A", 11), line=("G", "H"), side="ahead")
    m.lines("S", ("O2", "A"), {"through": "C", "direction": (0, 1)})
    m.body("ground", "O2", "G", "H", "S"); m.body("crank", "O2", "A"); m.body("rod", "A", "C")
    m.body("slider", "C")
    m.revolute("ground", "crank", at="O2"); m.revolute("crank", "rod", at="A")
    m.revolute("rod", "slider", at="C"); m.prismatic("ground", "slider", along=(1, 0))
    m.drive_omega("crank", 4)
    pts = solution_json(m.solve())["points"]
    t = math.radians(40)
    x = 3 * math.cos(t) + math.sqrt(121 - (3 * math.sin(t) + 2) ** 2)
    assert pts["C@slider"]["position"] == pytest.approx([x, -2], abs=1e-9)
    assert pts["S@ground"]["position"] == pytest.approx([x, x * math.tan(t)], abs=1e-9)
