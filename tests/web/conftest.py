"""Shared fixtures of the web tests: the page's server in-process (Starlette's TestClient)
for the API tests; one page server on a port and one Chromium for the whole session of a
test process, shared by every browser test module (two servers in one process would wait
for each other's worker threads when stopped, and one browser is cheaper)."""
from __future__ import annotations

import os
import shutil
import warnings
from pathlib import Path

import pytest

from kinematika.web.server import Start
from tests.conftest import EXAMPLES

from .page_server import PageServer


@pytest.fixture(scope="session")
def client():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # starlette's note about its HTTP client
        from starlette.testclient import TestClient

        from kinematika.web.server import create_app

        with TestClient(create_app()) as c:
            yield c


CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"]


def _chromium_or_skip() -> None:
    if Path(CHROMIUM).exists() or shutil.which("chromium"):
        return
    if os.environ.get("CI"):
        pytest.fail("Chromium is missing in CI: the test command runs scripts/browser.sh to install it")
    pytest.skip("Chromium is not installed (bash scripts/browser.sh, or apt-get install chromium)")


@pytest.fixture(scope="session")
def browser():
    _chromium_or_skip()
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM if Path(CHROMIUM).exists()
                              else shutil.which("chromium"), args=FLAGS)
        yield b
        b.close()


@pytest.fixture(scope="session")
def server():
    four_bar = EXAMPLES / "four_bar.yaml"
    s = PageServer(Start(text=four_bar.read_text(), fmt="yaml", name=four_bar.name))
    yield s
    s.stop()
