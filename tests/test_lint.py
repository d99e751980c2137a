"""The code's own checks, run by the test command: ruff (style and likely bugs) on the
package and the tests, mypy (types) on the modules pyproject.toml lists, and import-linter
(the layers, pyproject.toml's contract)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.early(0)      # mypy's run over the package, minutes of one worker: handed out before every other file (tests/conftest.py)

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(args, cwd=ROOT, capture_output=True, text=True, timeout=600)


def test_mypy_finds_nothing_in_the_typed_modules():
    """First in the file, and the file first in the run: mypy is the longest single test."""
    done = _run(sys.executable, "-m", "mypy")
    assert done.returncode == 0, done.stdout + done.stderr


def test_ruff_finds_nothing():
    done = _run(str(BIN / "ruff"), "check", "src", "tests", "benchmarks", "scripts", "docs")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_layers_hold():
    """import-linter's contract in pyproject.toml: each layer imports only the layers below it
    (cli, web, commands, api, the views, sweep, ..., the engine, the model, the joints, ...)."""
    done = _run(str(BIN / "lint-imports"))
    assert done.returncode == 0, done.stdout + done.stderr
