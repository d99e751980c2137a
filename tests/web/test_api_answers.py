"""The page's JSON API answers exactly what the command line prints, byte for byte, for one
bundled example of each kind (every example in a deep run; the contract's section "The
page's JSON API"); a file of its own, so that
the suite's workers share this long list with the rest of tests/web."""
from __future__ import annotations

import json

import pytest

from tests.conftest import EXAMPLES, KINDS, sampled

from .test_api import post, run_cli

EXAMPLE_FILES = sampled(sorted(EXAMPLES.glob("*.yaml")), KINDS)
SWEEP_STEPS = 24          # the whole motion in few rows: the same rows either way is what counts


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.stem)
@pytest.mark.parametrize("command", ["solve", "sweep", "centres"])
def test_answers_are_the_cli_json_byte_for_byte(client, path, command):
    steps = ["--steps", str(SWEEP_STEPS)] if command == "sweep" else []
    code, printed = run_cli(command, str(path), "--json", *steps)
    answer = post(client, command, model=path.read_text(encoding="utf-8"),
                  **({"steps": SWEEP_STEPS} if steps else {}))
    if code == 0:
        assert answer.status_code == 200
        assert answer.headers["content-type"].startswith("application/json")
        assert answer.content == printed
    else:      # the same error: kind and message (the CLI names the file where the API has none)
        assert code == 2 and answer.status_code == 400
        said, got = json.loads(printed)["error"], answer.json()["error"]
        assert (got["kind"], got["message"]) == (said["kind"], said["message"])
