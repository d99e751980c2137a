"""Write `fast_options.py`, the fast command line's option table, from the typer commands.

    python -m kinematika.cli.generate_options          # rewrite src/kinematika/cli/fast_options.py
    python -m kinematika.cli.generate_options --check  # exit 1 if it is not what it would write

For each command the fast path reads (`COMMANDS`), the table lists the options typer would
pass on to the command's body in `run` (`run.solve_command`…): their parameter, kind (a
flag, text, a path, an integer within its range, a number). Options the body does not take
(`--set`, `--move`, `--assembly`, gathered by the typer command) are left out: given on the
command line, they send it to typer. A command whose options the fast path could not read
as typer does (an environment variable, a callback, a prompt, a required or repeatable
option, another kind of value, a default other than the body's) is an error here, so the
table never disagrees with typer in silence. A test (tests/core/test_fast_paths.py)
regenerates the module and compares.
"""
from __future__ import annotations

import inspect
import sys
from pathlib import Path
from typing import Any, Optional

from ..generated import write_or_check
from . import fast, run

TARGET = Path(__file__).with_name("fast_options.py")
COMMAND = "python -m kinematika.cli.generate_options"
COMMANDS = ("solve", "centres", "sweep", "simulate")          # the commands the fast path reads
KINDS = {bool: fast.FLAG, str: fast.TEXT, Path: fast.PATH, int: fast.INT, float: fast.FLOAT}


def table() -> dict[str, dict[str, tuple]]:
    """Each fast command's options: `{"--steps": ("steps", "int", 1, 10000000), …}`."""
    import typer.main

    from . import _application

    group = typer.main.get_command(_application())
    return {name: _options(name, group.commands[name]) for name in COMMANDS}  # type: ignore[attr-defined]  # typer's app is a click Group (`commands`), typed as a Command


def _options(name: str, command: Any) -> dict[str, tuple]:
    body = inspect.signature(getattr(run, f"{name}_command")).parameters
    out: dict[str, tuple] = {}
    arguments = []
    for param in command.params:
        where = f"`kinematika {name}` {param.opts[0]}"
        if param.envvar or param.callback or param.is_eager or not param.expose_value:
            raise TypeError(f"{where}: the fast path cannot read an option with an environment "
                            "variable or a callback as typer does")
        if not param.opts[0].startswith("-"):
            arguments.append((param.name, param.type_descriptor.annotation))
            continue
        if param.name not in body:
            continue                       # gathered by the typer command: typer reads it
        if param.required or param.prompt or param.multiple or param.nargs != 1 or param.secondary_opts:
            raise TypeError(f"{where}: the fast path reads only plain options given once")
        kind = KINDS.get(param.type_descriptor.annotation)
        if kind is None or (kind == fast.FLAG) != bool(param.is_flag):
            raise TypeError(f"{where}: a kind of value the fast path does not read")
        if body[param.name].default != param.default:
            raise TypeError(f"{where}: typer's default {param.default!r} is not run.{name}_command's "
                            f"{body[param.name].default!r} (the fast path leaves the body's)")
        spec: tuple = (param.name, kind)
        if kind == fast.INT:
            spec += (param.min, param.max)
        elif getattr(param, "min", None) is not None or getattr(param, "max", None) is not None:
            raise TypeError(f"{where}: a range the fast path does not check")
        for opt in param.opts:
            out[opt] = spec
    if arguments != [("model", Path)]:
        raise TypeError(f"`kinematika {name}`: the fast path reads one argument, the model file")
    return out


def source() -> str:
    """The text of `fast_options.py` for the current typer commands."""
    lines = ['"""The fast command line\'s options (`fast`): each command\'s options as typer reads them.',
             "",
             f"GENERATED from the typer commands by `{COMMAND}`: do not edit.",
             "Change the typer command, then run that command (tests/core/test_fast_paths.py",
             "regenerates this module and compares).",
             "",
             "Each option: (the parameter of `run.<command>_command`, its kind[, smallest, largest]).",
             '"""', "", "OPTIONS: dict[str, dict[str, tuple]] = {"]
    for name, options in table().items():
        lines.append(f"    {name!r}: {{")
        lines.extend(f"        {opt!r}: {spec!r}," for opt, spec in options.items())
        lines.append("    },")
    lines.append("}")
    return "\n".join(lines) + "\n"


def main(argv: Optional[list[str]] = None) -> int:
    """Write `fast_options.py` (or, with --check, say whether it is current: status 1 if not)."""
    return write_or_check(TARGET, source(), COMMAND, argv)


if __name__ == "__main__":
    sys.exit(main())
