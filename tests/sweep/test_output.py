"""The contract's sweep outputs: JSON and CSV shapes, rows, units, directions; the CLI."""
from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from kinematika.cli import app
from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper

from .models import four_bar_tree, rocker_driven_tree, slider_crank_tree

EXAMPLES = Path(__file__).parents[2] / "examples"


def test_json_has_one_entry_per_row_for_every_body_and_material_point():
    tree = four_bar_tree()
    data = run_sweep(tree, by=360, steps=8).to_json()
    assert data["coordinate"] == pytest.approx(list(np.linspace(0, 360, 9)))
    assert set(data["bodies"]) == {"ground", "crank", "coupler", "rocker"}
    assert set(data["points"]) == {"O2@ground", "O4@ground", "O2@crank", "A@crank", "A@coupler",
                                   "B@coupler", "P@coupler", "B@rocker", "O4@rocker"}
    for values in data["bodies"].values():
        assert {k: len(v) for k, v in values.items()} == {"angle": 9, "omega": 9, "alpha": 9}
    for values in data["points"].values():
        for q in ("position", "velocity", "acceleration"):
            assert len(values[q]) == 9 and all(len(row) == 2 for row in values[q])
    assert data["bodies"]["crank"]["angle"][-1] == 360.0          # continuous: not 0
    assert data["bodies"]["crank"]["omega"] == [10.0] * 9
    json.dumps(data)


def test_negative_by_turns_back_whatever_the_driver_sign():
    tree = four_bar_tree(w=-10.0)
    forward = run_sweep(tree, by=90, steps=3)
    assert forward.bodies["crank"]["angle"] == pytest.approx([0, 30, 60, 90])
    assert forward.bodies["crank"]["omega"] == pytest.approx([-10] * 4)
    back = run_sweep(tree, by=-90, steps=3)
    assert back.coordinate == pytest.approx([0, -30, -60, -90])
    assert back.bodies["crank"]["angle"] == pytest.approx([0, -30, -60, -90])
    # the crank pin goes clockwise from (0, 1): at −90° it is at (1, 0)
    assert back.points["A@crank"]["position"][-1] == pytest.approx([1.0, 0.0], abs=1e-12)


def test_prismatic_sweep_is_in_length(tmp_path):
    tree = slider_crank_tree(1.0, 3.0, 0.0, crank_deg=90, w=0.0)
    tree["drivers"] = [{"joint": "j4", "rate": 0.5}]
    tree["sweep"] = {"joint": "j4", "by": 0.4, "steps": 4}
    result = run_sweep(tree)
    assert result.unit == "length"
    assert result.points["B@slider"]["position"][:, 0] == pytest.approx(np.sqrt(8) + np.linspace(0, 0.4, 5))
    path = tmp_path / "out.csv"
    result.to_csv(path)
    rows = list(csv.reader(path.open()))
    assert rows[0][0] == "coordinate_length" and len(rows) == 6


def test_csv_has_a_header_and_one_row_per_position(tmp_path):
    path = tmp_path / "sweep.csv"
    run_sweep(four_bar_tree(), by=360, steps=4).to_csv(path)
    rows = list(csv.reader(path.open()))
    header = rows[0]
    assert header[:4] == ["coordinate_deg", "ground.angle", "ground.omega", "ground.alpha"]
    assert "P@coupler.acceleration_y" in header
    assert len(rows) == 6 and all(len(r) == len(header) for r in rows)
    assert float(rows[-1][header.index("crank.angle")]) == 360.0


def _model_file(tmp_path, tree):
    path = tmp_path / "model.yaml"
    path.write_text(yaml.safe_dump(tree))
    return str(path)


def test_cli_json_csv_and_summary(tmp_path):
    runner = CliRunner()
    tree = four_bar_tree()
    tree["sweep"] = {"joint": "j1", "by": 360, "steps": 12}
    model = _model_file(tmp_path, tree)
    out = runner.invoke(app, ["sweep", model, "--json"])
    assert out.exit_code == 0
    assert len(json.loads(out.stdout)["coordinate"]) == 13
    out = runner.invoke(app, ["sweep", model, "--steps", "4", "--by", "-180", "--json"])
    assert json.loads(out.stdout)["coordinate"] == [0.0, -45.0, -90.0, -135.0, -180.0]
    target = tmp_path / "rows.csv"
    out = runner.invoke(app, ["sweep", model, "--csv", str(target)])
    assert out.exit_code == 0 and len(target.read_text().splitlines()) == 14
    assert out.stdout.endswith(f"\n\nwrote 13 rows to {target}\n")      # a blank line, not a shown '\\n'
    assert "Grashof crank-rocker" in out.stdout
    assert "transmission angle" in out.stdout and "limit position (extended)" in out.stdout


def test_cli_errors_are_one_line_with_status_2(tmp_path):
    runner = CliRunner()
    # driven from its rocker, the crank-rocker 4, 1, 4, 3 is at a dead point at 90° (a 3-4-5
    # triangle O2-O4-B with crank and coupler in line): the row at -30 lands on it
    model = _model_file(tmp_path, rocker_driven_tree())
    out = runner.invoke(app, ["sweep", model, "--by", "-30", "--steps", "3"])
    assert out.exit_code == 2
    assert out.stderr.strip().startswith("error (singular): sweep: the configuration at increment 3 "
                                         "(j4 = -30 deg) is singular")
    out = runner.invoke(app, ["sweep", model, "--by", "-30", "--steps", "3", "--json"])
    assert json.loads(out.stdout)["error"]["kind"] == "singular"
    out = runner.invoke(app, ["sweep", model, "--joint", "j2", "--json"])
    assert json.loads(out.stdout)["error"] == {
        "kind": "usage", "message": "joint 'j2' is not driven; a sweep advances a driven joint: j4",
        "where": "--joint"}
    out = runner.invoke(app, ["sweep", model, "--by", "-30", "--steps", "3", "--skip-bad", "--json"])
    assert out.exit_code == 0 and json.loads(out.stdout)["bodies"]["crank"]["omega"][3] is None


def test_cli_plot_to_a_format_matplotlib_cannot_write_is_a_clean_error(tmp_path):
    model = _model_file(tmp_path, four_bar_tree())
    out = CliRunner().invoke(app, ["sweep", model, "--steps", "4", "--plot", str(tmp_path / "curves.txt")])
    assert out.exit_code == 2
    assert out.stderr.strip() == f"error (usage): {tmp_path / 'curves.txt'}: cannot plot to 'curves.txt': give a .png, .svg or .pdf file"
    assert not (tmp_path / "curves.txt").exists()


# the fast writers: the same document, without a Python float per number -------------------------
def _bad_rows_result():
    """The triple rocker moved as `move` moves it (not through its limit positions): rows
    beyond them are bad."""
    return Sweeper(four_bar_tree(crank=2.5, coupler=3.0, rocker=3.0, side=1.0)).run(
        steps=36, skip_bad=True, through=False)


def _limits_result():
    return run_sweep(four_bar_tree(crank=2.5, coupler=3.0, rocker=3.0, side=1.0), steps=36)


@pytest.mark.parametrize("make", [lambda: run_sweep(four_bar_tree(), steps=24),
                                  lambda: run_sweep(EXAMPLES / "rssr_spatial_four_bar.yaml", steps=6),
                                  _bad_rows_result, _limits_result],
                         ids=["four-bar", "3d", "bad-rows", "limits"])
def test_the_json_pieces_are_the_json_document(make):
    result = make()
    assert json.loads(b"".join(result.json_chunks())) == result.to_json()


def test_columnar_files_hold_the_csv_columns(tmp_path):
    result = _bad_rows_result()
    path = tmp_path / "rows.npz"
    result.to_npz(path)
    stored = np.load(path)
    assert list(stored["ok"]) == list(result.ok)
    for header, values in result.columns():
        np.testing.assert_array_equal(stored[header], values)
    pq = pytest.importorskip("pyarrow.parquet")
    path = tmp_path / "rows.parquet"
    result.to_parquet(path)
    table = pq.read_table(path)
    assert table.column_names == ["ok"] + [h for h, _ in result.columns()]
    for header, values in result.columns():
        column = table.column(header).to_numpy(zero_copy_only=False)
        np.testing.assert_array_equal(column, values)       # null read back as NaN


def test_cli_writes_rows_in_the_format_asked(tmp_path):
    model = _model_file(tmp_path, four_bar_tree())
    runner = CliRunner()
    out = runner.invoke(app, ["sweep", model, "--steps", "4", "-o", str(tmp_path / "a.npz")])
    assert out.exit_code == 0 and "wrote 5 rows" in out.stdout
    assert np.load(tmp_path / "a.npz")["crank.angle"][-1] == 360.0
    out = runner.invoke(app, ["sweep", model, "--steps", "4", "--format", "json", "-o",
                              str(tmp_path / "a.txt")])
    assert out.exit_code == 0
    assert json.loads((tmp_path / "a.txt").read_text())["coordinate"][-1] == 360.0
    out = runner.invoke(app, ["sweep", model, "--steps", "4", "-o", str(tmp_path / "a.xlsx")])
    assert out.exit_code == 2 and out.stderr.startswith("error (usage): -o: 'xlsx' is not a sweep format")
    out = runner.invoke(app, ["sweep", model, "--format", "npz", "--json"])
    assert json.loads(out.stdout)["error"]["where"] == "--format"


def _clean_by_definition(values, scale):
    """12 significant digits, element by element: round(x·10^d)/10^d with d = 11 − ⌊log₁₀|x|⌋."""
    out = []
    for x in values:
        if x != x or abs(x) == float("inf"):
            out.append(float("nan"))
        elif abs(x) <= 1e-12 * scale:
            out.append(0.0)
        else:
            d = 11 - int(np.floor(np.log10(abs(x))))
            f = np.power(10.0, float(d))
            out.append(float(np.rint(x * f) / f) + 0.0)
    return np.array(out)


def test_cleaning_a_column_is_rounding_each_number():
    from kinematika.sweep.result import clean

    rng = np.random.default_rng(7)
    x = rng.standard_normal(3000) * 10.0 ** rng.uniform(-15, 15, 3000)
    x[::17], x[::19], x[::23], x[::29] = 0.0, np.nan, np.inf, 10.0 ** rng.integers(-9, 9, len(x[::29]))
    for scale in (1e6, 1.0, 0.0):
        np.testing.assert_array_equal(clean(x, scale), _clean_by_definition(x, scale))


def test_the_streamed_json_is_the_bytes_of_the_json_document():
    from kinematika.report.json_text import json_bytes

    result = run_sweep(four_bar_tree(), steps=24)
    assert b"".join(result.json_chunks()) == json_bytes(result.to_json())
