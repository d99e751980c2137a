"""The `kinematika` command: one module per subcommand, all views of the one engine."""
from __future__ import annotations

from . import centres, draw, explain, solve, sweep  # noqa: F401  (each module registers its command)
from .app import app


def main() -> None:
    app()
