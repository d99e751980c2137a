"""The `kinematika` command: one module per subcommand, all views of the one engine."""
from __future__ import annotations

from . import solve  # noqa: F401  (registers the command)
from .app import app


def main() -> None:
    app()
