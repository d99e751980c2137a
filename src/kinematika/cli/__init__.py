"""The `kinematika` command: one module per subcommand, all views of the one engine.

`solve`, `centres`, `sweep` and `simulate` with plain options take a fast path (`fast`) that imports
only what they use; everything else goes through the typer application (`app`).
"""
from __future__ import annotations

import os
import sys
import types
from typing import Any


def main() -> None:
    """Run the command line; a mistake in its options is one line (or the JSON error with
    `--json`) and exit status 2, like every other user error. A reader that stops reading
    (`kinematika sweep ... | head`) ends the command quietly, as `cat` ends (status 141,
    128 + SIGPIPE), never with a traceback."""
    try:
        _main()
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)     # the rest of the output goes nowhere
        os.dup2(devnull, sys.stdout.fileno())
        os._exit(141)


def _main() -> None:
    """`main` itself: the fast path for plain `solve`, `centres`, `sweep` and `simulate`, else typer."""
    for stream in (sys.stdout, sys.stderr):      # a terminal that cannot show a character
        if hasattr(stream, "reconfigure"):        # gets an escape, never an encoding error
            stream.reconfigure(errors="backslashreplace")
    import warnings

    from ..errors import KinematikaWarning, speak
    from ..languages import from_command_line

    speak(from_command_line(sys.argv[1:], os.environ))    # errors and warnings: --lang, else the locale
    if not os.environ.get("KINEMATIKA_DEBUG"):   # the output is the answer or one error line
        warnings.simplefilter("ignore")
    warnings.simplefilter("default", KinematikaWarning)     # ... and a line per likely mistake
    warnings.showwarning = _warning_line
    from . import fast

    call = fast.parse(sys.argv[1:])
    if call is not None:
        import gc

        from .run import flush_and_leave

        # a short-lived process: the cycle collector runs rarely (every 100 000 allocations,
        # not 700), since a model of 10 000 bodies makes it scan hundreds of thousands of
        # objects again and again (a quarter of the work); memory is given back at exit
        gc.set_threshold(100_000, 50, 50)

        name, kwargs = call
        run_command = fast.command(name)
        from .. import commands  # noqa: F401  (the engine and numpy, which every fast command uses)

        # the modules imported by now live until the process ends: frozen out of the
        # collector's scans (and its count restarted), so that a collection looks only at the
        # objects of the work (a 1000-body instant then needs none; one scan of numpy's and
        # the engine's objects cost 40 ms)
        gc.freeze()
        try:
            run_command(**kwargs)
        except SystemExit as done:
            flush_and_leave(_status(done.code))
        flush_and_leave(0)
    _typer_main()


def _warning_line(message: Any, category: type, filename: str, lineno: int, file: Any = None,
                  line: Any = None) -> None:
    """A warning on standard error as one line: `warning: points.A.angle: ...` (in the
    language of messages)."""
    from ..errors import Said

    print(Said("warning-line", text=str(message)), file=sys.stderr)


def _status(code: Any) -> int:
    if code is None or isinstance(code, int):
        return code or 0
    print(code, file=sys.stderr)
    return 1


def _application() -> Any:
    """The typer application, with every command registered (imports typer and the commands)."""
    from . import assemblies, cam, centres, draw, exercise, explain, explore, page, simulate, solve, sweep  # noqa: F401  (each registers)
    from .app import app

    return app


class _Package(types.ModuleType):
    """`kinematika.cli.app` is the typer application (as `from kinematika.cli import app`
    has always given), loaded on first use; the import system's binding of the submodule
    `cli/app.py` to the same name is ignored, so the order of imports does not matter."""

    @property
    def app(self) -> Any:
        return _application()

    @app.setter
    def app(self, value: Any) -> None:
        pass


sys.modules[__name__].__class__ = _Package


def _typer_main() -> None:
    import typer

    app = _application()
    try:
        code = app(standalone_mode=False)
    except typer.Abort:
        from ..errors import Said

        print(Said("aborted"), file=sys.stderr)
        sys.exit(1)
    except Exception as err:  # click's UsageError / BadParameter, vendored or not
        if not (hasattr(err, "exit_code") and hasattr(err, "format_message")):
            raise
        _usage_error(err)
    sys.exit(code if isinstance(code, int) else 0)


def _usage_error(err) -> None:
    """Report a command-line usage error in the contract's shape and exit with its status."""
    from ..errors import Said
    from ..limits import MESSAGE_CHARS
    from ..text import shown
    from .shared import print_json

    opts = getattr(getattr(err, "param", None), "opts", None)
    where = getattr(err, "param_hint", None) or (opts[0] if opts else "")
    where = shown(where if isinstance(where, str) else " / ".join(where), 60)
    text = " ".join(err.format_message().split())
    if not text:                      # `kinematika` alone: the help has been shown
        sys.exit(err.exit_code)
    message = shown(_click_said(err, text, where.strip("'")), MESSAGE_CHARS)
    if "--json" in sys.argv[1:]:
        print_json({"error": {"kind": "usage", "message": message, "where": where.strip("'")}})
    else:
        ctx = getattr(err, "ctx", None)
        command = getattr(ctx, "command_path", None) or "kinematika"
        print(Said("usage-line", text=message, command=command), file=sys.stderr)
    sys.exit(err.exit_code if err.exit_code else 2)


def _click_said(err: Any, text: str, where: str) -> Any:
    """click's complaint about a command line, said in the language of messages: by its kind
    (an unknown option, a missing argument, a value of the wrong type, …) where the
    catalogue says it, else in click's own (English) words."""
    from ..errors import Names, Said

    code = type(err).__name__
    args: dict[str, Any] = {"name": where}
    if code == "NoSuchOption":
        found = sorted(getattr(err, "possibilities", None) or [])
        args.update(name=err.option_name, suggestions=Names(found, joined="or"), count=len(found))
    elif code == "UsageError" and text.startswith("Got unexpected extra argument"):
        code = "ExtraArgument"
    elif code == "UsageError" and text.startswith("No such command"):
        code, args["name"] = "NoSuchCommand", text.partition("'")[2].rpartition("'")[0]
    return Said("click", code=code, text=text, **args)
