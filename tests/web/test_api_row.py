"""The API's `row` (an extension): the model at a row of its own sweep, through its limit
positions, as the page's slider shows it at rest.

The pin in a circular slot's crank swings: its default sweep goes up 62.8° to a limit
position and back down; row 100 is on the way back, at a coordinate the drawn branch also
reaches, but on the other branch.
"""
from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from kinematika.cli import app as cli
from tests.conftest import EXAMPLES

PIN = EXAMPLES / "pin_in_circular_slot.yaml"


def test_a_row_is_the_sweeps_row_and_a_move_is_the_drawn_branch(client):
    rows = json.loads(CliRunner().invoke(cli, ["sweep", str(PIN), "--json", "--skip-bad"]).stdout)
    text = PIN.read_text(encoding="utf-8")
    k = 100
    solved = client.post("/api/solve", json={"model": text, "row": k})
    assert solved.status_code == 200, solved.text
    point = solved.json()["points"]["C@rocker"]["position"]
    assert point == pytest.approx(rows["points"]["C@rocker"]["position"][k], abs=1e-9)
    moved = client.post("/api/solve", json={"model": text, "move": {"j1": rows["coordinate"][k]}})
    assert moved.json()["points"]["C@rocker"]["position"] != pytest.approx(point, abs=1e-3)
    drawn = client.post("/api/draw", json={"model": text, "row": k})
    assert drawn.status_code == 200


def test_a_row_past_the_sweep_is_a_usage_error(client):
    answer = client.post("/api/solve", json={"model": PIN.read_text(encoding="utf-8"), "row": 361})
    assert answer.status_code == 400
    assert answer.json()["error"] == {"kind": "usage", "message": "row 361: the sweep has rows 0 to 360",
                                      "where": "row"}
    answer = client.post("/api/sweep", json={"model": PIN.read_text(encoding="utf-8"), "row": 3})
    assert answer.status_code == 400 and answer.json()["error"]["where"] == "row"
