"""The contract every input must meet, whatever it holds, and how to run a command under it.

An answer is complete and finite (no NaN, no infinity anywhere); an error is a
`KinematikaError` of one of the contract's kinds, one printable line of bounded length;
nothing else ever comes out (no other exception, no hang). From the command line: exit
status 0 with the answer, or 2 with one line (the contract's error JSON with `--json`),
within a time and memory bound.
"""
from __future__ import annotations

import json
import math
import os
import resource
import signal
import subprocess
import sys
import unicodedata
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Iterator

from kinematika.errors import KINDS, KinematikaError
from kinematika.limits import MESSAGE_CHARS, WHERE_CHARS

SECONDS = 200.0                 # no command may take more CPU time: above the symbolic safety net
                                # (limits.SYMBOLIC_SECONDS); counts stop hostile input long before
MEMORY = 1 << 30                # nor hold more than this (resident)
ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


class Hang(Exception):
    """The work ran past `SECONDS`."""


@contextmanager
def deadline(seconds: float = SECONDS) -> Iterator[None]:
    """Raise `Hang` in the main thread if the body runs past `seconds` (a hang detector for
    in-process runs; kinematika's own symbolic budget is shorter, so it speaks first)."""
    def ring(signum: int, frame: Any) -> None:
        raise Hang(f"no answer within {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def finite(data: Any, where: str = "") -> None:
    """Every number in `data` is finite (NaN and infinities are never answers)."""
    stack = [(data, where)]
    while stack:
        node, at = stack.pop()
        if isinstance(node, float):
            assert math.isfinite(node), f"{node} at {at}"
        elif isinstance(node, dict):
            stack.extend((v, f"{at}.{k}") for k, v in node.items())
        elif isinstance(node, (list, tuple)):
            stack.extend((v, f"{at}[{i}]") for i, v in enumerate(node))


def one_line(text: str, limit: int) -> None:
    """A message line: printable, no line breaks or control characters, bounded."""
    assert len(text) <= limit, f"{len(text)} characters: {text[:80]}…"
    assert text.isprintable() or all(c.isprintable() or unicodedata.category(c) == "Zs" for c in text), \
        repr(text[:120])


def check_error(err: KinematikaError) -> None:
    assert err.kind in KINDS, err.kind
    one_line(err.message, MESSAGE_CHARS)
    one_line(err.where, WHERE_CHARS)
    assert err.message, "an error says what is wrong"


@dataclass
class Outcome:
    """What one call gave: its data, or the error."""

    data: Any = None
    error: KinematikaError | None = None


def call(work: Callable[[], Any], seconds: float = SECONDS) -> Outcome:
    """Run `work` in-process under the contract: its data (finite) or its error (well formed);
    anything else fails the test."""
    try:
        with deadline(seconds):
            data = work()
    except KinematikaError as err:
        check_error(err)
        return Outcome(error=err)
    finite(data)
    return Outcome(data=data)


# the command line in a subprocess -----------------------------------------------------------
@dataclass
class Run:
    args: list[str]
    status: int
    stdout: str
    stderr: str
    seconds: float
    memory: int                   # peak resident bytes of the child
    cpu: float = 0.0              # CPU seconds of the child (user + system)

    def describe(self) -> str:
        return f"kinematika {' '.join(self.args)} -> {self.status}: {self.stderr[:200] or self.stdout[:200]}"


def _limits() -> None:
    """In the child: no core files, at most a few GB of address space (far above `MEMORY`,
    which is measured, so that a runaway allocation fails there instead of swapping)."""
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_AS, (4 * MEMORY, 4 * MEMORY))


def run_cli(args: list[str], seconds: float = SECONDS, cwd: Path | None = None) -> Run:
    """`kinematika ARGS` in a subprocess with the contract's time bound and its own peak
    memory (from wait4, the child's resource usage alone)."""
    import tempfile
    import threading
    import time

    env = {**os.environ, "PYTHONIOENCODING": "utf-8"}
    env.pop("KINEMATIKA_DEBUG", None)
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        start = time.monotonic()
        proc = subprocess.Popen([sys.executable, "-m", "kinematika", *args], stdout=out, stderr=err,
                                stdin=subprocess.DEVNULL, preexec_fn=_limits, env=env, cwd=cwd)
        killed = threading.Event()

        def kill() -> None:
            killed.set()
            proc.kill()

        timer = threading.Timer(seconds, kill)
        timer.start()
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        finally:
            timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
        elapsed = time.monotonic() - start
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read().decode("utf-8", "replace"), err.read().decode("utf-8", "replace")
    code = -9 if killed.is_set() else proc.returncode
    return Run(args, code, stdout, stderr if code != -9 else "timeout", elapsed, usage.ru_maxrss * 1024,
               usage.ru_utime + usage.ru_stime)


# options that take a value: `--set --json` gives --set the value '--json' (no JSON asked)
VALUE_OPTIONS = {"--set", "--move", "--assembly", "--joint", "--by", "--steps", "--csv", "--plot", "-o",
                 "--output", "--format", "--lang", "--length-unit", "--points", "--view", "--width"}


def json_wanted(args: list[str]) -> bool:
    """Whether `--json` is given as a flag for certain (not only as another option's value,
    where the command line may read it either way)."""
    return any(a == "--json" and (i == 0 or args[i - 1] not in VALUE_OPTIONS) for i, a in enumerate(args))


def without_warnings(stderr: str) -> str:
    """Standard error less its warnings (`warning: PLACE: MESSAGE`, one line each, bounded:
    input answered as written that is most likely a mistake)."""
    kept = []
    for line in stderr.splitlines(keepends=True):
        if line.startswith("warning: "):
            one_line(line.rstrip("\n"), 40 + MESSAGE_CHARS + WHERE_CHARS)
        else:
            kept.append(line)
    return "".join(kept)


def check_run(run: Run) -> None:
    """The command line's contract: exit 0 with an answer, or 2 with one error line."""
    assert run.status != -9, f"hang: {run.describe()}"
    assert run.cpu <= SECONDS, f"{run.cpu:.1f} s of CPU: {run.describe()}"
    assert run.memory <= MEMORY, f"{run.memory >> 20} MB: {run.describe()}"
    assert run.status in (0, 2), run.describe()
    assert "Traceback" not in run.stderr, run.describe()
    as_json = "--json" in run.args
    if as_json and not json_wanted(run.args) and not run.stdout.strip():
        as_json = False            # `--set --json`: '--json' may be read as --set's value
    if "--help" in run.args and run.status == 0:
        return                                   # the help text, as asked
    if run.status == 2:
        if as_json:
            lines = run.stdout.splitlines()
            assert len(lines) == 1, run.describe()
            error = json.loads(lines[0])["error"]
            assert error["kind"] in KINDS, run.describe()
            one_line(error["message"], MESSAGE_CHARS)
        else:
            lines = without_warnings(run.stderr).splitlines()
            assert len(lines) == 1 and lines[0].startswith("error ("), run.describe()
            one_line(lines[0], 40 + MESSAGE_CHARS + WHERE_CHARS)
    elif json_wanted(run.args):
        finite(json.loads(run.stdout, parse_constant=float))
