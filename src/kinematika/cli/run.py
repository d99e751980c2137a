"""What `solve`, `centres`, `sweep` and `simulate` print once their options are read (the data from
`kinematika.commands`), without the command-line framework: the typer commands and the
fast path (`cli/fast.py`) call these."""
from __future__ import annotations

import functools
import sys
from pathlib import Path
from typing import Any, Optional

from ..errors import KinematikaError
from ..text import shown
from .shared import fail, guarded, options_named, output_file, respond, sweep_options, write_stdout, writing

SWEEP_FORMATS = ("json", "csv", "npz", "parquet")


def solve_command(model: Path, as_json: bool = False, symbolic: bool = False, how: Any = None) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers
    (the tables in the model's units)."""
    from ..commands import AS_GIVEN, solve_data

    if as_json:
        respond(True, lambda: solve_data(model, symbolic or None, _how(how) or AS_GIVEN), print)
        return
    length = {}

    def compute() -> dict:
        from ..report.units import length_of

        prepared = (_how(how) or AS_GIVEN).model(model)
        length["unit"] = length_of(prepared)
        return solve_data(prepared, symbolic or None, AS_GIVEN)

    def show(data: dict) -> None:
        from ..report.tables import print_solution

        print_solution(data, length=length["unit"])

    respond(False, compute, show)


def centres_command(model: Path, as_json: bool = False, symbolic: bool = False, how: Any = None) -> None:
    """All instant centres (planar), marking those found from joints and by Aronhold–Kennedy."""
    from ..commands import AS_GIVEN, centres_data

    def show(data: dict) -> None:
        from ..report.centres_table import print_centres     # the table (and rich) only when shown

        print_centres(data)

    respond(as_json, lambda: centres_data(model, symbolic or None, _how(how) or AS_GIVEN), show)


def _how(how: Any) -> Any:
    """`how` as `commands.How`: given, or built lazily by the typer commands (a callable, so
    that a malformed --set is reported like every other error)."""
    return how() if callable(how) else how


def sweep_command(model: Path, joint: Optional[str] = None, by: Optional[float] = None,
                  steps: Optional[int] = None, as_json: bool = False, csv: Optional[Path] = None,
                  skip_bad: bool = False, plot: Optional[Path] = None,
                  output: Optional[Path] = None, fmt: Optional[str] = None, how: Any = None) -> None:
    """Positions, velocities and accelerations over a range of a driven joint."""
    from ..commands import AS_GIVEN, sweep_run

    kind = guarded(as_json, lambda: _format(output, fmt))
    def run():
        with options_named(sweep_options(joint, by, steps)):
            try:
                return sweep_run(model, joint, by, steps, skip_bad, progress=not as_json,
                                 how=_how(how) or AS_GIVEN)
            except KinematikaError as err:
                if getattr(err, "partial", None) is not None:
                    _kept(err, csv, output, kind, plot, as_json)
                raise

    sweeper, result = guarded(as_json, run)
    if csv is not None:
        guarded(as_json, lambda: _write(result, csv, "csv", "--csv"))
    if output is not None:
        guarded(as_json, lambda: _write(result, output, kind))
    if plot is not None:
        guarded(as_json, lambda: _plot(result, plot, sweeper.model))
    if as_json:
        for piece in result.json_chunks():
            write_stdout(piece)
        write_stdout(b"\n")
        return
    from ..sweep.summary import summary_lines

    lines = summary_lines(result, guarded(False, sweeper.linkage), sweeper.groups)
    if csv is not None or output is not None:
        lines.append("")                     # a blank line (names are shown escaped, never a raw \n)
    if csv is not None:
        lines.append(f"wrote {len(result)} rows to {csv}")
    if output is not None:
        lines.append(f"wrote {len(result)} rows to {output} ({kind})")
    if plot is not None:
        lines.append(f"drew {plot}")
    print("\n".join(shown(line) for line in lines))


def _kept(err: KinematikaError, csv: Optional[Path], output: Optional[Path], kind: Optional[str],
          plot: Optional[Path], as_json: bool) -> None:
    """A motion that could not be followed further: the rows computed before are written
    where the rows were asked for (`--csv`, `-o`, `--plot`), and with `--json` printed beside
    the error (`{"error": ..., "partial": <the sweep's JSON>}`); the error follows."""
    partial = err.partial                  # type: ignore[attr-defined]  # set by `sweep.limit_positions.with_rows`
    if csv is not None:
        guarded(as_json, lambda: _write(partial, csv, "csv", "--csv"))
    if output is not None and kind is not None:     # a format whenever -o is given (_format)
        guarded(as_json, lambda: _write(partial, output, kind))
    if plot is not None and len(partial):
        guarded(as_json, lambda: _plot(partial, plot, None))
    if as_json:
        import orjson

        write_stdout(b'{"error":' + orjson.dumps(err.as_json()["error"]) + b',"partial":')
        for piece in partial.json_chunks():
            write_stdout(piece)
        write_stdout(b"}\n")
        sys.exit(2)


def _format(output: Optional[Path], fmt: Optional[str]) -> Optional[str]:
    """The format of `-o FILE`: `--format`, else the file's suffix."""
    if fmt is not None and output is None:
        raise KinematikaError("usage", "format-needs-output", "--format", format=fmt)
    if output is None:
        return None
    kind = fmt or output.suffix.lower().lstrip(".")
    if kind not in SWEEP_FORMATS:
        raise KinematikaError("usage", "sweep-format", "--format" if fmt else "-o", got=repr(kind or output.name),
                              formats="|".join(SWEEP_FORMATS))
    return kind


def _write(result, path: Path, kind: str, option: str = "-o") -> None:
    path = output_file(path, option)
    with writing(path, option):
        if kind == "json":
            with open(path, "wb") as f:
                f.writelines(result.json_chunks())
                f.write(b"\n")
        else:
            {"csv": result.to_csv, "npz": result.to_npz, "parquet": result.to_parquet}[kind](path)


def _plot(result, path: Path, model) -> None:
    from ..draw.plots import plot_sweep

    path = output_file(path, "--plot")
    with writing(path, "--plot"):
        plot_sweep(result, path, model)


def simulate_command(model: Path, time: Optional[float] = None, steps: Optional[int] = None,
                     method: Optional[str] = None, as_json: bool = False, csv: Optional[Path] = None,
                     plot: Optional[Path] = None, animation: Optional[Path] = None,
                     output: Optional[Path] = None, fmt: Optional[str] = None, how: Any = None) -> None:
    """Positions, velocities and accelerations in time: the motion integrated from the drawn
    configuration (drivers as written, or expressions in the parameter t), for mechanisms whose
    joints constrain velocities only (knife edges, discs rolling on a plane) and any other."""
    kind = guarded(as_json, lambda: _format(output, fmt))
    if animation is not None:
        guarded(as_json, lambda: _animation_format(animation))
    for path, option in ((csv, "--csv"), (output, "-o"), (plot, "--plot"), (animation, "--animate")):
        if path is not None:                       # before the motion is followed, not after
            guarded(as_json, functools.partial(output_file, path, option))
    simulator, result, stopped = guarded(as_json, lambda: _simulated(model, time, steps, method, as_json, how))
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
            write_stdout(b'{"error":' + _error_json(stopped.as_json()["error"]) + b',"partial":')
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


def _simulated(model: Path, time: Any, steps: Any, method: Any, as_json: bool, how: Any) -> tuple[Any, Any, Any]:
    """The simulator and its rows, and the error that stopped the motion early (or None)."""
    from ..commands import AS_GIVEN, simulate_run
    from ..simulate.run import SimulationStopped

    given = {"simulate.time": ("--time", time), "simulate.steps": ("--steps", steps)}
    with options_named(given):
        try:
            simulator, result = simulate_run(model, time, steps, method, progress=not as_json,
                                             how=_how(how) or AS_GIVEN)
        except SimulationStopped as err:
            return _Stopped(err), err.result, err
    return simulator, result, None


class _Stopped:
    """What the views need of a simulator whose motion stopped: its model (the result's)."""

    def __init__(self, err: Any) -> None:
        self.model = err.model


def _error_json(data: Any) -> bytes:
    from ..report.json_text import json_bytes

    return json_bytes(data)


def _animation_format(path: Path) -> None:
    from ..draw.animation import FORMATS

    if path.suffix.lower().lstrip(".") not in FORMATS:
        raise KinematikaError("usage", "animation-file-type", "--animate", name=repr(path.name))


def _animate(result: Any, path: Path, model: Any, progress: bool) -> None:
    from ..draw.animation import animate_rows

    path = output_file(path, "--animate")
    with writing(path, "--animate"):
        animate_rows(model, result, path, progress=progress)


def flush_and_leave(code: int = 0) -> None:
    """Exit at once once the output is out: nothing is gained by freeing every object first."""
    import os

    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
