"""`kinematika sweep`: the motion over a range of a driven joint's coordinate."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import typer

from .app import JsonOpt, ModelArg, app, guarded, output_file


@app.command()
def sweep(model: Path = ModelArg,
          joint: Optional[str] = typer.Option(None, "--joint", help="the driven joint to sweep"),
          by: Optional[float] = typer.Option(None, "--by", help="how far: degrees (revolute) or "
                                             "length (prismatic); negative goes back"),
          steps: Optional[int] = typer.Option(None, "--steps", min=1, max=10_000_000,
                                              help="number of equal increments"),
          as_json: bool = JsonOpt,
          csv: Optional[Path] = typer.Option(None, "--csv", help="write one row per position to FILE"),
          skip_bad: bool = typer.Option(False, "--skip-bad", help="leave positions that cannot be "
                                        "assembled (or are singular) empty instead of stopping"),
          plot: Optional[Path] = typer.Option(None, "--plot", help="draw the sweep's curves to FILE"),
          ) -> None:
    """Positions, velocities and accelerations over a range of a driven joint (default: the
    model's `sweep:` section, else a full turn in 360 steps)."""
    from ..commands import json_text, sweep_run

    sweeper, result = guarded(as_json, lambda: sweep_run(model, joint, by, steps, skip_bad,
                                                         progress=not as_json))
    if csv is not None:
        guarded(as_json, lambda: _write_csv(result, csv))
    if plot is not None:
        guarded(as_json, lambda: _plot(result, plot))
    if as_json:
        sys.stdout.write(json_text(result.to_json()))      # one write: dump() writes in pieces
        return
    from ..sweep.summary import summary_lines

    lines = summary_lines(result, guarded(False, sweeper.linkage), sweeper.groups)
    if csv is not None:
        lines.append(f"\nwrote {len(result)} rows to {csv}")
    if plot is not None:
        lines.append(f"drew {plot}")
    print("\n".join(lines))


def _write_csv(result, path: Path) -> None:
    result.to_csv(output_file(path, "--csv"))


def _plot(result, path: Path) -> None:
    from ..draw.plots import plot_sweep

    plot_sweep(result, output_file(path, "--plot"))
