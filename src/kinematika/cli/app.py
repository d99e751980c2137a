"""The typer application and what every command shares: options and error reporting."""
from __future__ import annotations

import typer

from .shared import fail, guarded, output_file, print_json, respond  # noqa: F401  (the commands' helpers)

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Kinematic analysis of mechanisms: velocities, accelerations, instant "
                       "centres, curvature, exactly or numerically.")

ModelArg = typer.Argument(..., help="model file (.yaml, .toml or .json)", show_default=False)
JsonOpt = typer.Option(False, "--json", help="print the contract's JSON")
SymbolicOpt = typer.Option(False, "--symbolic", help="keep every parameter given as a number as a symbol")


@app.callback()
def _group() -> None:
    """Kinematic analysis of mechanisms."""
