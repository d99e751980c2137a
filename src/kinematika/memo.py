"""What symbolic work remembers, for one command.

Formulas take long to simplify and to print, and the same ones recur (a point's velocity
is asked of every body that carries it; answers repeat the tables), so their forms are
remembered. What is remembered is kept for one command (`kinematika.budget.budget`
opens a fresh memory in its thread): how a form comes out may depend on what came before
it in the command (a root is written the way it was first met; optional steps stop at
the command's allowance), and a command must give the same formulas whether it runs
alone (the command line) or after others (the page's server, a notebook). Outside a
command, one memory serves the whole process.
"""
from __future__ import annotations

import threading
from contextlib import contextmanager
from typing import Any, Hashable, Iterator

_local = threading.local()
_process: dict[int, dict] = {}      # the memory outside any command


class Memo:
    """A bounded table from a formula to something formed from it (emptied when full)."""

    def __init__(self, size: int) -> None:
        self.size = size

    def _table(self) -> dict:
        tables = getattr(_local, "tables", None)
        if tables is None:
            tables = _process
        return tables.setdefault(id(self), {})

    def get(self, key: Hashable) -> Any:
        """The value remembered for `key`, or None."""
        return self._table().get(key)

    def put(self, key: Hashable, value: Any) -> Any:
        """Remember `value` for `key` and return it."""
        table = self._table()
        if len(table) >= self.size:
            table.clear()
        table[key] = value
        return value


@contextmanager
def fresh() -> Iterator[None]:
    """A new, empty memory for the work in this thread until the block ends."""
    before = getattr(_local, "tables", None)
    _local.tables = {}
    try:
        yield
    finally:
        _local.tables = before


class Pure:
    """A bounded table, shared by the whole process (every command, every thread), for a
    step whose result depends on its input formula alone — sympy's trigsimp, a seeded
    factor, factor_terms — so that a formula met again (the page's server solving the same
    model for each request, a test process solving it in several tests) is not worked again.
    Unlike `Memo`, what it keeps cannot depend on what came before in a command: only what
    a fresh call would return is kept, and a step stopped part-way (its time up, an error)
    keeps nothing. A caller whose step has a side effect keeps it with the result (a seeded
    factor keeps the state of sympy's random numbers after it) and repeats it on a hit."""

    def __init__(self, size: int) -> None:
        self.size = size
        self.table: dict = {}
        self.lock = threading.Lock()

    def get(self, key: Hashable) -> Any:
        """The value remembered for `key`, or None."""
        return self.table.get(key)

    def put(self, key: Hashable, value: Any) -> Any:
        """Remember `value` for `key` (the table emptied when full) and return it."""
        with self.lock:
            if len(self.table) >= self.size:
                self.table.clear()
            self.table[key] = value
        return value
