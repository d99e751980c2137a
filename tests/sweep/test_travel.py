"""A sweep's or a move's travel is bounded (`limits.SWEEP_TRAVEL`): `by: -1e308` was an
internal error (a math domain error) on some mechanisms and rows of round-off on others; it
is one clear line, exit 2, on every path (closed form, Newton, compiled), and a travel
within the limit still sweeps."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from kinematika import limits
from kinematika.commands import How, solve_data, sweep_run
from kinematika.errors import KinematikaError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("example", ["four_bar", "hooke_joint", "eccentric_cam", "slider_crank"])
def test_a_huge_by_is_one_clear_line_with_exit_2(example):
    run = subprocess.run([sys.executable, "-m", "kinematika.cli", "sweep", str(EXAMPLES / f"{example}.yaml"),
                          "--by", "-1e308", "--json"], capture_output=True, text=True)
    assert run.returncode == 2
    error = json.loads(run.stdout)["error"]
    assert "internal" not in error["kind"] and "1,000,000 turns" in error["message"]
    assert "Traceback" not in run.stderr


def test_the_models_own_sweep_section_and_a_move_are_bounded_too():
    tree = {"points": {"O": [0, 0], "A": [1, 0], "B": [3, 1], "C": [3, 0]},
            "bodies": {"ground": ["O", "C"], "crank": ["O", "A"], "coupler": ["A", "B"], "rocker": ["B", "C"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                       {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                       {"type": "revolute", "bodies": ["rocker", "ground"], "at": "C"}],
            "drivers": [{"omega": "crank", "value": 1}],
            "sweep": {"joint": "j1", "by": 1e300}}
    with pytest.raises(KinematikaError) as info:
        sweep_run(tree)
    assert info.value.kind == "schema" and info.value.where == "sweep.by"
    del tree["sweep"]
    with pytest.raises(KinematikaError) as info:
        solve_data(tree, how=How(move={"j1": "1e308"}))
    assert info.value.kind == "schema" and info.value.where == "move.j1"


def test_a_prismatic_travel_is_counted_in_the_mechanisms_size():
    """A slider whose model is 0.5 in size (its points 1 apart): 1000 sweeps, 10¹² is refused."""
    tree = {"points": {"O": [0, 0], "P": [1, 0]}, "bodies": {"ground": ["O"], "slider": ["P"]},
            "joints": [{"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
            "drivers": [{"joint": "j1", "rate": 1}]}
    _, result = sweep_run(tree, by=1000.0, steps=2)
    assert result.points["P@slider"]["position"][-1][0] == pytest.approx(1001.0)
    with pytest.raises(KinematikaError) as info:
        sweep_run(tree, by=limits.SWEEP_TRAVEL * 1e6, steps=2)
    assert "times the mechanism's size" in info.value.message
