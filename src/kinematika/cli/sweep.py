"""`kinematika sweep`: the motion over a range of a driven joint's coordinate."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from .app import AssemblyOpt, FormatOpt, JsonOpt, MessagesOpt, ModelArg, MoveOpt, OutputOpt, SetOpt, app, how, messages
from .run import sweep_command


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
          output: Optional[Path] = OutputOpt,
          fmt: Optional[str] = FormatOpt,
          sets: Optional[list[str]] = SetOpt, moves: Optional[list[str]] = MoveOpt,
          assembly: Optional[int] = AssemblyOpt, lang: Optional[str] = MessagesOpt,
          ) -> None:
    """Positions, velocities and accelerations over a range of a driven joint (default: the
    model's `sweep:` section, else a full turn in 360 steps)."""
    messages(lang, as_json)
    sweep_command(model, joint, by, steps, as_json, csv, skip_bad, plot, output, fmt,
                  lambda: how(sets, moves, assembly))
