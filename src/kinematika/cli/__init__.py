"""The `kinematika` command: one module per subcommand, all views of the one engine."""
from __future__ import annotations

import json
import sys

import typer

from . import centres, draw, explain, page, solve, sweep  # noqa: F401  (each module registers its command)
from .app import app


def main() -> None:
    """Run the command line; a mistake in its options is one line (or the JSON error with
    `--json`) and exit status 2, like every other user error."""
    try:
        code = app(standalone_mode=False)
    except typer.Abort:
        print("aborted", file=sys.stderr)
        sys.exit(1)
    except Exception as err:  # click's UsageError / BadParameter, vendored or not
        if not (hasattr(err, "exit_code") and hasattr(err, "format_message")):
            raise
        _usage_error(err)
    sys.exit(code if isinstance(code, int) else 0)


def _usage_error(err) -> None:
    """Report a command-line usage error in the contract's shape and exit with its status."""
    param = getattr(err, "param", None)
    where = getattr(err, "param_hint", None) or (param.opts[0] if getattr(param, "opts", None) else "")
    where = where if isinstance(where, str) else " / ".join(where)
    message = " ".join(err.format_message().split())
    if not message:                   # `kinematika` alone: the help has been shown
        sys.exit(err.exit_code)
    if "--json" in sys.argv[1:]:
        print(json.dumps({"error": {"kind": "usage", "message": message, "where": where.strip("'")}}))
    else:
        ctx = getattr(err, "ctx", None)
        command = getattr(ctx, "command_path", None) or "kinematika"
        print(f"error (usage): {message} (see {command} --help)", file=sys.stderr)
    sys.exit(err.exit_code if err.exit_code else 2)
