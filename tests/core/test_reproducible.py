"""Exact formulas are the same in every run: on a slower (or busier) machine, and whatever
Python's string hashes are. The steps that only make a formula read better are bounded by
a count of operations (`budget.within`), not by the clock."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import sympy
import yaml

from kinematika import budget
from tests.conftest import sampled
from tests.core.models import jansen

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

ROOT = Path(__file__).resolve().parents[2]

# the command line, with the clocks the budgets read running `factor` times as fast (the
# machine as a loaded or slower one looks to them)
RUN = """
import sys, time
factor = float(sys.argv[1])
for name in ("process_time", "thread_time"):
    real = getattr(time, name)
    setattr(time, name, lambda real=real: factor * real())
sys.argv = ["kinematika"] + sys.argv[2:]
from kinematika.cli import main
main()
"""


def _solve(model: Path, slower: float, hash_seed: str) -> dict:
    env = dict(os.environ, PYTHONHASHSEED=hash_seed)
    done = subprocess.run([sys.executable, "-c", RUN, str(slower), "solve", str(model),
                           "--symbolic", "--json"], capture_output=True, text=True, env=env,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _solve_here(model: Path) -> dict:
    """`kinematika solve MODEL --symbolic --json` in this process (click's runner): this
    process's clocks and string hashes."""
    from tests.model.test_cases import kinematika

    code, out = kinematika("solve", str(model), "--symbolic", "--json")
    assert code == 0, out
    return out


def _other_hash_seed() -> str:
    """A PYTHONHASHSEED under which a child's string hashes differ from this process's
    (checked: a child prints a string's hash)."""
    for seed in ("2", "3", "5"):
        child = subprocess.run([sys.executable, "-c", "print(hash('kinematika'))"], capture_output=True,
                               text=True, env=dict(os.environ, PYTHONHASHSEED=seed), check=True)
        if int(child.stdout) != hash("kinematika"):
            return seed
    raise AssertionError("no other string hashes found")


def jansen_model(whole: bool) -> dict:
    """Jansen's leg with its crank angle a symbol, or its top (`tests.core.models.jansen`)."""
    return jansen(top=not whole)


@pytest.mark.parametrize("part", sampled(["top", "whole"], {"top"}))
def test_formulas_do_not_depend_on_the_clock_or_the_hashes(tmp_path, part):
    """Jansen's leg's top (the whole leg in a deep run, 8 times the work) with every length
    and its crank angle symbols (named coordinates, many optional rewritings): the same
    answer, formula for formula and key for key, when the clocks run three times as fast and
    the string hashes differ (it differed from run to run when the rewritings had 1 s of
    processor time in all). Solved here, then in a child whose clocks run three times as fast
    and whose string hashes are not this process's."""
    model = tmp_path / f"jansen_{part}.yaml"
    model.write_text(yaml.safe_dump(jansen_model(part == "whole"), sort_keys=False))
    first = _solve_here(model)
    again = _solve(model, 3.0, _other_hash_seed())
    assert {"x_B", "y_B", "x_E", "y_E"} <= set(first["where"])
    assert list(first["where"]) == list(again["where"])
    assert json.dumps(first) == json.dumps(again)


def test_optional_steps_stop_at_the_allowance(monkeypatch):
    """Within a command's budget the optional steps are given at most `POLISH_OPS`
    operations in all: a step larger than what is left keeps its input's form, a smaller
    one later still runs; outside a budget every step runs."""
    monkeypatch.setattr(budget, "POLISH_OPS", 100)
    ran = []

    def step(x):
        ran.append(x)
        return x + 1

    with budget.budget("the exact formulas", 60):
        assert budget.within(60, step, 1, default=-1) == 2       # 40 left
        assert budget.within(50, step, 2, default=-1) == -1      # more than is left
        assert budget.within(40, step, 3, default=-1) == 4       # exactly what is left
        assert budget.within(1, step, 4, default=-1) == -1
    assert ran == [1, 3]
    assert budget.within(10**9, step, 5) == 6


def test_factoring_with_roots_is_the_same_for_any_hashes():
    """`fields.factored` holds each root as a stand-in while it factors: the stand-ins are
    made in one order, so the factored form (its sign included) does not follow the order of
    a set of roots, which follows the string hashes: the same here and in processes with
    other hashes."""
    from kinematika.algebra.fields import factored

    code = ("import sympy; from kinematika.algebra.fields import factored; "
            "s2, s5, s10 = sympy.sqrt(2), sympy.sqrt(5), sympy.sqrt(10); w = sympy.Symbol('w'); "
            "print(factored(-w**2*1178 - 321*s10*w**2 - 372*s2*w**2 + 1440*s5*w**2))")
    w = sympy.Symbol("w")
    s2, s5, s10 = sympy.sqrt(2), sympy.sqrt(5), sympy.sqrt(10)
    here = str(factored(-w**2*1178 - 321*s10*w**2 - 372*s2*w**2 + 1440*s5*w**2))
    expected = w**2 * (-1178 - 321 * sympy.sqrt(10) - 372 * sympy.sqrt(2) + 1440 * sympy.sqrt(5))
    assert sympy.simplify(sympy.sympify(here) - expected) == 0
    for hash_seed in ("0", "7"):
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             env=dict(os.environ, PYTHONHASHSEED=hash_seed), check=True).stdout.strip()
        assert out == here, hash_seed


def test_what_a_command_remembers_is_its_own():
    """Forms remembered in a command (`budget.budget`) are forgotten when it ends and not
    seen by another command, so that the page's server (many commands in one process)
    answers as a fresh command line does; outside a command one memory serves the process."""
    from kinematika.memo import Memo

    memo = Memo(4)
    memo.put("outside", 1)
    with budget.budget("the exact formulas", 60):
        assert memo.get("outside") is None
        memo.put("first", 2)
        with budget.budget("a nested stage", 60):       # the same command
            assert memo.get("first") == 2
    with budget.budget("the exact formulas", 60):
        assert memo.get("first") is None
    assert memo.get("outside") == 1
    assert memo.get("first") is None
    for k in range(5):                                  # bounded: emptied when full
        memo.put(k, k)
    assert memo.get(0) is None and memo.get(4) == 4


def test_pure_steps_remembered_for_the_process_answer_as_a_fresh_call():
    """trigsimp, the seeded factor and factor_terms are remembered for the whole process
    (`memo.Pure`: the page's server solving one model for each request): a formula met
    again, in another command, gets what sympy itself gives (by hand: x² − y² is
    (x − y)(x + y); 2x + 2xy is 2x(y + 1); sin² + cos² is 1), and a remembered factoring
    leaves sympy's random numbers as a fresh seeded factor leaves them."""
    import sympy
    from sympy.core import random

    from kinematika.algebra import backend, fields

    x, y, t = sympy.symbols("x y t")
    fresh_state = None
    for _ in range(2):                                     # computed, then remembered
        with budget.budget("the exact formulas", 60):
            random.rng.seed(12345)
            assert fields.factor(x**2 - y**2) == (x - y) * (x + y)
            state = random.rng.getstate()
            fresh_state = fresh_state or state
            assert state == fresh_state
            assert fields.common_factors(2*x + 2*x*y) == 2 * x * (y + 1)
            assert backend._trigsimp_keeping_angles(sympy.sin(t)**2 + sympy.cos(t)**2 + x) == x + 1
    random.rng.seed(fields.FACTOR_SEED)
    sympy.factor(x**2 - y**2)
    assert random.rng.getstate() == fresh_state            # as a fresh seeded factor leaves it
    assert fields._FACTORED.get(x**2 - y**2)[0] == (x - y) * (x + y)


def test_other_threads_work_does_not_cut_a_step_short(monkeypatch):
    """The safety net of an optional step counts the main thread's own processor time: a
    step of 0.15 s of it ends whole while another thread works (the page's server answering
    while the command line solves in the same process), though the process as a whole
    spends more than the step's 0.2 s meanwhile. A step past its time is still stopped."""
    import threading
    import time

    monkeypatch.setattr(budget, "STEP_SECONDS", 0.2)

    def spend(seconds):
        start = time.thread_time()
        while time.thread_time() - start < seconds:
            pass
        return "whole"

    stop = threading.Event()

    def busy():
        while not stop.is_set():
            sum(range(1000))

    other = threading.Thread(target=busy)
    other.start()
    try:
        process = time.process_time()
        assert budget.within(1, spend, 0.15, default="stopped") == "whole"
        assert time.process_time() - process > 0.2          # the others worked meanwhile
        assert budget.within(1, spend, 2.0, default="stopped") == "stopped"
    finally:
        stop.set()
        other.join()


def test_the_exact_field_stops_at_its_work_not_at_a_time():
    """A canonical form's work is counted (terms formed, products of terms taken): (a + b)⁵
    by squaring takes 2 + 4 + 9 + 10 products of terms and, with a + b itself, 2 + 2 + 3 + 5
    + 6 terms formed: 43; a field allowed 40 stops with `TooLarge` and one allowed more
    finishes, whatever the clock."""
    from kinematika.algebra.fields import ExactField, TooLarge

    a, b = sympy.symbols("a b", positive=True)
    e = (a + b) ** 5
    with pytest.raises(TooLarge):
        small = ExactField([e], max_work=40)
        small.back(small.to(e))
    field = ExactField([e], max_work=10_000)
    assert sympy.expand(field.back(field.to(e)) - e) == 0


def test_whether_a_model_is_answered_is_decided_by_a_count(monkeypatch):
    """The exact algebra's work is counted (`budget.spend`): past `limits.EXACT_WORK` a model
    is refused with a `limit` error that says so, whatever the clock; the slider-crank in
    its lengths needs some thousands of steps (about 3 500), so 2 000 refuse it and the
    default answers it."""
    from kinematika import limits
    from kinematika.budget import OverBudget
    from kinematika.commands import solve_data

    model = ROOT / "tests" / "cases" / "tb_slider_crank_symbolic_lengths.yaml"
    assert solve_data(model)["symbolic"] is True
    monkeypatch.setattr(limits, "EXACT_WORK", 2000)
    with pytest.raises(OverBudget) as info:
        solve_data(model)
    assert info.value.kind == "limit"
    assert info.value.message.startswith("finding the exact formulas takes more than 2 000 steps of exact algebra")
