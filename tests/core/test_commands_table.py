"""The README's commands table is the command line's: a row for every command, no row for a
command that does not exist, and only options the command has (a twin kept equal by this
test; docs/architecture.md lists the others)."""
from __future__ import annotations

import re
from pathlib import Path

README = (Path(__file__).parents[2] / "README.md").read_text(encoding="utf-8")
ROW = re.compile(r"^\| `kinematika ([a-z-]+)([^`]*)` \|", re.MULTILINE)


def _commands() -> dict[str, set[str]]:
    import typer.main

    from kinematika.cli import app

    group = typer.main.get_command(app)
    return {name: {opt for p in command.params for opt in (*p.opts, *p.secondary_opts) if opt.startswith("-")}
            for name, command in group.commands.items()}


def test_every_command_has_its_row_with_its_own_options():
    rows = {name: set(re.findall(r"(?<![\w-])(--?[a-z][a-z-]*)", rest)) for name, rest in ROW.findall(README)}
    commands = _commands()
    assert set(rows) == set(commands)
    for name, options in rows.items():
        assert options <= commands[name], (name, sorted(options - commands[name]))
