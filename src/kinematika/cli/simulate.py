"""`kinematika simulate`: a mechanism's motion followed in time (vehicles on knife edges, discs
rolling on a plane, or any mechanism its drivers move)."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from ..limits import SIMULATE_STEPS
from .app import AssemblyOpt, FormatOpt, JsonOpt, MessagesOpt, ModelArg, MoveOpt, OutputOpt, SetOpt, app, how, messages
from .run import simulate_command


@app.command()
def simulate(model: Path = ModelArg,
             time: Optional[float] = typer.Option(None, "--time", help="how long to follow the motion, in "
                                                  "seconds (default: the model's simulate section)"),
             steps: Optional[int] = typer.Option(None, "--steps", min=1, max=SIMULATE_STEPS,
                                                 help="number of equal steps of time (rows: steps + 1)"),
             method: Optional[str] = typer.Option(None, "--method", help="scipy's ODE solver: DOP853 "
                                                  "(default), RK45, LSODA, Radau or BDF"),
             as_json: bool = JsonOpt,
             csv: Optional[Path] = typer.Option(None, "--csv", help="write one row per instant to FILE"),
             plot: Optional[Path] = typer.Option(None, "--plot", help="draw the motion's curves to FILE"),
             animation: Optional[Path] = typer.Option(None, "--animate", help="draw the motion to FILE "
                                                      "(.gif, or .mp4 with ffmpeg; planar models)"),
             output: Optional[Path] = OutputOpt,
             fmt: Optional[str] = FormatOpt,
             sets: Optional[list[str]] = SetOpt, moves: Optional[list[str]] = MoveOpt,
             assembly: Optional[int] = AssemblyOpt, lang: Optional[str] = MessagesOpt,
             ) -> None:
    """Positions, velocities and accelerations in time: the motion integrated from the drawn
    configuration (drivers as written, or expressions in the parameter t), for mechanisms whose
    joints constrain velocities only (knife edges, discs rolling on a plane) and any other."""
    messages(lang, as_json)
    simulate_command(model, time, steps, method, as_json, csv, plot, animation, output, fmt,
                     lambda: how(sets, moves, assembly))
