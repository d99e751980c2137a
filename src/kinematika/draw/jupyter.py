"""Jupyter's drawings: a `Mechanism` (or `Model`) and a `Solution` show themselves as SVG.

A model that cannot be solved yet (a driver missing while it is being built) is still
drawn — its geometry alone, with the reason in a note; one that cannot even be evaluated
gives None, and Jupyter falls back to the text form.
"""
from __future__ import annotations

from typing import Any, Optional

from ..errors import KinematikaError
from .options import DrawOptions

WIDTH = 6.5     # inches: a notebook cell


def solution_svg(sol: Any, options: Optional[DrawOptions] = None) -> str:
    """The drawing of a solved instant as SVG text."""
    from . import svg

    return svg(sol, options or DrawOptions(width=WIDTH))


def model_svg(model: Any, options: Optional[DrawOptions] = None) -> Optional[str]:
    """The drawing of a model: solved when it can be, else its geometry with the reason."""
    from ..engine.instant import instantiate
    from ..sweep.posing import solved as solve
    from .figure import render, svg_text
    from .build import build_scene

    options = options or DrawOptions(width=WIDTH)
    try:
        return solution_svg(solve(model), options)
    except KinematikaError as err:
        reason = f"not solved: {err}"
    try:
        scene = build_scene(instantiate(model), None, options)
    except KinematikaError:
        return None
    scene.notes.append(reason)
    return svg_text(render(scene, options))
