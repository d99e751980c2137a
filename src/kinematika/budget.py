"""A time budget for work whose cost the input decides (exact formulas): past it, a clear
`limit` error naming the work, instead of a computation that runs for minutes."""
from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager
from typing import Any, Iterator

from .errors import KinematikaError
from .limits import symbolic_seconds


class OverBudget(KinematikaError):
    """Symbolic work ran out of its time budget (a `limit` error naming the stage)."""


_deadline = threading.local()


def _state() -> list:
    if not hasattr(_deadline, "stack"):
        _deadline.stack = []
    return _deadline.stack


@contextmanager
def budget(what: str, seconds: float | None = None) -> Iterator[None]:
    """Run the body within a time budget; past it, `OverBudget` naming `what` is raised.

    Nested budgets keep the earliest deadline. Checks are cooperative (`check`, called
    between steps of the work); in the main thread a timer signal also interrupts a single
    long computation (a factorisation of huge polynomials), so the limit holds in any case.
    """
    seconds = symbolic_seconds() if seconds is None else seconds
    stack = _state()
    end = time.monotonic() + seconds
    if stack:
        end = min(end, stack[-1][0])
    stack.append((end, what, seconds))
    alarm = _arm(end) if len(stack) == 1 else None
    try:
        yield
    finally:
        stack.pop()
        if alarm is not None:
            _disarm(alarm)


def check(stage: str = "") -> None:
    """Raise `OverBudget` if the current time budget is spent (no budget: nothing)."""
    stack = _state()
    if stack and time.monotonic() > stack[-1][0]:
        raise _over(stage)


def _over(stage: str = "") -> OverBudget:
    _, what, seconds = _state()[-1]
    at = f" (while {stage})" if stage else ""
    return OverBudget("limit", f"{what} take longer than {seconds:g} s{at}: the formulas are too "
                      "large; give some parameters numbers, or solve without --symbolic", "")


def _arm(end: float) -> Any:
    """A timer signal at `end` in the main thread (elsewhere only cooperative checks work)."""
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        return None
    try:
        previous = signal.signal(signal.SIGALRM, _ring)
    except (ValueError, OSError):
        return None
    signal.setitimer(signal.ITIMER_REAL, max(end - time.monotonic(), 0.001), 0.25)
    return previous


def _disarm(previous: Any) -> None:
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, previous)


def _ring(signum: int, frame: Any) -> None:
    """The timer: raise inside whatever runs (and again every 0.25 s until it is out)."""
    if _state():
        raise _over()
