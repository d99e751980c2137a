"""The typer application and what every command shares: options and error reporting."""
from __future__ import annotations

from typing import Any, Optional

import typer

from ..errors import KinematikaError

from .shared import fail, guarded, output_file, print_json, respond  # noqa: F401  (the commands' helpers)

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Kinematic analysis of mechanisms: velocities, accelerations, instant "
                       "centres, curvature, exactly or numerically.")

ModelArg = typer.Argument(..., help="model file (.yaml, .toml or .json)", show_default=False)
JsonOpt = typer.Option(False, "--json", help="print the contract's JSON")
SymbolicOpt = typer.Option(False, "--symbolic", help="keep every parameter given as a number as a symbol")
SetOpt = typer.Option(None, "--set", metavar="NAME=VALUE",
                      help="give a parameter a value (repeatable): re-poses a model built by "
                           "construction; a symbolic model then solves with numbers")
MoveOpt = typer.Option(None, "--move", metavar="JOINT=AMOUNT",
                       help="advance a driven joint from the drawn configuration (degrees or "
                            "length, repeatable), as a sweep reaches it")
AssemblyOpt = typer.Option(None, "--assembly", min=1, metavar="N",
                           help="analyse assembly N (see `kinematika assemblies`)")
OutputOpt = typer.Option(None, "-o", "--output", help="write the rows to FILE "
                         "(json, csv, npz or parquet: --format, else the suffix)")
FormatOpt = typer.Option(None, "--format", help="the format of -o: json, csv, npz "
                         "(numpy) or parquet (needs pyarrow)")
MessagesOpt = typer.Option(None, "--lang", metavar="LANG",
                           help="the language of errors and warnings: en, es, ca or eu (default: the "
                                "locale's, from LC_ALL, LC_MESSAGES or LANG; else en)")


def messages(lang: Optional[str], as_json: bool = False) -> None:
    """`--lang`'s value checked: a language kinematika speaks, else the `usage` error. The
    language itself is chosen when the command line is read (`cli.main`), so that every
    message, the options' own included, is said in it."""
    if lang is not None:
        from ..languages import known

        guarded(as_json, lambda: known(lang, "--lang", "usage"))


def how(sets: Optional[list[str]] = None, moves: Optional[list[str]] = None,
        assembly: Optional[int] = None) -> Any:
    """The `--set`, `--move` and `--assembly` choices as `commands.How` (a malformed
    NAME=VALUE is a `usage` error, reported as every error is)."""
    from ..commands import How

    return How(set=pairs(sets, "--set"), move=pairs(moves, "--move"), assembly=assembly)


def pairs(items: Optional[list[str]], option: str) -> dict[str, str]:
    """`["r=0.1", "w=10"]` as a mapping; a malformed item is a `usage` error."""
    out: dict[str, str] = {}
    for item in items or []:
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise KinematikaError("usage", "option-name-value", option, option=option, got=repr(item))
        out[name.strip()] = value.strip()
    return out


@app.callback()
def _group() -> None:
    """Kinematic analysis of mechanisms."""
