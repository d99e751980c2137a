"""Motion over a cycle: position analysis and sweeps of a driven joint's coordinate.

    >>> from kinematika.sweep import run_sweep
    >>> result = run_sweep("examples/four_bar.yaml", by=360, steps=360)
    >>> result.bodies["rocker"]["angle"], result.points["B@coupler"]["position"]
"""
from .result import SweepResult
from .run import run_sweep

__all__ = ["SweepResult", "run_sweep"]
