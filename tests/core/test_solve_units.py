"""`kinematika solve` prints its three tables with units (issue 35), the model's: positions
in its length unit L, velocities in L/s, accelerations in L/s², ω in rad/s, α in rad/s²;
L is the model's `exercise.length` when it states one, else m. Both command lines (the fast
path and typer's) print them.

The slider-crank by hand (as in tests/web/test_build.py): crank 50 at 30°, rod 150, the
slider's line 20 below O, 10 rad/s: v_B = −0.3862 m/s, a_B = −4.984 m/s², ω_rod =
−3.026 rad/s — in millimetres −386.2 mm/s and −4984 mm/s² (ω does not change)."""
from __future__ import annotations

import re

import pytest
from typer.testing import CliRunner

from kinematika.cli import app
from kinematika.cli.run import solve_command
from kinematika.web.templates import template

MM = """\
exercise:
  length: mm
"""


def printed(tmp_path, text: str, fast: bool, capsys) -> str:
    path = tmp_path / "model.yaml"
    path.write_text(text)
    if fast:                                    # the fast path's body (cli/fast.py calls it)
        solve_command(path)
        return capsys.readouterr().out
    out = CliRunner().invoke(app, ["solve", str(path), "--set", "w=10"])
    assert out.exit_code == 0, out.output
    return out.stdout


def cells(text: str) -> list[list[str]]:
    return [[c.strip() for c in line.strip("│┃ ").split("│" if "│" in line else "┃")]
            for line in text.splitlines() if line.startswith(("│", "┃"))]


@pytest.mark.parametrize("fast", [True, False])
def test_the_three_tables_have_units(tmp_path, capsys, fast):
    rows = cells(printed(tmp_path, template("slider_crank"), fast, capsys))
    assert ["body", "ω (rad/s)", "α (rad/s²)"] in rows
    assert ["point", "position (m)", "velocity (m/s)", "acceleration (m/s²)"] in rows
    answers = {r[0]: r[1] for r in rows if len(r) == 2}
    assert re.fullmatch(r"\(-0\.3861\d*, 0\) m/s", answers["velocity B"])
    assert re.fullmatch(r"\(-4\.983\d*, 0\) m/s²", answers["acceleration B"])
    assert re.fullmatch(r"-3\.026\d* rad/s", answers["omega rod"])


def test_the_models_length_unit(tmp_path, capsys):
    text = template("slider_crank")
    for name, value in (("r", "0.05"), ("l", "0.15"), ("e", "0.02")):          # the same, in mm
        text = re.sub(rf"(?m)^  {name}: {re.escape(value)}", f"  {name}: {float(value) * 1000:g}", text)
    rows = cells(printed(tmp_path, text + MM, True, capsys))
    assert ["point", "position (mm)", "velocity (mm/s)", "acceleration (mm/s²)"] in rows
    answers = {r[0]: r[1] for r in rows if len(r) == 2}
    assert re.fullmatch(r"\(-386\.1\d*, 0\) mm/s", answers["velocity B"])
    assert re.fullmatch(r"\(-4983\.\d*, 0\) mm/s²", answers["acceleration B"])
    assert re.fullmatch(r"-3\.026\d* rad/s", answers["omega rod"])


def test_a_compound_answer_has_a_unit_for_each_field(tmp_path, capsys):
    """The curvature of A's path (a circle of radius r = 0.05 about O): radius and centre
    in metres."""
    text = template("slider_crank").replace("  - {omega: rod}", "  - {omega: rod}\n  - {curvature: A}")
    answers = {r[0]: r[1] for r in cells(printed(tmp_path, text, True, capsys)) if len(r) == 2}
    assert re.fullmatch(r"radius: 0\.05 m\s+center: \(0, 0\) m", answers["curvature A"])
