"""`POST /api/simulate` answers exactly what `kinematika simulate --json` prints; a motion
that stops early answers 400 with the error and the rows before it; the figure's data says
the slider moves through time for a model whose joints constrain velocities only."""
from __future__ import annotations

import json
import math

import pytest

from typer.testing import CliRunner

from kinematika.cli import app as cli
from tests.conftest import EXAMPLES

TRAILER = EXAMPLES / "tractor_trailer_turning.yaml"


def test_the_answer_is_the_cli_json_byte_for_byte(client):
    printed = CliRunner().invoke(cli, ["simulate", str(TRAILER), "--time", "3", "--steps", "6", "--json"])
    assert printed.exit_code == 0
    answer = client.post("/api/simulate", json={"model": TRAILER.read_text(encoding="utf-8"), "time": 3, "steps": 6})
    assert answer.status_code == 200 and answer.content == printed.stdout_bytes
    csv = client.post("/api/simulate", json={"model": TRAILER.read_text(encoding="utf-8"), "time": 3, "steps": 6,
                                             "as": "csv"})
    assert csv.status_code == 200 and csv.text.splitlines()[0].startswith("time_s,drift,")
    assert len(csv.text.splitlines()) == 8


def test_a_motion_that_stops_answers_its_error_and_the_rows_before(client):
    model = (EXAMPLES / "seed_c5_2_1_tricycle.yaml").read_text(encoding="utf-8")
    answer = client.post("/api/simulate", json={"model": model, "time": 1.0, "steps": 10})
    assert answer.status_code == 400
    body = answer.json()
    assert body["error"]["kind"] == "singular" and "dead point at t = 0.848528 s" in body["error"]["message"]
    assert body["partial"]["time"] == [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8]


def test_bad_options_are_usage_errors(client):
    model = TRAILER.read_text(encoding="utf-8")
    for body, where in (({"steps": 0}, "steps"), ({"method": "Euler"}, "method"), ({"time": "long"}, "time"),
                        ({"by": 3}, "by")):
        answer = client.post("/api/simulate", json={"model": model, **body})
        assert answer.status_code == 400 and answer.json()["error"]["where"] == where, body


def test_the_slider_moves_through_time_for_a_vehicle(client):
    def slider(name: str) -> dict:
        data = client.post("/api/draw", json={"model": (EXAMPLES / name).read_text(encoding="utf-8"),
                                              "as": "data"}).json()
        return data["input"]

    assert slider("tractor_trailer_turning.yaml") == {"joint": None, "unit": "s", "time": 60.0, "steps": 300}
    assert slider("tractor_trailer.yaml") == {"joint": None, "unit": "s", "time": 3.5, "steps": 200}
    assert slider("seed_c5_1_8_contact_points.yaml")["time"] == pytest.approx(6 * math.pi / 2)   # 6π/w0 at draw_at
    no_section = (EXAMPLES / "tractor_trailer.yaml").read_text(encoding="utf-8").replace("simulate: {time: 3.5}", "")
    data = client.post("/api/draw", json={"model": no_section, "as": "data"}).json()
    assert data["input"] == {"joint": None, "unit": "s", "time": 10.0, "steps": 200}     # DEFAULT_TIME
    assert slider("four_bar.yaml")["unit"] == "deg"
    assert json.loads(json.dumps(slider("coin_rolling.yaml")))["unit"] == "s"


def test_every_example_gives_the_page_its_slider():
    """The page's slider for every bundled example (what `/api/draw` gives the page as its
    `input`, read without drawing): the joint a sweep advances, or the time of its own
    `simulate:` section, as tests/simulate/test_every_example.py says it moves."""
    from kinematika.sweep.posing import prepare
    from kinematika.web.server import _input
    from tests.simulate.test_every_example import MOVES, TIME

    for name, how in MOVES.items():
        given = _input(prepare(EXAMPLES / f"{name}.yaml"))
        assert given is not None, name
        assert (given["unit"] == "s") == (how == TIME), (name, given)
        assert how == TIME or given["joint"], name
