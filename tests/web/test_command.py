"""`kinematika app MODEL`: the command starts the server with the model it read, on
127.0.0.1 unless told otherwise (and then it warns), and refuses a model it cannot read."""
from __future__ import annotations

import re
import subprocess
import sys
import time

import httpx
import pytest

from tests.conftest import EXAMPLES, HANG_SECONDS, ROOT

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

WAIT = HANG_SECONDS     # seconds an answer may take before the test calls it a hang


def start(*args: str) -> tuple[subprocess.Popen, str]:
    """The command running and its page's URL (once it answers)."""
    proc = subprocess.Popen([sys.executable, "-m", "kinematika", "app", *args, "--no-browser",
                             "--port", "0"], cwd=ROOT, text=True, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    line = proc.stdout.readline()
    m = re.search(r"http://[\d.]+:\d+/", line)
    if not m:
        proc.kill()
        pytest.fail(f"no URL in {line!r}: {proc.stderr.read()}")
    deadline = time.monotonic() + HANG_SECONDS      # a hang detector: a busy machine starts slowly
    while True:
        try:
            httpx.get(m.group(0) + "api/start", timeout=WAIT)
            break
        except httpx.HTTPError:
            if time.monotonic() > deadline:
                proc.kill()
                raise
            time.sleep(0.05)
    return proc, m.group(0)


def stop(proc: subprocess.Popen) -> str:
    proc.terminate()
    _, err = proc.communicate(timeout=WAIT)
    return err


def test_the_command_serves_the_model_it_was_given():
    path = EXAMPLES / "four_bar.yaml"
    proc, url = start(str(path))
    try:
        assert url.startswith("http://127.0.0.1:")
        opening = httpx.get(url + "api/start", timeout=WAIT).json()
        assert opening["model"] == path.read_text() and opening["name"] == "four_bar.yaml"
        solved = httpx.post(url + "api/solve", json={"model": opening["model"]}, timeout=WAIT).json()
        assert solved["points"]["A@crank"]["velocity"] == [-10.0, 0.0]     # ω × O2A = 10 × (0, 1)
        assert "data-testid=\"figure\"" in httpx.get(url, timeout=WAIT).text
        assert httpx.get(url, headers={"host": "elsewhere.example"}, timeout=WAIT).status_code == 400
    finally:
        stop(proc)


def test_another_address_is_served_with_a_warning():
    proc, url = start("--host", "127.0.0.2")             # loopback, but not the default
    try:
        assert url.startswith("http://127.0.0.2:")
        assert httpx.get(url + "api/start", timeout=WAIT).status_code == 200
    finally:
        err = stop(proc)
    assert "warning: serving on 127.0.0.2" in err


def test_a_model_that_cannot_be_read_is_refused():
    """Refused before any server starts: in-process (the command's own code, as a child
    process runs it; the two tests above run the child process)."""
    from typer.testing import CliRunner

    from kinematika.cli import app as cli

    done = CliRunner().invoke(cli, ["app", "no_such_model.yaml", "--no-browser"])
    assert done.exit_code == 2
    assert done.stderr.strip() == "error (syntax): no_such_model.yaml: no such file"
