"""docs/from-a-problem.md and the README's tour: the models they show solve to what the
hand derivations give (Freudenstein's equation and Norton's rate equations for the
four-bar and its coupler point, the closed form ω(θ) derived on the page, the
slider-crank's textbook v_B), and the numbers the page quotes are those."""
from __future__ import annotations

import math
import re

import pytest
import sympy
import yaml

import kinematika
from kinematika.report.json_answer import solution_json
from tests.conftest import DEEP, hand_derivations

from .helpers import EXAMPLES

ROOT = EXAMPLES.parent
DOC = (ROOT / "docs" / "from-a-problem.md").read_text(encoding="utf-8")
PROBLEM = ROOT / "docs" / "from-a-problem" / "four_bar_problem.yaml"
THETA = ROOT / "docs" / "from-a-problem" / "four_bar_theta.yaml"


derive = hand_derivations()
A, B, C, D, P, DELTA, T2, W2, AL2 = 3, 7.5, 8, 9, 4, math.radians(30), math.radians(120), 10, -5


def by_hand(open_circuit: bool) -> tuple:
    """θ3, θ4, ω3, ω4, α3, α4, v_P, a_P of the page's problem (Norton 4.10-4.13, 6.18, 7.12,
    6.36, 7.32)."""
    t3, t4 = derive.freudenstein(A, B, C, D, T2, open_circuit)
    w3, w4, al3, al4 = derive.norton_rates(A, B, C, T2, t3, t4, W2, AL2)
    pa = [A * math.cos(T2), A * math.sin(T2)]
    va = derive.turn(W2, pa)
    aa = [x - W2 ** 2 * y for x, y in zip(derive.turn(AL2, pa), pa)]
    e, n = [math.cos(t3 + DELTA), math.sin(t3 + DELTA)], [-math.sin(t3 + DELTA), math.cos(t3 + DELTA)]
    vp = [v + P * w3 * k for v, k in zip(va, n)]
    ap = [a + P * al3 * k - P * w3 ** 2 * j for a, k, j in zip(aa, n, e)]
    return t3, t4, w3, w4, al3, al4, vp, ap


def answers(source, **options) -> list:
    return [a["value"] for a in solution_json(kinematika.solve(source, **options))["answers"]]


def raw_answers(source) -> list[str]:
    """The answers' formulas as the solver gives them (`questions.answer`), without the JSON
    answer's tables: the symbolic accelerations of every body and point, which the JSON
    writes and these tests do not read, are seconds of work (the JSON's path: a deep run)."""
    from kinematika.questions import answer

    sol = kinematika.solve(source)
    return [str(answer(sol, q)) for q in sol.model.questions]


def quoted(name: str) -> list[float]:
    """The numbers the page prints in its answer table for `name` (the first table)."""
    line = next(l for l in DOC.splitlines() if l.startswith(f"│ {name} "))
    return [float(x) for x in re.findall(r"-?\d+\.?\d*(?:e-?\d+)?", line.split("│")[2])]


def test_the_problem_solves_to_freudenstein_and_norton():
    _, _, w3, w4, al3, al4, vp, ap = by_hand(open_circuit=True)
    got = answers(PROBLEM)
    assert got[:4] == pytest.approx([w3, w4, al3, al4], rel=1e-9)
    assert got[4] == pytest.approx(vp, rel=1e-9) and got[5] == pytest.approx(ap, rel=1e-9)
    # and the page prints those numbers (6 significant digits)
    for name, value in (("omega coupler", [w3]), ("omega rocker", [w4]), ("alpha coupler", [al3]),
                        ("alpha rocker", [al4]), ("velocity P", vp), ("acceleration P", ap)):
        assert quoted(name) == pytest.approx(value, rel=1e-5), name


def test_the_page_quotes_freudensteins_angles():
    t3, t4, *_ = by_hand(open_circuit=True)
    c3, c4, *_ = by_hand(open_circuit=False)
    for angle in (t3, t4, c3, c4):
        degrees = (math.degrees(angle) + 180) % 360 - 180
        assert f"{degrees:.3f}°".replace("-", "−") in DOC, degrees


def test_the_other_assembly_is_the_crossed_circuit():
    _, _, w3, w4, al3, al4, vp, ap = by_hand(open_circuit=False)
    tree = yaml.safe_load(PROBLEM.read_text())
    tree["points"]["B"]["side"] = "right"
    assert answers(tree)[:4] == pytest.approx([w3, w4, al3, al4], rel=1e-9)
    assert answers(PROBLEM, assembly=2)[:4] == pytest.approx([w3, w4, al3, al4], rel=1e-9)
    assert f"omega coupler  │ {w3:.6g}" in DOC and f"omega rocker   │ {w4:.6g}" in DOC


def test_the_symbolic_crank_angle_is_the_closed_form_of_the_page():
    th, w = sympy.symbols("theta2 w2", positive=True)
    w3_text, w4_text = answers(THETA) if DEEP else raw_answers(THETA)
    got3, got4 = (sympy.sympify(t, locals={"theta2": th, "w2": w}) for t in (w3_text, w4_text))
    # the page's closed form, with its e, k, D
    e = A ** 2 + D ** 2 - 2 * A * D * sympy.cos(th)
    k = B ** 2 - C ** 2 + e
    root = sympy.sqrt(4 * B ** 2 * e - k ** 2)
    hand4 = w * A * (k * D * sympy.sin(th) - root * (D * sympy.cos(th) - A)) / (e * root)
    hand3 = w * A * ((k - 2 * e) * D * sympy.sin(th) - root * (D * sympy.cos(th) - A)) / (e * root)
    for deg in (5, 60, 120, 200, 290):
        t2 = math.radians(deg)
        t3, t4 = derive.freudenstein(A, B, C, D, t2)
        n3, n4, _, _ = derive.norton_rates(A, B, C, t2, t3, t4, 1.0, 0.0)
        at = {th: t2, w: 1}
        assert float(got3.subs(at)) == pytest.approx(n3, abs=1e-10)
        assert float(got4.subs(at)) == pytest.approx(n4, abs=1e-10)
        assert float(hand3.subs(at)) == pytest.approx(n3, abs=1e-10)
        assert float(hand4.subs(at)) == pytest.approx(n4, abs=1e-10)
    # the page shows the tool's ω4 and says 16 D is its root
    shown = re.search(r"omega rocker: (.*?)\n```", DOC, re.S).group(1)
    page4 = sympy.sympify(" ".join(shown.split()), locals={"theta2": th, "w2": w})
    assert page4 == got4 or sympy.simplify(page4 - got4) == 0     # the same formula: no simplify
    # (sin² = 1 − cos² makes both sides polynomials in cos θ2: expanded, their difference is 0)
    assert sympy.expand((16 * (4 * B ** 2 * e - k ** 2) - (46656 * sympy.sin(th) ** 2 - 52272 * sympy.cos(th)
                                                          + 169103)).subs(sympy.sin(th), sympy.sqrt(1 - sympy.cos(th) ** 2))) == 0


# the README's tour -----------------------------------------------------------------------
README = (ROOT / "README.md").read_text(encoding="utf-8")
TOUR = README[README.index("## A model in a few lines"):README.index("## Examples")]


def test_the_tours_model_gives_the_textbook_piston_velocity():
    tree = yaml.safe_load(re.search(r"```yaml\n(.*?)```", TOUR, re.S).group(1))
    th = sympy.Symbol("theta", positive=True)
    vb = answers(tree)[0]
    got = sympy.sympify(vb[0], locals={"theta": th})
    r, l, w = 0.1, 0.3, 10
    for deg in (10, 30, 100, 250):
        t = math.radians(deg)
        textbook = -r * w * math.sin(t) * (1 + r * math.cos(t) / math.sqrt(l * l - (r * math.sin(t)) ** 2))
        assert float(got.subs(th, t)) == pytest.approx(textbook, abs=1e-12)
    assert vb[1] == "0"
    assert "`" + vb[0] + "`" in TOUR                     # the formula the tour quotes


def test_the_tours_python_builds_the_same_slider_crank():
    code = re.search(r"```python\n(.*?)```", TOUR, re.S).group(1)
    scope: dict = {}
    exec(code, scope)                                    # the README's own snippet
    sol = scope["sol"]
    t, r, l, w = math.radians(30), 0.1, 0.3, 10
    root = math.sqrt(l * l - (r * math.sin(t)) ** 2)
    assert sol.velocity("B")[0] == pytest.approx(-r * w * math.sin(t) * (1 + r * math.cos(t) / root), rel=1e-12)
    assert sol.omega("rod") == pytest.approx(-r * w * math.cos(t) / root, rel=1e-12)
    assert "v_B = (−0.6464, 0)" in code
