"""The same model as YAML, TOML, JSON and from Python gives the same answers."""
from __future__ import annotations

import json
import math

import pytest
import yaml

from kinematika import Mechanism, solve
from kinematika.report.json_answer import solution_json

from .models import FOUR_BAR

TOML = """
name = "Four-bar"
[parameters]
w2 = 10
[points]
O2 = [0, 0]
A = [0, 1]
B = ["(48 + 8*sqrt(2))/17", "4*(48 + 8*sqrt(2))/17 - 11"]
O4 = [4, 0]
[bodies]
ground = ["O2", "O4"]
crank = ["O2", "A"]
coupler = ["A", "B"]
rocker = ["B", "O4"]
""" + "".join(f"""[[joints]]
type = "revolute"
bodies = ["{a}", "{b}"]
at = "{at}"
""" for a, b, at in [("ground", "crank", "O2"), ("crank", "coupler", "A"),
                      ("coupler", "rocker", "B"), ("rocker", "ground", "O4")]) + """[[drivers]]
omega = "crank"
value = "w2"
alpha = 0
"""


def built_in_python() -> Mechanism:
    m = Mechanism("Four-bar", parameters={"w2": 10})
    m.points(O2=(0, 0), A=(0, 1), B=("(48 + 8*sqrt(2))/17", "4*(48 + 8*sqrt(2))/17 - 11"),
             O4=(4, 0))
    m.body("ground", "O2", "O4")
    m.body("crank", "O2", "A")
    m.body("coupler", "A", "B")
    m.body("rocker", "B", "O4")
    m.revolute("ground", "crank", at="O2")
    m.revolute("crank", "coupler", at="A")
    m.revolute("coupler", "rocker", at="B")
    m.revolute("rocker", "ground", at="O4")
    m.drive_omega("crank", "w2", alpha=0)
    return m


def test_every_format_gives_the_same_answer(tmp_path):
    (tmp_path / "m.yaml").write_text(yaml.safe_dump(FOUR_BAR, sort_keys=False))
    (tmp_path / "m.json").write_text(json.dumps(FOUR_BAR))
    (tmp_path / "m.toml").write_text(TOML)
    reference = solution_json(solve(FOUR_BAR))
    for name in ("m.yaml", "m.json", "m.toml"):
        assert solution_json(solve(tmp_path / name)) == reference, name
    assert solution_json(built_in_python().solve()) == reference


def test_toml_symbols_use_the_symbolic_flag(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(TOML.replace("w2 = 10", "w2 = {symbolic = true}"))
    data = solution_json(solve(path))
    assert data["symbolic"] is True
    assert data["bodies"]["crank"]["omega"] == "w2"


def test_builder_answers_by_name():
    sol = built_in_python().solve()
    assert sol.velocity("A") == pytest.approx((-10.0, 0.0))
    assert sol.velocity("A@coupler") == pytest.approx((-10.0, 0.0))


def _crank_at(angle_text: str, symbolic: bool = False) -> dict:
    """A crank of length 2 drawn at `angle_text`, turning at 1 rad/s: v_A = ω k × OA."""
    tree = {"parameters": {"r": 2},
            "points": {"O": [0, 0], "A": [f"r*cos({angle_text})", f"r*sin({angle_text})"]},
            "bodies": {"ground": ["O"], "crank": ["O", "A"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"}],
            "drivers": [{"omega": "crank", "value": 1}]}
    return tree


@pytest.mark.parametrize("text", ["deg(60)", "rad(60)", "radians(60)", "pi/3", "degrees(pi/3)*pi/180"])
def test_angle_conversions_read_degrees_as_sympy_and_python_do(text):
    # 60° from O at length 2: A = (1, √3), v_A = k × OA = (−√3, 1)
    sol = solve(_crank_at(text))
    assert [float(c) for c in sol.position("A")] == pytest.approx([1, math.sqrt(3)])
    assert [float(c) for c in sol.velocity("A")] == pytest.approx([-math.sqrt(3), 1])


def test_forced_symbols_are_probed_at_their_given_values():
    """A wheel of radius ρ = 0.5 touching a line only at that radius: with --symbolic the
    geometry is checked where it holds, not at a generic value of ρ."""
    tree = {"parameters": {"rho": 0.5, "v": 1},
            "points": {"J": [0, 0], "C": [0, 0.5]},
            "bodies": {"ground": {"points": ["J"], "line": {"through": "J", "direction": [1, 0]}},
                       "wheel": {"points": ["C", "J"], "circle": {"center": "C", "radius": "rho"}}},
            "joints": [{"type": "rolling", "bodies": ["ground", "wheel"]}],
            "drivers": [{"velocity": "C", "along": [1, 0], "value": "v"}]}
    sol = solve(tree, symbolic=True)
    # rolling: ω = −v/h with h = 1/2 the centre's height as drawn (the contact is found from
    # the centre and the line; ρ is only checked against it, at its given value)
    assert str(sol.omega("wheel")) == "-2*v"


def test_without_questions_every_body_and_point_is_answered():
    tree = _crank_at("pi/3")
    from kinematika.api import answers

    asked = [(q.kind, str(q.target)) for q, _ in answers(solve(tree))]
    assert asked == [("omega", "ground"), ("alpha", "ground"), ("omega", "crank"), ("alpha", "crank"),
                     ("velocity", "O@ground"), ("acceleration", "O@ground"),
                     ("velocity", "O@crank"), ("acceleration", "O@crank"),
                     ("velocity", "A@crank"), ("acceleration", "A@crank")]
