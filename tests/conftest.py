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
import re
import sys
from pathlib import Path
from types import ModuleType

import pytest
from hypothesis import HealthCheck, settings

DEEP = os.environ.get("KINEMATIKA_DEEP", "") not in ("", "0")

# Bytecode is written during the run, whatever the environment says (PYTHONDONTWRITEBYTECODE=1
# here and maybe in CI): a fresh clone has none, and without writing it every xdist worker
# and every `kinematika` process a test starts compiles the package again, and pytest
# rewrites every test module's asserts in each worker. Written once (into the clone's ignored
# __pycache__ directories, atomically), then read. The workers and child processes inherit
# the environment without the variable.
sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)

deep_only = pytest.mark.skipif(not DEEP, reason="seconds of work: in a deep run (KINEMATIKA_DEEP=1)")
"""A test whose work repeats what a quicker one shows, kept for the deep run."""


def sampled(cases: list, keep) -> list:
    """Every case in a deep run; in a default run those `keep` names (a set of names, or a
    predicate on a case) — one of each kind the test tells apart, so that the 8-minute
    suite still meets every kind and the deep run meets every case. Cases are compared by
    their `stem`/`name`/`id`/str."""
    if DEEP:
        return list(cases)
    def name(case) -> str:
        for attr in ("stem", "name", "id"):
            if isinstance(getattr(case, attr, None), str):
                return getattr(case, attr)
        return str(case)
    chosen = [c for c in cases if (keep(c) if callable(keep) else name(c) in keep)]
    assert chosen, f"none of {keep} among the cases"      # a renamed case is said, not skipped
    return chosen


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
# one example of each kind of model (pairs, higher pairs, trains, vehicles, space, symbols,
# groups that are not dyads): what a default run checks where a deep run checks every example
KINDS = frozenset({
    "four_bar", "slider_crank", "quick_return", "pin_in_circular_slot", "seed_001_rolling_pair",
    "seed_c5_1_4_epicyclic", "eccentric_cam", "seed_c5_1_6_belt", "seed_c5_e6_bicycle",
    "tractor_trailer", "spherical_four_bar", "fan_symbolic", "triad_six_bar",
    "seed_c5_1_8_contact_points"})


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


# Test directories whose files are one unit of work for xdist, run one after the other by
# one worker: their files share what a helper module caches per process (tests/explain: each
# example solved and explained once, each seed's page written once per language, by
# `tests/explain/helpers`; tests/examples: each example solved once, by
# `tests/examples/helpers`; tests/exercise: the session's two exercises of 30 variants and
# their folders, `tests/exercise/conftest`; tests/web: the session's Chromium, its page server
# and its API client, `tests/web/conftest`), which, handed to different workers, each worker
# made again.
ONE_WORKER = ("tests/explain/", "tests/examples/", "tests/exercise/", "tests/web/")


def unit(nodeid: str) -> str:
    """The unit of work a test belongs to: its file, or its directory when the directory is
    one of `ONE_WORKER`."""
    path = nodeid.split("::", 1)[0]
    return next((d for d in ONE_WORKER if path.startswith(d)), path)


@pytest.hookimpl(tryfirst=True)         # before xdist's own, which answers for every --dist
def pytest_xdist_make_scheduler(config, log):
    """`--dist loadfile`, with the files of a `ONE_WORKER` directory as one unit."""
    if config.getvalue("dist") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class LoadUnitScheduling(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return unit(nodeid)

    return LoadUnitScheduling(config, log)


# A test module's file name as pytest rewrites its asserts (its `python_files` and conftest.py)
REWRITTEN = re.compile(r"(^|/)(test_[^/]*|[^/]*_test|conftest)\.py$")


@pytest.hookimpl(tryfirst=True)         # before xdist's own, which starts the workers
def pytest_sessionstart(session) -> None:
    """Under xdist, in the controller before the workers start: the package compiled and the
    test modules' asserts rewritten once, into the clone's `__pycache__`, which every worker
    then reads. Without it, on a fresh clone, each of the three workers compiled the package
    and rewrote the ~3 000 asserts of the tests itself, at the same moment (~4 s of CPU a
    worker: docs/testing.md). Only the files of the paths given are rewritten."""
    config = session.config
    if hasattr(config, "workerinput") or not config.getoption("numprocesses", default=0) or sys.dont_write_bytecode:
        return
    compiled_once(config, [Path(a.split("::", 1)[0]) for a in config.args])


def compiled_once(config, paths: list[Path]) -> None:
    """`compileall` for the package and the tests' own helpers, and pytest's assertion
    rewriter (private to pytest, so each step is skipped if pytest moved it) for the test
    modules, written where the import would write them; a file already written is kept."""
    import compileall

    quiet = re.compile(r"(^|/)(\.venv|__pycache__)(/|$)")
    compileall.compile_dir(ROOT / "src" / "kinematika", quiet=1)
    folders = [p for p in paths if p.is_dir()]
    for folder in folders:
        compileall.compile_dir(folder, quiet=1, rx=re.compile(f"{REWRITTEN.pattern}|{quiet.pattern}"))
    try:
        from _pytest.assertion import rewrite

        state = config.stash[rewrite.assertstate_key]
    except (ImportError, AttributeError, KeyError):
        return
    files = [p for p in paths if p.is_file()] + [f for d in folders for f in sorted(d.rglob("*.py"))]
    for fn in files:
        if not REWRITTEN.search(fn.as_posix()) or quiet.search(fn.as_posix()):
            continue
        fn = fn.resolve()
        pyc = rewrite.get_cache_dir(fn) / (fn.name[:-3] + rewrite.PYC_TAIL)
        if rewrite._read_pyc(fn, pyc, state.trace) is None and rewrite.try_makedirs(pyc.parent):
            source_hash, code = rewrite._rewrite_test(fn, config)
            rewrite._write_pyc(state, code, source_hash, pyc)


def pytest_collection_modifyitems(config, items) -> None:
    """The order in which the workers are handed the units of work (`unit`: a test file, or
    a `ONE_WORKER` directory; `--dist loadfile`, with xdist's own reordering off in
    pyproject.toml): first the units marked `early(rank)`, lowest rank first (mypy's single
    run over the package, 0; the browser pages, the exact solves: minutes of one worker
    that, handed out last, would end the run alone), then the others by their number of
    tests, most first (what xdist's reordering did). A file's tests keep their order; the
    order depends on nothing but the files."""
    files: dict[str, list] = {}
    for item in items:
        files.setdefault(unit(item.nodeid), []).append(item)
    def rank(tests: list) -> tuple:
        marks = [m for t in tests for m in t.iter_markers("early")]
        return (min((m.args[0] if m.args else 1) for m in marks) if marks else 2, -len(tests))
    items[:] = [item for tests in sorted(files.values(), key=rank) for item in tests]


def pytest_runtest_logreport(report) -> None:
    """With KINEMATIKA_DURATIONS=FILE, each test's seconds, outcome, phase and id, then its
    worker's CPU seconds so far and process id, are appended to FILE as they finish (a run
    stopped half way still says where its time went), once a test (by the worker that ran
    it, not again by xdist's controller). `scripts/durations.py FILE` sums them."""
    path = os.environ.get("KINEMATIKA_DURATIONS")
    if hasattr(report, "node"):         # under xdist, the controller's copy of a worker's report
        return
    # a test's call; its setup or teardown when it takes a tenth of a second or more (a
    # module's or a worker's shared fixture: a server, a browser, a solved model) or fails
    if path and (report.when == "call" or report.outcome != "passed" or report.duration >= 0.1):
        with open(path, "a", encoding="utf-8") as out:
            out.write(f"{report.duration:.2f}\t{report.outcome}\t{report.when}\t{report.nodeid}\t"
                      f"{_cpu_so_far():.2f}\t{os.getpid()}\n")


def _cpu_so_far() -> float:
    """This worker's CPU seconds so far (user + system), its finished child processes
    included (a `kinematika` command, a page server): in the durations file, the difference
    between two lines of one worker (the last column, its process id) is the CPU the tests
    between them took, whatever the load made of their wall time. Children still running
    (the session's Chromium and page server) count when they end."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system
