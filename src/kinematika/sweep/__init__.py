"""Motion over a cycle: position analysis and sweeps of a driven joint's coordinate, and the
posing of a model (`posing`: moved along its driven joints as a sweep moves it).

    >>> from kinematika.sweep import run_sweep
    >>> result = run_sweep("examples/four_bar.yaml", by=360, steps=360)
    >>> result.bodies["rocker"]["angle"], result.points["B@coupler"]["position"]

The names are imported on first use: posing a model for one instant loads no sweep.
"""
from __future__ import annotations

from importlib import import_module
from typing import Any

_EXPORTS = {"SweepResult": "result", "run_sweep": "posing"}
__all__ = ["SweepResult", "run_sweep"]


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(import_module(f".{_EXPORTS[name]}", __name__), name)
    raise AttributeError(f"module 'kinematika.sweep' has no attribute {name!r}")
