"""What `kinematika simulate` writes: the sweep's shapes with `time` in place of
`coordinate` (row 0 the drawn configuration, as `solve` answers it), the drift, CSV and
Parquet columns, and bad input as one line with exit status 2, the rows computed before a
stop kept in every output."""
from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from kinematika.cli import app as cli
from kinematika.simulate import run_simulation
from kinematika.simulate.run import SimulationStopped

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TRAILER = EXAMPLES / "tractor_trailer_turning.yaml"
RUNNER = CliRunner()

STOPPING = """name: Crank slowing down
parameters: {t: 0, r: 0.1}
points: {O: [0, 0], A: [r, 0]}
bodies: {ground: [O], crank: [O, A]}
joints: [{type: revolute, bodies: [ground, crank], at: O}]
drivers: [{omega: crank, value: "2*sqrt(1 - t)"}]
"""


def run(*args: str):
    result = RUNNER.invoke(cli, [str(a) for a in args])
    return result.exit_code, result.stdout, result.stderr


def test_the_json_is_the_sweeps_with_time_and_row_0_is_the_drawn_instant():
    code, out, _ = run("simulate", TRAILER, "--time", 2, "--steps", 4, "--json")
    assert code == 0
    data = json.loads(out)
    assert list(data) == ["time", "bodies", "points", "drift"]
    assert data["time"] == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert all(len(v) == 5 for b in data["bodies"].values() for v in b.values())
    assert all(len(v) == 5 for p in data["points"].values() for v in p.values())
    assert len(data["drift"]) == 5 and max(data["drift"]) < 1e-8
    solved = json.loads(run("solve", TRAILER, "--json")[1])
    assert set(data["points"]) == set(solved["points"])
    for key, point in solved["points"].items():
        for q in ("position", "velocity", "acceleration"):
            assert data["points"][key][q][0] == pytest.approx(point[q], abs=1e-12), (key, q)
    for name, body in solved["bodies"].items():
        assert data["bodies"][name]["omega"][0] == pytest.approx(body["omega"], abs=1e-12)
        assert data["bodies"][name]["alpha"][0] == pytest.approx(body["alpha"], abs=1e-12)
    # the rear axle keeps its speed along the tractor; the tractor's ω stays v tan δ / wb
    speed = np.linalg.norm(data["points"]["R@tractor"]["velocity"], axis=1)
    assert speed == pytest.approx(np.full(5, 2.0))


def test_csv_and_parquet_have_time_and_drift_first(tmp_path):
    code, out, _ = run("simulate", TRAILER, "--time", 1, "--steps", 2, "--csv", tmp_path / "rows.csv",
                       "-o", tmp_path / "rows.parquet")
    assert code == 0 and "wrote 3 rows" in out
    with open(tmp_path / "rows.csv", encoding="utf-8") as f:
        table = list(csv.reader(f))
    assert table[0][:4] == ["time_s", "drift", "ground.angle", "ground.omega"]
    assert [row[0] for row in table[1:]] == ["0.0", "0.5", "1.0"]
    pq = pytest.importorskip("pyarrow.parquet")
    columns = pq.read_table(tmp_path / "rows.parquet").column_names
    assert columns[:3] == ["ok", "time_s", "drift"] and "T@trailer.position_x" in columns


def test_a_driver_that_cannot_be_evaluated_stops_the_motion_and_keeps_the_rows(tmp_path):
    """ω = 2√(1 − t): at t = 1 its derivative (the crank's α) is infinite, past it the rate
    itself is not real. The rows before t = 1 are kept, in the JSON and in the CSV."""
    model = tmp_path / "crank.yaml"
    model.write_text(STOPPING, encoding="utf-8")
    code, out, _ = run("simulate", model, "--time", 2, "--steps", 20, "--json", "--csv", tmp_path / "rows.csv")
    assert code == 2
    data = json.loads(out)
    assert (data["error"]["kind"], data["error"]["where"]) == ("schema", "drivers[0]")
    assert data["error"]["message"].startswith("at t = 1 s: the rate's derivative in time is not a finite")
    t = np.array(data["partial"]["time"])
    assert t == pytest.approx(np.arange(10) / 10)
    # ω = 2√(1 − t) integrated: θ = (4/3)(1 − (1 − t)^(3/2))
    assert data["partial"]["bodies"]["crank"]["angle"] == pytest.approx(
        np.degrees(4 / 3 * (1 - (1 - t) ** 1.5)), abs=1e-7)
    assert len((tmp_path / "rows.csv").read_text(encoding="utf-8").splitlines()) == 11


def test_too_many_evaluations_stop_a_stiff_motion(monkeypatch, tmp_path):
    """A count, never the clock: a trailer 1 mm long behind a hitch moving at 2 m/s settles in
    a millisecond; followed for a minute, an explicit method needs more solutions than the
    limit allows (lowered here), and the motion stops there, the rows before kept."""
    from kinematika import limits

    monkeypatch.setattr(limits, "SIMULATE_EVALUATIONS", 400)
    tree = {"name": "Short trailer", "parameters": {"L": 0.001},
            "points": {"H": [0, 0], "T": ["-L", 0.0005]},
            "bodies": {"ground": [], "hitch": ["H"], "trailer": ["H", "T"]},
            "joints": [{"type": "prismatic", "bodies": ["ground", "hitch"], "along": [1, 0]},
                       {"type": "revolute", "bodies": ["hitch", "trailer"], "at": "H"},
                       {"type": "wheel", "bodies": ["ground", "trailer"], "at": "T", "along": [1, 0]}],
            "drivers": [{"omega": "hitch", "value": 0}, {"velocity": "H@hitch", "along": [1, 0], "value": 2}]}
    with pytest.raises(SimulationStopped) as stop:
        run_simulation(tree, time=60, steps=60)
    assert stop.value.kind == "assembly" and "more than 400 velocity solutions" in stop.value.message
    assert 1 <= len(stop.value.result) < 61
    model = tmp_path / "short.json"
    model.write_text(json.dumps(tree), encoding="utf-8")
    code, out, err = run("simulate", model, "--time", 60, "--steps", 60, "--csv", tmp_path / "rows.csv")
    assert code == 2
    assert err.strip().splitlines() == [f"error (assembly): simulate: {stop.value.message}"]
    assert f"wrote {len(stop.value.result)} rows" in out


@pytest.mark.parametrize("args, where", [
    (["--time", "-1"], "--time"), (["--time", "0"], "--time"), (["--time", "1", "--method", "Euler"], "--method"),
    ([], "simulate.time")])
def test_bad_options_are_one_line(args, where):
    code, out, err = run("simulate", TRAILER.parent / "four_bar.yaml", *args, "--json")
    assert code == 2
    assert json.loads(out)["error"]["where"] == where


def test_steps_and_time_are_bounded_by_counts():
    with pytest.raises(Exception) as err:
        run_simulation(TRAILER, time=1, steps=0)
    assert (err.value.kind, err.value.where) == ("schema", "simulate.steps")
    with pytest.raises(Exception) as err:
        run_simulation(TRAILER, time=float("inf"))
    assert (err.value.kind, err.value.where) == ("schema", "simulate.time")


def test_time_reaches_only_the_drivers_rates(tmp_path):
    model = tmp_path / "moving.yaml"
    model.write_text(STOPPING.replace("A: [r, 0]", "A: [r, t]"), encoding="utf-8")
    code, out, _ = run("simulate", model, "--time", 1, "--json")
    error = json.loads(out)["error"]
    assert code == 2 and (error["kind"], error["where"]) == ("schema", "points.A[1]")
    assert "only in drivers' rates" in error["message"]


def test_symbols_need_numbers(tmp_path):
    model = tmp_path / "symbolic.yaml"
    model.write_text(STOPPING.replace("r: 0.1", "r: null"), encoding="utf-8")
    code, out, _ = run("simulate", model, "--time", 1, "--json")
    error = json.loads(out)["error"]
    assert code == 2 and error["where"] == "parameters" and "give r a value" in error["message"]
    code, out, _ = run("simulate", model, "--time", 0.5, "--steps", 2, "--set", "r=0.2", "--json")
    assert code == 0 and json.loads(out)["points"]["A@crank"]["position"][0] == [0.2, 0.0]


def test_a_written_acceleration_of_a_constant_rate_is_left_out_and_said(tmp_path):
    model = tmp_path / "crank.yaml"
    model.write_text(STOPPING.replace('value: "2*sqrt(1 - t)"', "value: 2, alpha: 0.5"), encoding="utf-8")
    result = run_simulation(model, time=1, steps=2)
    assert result.bodies["crank"]["alpha"] == pytest.approx([0.0, 0.0, 0.0])
    assert result.bodies["crank"]["angle"] == pytest.approx(np.degrees([0.0, 1.0, 2.0]))
    assert any("drivers[0]: its accel is left out" in note for note in result.notes)


@pytest.mark.parametrize("option", ["--csv", "-o", "--plot", "--animate"])
def test_an_output_that_cannot_be_written_is_said_before_the_motion_is_followed(tmp_path, option):
    name = {"--plot": "x.png", "--animate": "x.gif", "-o": "x.parquet"}.get(option, "x.csv")
    code, out, _ = run("simulate", TRAILER, "--time", 1, option, tmp_path / "missing" / name, "--json")
    error = json.loads(out)["error"]
    assert code == 2 and (error["kind"], error["where"]) == ("output", option)


def test_a_stop_is_said_in_the_readers_language(tmp_path):
    """The errors of a motion in time are catalogue messages: the time written with the
    language's decimal sign, the course's term (punto muerto, punt mort, puntu hil), the place
    the same in every language, and a nested reason (a driver's rate at t = 1) said in the same
    language as the sentence around it."""
    from kinematika.errors import speaking

    with pytest.raises(SimulationStopped) as stop:
        run_simulation(EXAMPLES / "seed_c5_2_1_tricycle.yaml", time=1.0, steps=10)
    dead = {"en": ("dead point", "0.848528"), "es": ("punto muerto", "0,848528"),
            "ca": ("punt mort", "0,848528"), "eu": ("puntu hil", "0,848528")}
    for lang, words in dead.items():
        with speaking(lang):
            error = stop.value.as_json()["error"]
        assert (error["kind"], error["where"]) == ("singular", "simulate")
        assert all(w in error["message"] for w in words), (lang, error["message"])
    model = tmp_path / "crank.yaml"
    model.write_text(STOPPING, encoding="utf-8")
    with pytest.raises(SimulationStopped) as stop:
        run_simulation(model, time=2, steps=20)
    starts = {"en": "at t = 1 s: the rate's derivative in time is not a finite real number",
              "es": "en t = 1 s: la derivada en el tiempo de la velocidad impuesta no es un número real finito",
              "ca": "a t = 1 s: la derivada en el temps de la velocitat imposada no és un nombre real finit",
              "eu": "t = 1 s unean: ezarritako abiaduraren denborarekiko deribatua ez da zenbaki erreal finitu bat"}
    for lang, start in starts.items():
        with speaking(lang):
            assert stop.value.message.startswith(start), (lang, stop.value.message)
            assert stop.value.where == "drivers[0]"
