"""The page's server in-process (Starlette's TestClient), shared by the API tests."""
from __future__ import annotations

import warnings

import pytest


@pytest.fixture(scope="session")
def client():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # starlette's note about its HTTP client
        from starlette.testclient import TestClient

        from kinematika.web.server import create_app

        with TestClient(create_app()) as c:
            yield c
