"""Shared test settings: one fixed set of inputs on every run, and small helpers.

Every run of the suite draws the same inputs, on any machine and any day: hypothesis derives
each test's examples from the test itself (`derandomize`, no example database), the fuzz
campaign uses a fixed seed. `KINEMATIKA_DEEP=1` runs the same tests deeper (500 examples a
property, a campaign of 1 000 hostile inputs, every parameter set); a campaign with fresh
seeds is its own command, `tests/fuzz/campaign.py` (see docs/testing.md).
"""
from __future__ import annotations

import importlib.util
import os
from pathlib import Path
from types import ModuleType

from hypothesis import HealthCheck, settings

DEEP = os.environ.get("KINEMATIKA_DEEP", "") not in ("", "0")

_fixed = {"deadline": None, "derandomize": True, "database": None, "print_blob": True,
          "suppress_health_check": [HealthCheck.too_slow]}
settings.register_profile("default", max_examples=20, **_fixed)
settings.register_profile("deep", max_examples=500, **_fixed)
settings.load_profile("deep" if DEEP else "default")

# How long a test waits for a page, a server or a child process before it calls the wait a
# hang: far above what any wait takes on a 2-core machine busy with other work (the slowest
# seen, an exercise page's background requests, ~30 s), so that a loaded machine is slow,
# never red. Playwright counts in milliseconds.
HANG_SECONDS = 120.0
BROWSER_WAIT = int(HANG_SECONDS * 1000)
# A page that waits on the server's computation (an exact solve of a large model, a long
# simulation) is waited on by the server's CPU time, not the clock: what a loaded machine
# stretches is the wall time, never the work. Past this much CPU time the work is a hang.
HANG_CPU_SECONDS = 200.0

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


def hand_derivations() -> ModuleType:
    """tests/cases/derive.py, the textbook cases' hand derivations (Freudenstein, Norton's
    rate equations, loop closures), as a module; it is also a script, so it is loaded by
    path."""
    spec = importlib.util.spec_from_file_location("hand_derivations", ROOT / "tests" / "cases" / "derive.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def pytest_xdist_auto_num_workers(config) -> int:
    """`-n auto`: one worker more than the cores. A third of the browser and command-line
    tests' time is spent waiting (Chromium, a pause of the slow drag, a child process), and
    on a machine busy with other work the extra worker keeps the suite's share of the cores:
    on 2 cores under two busy loops the suite took 412 s with two workers, 329 s with three
    (docs/testing.md)."""
    return (len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1) + 1


def pytest_runtest_logreport(report) -> None:
    """With KINEMATIKA_DURATIONS=FILE, each test's phase, outcome and seconds are appended to
    FILE as they finish (a run stopped half way still says where its time went)."""
    path = os.environ.get("KINEMATIKA_DURATIONS")
    if path and (report.when == "call" or report.outcome != "passed"):
        with open(path, "a", encoding="utf-8") as out:
            out.write(f"{report.duration:.2f}\t{report.outcome}\t{report.when}\t{report.nodeid}\n")
