"""`kinematika draw` and `kinematika animate` from the command line: files and clean errors."""
from __future__ import annotations

import json

from typer.testing import CliRunner

from kinematika.cli import app

from .mechanisms import four_bar_tree, slider_crank_tree

runner = CliRunner()


def model_file(tmp_path, tree) -> str:
    path = tmp_path / "model.json"
    path.write_text(json.dumps(tree))
    return str(path)


def test_draw_writes_the_file(tmp_path):
    out = tmp_path / "f.svg"
    result = runner.invoke(app, ["draw", model_file(tmp_path, four_bar_tree()), "-o", str(out),
                                 "--centres", "--accelerations", "--no-labels"])
    assert result.exit_code == 0, result.output
    assert out.read_text().startswith("<?xml") and 'id="centre:ground-coupler"' in out.read_text()


def test_draw_errors_are_one_clean_message(tmp_path):
    src = model_file(tmp_path, four_bar_tree())
    cases = [(["-o", str(tmp_path / "f.bmp")], ".png, .svg, .pdf"),
             (["-o", str(tmp_path / "f.png"), "--set", "zz=1"], "unknown parameter 'zz'"),
             (["-o", str(tmp_path / "f.png"), "--set", "w2"], "NAME=VALUE"),
             (["-o", str(tmp_path / "f.png"), "--points", "Q"], "unknown point 'Q'"),
             (["-o", str(tmp_path / "f.png"), "--view", "left"], "iso, top, front, side")]
    for args, message in cases:
        result = runner.invoke(app, ["draw", src, *args])
        assert result.exit_code == 2, (args, result.output)
        assert message in result.output and "Traceback" not in result.output, args


def test_draw_a_broken_model_fails_cleanly(tmp_path):
    tree = four_bar_tree()
    tree["joints"][1]["at"] = "P"              # P is not on the crank
    result = runner.invoke(app, ["draw", model_file(tmp_path, tree), "-o", str(tmp_path / "f.png")])
    assert result.exit_code == 2 and "error (" in result.output
    assert not (tmp_path / "f.png").exists()


def test_animate_writes_a_gif(tmp_path):
    out = tmp_path / "m.gif"
    result = runner.invoke(app, ["animate", model_file(tmp_path, slider_crank_tree()), "-o",
                                 str(out), "--by", "60", "--steps", "6", "--frames", "4"])
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:3] == b"GIF"


def test_animate_refuses_other_formats(tmp_path):
    result = runner.invoke(app, ["animate", model_file(tmp_path, slider_crank_tree()), "-o",
                                 str(tmp_path / "m.avi")])
    assert result.exit_code == 2 and ".gif, .mp4" in result.output
