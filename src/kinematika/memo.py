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
