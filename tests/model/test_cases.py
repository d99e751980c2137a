"""The textbook cases in tests/cases (Norton-, Shigley/Uicker-style problems written by
construction): each NAME.yaml is solved by `kinematika solve NAME.yaml --json` (in this
process, by click's runner; a number and an error in a child process instead, as the
contract's outside tests run it, and every case both ways in a deep run), and
compared with NAME.expect.json under the rules of the
shared `check-cases` tool (numbers to a relative tolerance; formulas equal as functions of
their symbols; errors by their kind, with exit status 2). The expected answers are those
of tests/cases/derive.py, hand derivations that never call kinematika; the first test
checks that the files still hold exactly them.
"""
from __future__ import annotations

import json
import random
import subprocess
import sys
from pathlib import Path

import pytest
import sympy

from tests.conftest import hand_derivations, sampled

CASES = Path(__file__).resolve().parents[1] / "cases"


derive = hand_derivations()
NAMES = sorted(p.stem for p in CASES.glob("*.yaml"))


def test_every_case_has_its_derivation_and_expectation():
    every_case_derived(CASES, derive)


def every_case_derived(folder: Path, module) -> None:
    """Each NAME.yaml in `folder` has its derivation in `module` and its NAME.expect.json."""
    names = sorted(p.stem for p in folder.glob("*.yaml"))
    assert names == module.CASES
    assert sorted(p.name for p in folder.glob("*.expect.json")) == [f"{n}.expect.json" for n in names]


@pytest.mark.parametrize("name", NAMES)
def test_the_expectation_is_the_hand_derivation(name):
    expectation_is_derivation(CASES, derive, name)


def expectation_is_derivation(folder: Path, module, name: str) -> None:
    """NAME.expect.json in `folder` is what `module`'s hand derivation gives."""
    written = json.loads((folder / f"{name}.expect.json").read_text(encoding="utf-8"))
    derived = json.loads(json.dumps(module.expected(name)))          # tuples → lists
    assert written.keys() == derived.keys()
    assert written.get("error") == derived.get("error")
    _same(written.get("answers"), derived.get("answers"), rel=1e-12)


def _same(got, exp, rel):
    if isinstance(exp, list):
        assert isinstance(got, list) and len(got) == len(exp)
        for g, e in zip(got, exp):
            _same(g, e, rel)
    elif isinstance(exp, dict):
        assert got.keys() == exp.keys()
        for k in exp:
            _same(got[k], exp[k], rel)
    elif isinstance(exp, float):
        assert got == pytest.approx(exp, rel=rel, abs=1e-15)
    else:
        assert got == exp


# the cases through the command line -------------------------------------------------------
# Symbolic cases whose solve takes seconds (a four-bar's roots in closed form): another
# symbolic case of the same kind is checked in a default run, these in a deep run.
SLOW = {"tb_fourbar_symbolic_theta", "tb_crank_shaper_symbolic_theta"}
# through a child process (in a default run, instead of in this one): a number, an error
IN_A_PROCESS = {"tb_fourbar_moved", "tb_err_no_side"}


@pytest.mark.parametrize("name", sampled(NAMES, lambda n: n not in SLOW | IN_A_PROCESS))
def test_case_through_the_command_line(name):
    case_through_the_command_line(CASES, name)


@pytest.mark.parametrize("name", sampled(NAMES, IN_A_PROCESS))
def test_case_through_a_child_process(name):
    case_through_the_command_line(CASES, name, child=True)


def kinematika(*args: str, child: bool = False) -> tuple[int, dict]:
    """`kinematika ARGS` (with `--json` among them): its exit status and printed JSON — in
    a child process `python -m kinematika` when `child`, else in this process by click's
    runner (the same command, without a second interpreter's start-up). Never a traceback."""
    if child:
        run = subprocess.run([sys.executable, "-m", "kinematika", *args], capture_output=True, text=True,
                             timeout=300)
        assert "Traceback" not in run.stdout + run.stderr, run.stderr
        return run.returncode, json.loads(run.stdout)
    from typer.testing import CliRunner

    from kinematika.cli import app

    run = CliRunner().invoke(app, list(args))
    assert run.exception is None or isinstance(run.exception, SystemExit), repr(run.exception)
    return run.exit_code, json.loads(run.stdout)


def case_through_the_command_line(folder: Path, name: str, child: bool = False) -> None:
    """`kinematika solve NAME.yaml --json` against NAME.expect.json, by check-cases' rules."""
    expect = json.loads((folder / f"{name}.expect.json").read_text(encoding="utf-8"))
    code, out = kinematika("solve", str(folder / f"{name}.yaml"), "--json", child=child)
    if "error" in expect:
        assert code == 2 and out["error"]["kind"] == expect["error"], out
        return
    assert code == 0, out
    got = [a["value"] for a in out["answers"]]
    assert len(got) == len(expect["answers"])
    for i, (g, e) in enumerate(zip(got, expect["answers"])):
        _matches(g, e, expect, f"answers[{i}]")


def _matches(got, exp, opts, where):
    """The check-cases rules: numbers within max(tol·max(|a|, |b|), abs); formulas equal; an
    ICR's direction in either sense."""
    if isinstance(exp, dict):
        assert isinstance(got, dict), where
        for key, value in exp.items():
            if key == "direction" and value is not None:                 # either sense
                try:
                    _matches(got[key], value, opts, f"{where}.{key}")
                    continue
                except AssertionError:
                    value = [f"-({v})" if isinstance(v, str) else -v for v in value]
            _matches(got[key], value, opts, f"{where}.{key}")
    elif isinstance(exp, list):
        assert isinstance(got, list) and len(got) == len(exp), where
        for i, (g, e) in enumerate(zip(got, exp)):
            _matches(g, e, opts, f"{where}[{i}]")
    elif exp is None or isinstance(exp, bool):
        assert got == exp, where
    elif opts.get("symbolic"):
        assert _same_function(str(got), str(exp)), f"{where}: expected {exp}, got {got}"
    else:
        tol, abs_tol = opts.get("tolerance", 1e-6), opts.get("abs", 1e-9)
        assert abs(got - exp) <= max(tol * max(abs(got), abs(exp)), abs_tol), f"{where}: {exp} vs {got}"


def _same_function(got: str, exp: str, samples: int = 4) -> bool:
    """Two formulas over positive symbols agree at random points (and name the same symbols);
    check-cases proves it with simplify, which takes seconds on a four-bar's roots."""
    names = {s.name for text in (got, exp) for s in sympy.sympify(text).free_symbols}
    symbols = {n: sympy.Symbol(n, positive=True) for n in names}
    f, g = (sympy.sympify(text, locals=symbols) for text in (got, exp))
    if f.free_symbols != g.free_symbols:
        return False
    rng, agreed = random.Random(13), 0
    for _ in range(20 * samples):
        point = {s: rng.uniform(0.2, 3.0) for s in f.free_symbols}
        a, b = complex(f.evalf(30, subs=point)), complex(g.evalf(30, subs=point))
        if abs(a.imag) > 1e-12 * abs(a) or abs(b.imag) > 1e-12 * abs(b):
            continue                          # a point where the mechanism does not assemble
        if abs(a - b) > 1e-9 * max(1.0, abs(a), abs(b)):
            return False
        agreed += 1
        if agreed == samples:
            return True
    return False
