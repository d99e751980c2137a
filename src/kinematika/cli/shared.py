"""What every command shares, without the command-line framework: error reporting, output
files and JSON printing. The fast path (`cli/fast.py`) and the typer commands both use it,
so a command that needs none of typer's parsing never imports it."""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, Iterator, NoReturn

from ..errors import KinematikaError, Said
from ..errors import reason as os_reason
from ..limits import MESSAGE_CHARS
from ..report.json_text import json_bytes
from ..text import clip_middle, shown


def fail(err: KinematikaError, as_json: bool) -> NoReturn:
    """Report a user error in one line (or the contract's JSON) and exit with status 2.
    An error whose place is a command-line option (`--lang`, `--set w`) is a `usage` error,
    whichever part of the program found it: one kind of mistake, one kind of error."""
    if err.where.startswith("-") and err.kind not in ("usage", "output"):
        err = KinematikaError("usage", err.said, err.where)
    if as_json:
        print_json(err.as_json())
    else:
        print(Said("error-line", kind=err.kind, text=str(err)), file=sys.stderr)
    sys.exit(2)


def guarded(as_json: bool, work: Callable[[], Any]) -> Any:
    """Run `work`; user errors become one line, internal ones a short note (no traceback)."""
    try:
        return work()
    except KinematikaError as err:
        fail(err, as_json)
    except OSError as err:            # reading is checked where models are read: this is writing
        fail(_write_error(err.filename or Said("the-output-file"), err), as_json)
    except MemoryError:
        fail(KinematikaError("limit", "out-of-memory"), as_json)
    except Exception as err:
        if os.environ.get("KINEMATIKA_DEBUG"):
            raise
        detail = shown(f"{type(err).__name__}: {err}", MESSAGE_CHARS - 80)
        message = str(Said("internal-error", detail=detail))
        if as_json:
            print_json({"error": {"kind": "internal", "message": message, "where": ""}})
        else:
            print(Said("internal-line", text=message), file=sys.stderr)
        sys.exit(1)


PATH_CHARS = 90       # a path in an error is cut in the middle to this, so the reason shows


def cannot_write(path: Any, reason: Any, option: str = "") -> KinematikaError:
    """An `output` error: the file (a long path cut in the middle, its name kept), why it
    cannot be written (a message), and the option that named it."""
    return KinematikaError("output", "cannot-write", option, path=clip_middle(shown(path), PATH_CHARS), reason=reason)


def _write_error(path: Any, err: OSError, option: str = "") -> KinematikaError:
    return cannot_write(path, os_reason(err), option)


@contextmanager
def writing(path: Path, option: str) -> Iterator[None]:
    """Writing `path` (given by `option`): a failure (a full disk, no permission) is an
    `output` error naming the file."""
    try:
        yield
    except OSError as err:
        raise _write_error(path, err, option) from None


@contextmanager
def options_named(given: dict[str, tuple[str, Any]]) -> Iterator[None]:
    """Errors found in a value that came from the command line name its option: `given`
    maps a model place (``sweep.joint``) to the option that set it and its value."""
    try:
        yield
    except KinematikaError as err:
        option, value = given.get(err.where, (None, None))
        if option is None or value is None:
            raise
        raise KinematikaError("usage", err.said, option) from None


def sweep_options(joint: Any, by: Any, steps: Any) -> dict:
    """The places in a model that a sweep's options override, with the options."""
    return {"sweep.joint": ("--joint", joint), "sweep.by": ("--by", by), "sweep.steps": ("--steps", steps)}


def output_file(path: Path, option: str) -> Path:
    """`path` if a file can be written there; else an `output` error naming the option."""
    parent = path.parent
    try:
        if not parent.is_dir():
            raise cannot_write(path, Said("no-folder", folder=clip_middle(shown(parent), PATH_CHARS // 2)), option)
        if path.is_dir():
            raise cannot_write(path, Said("it-is-a-folder"), option)
    except OSError as err:                  # a name too long, a folder that cannot be read
        raise _write_error(path, err, option) from None
    return path


def respond(as_json: bool, compute: Callable[[], dict], show: Callable[[dict], None]) -> None:
    """Compute a command's data (errors reported by `guarded`); print JSON or `show` it."""
    data = guarded(as_json, compute)
    if as_json:
        print_json(data)
    else:
        show(data)


def print_json(data: Any) -> None:
    """`data` as one line of JSON on standard output (orjson: numpy arrays written directly)."""
    write_stdout(json_bytes(data) + b"\n")


def write_stdout(data: bytes) -> None:
    """Bytes to standard output, after whatever text was printed before them."""
    sys.stdout.flush()
    buffer = getattr(sys.stdout, "buffer", None)
    if buffer is None:                   # a text-only stream (some test runners)
        sys.stdout.write(data.decode())
    else:
        buffer.write(data)
