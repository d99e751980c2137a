"""The package's source as the registries' grep tests read it: which lines name a kind
(joints, questions) outside the module that says what the kind means."""
from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "kinematika"


def source_lines(skip: set[str] | Mapping[str, object]) -> Iterator[tuple[str, int, str]]:
    """(path relative to the package, line number, line) of every Python and JavaScript file
    of the package, but those under the top folders in `skip` (where the words mean
    something else)."""
    for p in sorted(SRC.rglob("*")):
        if p.suffix in (".py", ".js") and p.relative_to(SRC).parts[0] not in skip:
            rel = str(p.relative_to(SRC))
            for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
                yield rel, i, line


def names_written(skip, literal: re.Pattern, allowed: Mapping[str, tuple[str, ...]]) -> list[str]:
    """`path:line: text` of every string literal `literal` finds (a kind's name, its group 1)
    in a file that `allowed` does not list for that name."""
    return [f"{rel}:{i}: {line.strip()}" for rel, i, line in source_lines(skip)
            for m in literal.finditer(line) if rel not in allowed.get(m.group(1), ())]
