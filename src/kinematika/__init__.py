"""kinematika: kinematic analysis of mechanisms, exactly as a careful textbook solution would.

    >>> from kinematika import solve
    >>> sol = solve("examples/four_bar.yaml")
    >>> sol.velocity("B@rocker")

Everything goes through one engine: a model (file, dict or `Mechanism`) is parsed once into
a `Model`, evaluated on numbers or symbols, and its velocity and acceleration systems
solved; views (CLI, JSON, tables, figures, explanations) read the `Solution`.
The names below are imported on first use, so a command loads only what it needs.
"""
from __future__ import annotations

from importlib import import_module
from typing import Any

__version__ = "0.1.0"

_EXPORTS = {
    "solve": "api", "answers": "api", "as_model": "api", "load_model": "model.files",
    "Mechanism": "api", "Solution": "solution", "KinematikaError": "errors",
    "run_sweep": "sweep", "run_simulation": "simulate",
}
__all__ = [*sorted(_EXPORTS), "__version__"]  # noqa: PLE0604 (the names _EXPORTS lists)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(import_module(f".{_EXPORTS[name]}", __name__), name)
    raise AttributeError(f"module 'kinematika' has no attribute {name!r}")
