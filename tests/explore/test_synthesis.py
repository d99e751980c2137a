"""Synthesis recovers a design from its own output (path, function), and its figures are drawn."""
from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from kinematika.api import as_model
from kinematika.cli import app
from kinematika.explore.plots import pareto_front
from kinematika.explore.synthesis import function_targets, synthesize
from kinematika.sweep import run_sweep
from tests.sweep.models import four_bar_closed_form

from .models import FOUR_BAR

KNOWN = {"a": 2.25, "b": 6.1, "c": 4.35}


def coupler_points(angles_deg) -> str:
    """Points of the known design's coupler curve, by loop closure, off the sweep's rows."""
    ex = four_bar_closed_form(np.radians(angles_deg), 5.2, 2.25, 6.1, 4.35, 1.0, 9.5, -21.0, (3.4, -1.15))
    return "x,y\n" + "".join(f"{float(x)!r},{float(y)!r}\n" for x, y in zip(*ex["P"]))


def test_path_synthesis_recovers_the_link_lengths_from_their_coupler_curve():
    targets = coupler_points([60.5, 95.3, 150.2, 210.7, 260.1, 300.9, 340.4])
    result = synthesize(FOUR_BAR, ["a=1.5:3", "b=5:7", "c=3.5:5.5"], "path_error:P=t.csv",
                        population=45, generations=80, seed=2, files={"t.csv": targets})
    best = result.designs[0]
    assert best == pytest.approx(KNOWN, abs=2e-3)
    assert result.errors[0] < 1e-3
    assert len(result.designs) == 3 and result.errors == sorted(result.errors)


def test_function_synthesis_recovers_the_rocker_of_a_known_four_bar():
    model = as_model(FOUR_BAR)
    rotation = run_sweep(model, steps=360).bodies["rocker"]["angle"]
    table = "".join(f"{x},{float(rotation[x])!r}\n" for x in (10, 25, 40, 55, 70, 85))
    result = synthesize(FOUR_BAR, ["a=1.5:3", "c=3.5:5.5"], "structural_error:rocker=f.csv",
                        population=30, generations=60, seed=0, files={"f.csv": table})
    assert result.designs[0] == pytest.approx({"a": 2.25, "c": 4.35}, abs=1e-3)
    assert result.errors[0] < 1e-3


def test_function_targets_are_chebyshev_precision_points():
    rows = [tuple(map(float, line.split(","))) for line in function_targets("x/2 + 1", (0, 90), 3).split()]
    expect_x = [45 - 45 * np.cos(np.pi * (2 * k - 1) / 6) for k in (1, 2, 3)]
    assert [x for x, _ in rows] == pytest.approx(expect_x)
    assert [y for _, y in rows] == pytest.approx([x / 2 + 1 for x in expect_x])


def test_the_pareto_front_keeps_designs_no_other_beats_in_both():
    a = np.array([1.0, 2.0, 3.0, 2.5, 4.0, 1.5])
    b = np.array([5.0, 3.0, 1.0, 3.5, 0.5, 6.0])
    assert sorted(pareto_front(a, b).tolist()) == [0, 1, 2, 4]


def test_synthesize_writes_models_that_solve_and_a_figure(tmp_path):
    (tmp_path / "m.yaml").write_text(FOUR_BAR)
    (tmp_path / "t.csv").write_text(coupler_points([70.2, 130.4, 200.6, 290.8]))
    out = CliRunner().invoke(app, ["synthesize", str(tmp_path / "m.yaml"), "--vary", "a=2:2.5",
                                   "--vary", "c=4:4.7", "--target", str(tmp_path / "t.csv"), "--point", "P",
                                   "--population", "20", "--generations", "25", "--best", "2",
                                   "-o", str(tmp_path / "best"), "--plot", str(tmp_path / "curves.png")])
    assert out.exit_code == 0, out.output
    assert (tmp_path / "curves.png").stat().st_size > 10_000
    solved = CliRunner().invoke(app, ["solve", str(tmp_path / "best" / "best-1.yaml"), "--json"])
    assert solved.exit_code == 0, solved.output
    best = as_model(tmp_path / "best" / "best-1.yaml")
    assert float(best.parameters["a"].value.text) == pytest.approx(2.25, abs=0.02)


def test_study_figures_are_drawn(tmp_path):
    (tmp_path / "m.yaml").write_text(FOUR_BAR)
    study = tmp_path / "s.csv"
    run = CliRunner().invoke(app, ["explore", str(tmp_path / "m.yaml"), "--vary", "a=1:3.5", "--vary", "c=2:6",
                                   "--grid", "8", "--metric", "grashof", "--metric", "transmission",
                                   "--metric", "peak_speed:P", "-o", str(study), "--workers", "1"])
    assert run.exit_code == 0, run.output
    for option, value in (("--map", "a,c,transmission"), ("--map", "a,c,grashof"),
                          ("--pareto", "peak_speed:P,transmission")):
        out = CliRunner().invoke(app, ["plot-study", str(study), option, value, "-o",
                                       str(tmp_path / "f.png")])
        assert out.exit_code == 0, out.output
        assert (tmp_path / "f.png").stat().st_size > 10_000
    bad = CliRunner().invoke(app, ["plot-study", str(study), "--map", "a,c,nothing", "-o", str(tmp_path / "f.png")])
    assert bad.exit_code == 2 and "no column 'nothing'" in bad.output


def test_function_generation_from_an_expression_on_the_command_line(tmp_path):
    """ψ = 0.4 θ over the first 60° of crank travel: the family's rockers turn that way, and the
    best design found meets the five precision points within a degree."""
    (tmp_path / "m.yaml").write_text(FOUR_BAR)
    out = CliRunner().invoke(app, ["synthesize", str(tmp_path / "m.yaml"), "--vary", "a=1.5:3", "--vary",
                                   "c=3.5:5.5", "--target-function", "0.4*x", "--output", "rocker",
                                   "--over", "0:60", "--points", "5", "--population", "16",
                                   "--generations", "15", "--best", "1", "-o", str(tmp_path / "best"),
                                   "--plot", str(tmp_path / "f.png")])
    assert out.exit_code == 0, out.output
    error = float(out.output.split("structural_error:rocker=function.csv = ")[1].split()[0])
    assert error < 1.0
    assert (tmp_path / "best" / "best-1.yaml").exists() and (tmp_path / "f.png").stat().st_size > 10_000
