"""Modules generated from another source of truth: written, or checked to be current.

`model/shape.py` is generated from `model/schema.py`, `cli/fast_options.py` from the
CLI's typer commands (docs/architecture.md lists the twins). Each generator computes the
module's text; `write_or_check` writes it, or with `--check` says whether the file on disk
is that text, so that a test and CI can refuse a stale copy.
"""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional


def write_or_check(target: Path, text: str, command: str, argv: Optional[list[str]] = None) -> int:
    """Write `text` to `target` (or, with --check in `argv`, status 1 if the file differs)."""
    args = sys.argv[1:] if argv is None else argv
    current = target.read_text(encoding="utf-8") if target.exists() else ""
    if "--check" in args:
        if text != current:
            print(f"{target} is out of date: run {command}", file=sys.stderr)
            return 1
        return 0
    if text != current:
        target.write_text(text, encoding="utf-8")
        print(f"wrote {target}")
    return 0
