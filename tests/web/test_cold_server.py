"""A page opened on a server that has computed nothing yet sends its first requests together
(solve, draw, sweep, sketch, then its explanation and assemblies): each is answered as it
would be alone. Before `web/warm.py`, two threads importing sympy at once made some of them
internal errors ("cannot import name 'sstr' from partially initialized module
'sympy.printing'"; six runs out of six) — the page then waited for a motion that never came.
The server must be cold, so it runs in a fresh process."""
from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from tests.conftest import HANG_SECONDS

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

ROOT = Path(__file__).resolve().parents[2]

CLIENT = textwrap.dedent("""
    import json, sys, threading, urllib.error, urllib.request
    from pathlib import Path
    from kinematika.web.server import Start
    from tests.web.page_server import PageServer

    examples = Path("examples")
    server = PageServer(Start(text=(examples / "four_bar.yaml").read_text(), fmt="yaml", name="four_bar.yaml"))
    answers = []

    def post(endpoint, body):
        request = urllib.request.Request(server.url + "api/" + endpoint, data=json.dumps(body).encode(),
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request) as r:
                answers.append([endpoint, r.status, ""])
        except urllib.error.HTTPError as err:
            answers.append([endpoint, err.code, json.loads(err.read())["error"]["kind"]])

    def model(name):
        return {"model": (examples / name).read_text(), "format": "yaml", "lang": "en"}

    first = (("solve", {}), ("draw", {"centres": True}), ("sweep", {"skip_bad": True}), ("sketch", {}))
    asked = [(endpoint, {**model("four_bar.yaml"), **extra})
             for endpoint, extra in first + (("explain", {}), ("assemblies", {}))]
    asked += [(endpoint, {**model("seed_c5_2_2_articulated.yaml"), **extra}) for endpoint, extra in first]
    asked.append(("simulate", model("seed_c5_2_2_articulated.yaml")))
    threads = [threading.Thread(target=post, args=a) for a in asked]
    [t.start() for t in threads]
    [t.join() for t in threads]
    server.stop()
    print(json.dumps(sorted(answers)))
""")


def test_a_cold_servers_first_requests_at_once_are_each_answered():
    done = subprocess.run([sys.executable, "-c", CLIENT], cwd=ROOT, capture_output=True, text=True,
                          timeout=10 * HANG_SECONDS)
    assert done.returncode == 0, done.stderr[-2000:]
    answers = json.loads(done.stdout.strip().splitlines()[-1])
    # the vehicle's position depends on its path: a sweep refuses it (400, the contract's error), simulate follows it
    expected = sorted([[endpoint, 200, ""] for endpoint in ("solve", "draw", "sweep", "sketch", "explain", "assemblies")]
                      + [[endpoint, 200, ""] for endpoint in ("solve", "draw", "sketch")]
                      + [["simulate", 200, ""], ["sweep", 400, "schema"]])
    assert answers == expected
