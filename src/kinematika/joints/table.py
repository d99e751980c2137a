"""docs/joints.md's table of the kinds, written from the registry: one row per kind in
`KINDS`, with its module, its condition at the velocity level (`JointKind.condition`), the
keys a joint of it takes (`fields`) and its capabilities — so the table cannot say what a
kind does not (as `model/shape.py` is written from the schema).

    python -m kinematika.joints.table          # rewrite the table in docs/joints.md
    python -m kinematika.joints.table --check  # exit 1 if it is not what it would write

The table sits between two marker lines of docs/joints.md; the rest of the page is written
by hand. A test (tests/joints/test_registry.py) regenerates it and compares.
"""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

from ..generated import write_or_check
from . import KINDS, MODULES
from .base import JointKind
from .capabilities import Centre, Side

TARGET = Path(__file__).resolve().parents[3] / "docs" / "joints.md"
COMMAND = "python -m kinematika.joints.table"
BEGIN = f"<!-- the table is written by `{COMMAND}` from the registry: edit the kinds, not it -->"
END = "<!-- end of the written table -->"
HEADER = ("| kind | module | condition (velocity level) | keys | capabilities |\n"
          "| --- | --- | --- | --- | --- |\n")
FLAGS = {                   # yes/no capabilities, in the order the table says them
    "pins": "pins", "ball": "ball", "rigid": "rigid", "slides": "slides", "guides_point": "guides a point",
    "touches": "touches", "rolls": "rolls", "pitch": "pitch circles", "knife_edge": "knife edge",
}
CENTRES = {
    Centre.PIN: "centre at the pin", Centre.CONTACT: "centre at the contact", Centre.INFINITY: "centre at infinity",
    Centre.REST: "centre: at rest", Centre.NORMAL: "centre on a line",
}
LINES = {"normal": "centre on the common normal", "slot": "centre on the slot's normal", "wheel": "centre on the axle"}
NEEDS = {"required": "", "optional": "optional", "required in 3D": "3D", "optional in 3D": "optional, 3D"}


def keys(kind: JointKind) -> str:
    """The keys a joint of the kind takes besides its bodies: `at`, `axis` (3D), …"""
    said = [f"`{key}`" + (f" ({NEEDS[need]})" if NEEDS[need] else "") for key, need in kind.fields.items()]
    return ", ".join(said) or "—"


def capabilities(kind: JointKind) -> str:
    """What the kind says of itself, in words: its yes/no capabilities, its coordinate, its
    chain letters, where it puts the centre, the models it exists in."""
    words = [word for flag, word in FLAGS.items() if getattr(kind, flag)]
    if kind.coordinate is not None:
        words.append(f"coordinate: {kind.coordinate.value}")
    if kind.sweepable:
        words.append("sweepable")
    if kind.chain.pairs:
        words.append(f"chain {kind.chain.value}")
    if kind.centre is Centre.NORMAL and kind.centre_line:
        words.append(LINES[kind.centre_line])
    elif kind.centre is not Centre.NONE:
        words.append(CENTRES[kind.centre])
    if kind.along_in is Side.B:
        words.append("`along` fixed in the second body")
    if kind.velocity_only:
        words.append("on velocities only in " + " and ".join(f"{d}D" for d in kind.velocity_only))
    if tuple(kind.dimensions) != (2, 3):
        words.append(" and ".join(f"{d}D" for d in kind.dimensions) + " only")
    return ", ".join(words)


def table() -> str:
    """The markdown table, one row per registered kind, in the registry's order."""
    rows = [f"| `{name}` | `{MODULES[name]}.py` | {kind.condition} | {keys(kind)} | {capabilities(kind)} |\n"
            for name, kind in KINDS.items()]
    return HEADER + "".join(rows)


def page(current: str) -> str:
    """docs/joints.md with the table between its markers written anew."""
    start, end = current.index(BEGIN) + len(BEGIN), current.index(END)
    return current[:start] + "\n" + table() + current[end:]


def main(argv: Optional[list[str]] = None) -> int:
    """Write the table (or, with --check, say whether it is current: status 1 if not)."""
    return write_or_check(TARGET, page(TARGET.read_text(encoding="utf-8")), COMMAND, argv)


if __name__ == "__main__":
    sys.exit(main())
