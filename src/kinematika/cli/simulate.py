"""`kinematika simulate`: a mechanism's motion followed in time (vehicles on knife edges, discs
rolling on a plane, or any mechanism its drivers move)."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Any, Optional

import typer

from ..limits import SIMULATE_STEPS
from ..text import shown
from .app import AssemblyOpt, JsonOpt, MessagesOpt, ModelArg, MoveOpt, SetOpt, app, how, messages
from .shared import fail, guarded, options_named, output_file, write_stdout, writing


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
             output: Optional[Path] = typer.Option(None, "-o", "--output", help="write the rows to FILE "
                                                   "(json, csv, npz or parquet: --format, else the suffix)"),
             fmt: Optional[str] = typer.Option(None, "--format", help="the format of -o: json, csv, npz "
                                               "(numpy) or parquet (needs pyarrow)"),
             sets: Optional[list[str]] = SetOpt, moves: Optional[list[str]] = MoveOpt,
             assembly: Optional[int] = AssemblyOpt, lang: Optional[str] = MessagesOpt,
             ) -> None:
    """Positions, velocities and accelerations in time: the motion integrated from the drawn
    configuration (drivers as written, or expressions in the parameter t), for mechanisms whose
    joints constrain velocities only (knife edges, discs rolling on a plane) and any other."""
    from .run import _format

    messages(lang, as_json)
    kind = guarded(as_json, lambda: _format(output, fmt))
    if animation is not None:
        guarded(as_json, lambda: _animation_format(animation))
    for path, option in ((csv, "--csv"), (output, "-o"), (plot, "--plot"), (animation, "--animate")):
        if path is not None:                       # before the motion is followed, not after
            guarded(as_json, lambda path=path, option=option: output_file(path, option))
    simulator, result, stopped = guarded(as_json, lambda: _run(model, time, steps, method, as_json,
                                                               lambda: how(sets, moves, assembly)))
    written = []
    if csv is not None:
        guarded(as_json, lambda: _write(result, csv, "csv", "--csv"))
        written.append(f"wrote {len(result)} rows to {csv}")
    if output is not None:
        guarded(as_json, lambda: _write(result, output, kind, "-o"))
        written.append(f"wrote {len(result)} rows to {output} ({kind})")
    if plot is not None and len(result) > 1:
        guarded(as_json, lambda: _plot(result, plot, simulator.model))
        written.append(f"drew {plot}")
    if animation is not None and len(result) > 1:
        guarded(as_json, lambda: _animate(result, animation, simulator.model, not as_json))
        written.append(f"drew {animation}")
    if as_json:
        if stopped is not None:
            write_stdout(b'{"error":' + _json(stopped.as_json()["error"]) + b',"partial":')
            for piece in result.json_chunks():
                write_stdout(piece)
            write_stdout(b"}\n")
            sys.exit(2)
        for piece in result.json_chunks():
            write_stdout(piece)
        write_stdout(b"\n")
        return
    from ..simulate.summary import summary_lines

    lines = summary_lines(result)
    if written:
        lines += [""] + written
    print("\n".join(shown(line) for line in lines))
    if stopped is not None:
        fail(stopped, False)


def _run(model: Path, time: Any, steps: Any, method: Any, as_json: bool, choices: Any) -> tuple[Any, Any, Any]:
    """The simulator and its rows, and the error that stopped the motion early (or None)."""
    from ..commands import simulate_run
    from ..simulate.run import SimulationStopped

    given = {"simulate.time": ("--time", time), "simulate.steps": ("--steps", steps)}
    with options_named(given):
        try:
            simulator, result = simulate_run(model, time, steps, method, progress=not as_json, how=choices())
        except SimulationStopped as err:
            return _Stopped(err), err.result, err
    return simulator, result, None


class _Stopped:
    """What the views need of a simulator whose motion stopped: its model (the result's)."""

    def __init__(self, err: Any) -> None:
        self.model = err.model


def _json(data: Any) -> bytes:
    from ..report.json_text import json_bytes

    return json_bytes(data)


def _write(result: Any, path: Path, kind: str, option: str) -> None:
    from .run import _write as write

    write(result, path, kind, option)


def _plot(result: Any, path: Path, model: Any) -> None:
    from ..draw.plots import plot_sweep

    path = output_file(path, "--plot")
    with writing(path, "--plot"):
        plot_sweep(result, path, model)


def _animation_format(path: Path) -> None:
    from ..draw.animation import FORMATS
    from ..errors import KinematikaError

    if path.suffix.lower().lstrip(".") not in FORMATS:
        raise KinematikaError("usage", "animation-file-type", "--animate", name=repr(path.name))


def _animate(result: Any, path: Path, model: Any, progress: bool) -> None:
    from ..draw.animation import animate_rows

    path = output_file(path, "--animate")
    with writing(path, "--animate"):
        animate_rows(model, result, path, progress=progress)
