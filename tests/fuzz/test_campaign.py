"""The fuzzing campaign (`campaign.py`) in the test suite: 7 generated inputs on every run,
one of each class (each through the command line in its own process, one of them a fresh
`python -m kinematika`), a thousand in a deep run.

The inputs are drawn from a fixed seed, so every run of the suite, on any day, checks the
same inputs (a failure names its seed and number: `tests/fuzz/campaign.py --seed S --case N`
runs it again). New inputs come from new seeds, on demand:

    KINEMATIKA_DEEP=1 .venv/bin/python -m pytest tests/fuzz/test_campaign.py -s   # 1 000 inputs
    KINEMATIKA_FUZZ=5000 KINEMATIKA_FUZZ_SEED=123 .venv/bin/python -m pytest tests/fuzz/test_campaign.py -s
    .venv/bin/python tests/fuzz/campaign.py --count 5000 --seed 123 --keep DIR   # the campaign alone
"""
from __future__ import annotations

import os
import time

import pytest

from tests.conftest import DEEP

from .campaign import run
from .cases import CLASSES, case
from .contract import check_run
from .forks import run_forked

SEED = 20261744          # the suite's campaign: the same inputs on every run and every day; its
                         # first 7 are one of each class of input (the first seed from 20261128
                         # on whose first 7 are: 20261128 needed 15)
DEFAULT_COUNT = 7
DEEP_SEED = 20261128     # the deep run's thousand inputs, as they were


def _count() -> int:
    raw = os.environ.get("KINEMATIKA_FUZZ", "")
    if raw.isdigit():
        return int(raw)
    return 1000 if DEEP else DEFAULT_COUNT


def _seed() -> int:
    raw = os.environ.get("KINEMATIKA_FUZZ_SEED", "")
    return int(raw) if raw.isdigit() else DEEP_SEED if DEEP else SEED


def test_the_campaign_meets_the_contract():
    count = _count()
    summary = run(count, _seed(), workers=2, fresh_every=25 if count >= 100 else min(10, count), examples=count >= 1000)
    print("\n" + summary.report())
    assert not summary.failures, summary.report()


def test_every_class_of_input_is_drawn():
    drawn = {case(0, n).klass for n in range(50)}       # seed 0 meets the last class at input 16
    assert drawn == set(CLASSES)
    # the suite's few inputs are one of each class at least
    assert {case(SEED, n).klass for n in range(DEFAULT_COUNT)} == set(CLASSES)


def test_a_forked_run_is_a_separate_process_with_its_own_status_and_streams(tmp_path):
    good = run_forked(["solve", "examples/four_bar.yaml", "--json"], cwd=os.getcwd())
    assert good.status == 0 and good.stdout.startswith('{"name":"Four-bar linkage"') and good.stderr == ""
    bad = run_forked(["solve", str(tmp_path / "none.yaml")])
    assert bad.status == 2 and bad.stderr.startswith("error (syntax):") and bad.stdout == ""
    # '--json' as another option's value asks for no JSON: the explanation is the answer
    taken = run_forked(["explain", "examples/wheel_rolling.yaml", "--length-unit", "--json"], cwd=os.getcwd())
    check_run(taken)
    assert taken.status == 0 and "# Wheel rolling" in taken.stdout


@pytest.mark.parametrize("behaviour", ["raise", "hang", "shout"])
def test_the_campaign_catches_what_breaks_the_contract(monkeypatch, behaviour):
    # a child that raises is seen as a traceback, one that hangs is killed and seen as a
    # hang, one that answers with control characters is caught by the campaign's checks
    import sys

    import kinematika.cli.run

    from . import campaign
    from .cases import Case

    def command(*args, **kwargs):
        if behaviour == "raise":
            raise RuntimeError("boom")
        if behaviour == "hang":
            time.sleep(30)
        print("answer \x1b]0;owned\x07")
        sys.exit(0)

    monkeypatch.setattr(kinematika.cli.run, "solve_command", command)
    args = ["solve", "examples/four_bar.yaml"]
    got = run_forked(args, wall=2)
    failure = campaign.check(Case(0, "test", args), got, "")
    assert {"raise": "Traceback", "hang": "hang", "shout": "control character"}[behaviour] in failure
