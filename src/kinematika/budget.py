"""A time budget for work whose cost the input decides (exact formulas): past it, a clear
`limit` error naming the work, instead of a computation that runs for minutes."""
from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager, nullcontext
from typing import Any, ContextManager, Iterator

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
    stack.append([end, what, seconds, ""])
    alarm = _arm(end) if len(stack) == 1 else None
    try:
        yield
    finally:
        stack.pop()
        if alarm is not None:
            _disarm(alarm)


def exact_work(model: Any, symbolic: bool | None = None) -> ContextManager:
    """The time budget of the work on `model` when it is solved with exact formulas (asked
    with `symbolic`, or a parameter without a value); numbers need none."""
    exact = bool(symbolic) or any(p.value is None for p in model.parameters.values())
    return budget("the exact formulas") if exact else nullcontext()


def check(stage: str = "") -> None:
    """Raise `OverBudget` if the current time budget is spent (no budget: nothing); `stage`
    names the work under way, for the message."""
    stack = _state()
    if stack:
        if stage:
            stack[-1][3] = stage
        if time.monotonic() > stack[-1][0]:
            raise _over()


def _over() -> OverBudget:
    _, what, seconds, stage = _state()[-1]
    at = f" ({stage})" if stage else ""
    return OverBudget("limit", f"finding {what} takes longer than {seconds:g} s{at}: they are too "
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
