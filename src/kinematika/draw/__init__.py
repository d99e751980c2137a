"""Figures of kinematika's results: the mechanism at an instant with its vectors, instant
centres and curvature circles (`draw`), its motion over a sweep (`animate`), sweep plots
(`plot_sweep`), and Jupyter's drawings (`jupyter`).

Every figure reads results (a `Solution`, a sweep's arrays); given a model instead, `draw`
and `animate` have it solved by the sweep layer (`sweep.posing`) first. What a figure shows
is a `Scene` (`scene`); what it draws is a picture of marks (`picture`: the rules of how
bodies, joints, centres, curvature and arrows are drawn), which `paint` paints with
matplotlib and the page (`web/static/js/figure.js`) as SVG. Drawing uses matplotlib
without a display (the Agg canvas): no window ever opens.
"""
from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any, Optional

from .options import DrawOptions

# a name with a character the font lacks (emoji, CJK, a control) is drawn as a box: no warning
warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from font", category=UserWarning)

__all__ = ["DrawOptions", "animate", "draw", "plot_sweep", "svg"]


def draw(source: Any, path: Optional[Path | str] = None, options: Optional[DrawOptions] = None,
         symbolic: Optional[bool] = None, **choices: Any) -> Any:
    """The figure (a matplotlib `Figure`) of a model or `Solution` at its instant; written to
    `path` (.png, .svg, .pdf) when given. `choices` are `DrawOptions` fields."""
    from ..solution import Solution
    from ..sweep.posing import solved as solve
    from .figure import render, save
    from .build import build_scene

    from .lock import MATPLOTLIB

    sol = source if isinstance(source, Solution) else solve(source, symbolic)
    options = options or DrawOptions(**choices)
    with MATPLOTLIB:
        fig = render(build_scene(sol.inst, sol, options), options)
        if path is not None:
            save(fig, path)
    return fig


def svg(source: Any, options: Optional[DrawOptions] = None, symbolic: Optional[bool] = None,
        **choices: Any) -> str:
    """The figure of a model or `Solution` as SVG text (an `<svg>` element with its XML
    prologue), for pages and explanations to embed. Same arguments as `draw`."""
    from .figure import svg_text

    return svg_text(draw(source, None, options, symbolic, **choices))


def plot_sweep(result: Any, path: Optional[Path | str] = None, model: Any = None) -> Any:
    """Absolute angles, ω and α of the bodies, sliders' positions, velocities and
    accelerations (signed, with stroke and time ratio), other points' speed and tangential
    acceleration, against the crank angle; dead points marked (see `draw.plots`)."""
    from .plots import plot_sweep as plot

    return plot(result, path, model)


def animate(source: Any, path: Path | str, **kw: Any) -> Path:
    """A GIF or MP4 of the motion over the model's sweep (see `draw.animation`)."""
    from .animation import animate as run

    return run(source, path, **kw)
