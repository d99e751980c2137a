"""The typer application and what every command shares: options and error reporting."""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import Any, Callable, NoReturn

import typer

from ..errors import KinematikaError

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Kinematic analysis of mechanisms: velocities, accelerations, instant "
                       "centres, curvature, exactly or numerically.")

ModelArg = typer.Argument(..., help="model file (.yaml, .toml or .json)", show_default=False)
JsonOpt = typer.Option(False, "--json", help="print the contract's JSON")
SymbolicOpt = typer.Option(False, "--symbolic", help="keep every parameter given as a number as a symbol")


@app.callback()
def _group() -> None:
    """Kinematic analysis of mechanisms."""


def fail(err: KinematikaError, as_json: bool) -> NoReturn:
    """Report a user error in one line (or the contract's JSON) and exit with status 2."""
    if as_json:
        print(json.dumps(err.as_json()))
    else:
        print(f"error ({err.kind}): {err}", file=sys.stderr)
    raise typer.Exit(2)


def guarded(as_json: bool, work: Callable[[], Any]) -> Any:
    """Run `work`; user errors become one line, internal ones a short note (no traceback)."""
    try:
        return work()
    except KinematikaError as err:
        fail(err, as_json)
    except typer.Exit:
        raise
    except OSError as err:            # reading is checked where models are read: this is writing
        name = err.filename or ""
        fail(KinematikaError("output", f"cannot write {name}: {err.strerror or err}", str(name)),
             as_json)
    except Exception as err:  # noqa: BLE001 - never show users a traceback
        if os.environ.get("KINEMATIKA_DEBUG"):
            raise
        message = f"internal error ({type(err).__name__}: {err}); rerun with KINEMATIKA_DEBUG=1 " \
                  "and report it"
        if as_json:
            print(json.dumps({"error": {"kind": "internal", "message": message, "where": ""}}))
        else:
            print(f"error: {message}", file=sys.stderr)
        raise typer.Exit(1)


def output_file(path: Path, option: str) -> Path:
    """`path` if a file can be written there; else an `output` error naming the option."""
    parent = path.parent
    if not parent.is_dir():
        raise KinematikaError("output", f"cannot write {path}: there is no folder {parent}", option)
    if path.is_dir():
        raise KinematikaError("output", f"cannot write {path}: it is a folder", option)
    return path


def respond(as_json: bool, compute: Callable[[], dict], show: Callable[[dict], None]) -> None:
    """Compute a command's data (errors reported by `guarded`); print JSON or `show` it."""
    from ..commands import json_text

    data = guarded(as_json, compute)
    if as_json:
        sys.stdout.write(json_text(data))
    else:
        show(data)
