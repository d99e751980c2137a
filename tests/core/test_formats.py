"""The same model as YAML, TOML, JSON and from Python gives the same answers."""
from __future__ import annotations

import json

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
