"""Optional dependencies: which extra installs each, and the one line that says so.

kinematika's core (solve, explain, draw, sweep, the page) needs only what `pip install -e .`
installs. Design studies need pyarrow and pandas (and dask.distributed for a cluster), Parquet
sweeps need pyarrow, a cam's DXF needs ezdxf: they are the extras of pyproject.toml. A command that needs a missing one
says, in one line naming the command, what to install, in the README's own terms, and exits
with status 2 (`usage`); it never ends in an internal error.
"""
from __future__ import annotations

import importlib
from types import ModuleType
from typing import Any

from .errors import KinematikaError

EXTRA = {                       # the module imported -> the extra of pyproject.toml that installs it
    "pyarrow": "explore",
    "pandas": "explore",
    "dask": "explore",
    "distributed": "explore",
    "playwright": "exercise",
    "ezdxf": "cad",             # a cam's profile as DXF (`kinematika cam --dxf`)
}


def install_hint(extra: str) -> str:
    """How to install an extra: in a clone (the README's set-up) and from PyPI."""
    return f".venv/bin/pip install -e '.[{extra}]' (or pip install 'kinematika[{extra}]')"


def missing(module: str, what: Any, where: str = "", extra: str | None = None) -> KinematikaError:
    """The error for `what` (a command or a feature) needing `module`, which is not installed;
    `extra` names the extra to install when it is not the module's usual one (`EXTRA`)."""
    top = module.partition(".")[0]
    extra = extra or EXTRA.get(top)
    how = install_hint(extra) if extra else f"pip install {top}"
    return KinematikaError("usage", "module-missing", where, what=what, module=top, command=how)


def need(module: str, what: Any, where: str = "", extra: str | None = None) -> ModuleType:
    """`module`, imported; if it is not installed, the `missing` error for `what`."""
    try:
        return importlib.import_module(module)
    except ImportError as err:
        raise missing(err.name or module, what, where, extra) from None


def available(module: str) -> bool:
    """Whether `module` can be imported (an optional path may then be taken)."""
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True
