"""Models with symbols sweep at their `draw_at` numbers (the contract), and say so: a warning
on standard error and under the JSON's `warnings`; a move the symbols cannot follow exactly
is made at those numbers too, with a warning, instead of refused. The values are checked
against the notes' answers and Willis's equation, by hand."""
from __future__ import annotations

import json
import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

from kinematika.commands import How, solve_data, sweep_run
from kinematika.errors import KinematikaError, KinematikaWarning

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EPICYCLIC = EXAMPLES / "seed_c5_1_4_epicyclic.yaml"


def test_the_epicyclic_train_in_symbols_sweeps_at_its_draw_at_numbers():
    """C5-1.4 (r, w symbols; draw_at r = 0.05, w = 10): the carrier swept a turn with the
    ring's place held, Willis's equations give the sun (ω_s − ω_c)/(ω_r − ω_c) = −3r/r, so 4
    turns, and a planet inside the ring (ω_p − ω_c)/(ω_r − ω_c) = 3r/r, so −2 turns; the rates
    are the drivers' as written (carrier w, ring −w): the sun at 7w = 70 and the planets at
    −5w = −50 (the notes' answers)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _, result = sweep_run(EPICYCLIC, steps=90)
    said = [w.message for w in caught if isinstance(w.message, KinematikaWarning)]
    assert [str(w) for w in said] == ["draw_at: swept at the draw_at numbers of its symbols: r = 0.05, w = 10"]
    carrier = np.asarray(result.bodies["carrier"]["angle"])
    assert carrier[-1] == pytest.approx(360.0)
    assert np.asarray(result.bodies["sun"]["angle"]) == pytest.approx(4 * carrier, abs=1e-7)
    assert np.asarray(result.bodies["planet1"]["angle"]) == pytest.approx(-2 * carrier, abs=1e-7)
    assert np.asarray(result.bodies["sun"]["omega"]) == pytest.approx(70.0)
    assert np.asarray(result.bodies["planet2"]["omega"]) == pytest.approx(-50.0)
    a1 = np.asarray(result.points["A1@carrier"]["position"])
    assert np.hypot(a1[:, 0], a1[:, 1]) == pytest.approx(0.1)        # 2r from O
    assert result.to_json()["warnings"] == [{"message": str(said[0]).split(": ", 1)[1], "where": "draw_at"}]


def test_the_command_line_says_where_it_swept():
    run = subprocess.run([sys.executable, "-m", "kinematika.cli", "sweep", str(EPICYCLIC), "--steps", "4", "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 0
    assert "swept at the draw_at numbers of its symbols: r = 0.05, w = 10" in run.stderr
    assert json.loads(run.stdout)["warnings"][0]["where"] == "draw_at"


def test_a_symbol_without_a_draw_at_number_is_named():
    tree = yaml.safe_load(EPICYCLIC.read_text())
    del tree["draw_at"]["w"]
    with pytest.raises(KinematikaError) as info:
        sweep_run(tree, steps=4)
    assert info.value.kind == "schema" and "give w a value, or the model a `draw_at` number" in info.value.message


def test_a_move_the_symbols_cannot_follow_is_made_at_the_draw_at_numbers():
    """C5-1.6's belt (r, w symbols; draw_at r = 0.1, w = 2) has no exact move; moved 10° it is
    solved at the figure's numbers: the pulley turns at w clockwise whatever the arm's place
    (the notes), and A = (4r, r) turned 10° moves at w k × A."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data = solve_data(EXAMPLES / "seed_c5_1_6_belt.yaml", how=How(move={"j1": 10}))
    assert any("moved at the draw_at numbers of its symbols: r = 0.1, w = 2" in str(w.message) for w in caught)
    answers = [a["value"] for a in data["answers"]]
    assert answers[0] == pytest.approx(-2.0, abs=1e-9)
    t = math.radians(10)
    a = (0.4 * math.cos(t) - 0.1 * math.sin(t), 0.4 * math.sin(t) + 0.1 * math.cos(t))
    assert answers[4] == pytest.approx([-2 * a[1], 2 * a[0]], abs=1e-9)
