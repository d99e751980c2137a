"""Motion in time: a mechanism followed by integrating its velocities (`kinematika simulate`).

Knife edges (`wheel`), and discs rolling on a plane, constrain velocities only: where a
vehicle is after a while depends on the path it took, so its positions are found by
integrating, in time, the velocities the engine solves at each instant (scipy's ODE solvers),
the poses kept on the joints' position conditions by projection. A mechanism a sweep can
follow may be simulated too: its drivers then advance in time.

    >>> from kinematika.simulate import run_simulation
    >>> result = run_simulation("examples/tractor_trailer_turning.yaml", time=60, steps=600)
    >>> result.time, result.points["T@trailer"]["position"], result.drift

The names are imported on first use.
"""
from __future__ import annotations

from importlib import import_module
from typing import Any

_EXPORTS = {"SimulationResult": "result", "run_simulation": "run", "Simulator": "run",
            "needs_time": "run"}
__all__ = ["SimulationResult", "Simulator", "needs_time", "run_simulation"]


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(import_module(f".{_EXPORTS[name]}", __name__), name)
    raise AttributeError(f"module 'kinematika.simulate' has no attribute {name!r}")
