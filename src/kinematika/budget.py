"""The budgets of work whose cost the input decides (exact formulas): past one, a clear
`limit` error naming the work and what asked for it, instead of a computation that runs
for minutes.

What a model answers is a function of the model, never of the machine: the budgets that
decide are counts. `spend` counts the exact algebra's work (terms formed and products of
terms taken, `limits.EXACT_WORK` a command); `within` gives the steps that only make a
formula read better a count of operations (`POLISH_OPS` a command), so that the formulas
shown are the same in every run. A time limit stays only as a safety net, far above what
the counts admit (`limits.SYMBOLIC_SECONDS` of the working thread's CPU time, 14 times the
slowest valid model's; `STEP_SECONDS` a step): a valid model never meets it, however slow or
busy the machine.
"""
from __future__ import annotations

import signal
import sys
import threading
import time
from contextlib import contextmanager, nullcontext
from typing import Any, Callable, ContextManager, Iterator, TypeVar

from . import memo
from .errors import KinematikaError, Said
from . import limits
from .limits import symbolic_seconds


class OverBudget(KinematikaError):
    """Symbolic work ran out of its time budget (a `limit` error naming the stage)."""


class TimeUp(BaseException):
    """An optional step ran past its own time (`within`); never seen outside `within`."""


POLISH_OPS = 20_000         # the operations all optional steps of a command may be given
                            # (their inputs' sizes, summed); past it, formulas are shown in the
                            # form found. A count, not a time: every run, on any machine and
                            # under any load, gives the same forms
STEP_SECONDS = 2.0          # processor time one optional step may take: a safety net for a
                            # rare input whose cost jumps (the benchmark's 113 models take at
                            # most 0.09 s a step: 22 times less)

_deadline = threading.local()
_unraisable = sys.unraisablehook
_soft: list[float] = []     # the ends of the optional steps under way (main thread only)
T = TypeVar("T")
_clock = time.thread_time   # CPU seconds of this thread (a server's other requests not counted)


def _state() -> list:
    if not hasattr(_deadline, "stack"):
        _deadline.stack = []
    return _deadline.stack


@contextmanager
def budget(what: str, seconds: float | None = None, why: str = "") -> Iterator[None]:
    """Run the body within a budget of `seconds` of CPU time; past it, `OverBudget` naming
    `what` (and `why` it was asked, for the advice) is raised.

    Nested budgets keep the earliest deadline. Checks are cooperative (`check`, called
    between steps of the work); in the main thread a CPU-time timer signal also interrupts
    a single long computation (a factorisation of huge polynomials), so the limit holds in
    any case.
    """
    seconds = symbolic_seconds() if seconds is None else seconds
    stack = _state()
    end = _clock() + seconds
    polish = [POLISH_OPS]           # the operations left for optional steps, shared when nested
    work = [limits.EXACT_WORK]      # the exact algebra's work left, shared when nested
    if stack:
        end = min(end, stack[-1][0])
        polish, work = stack[-1][4], stack[-1][6]
        why = why or stack[-1][5]
    stack.append([end, what, seconds, "", polish, why, work])
    alarm = _arm(end) if len(stack) == 1 else None
    try:
        with memo.fresh() if len(stack) == 1 else nullcontext():   # a command's own memory
            yield
    finally:
        stack.pop()
        if alarm is not None:
            _disarm(alarm)


def exact_work(model: Any, symbolic: bool | None = None) -> ContextManager:
    """The time budget of the work on `model` when it is solved with exact formulas (asked
    with `symbolic`, or a parameter without a value); numbers need none. The error's advice
    names what the user did: the option, or the parameters left as symbols."""
    if symbolic:
        return budget("exact-formulas", why="--symbolic")
    free = [name for name, p in model.parameters.items() if p.value is None]
    if not free:
        return nullcontext()
    return budget("exact-formulas", why="null:" + ", ".join(free))


def check(stage: str = "") -> None:
    """Raise `OverBudget` if the current time budget is spent (no budget: nothing); `stage`
    names the work under way, for the message."""
    stack = _state()
    if stack:
        if stage:
            stack[-1][3] = stage
        if _clock() > stack[-1][0]:
            raise _over()


def spend(units: int) -> None:
    """Count `units` of the exact algebra's work (terms formed, products of terms taken)
    against the command's allowance, `limits.EXACT_WORK`; past it, the `limit` error. A
    count, so that whether a model is answered never depends on the machine or its load."""
    stack = _state()
    if stack:
        left = stack[-1][6]
        left[0] -= units
        if left[0] < 0:
            raise _over(counted=True)


def within(size: int, step: Callable[..., T], *args: Any, default: Any = None) -> T:
    """`step(*args)` for work that only makes a result read better (factoring, trigonometric
    rewriting), or `default` when its input's `size` (in operations) is more than is left of
    the command's allowance (`POLISH_OPS`), which it then takes from. The allowance is a
    count so that the forms shown never depend on the machine or its load. In the main
    thread a timer signal also stops a step that takes more than `STEP_SECONDS` of the
    thread's own processor time (a rare input whose cost jumps; other threads' work, such as
    the page's server answering other requests, does not count); in other threads a step
    runs whole."""
    stack = _state()
    if stack:
        allowance = stack[-1][4]
        if size > allowance[0]:
            return default
        allowance[0] -= size
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        return step(*args)
    previous = signal.signal(signal.SIGVTALRM, _time_up)
    _soft.append(_clock() + STEP_SECONDS)
    try:
        try:
            signal.setitimer(signal.ITIMER_VIRTUAL, STEP_SECONDS, 0.02)
            return step(*args)
        finally:
            signal.setitimer(signal.ITIMER_VIRTUAL, 0)
    except TimeUp:
        return default
    finally:
        _soft.pop()
        signal.setitimer(signal.ITIMER_VIRTUAL, 0)
        signal.signal(signal.SIGVTALRM, previous)
        if _soft:                           # an outer step's timer, as it was
            signal.setitimer(signal.ITIMER_VIRTUAL, max(_soft[-1] - _clock(), 0.001), 0.02)


def _time_up(signum: int, frame: Any) -> None:
    """The timer of `within`: stop the step under way once this thread's processor time is
    past its end. The timer counts the whole process (the page's server threads, BLAS
    threads), so it rings early when other threads work; it then rings every 0.02 s until
    the thread's own time is up."""
    if _soft and _clock() + 0.002 >= _soft[-1]:
        raise TimeUp()


def _over(counted: bool = False) -> OverBudget:
    _, what, seconds, stage, _, why, _ = _state()[-1]
    return OverBudget("limit", "over-budget", "", what=Said.of(what, {}), counted=str(counted).lower(),
                      steps=f"{limits.EXACT_WORK:,}".replace(",", " "), seconds=float(seconds),
                      staged=str(bool(stage)).lower(), stage=Said.of(stage or "nothing", {}), advice=_advice(why))


def _advice(why: str) -> Said:
    """What to change, from what made the work exact: the option, or symbols in the model."""
    if why == "--symbolic":
        return Said("advice-symbolic")
    if why.startswith("null:"):
        names = why[5:]
        if len(names) > 60:
            names = names[:59] + "…"
        return Said("advice-null", names=names)
    return Said("advice-numbers")


def _arm(end: float) -> Any:
    """A CPU-time timer signal (SIGPROF) at `end` in the main thread (elsewhere only
    cooperative checks work). The process's CPU time, counted by the timer, is at least
    the thread's, so the signal never comes early."""
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        return None
    try:
        previous = signal.signal(signal.SIGPROF, _ring)
    except (ValueError, OSError):
        return None
    signal.setitimer(signal.ITIMER_PROF, max(end - _clock(), 0.001), 0.25)
    return previous


def _disarm(previous: Any) -> None:
    signal.setitimer(signal.ITIMER_PROF, 0)
    signal.signal(signal.SIGPROF, previous)


def _ring(signum: int, frame: Any) -> None:
    """The timer: raise inside whatever runs once the thread's budget is spent (and check
    again every 0.25 s of CPU time until it is out)."""
    stack = _state()
    if stack and _clock() > stack[-1][0]:
        raise _over()


def _quiet(info: Any) -> None:
    """A timer signal that lands in a weakref callback is printed and dropped by Python
    ("Exception ignored in …"); the timer raises it again at its next tick, so it is not
    news for the user's terminal."""
    if not isinstance(info.exc_value, (TimeUp, OverBudget)):
        _unraisable(info)


sys.unraisablehook = _quiet
