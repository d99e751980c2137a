"""The command line run in a separate process per input, thousands of times: a parent that
has imported kinematika (and sympy, matplotlib, typer) forks one child per command, which
runs `kinematika.cli.main` with its own arguments, standard streams, limits and exit status.

A fresh `python -m kinematika` spends most of a simple command starting up (0.3 to 1.5 s);
a fork starts in milliseconds, so a campaign of thousands of inputs takes minutes, and
each input still runs alone in its own process, with its own address-space limit, its own
time bound and its own exit status, as a user's would. `contract.run_cli` runs the real
executable; the campaign runs a share of its inputs that way too, to keep the two honest.
"""
from __future__ import annotations

import os
import resource
import signal
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator

from .contract import MEMORY, SECONDS, Run

CPU = SECONDS       # the contract's time bound, in CPU seconds of the child: killed past it
WALL = 600.0        # a child still running after this is killed, whatever its CPU time (a hang
                    # that waits); CPU time, not wall time, is the bound otherwise, so that
                    # a loaded machine (other work on its 2 cores) fails no valid input
_ready = False


def preload() -> None:
    """Import in the parent what commands import, so that children start at once (the
    modules only: no model is read, no cache is filled)."""
    global _ready
    if _ready:
        return
    os.environ.setdefault("MPLBACKEND", "Agg")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot
    import numpy  # noqa: F401
    import sympy  # noqa: F401

    import kinematika.cli as cli
    import kinematika.cli.fast
    import kinematika.cli.run  # noqa: F401

    cli._application()          # typer and every command module
    _ready = True


@dataclass
class Child:
    args: list[str]
    pid: int
    start: float
    out: object
    err: object
    killed: bool = False


def _child(args: list[str], out: int, err: int, cwd: str | None) -> None:
    """In the forked child: limits, streams, arguments; run the command line; exit."""
    import io

    code = 70
    try:
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        resource.setrlimit(resource.RLIMIT_AS, (4 * MEMORY, 4 * MEMORY))
        for sig in (signal.SIGALRM, signal.SIGPROF, signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, signal.SIG_DFL if sig != signal.SIGINT else signal.default_int_handler)
        signal.setitimer(signal.ITIMER_REAL, 0)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.dup2(out, 1)
        os.dup2(err, 2)
        if cwd:
            os.chdir(cwd)
        sys.stdin = io.TextIOWrapper(io.FileIO(0, "r", closefd=False))
        sys.stdout = io.TextIOWrapper(io.FileIO(1, "w", closefd=False), encoding="utf-8")
        sys.stderr = io.TextIOWrapper(io.FileIO(2, "w", closefd=False), encoding="utf-8",
                                      line_buffering=True)
        sys.argv = ["kinematika", *args]
        os.environ.pop("KINEMATIKA_DEBUG", None)
        from kinematika.cli import main

        try:
            main()
            code = 0
        except SystemExit as done:
            code = done.code if isinstance(done.code, int) else (0 if done.code is None else 1)
            if not isinstance(done.code, (int, type(None))):
                print(done.code, file=sys.stderr)
        except BaseException:                         # what a real process would print
            import traceback

            traceback.print_exc()
            code = 1
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        os._exit(code)


def start(args: list[str], cwd: Path | None = None) -> Child:
    """Fork a child running `kinematika ARGS`."""
    out, err = tempfile.TemporaryFile(), tempfile.TemporaryFile()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        _child(list(args), out.fileno(), err.fileno(), str(cwd) if cwd else None)
    return Child(list(args), pid, time.monotonic(), out, err)


def _finish(child: Child, status: int, usage: resource.struct_rusage) -> Run:
    elapsed = time.monotonic() - child.start
    texts = []
    for f in (child.out, child.err):
        f.seek(0)
        texts.append(f.read().decode("utf-8", "replace"))
        f.close()
    code = -9 if child.killed else os.waitstatus_to_exitcode(status)
    run = Run(child.args, code, texts[0], texts[1] if code != -9 else "timeout", elapsed,
              usage.ru_maxrss * 1024)
    run.cpu = usage.ru_utime + usage.ru_stime
    return run


def run_all(jobs: Iterable[tuple[object, list[str], Path | None]], workers: int = 2,
            wall: float = WALL) -> Iterator[tuple[object, Run]]:
    """Run (key, args, cwd) jobs, at most `workers` at once, yielding (key, Run) as each
    ends; a child past `wall` seconds is killed (its Run has status -9)."""
    preload()
    pending = iter(jobs)
    running: dict[int, tuple[object, Child]] = {}
    exhausted = False
    while True:
        while not exhausted and len(running) < workers:
            job = next(pending, None)
            if job is None:
                exhausted = True
                break
            key, args, cwd = job
            child = start(args, cwd)
            running[child.pid] = (key, child)
        if not running:
            return
        done = False
        for pid, (key, child) in list(running.items()):
            got, status, usage = os.wait4(pid, os.WNOHANG)
            if got:
                del running[pid]
                done = True
                yield key, _finish(child, status, usage)
            elif not child.killed and (time.monotonic() - child.start > wall or _cpu(pid) > CPU):
                child.killed = True
                os.kill(pid, signal.SIGKILL)
        if not done:
            time.sleep(0.005)


_TICK = os.sysconf("SC_CLK_TCK")


def _cpu(pid: int) -> float:
    """CPU seconds (user + system) a running child has used so far."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
    except OSError:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / _TICK


def run_forked(args: list[str], cwd: Path | None = None, wall: float = WALL) -> Run:
    """One command in a forked child (see `run_all`)."""
    return next(run_all([(None, args, cwd)], 1, wall))[1]
