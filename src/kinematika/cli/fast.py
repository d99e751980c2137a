"""The fast path of the command line: `solve`, `centres`, `sweep` and `simulate` with plain options are
read here, without importing typer (and the pydantic and click it brings), which would
cost more than the work itself.

Only what is certainly valid is taken: a known option given once, a number written plainly,
one model file. Anything else (`--help`, an unknown or repeated option, a value typer would
refuse or convert differently) returns None and the typer application reads the command
line, so errors and help are typer's. The options' table (`fast_options.OPTIONS`) is
generated from the typer commands (`python -m kinematika.cli.generate_options`); a test
regenerates it and compares.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Callable, Optional

FLAG, TEXT, PATH, INT, FLOAT = "flag", "text", "path", "int", "float"
_INT = re.compile(r"[+-]?[0-9]+\Z")
_FLOAT = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?\Z")

Spec = tuple  # (parameter, kind) or (parameter, INT, smallest, largest); None: no bound


def command(name: str) -> Callable[..., None]:
    """The command function the fast path calls for `name` (``solve`` → `run.solve_command`),
    imported only when the fast path takes the command line."""
    from . import run

    return getattr(run, f"{name}_command")


def parse(argv: list[str]) -> Optional[tuple[str, dict[str, Any]]]:
    """(command, keyword arguments) when the fast path can read `argv`, else None."""
    from .fast_options import OPTIONS     # (generated; imported here so its generator imports this module
                                          # even when the table is broken)
    if not argv or argv[0] not in OPTIONS:
        return None
    table = OPTIONS[argv[0]]
    kwargs: dict[str, Any] = {}
    models = []
    tokens = iter(argv[1:])
    for token in tokens:
        if not token.startswith("-") or token == "-":
            models.append(token)
            continue
        name, eq, value = token.partition("=") if token.startswith("--") else (token, "", "")
        spec = table.get(name)
        if spec is None or spec[0] in kwargs:
            return None
        if spec[1] == FLAG:
            if eq:
                return None
            kwargs[spec[0]] = True
            continue
        if not eq:
            following = next(tokens, None)
            if following is None:
                return None
            value = following
        converted = _convert(value, spec)
        if converted is None:
            return None
        kwargs[spec[0]] = converted
    if len(models) != 1 or not models[0]:
        return None
    kwargs["model"] = Path(models[0])
    return argv[0], kwargs


def _convert(value: str, spec: Spec) -> Any:
    """`value` as typer would pass it for an option of `spec`; None when typer might not."""
    kind = spec[1]
    if kind == TEXT:
        return value
    if kind == PATH:
        return Path(value) if value else None
    if kind == INT:
        if not _INT.match(value):
            return None
        number = int(value)
        low, high = spec[2:]
        return None if (low is not None and number < low) or (high is not None and number > high) else number
    return float(value) if _FLOAT.match(value) else None
