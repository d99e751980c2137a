"""Careless or hostile input: never a wrong model, a crash or a traceback; always the error
that names the place. Each case here once slipped through (found by fuzzing the CLI)."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
import yaml

from kinematika import KinematikaError, Mechanism, run_sweep, solve

from fuzz.contract import Run, run_cli
from fuzz.forks import run_forked

from .models import four_bar, four_bar_closed_form

EXAMPLES = Path(__file__).parents[2] / "examples"


def error_of(source) -> KinematikaError:
    with pytest.raises(KinematikaError) as info:
        solve(source)
    return info.value


def cli(*args: str, fresh: bool = False) -> Run:
    """`kinematika ARGS` in a process of its own: a fork of this one (`fuzz.forks`, the
    modules already imported), or with `fresh` a new `python -m kinematika`."""
    return run_cli(list(args)) if fresh else run_forked(list(args))


# files ------------------------------------------------------------------------------------
@pytest.mark.parametrize("name,text", [
    ("dup.yaml", "points: {O: [0, 0], A: [1, 0], A: [0, 2]}\n"),
    ("dup.json", '{"points": {"O": [0, 0]}, "points": {"A": [1, 0]}}'),
])
def test_a_repeated_key_is_refused_not_silently_overwritten(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    err = error_of(path)
    assert err.kind == "syntax" and err.where == str(path)
    assert "duplicate key" in err.message


@pytest.mark.parametrize("name,text,problem", [
    ("deep.yaml", "points: " + "[" * 5000 + "]" * 5000, "nested too deeply"),
    ("deep.json", "[" * 100000 + "]" * 100000, "nested too deeply"),
    ("long.json", '{"points": {"A": [' + "9" * 5000 + ", 0]}}", "unreadable JSON"),
    ("empty.yaml", "# only a comment\n\n", "the file is empty"),
    ("empty.json", "  \n", "the file is empty"),
    ("model.txt", "points: {}", "unknown file type '.txt'"),
])
def test_unreadable_files_are_syntax_errors(tmp_path, name, text, problem):
    path = tmp_path / name
    path.write_text(text)
    err = error_of(path)
    assert (err.kind, err.where) == ("syntax", str(path))
    assert problem in err.message


def test_json_with_a_byte_order_mark_is_read(tmp_path):
    path = tmp_path / "four_bar.json"
    path.write_text("\ufeff" + json.dumps(four_bar()), encoding="utf-8")
    w3, _, _, _ = four_bar_closed_form()
    assert float(solve(path).omega("coupler")) == pytest.approx(w3)


# vectors of the wrong size ----------------------------------------------------------------
def _robot_arm() -> dict:
    return yaml.safe_load((EXAMPLES / "robot_arm_3d.yaml").read_text())


def test_a_planar_axis_in_a_3d_model_is_refused():
    tree = _robot_arm()
    joint = next(j for j in tree["joints"] if "axis" in j)
    joint["axis"] = joint["axis"][:2]
    err = error_of(tree)
    assert err.kind == "schema" and err.where.endswith(".axis")
    assert err.message == "a 3D model needs 3 components, got 2"


def test_a_planar_point_in_a_3d_model_is_refused():
    tree = _robot_arm()
    name = next(iter(tree["points"]))
    tree["points"][name] = tree["points"][name][:2]
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", f"points.{name}")
    assert err.message == "a 3D model needs 3 coordinates, got 2"


def test_a_third_component_in_a_planar_direction_is_refused():
    tree = four_bar()
    tree["joints"][3] = {"type": "slot", "bodies": ["rocker", "ground"], "at": "O4",
                         "along": [1, 0, 5]}
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "joints[3] (j4).along")
    assert err.message == "a planar model needs 2 components, got 3"


def test_a_planar_revolute_has_no_axis():
    tree = four_bar()
    tree["joints"][1]["axis"] = [0, 0, 1]
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "joints[1] (j2)")
    assert "has no `axis` in a planar model" in err.message


# sizes of numbers ---------------------------------------------------------------------------
def test_a_large_rate_is_not_rounded_away_by_a_larger_acceleration(tmp_path):
    # ω = 1e12 rad/s: accelerations ~1e24 must not make ω or the positions look like round-off
    path = tmp_path / "fast.json"
    path.write_text(json.dumps(four_bar(parameters={"w2": 1e12},
                                        drivers=[{"omega": "crank", "value": "w2", "alpha": 1e14}])))
    out = cli("solve", str(path), "--json", fresh=True)
    data = json.loads(out.stdout)
    w3, _, _, _ = four_bar_closed_form(w2=1e12)
    assert data["bodies"]["crank"]["omega"] == pytest.approx(1e12)
    assert data["bodies"]["coupler"]["omega"] == pytest.approx(w3)
    assert data["points"]["A@crank"]["position"] == [0.0, 1.0]
    assert data["points"]["A@crank"]["velocity"] == pytest.approx([-1e12, 0.0], abs=1e-3)


def test_values_that_overflow_floats_are_an_error_not_nan():
    err = error_of(four_bar(parameters={"w2": 1.7e308}))
    assert (err.kind, err.where) == ("schema", "drivers[0]")
    assert "out of range" in err.message


# names and places ----------------------------------------------------------------------------
@pytest.mark.parametrize("driver,where,message", [
    ({"omega": 5, "value": 1}, "drivers[0].omega", "unexpected value 5"),
    ({"joint": 1, "rate": 1}, "drivers[0].joint", "unexpected value 1"),
    ({"omega": "crank", "joint": "j1", "value": 1, "rate": 1}, "drivers[0].joint",
     "a driver has exactly one of joint, omega, velocity; 'joint' is a second one"),
])
def test_a_bad_driver_is_named_by_its_own_key(driver, where, message):
    err = error_of(four_bar(drivers=[driver]))
    assert (err.kind, err.where) == ("schema", where)
    assert err.message.startswith(message)


@pytest.mark.parametrize("section,name", [("points", "P@x"), ("bodies", "cr@nk"), ("points", " ")])
def test_names_cannot_hold_the_at_sign_or_be_blank(section, name):
    tree = four_bar()
    if section == "points":
        tree["points"][name] = [0, 1]
        tree["bodies"]["crank"].append(name)
    else:
        tree["bodies"][name] = tree["bodies"].pop("crank")
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", f"{section}.{name}")


def test_an_empty_body_after_the_at_sign_is_refused():
    err = error_of(four_bar(ask=[{"velocity": "B@"}]))
    assert err.kind == "schema" and "name the body after '@'" in err.message


# the Python API raises the package's own error ------------------------------------------------
@pytest.mark.parametrize("call", [
    lambda: solve(None), lambda: solve(42), lambda: solve([]), lambda: solve(b"points: {}"),
    lambda: Mechanism("x", parameters=[1, 2]),
    lambda: solve(four_bar()).velocity(None), lambda: solve(four_bar()).velocity(5),
    lambda: solve(four_bar()).omega(None),
    lambda: run_sweep(four_bar(), steps="5"), lambda: run_sweep(four_bar(), steps=10 ** 12),
], ids=["none", "int", "list", "bytes", "parameters", "velocity-none", "velocity-int",
        "omega-none", "steps-str", "steps-huge"])
def test_api_misuse_raises_kinematika_error(call):
    with pytest.raises(KinematikaError) as info:
        call()
    assert info.value.kind == "schema" and info.value.message


def test_the_api_reads_a_model_given_as_text():
    text = yaml.safe_dump(four_bar())
    w3, _, _, _ = four_bar_closed_form()
    assert float(solve(text).omega("coupler")) == pytest.approx(w3)


# the command line ---------------------------------------------------------------------------
def test_usage_errors_follow_json_and_exit_2():
    model = str(EXAMPLES / "four_bar.yaml")
    out = cli("sweep", model, "--steps", "abc", "--json")
    assert out.status == 2
    error = json.loads(out.stdout)["error"]
    assert (error["kind"], error["where"]) == ("usage", "--steps")
    plain = cli("sweep", model, "--steps", "abc")
    assert plain.status == 2 and "Traceback" not in plain.stderr
    assert plain.stderr.startswith("error (usage): Invalid value for '--steps'")
    assert len(plain.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("args", [
    ["draw", "{model}", "-o", "{missing}/x.png"],
    ["sweep", "{model}", "--steps", "4", "--plot", "{missing}/x.png"],
    ["sweep", "{model}", "--steps", "4", "--csv", "{missing}/x.csv"],
    ["explain", "{model}", "-o", "{missing}/x.md"],
], ids=["draw", "plot", "csv", "explain"])
def test_writing_into_a_missing_folder_is_an_output_error(tmp_path, args):
    model, missing = str(EXAMPLES / "four_bar.yaml"), str(tmp_path / "nowhere")
    out = cli(*(a.format(model=model, missing=missing) for a in args))
    assert out.status == 2 and "Traceback" not in out.stderr
    assert out.stderr.startswith("error (output):") and "there is no folder" in out.stderr


@pytest.mark.parametrize("args", [["draw", "--width", "0"], ["animate", "--fps", "0"],
                                  ["animate", "--frames", "0"], ["sweep", "--steps", "99999999999"]])
def test_out_of_range_options_are_usage_errors(tmp_path, args):
    command, *options = args
    output = ["-o", str(tmp_path / ("x.gif" if command == "animate" else "x.png"))]
    out = cli(command, str(EXAMPLES / "four_bar.yaml"), *options,
              *(output if command != "sweep" else []))
    assert out.status == 2 and out.stderr.startswith("error (usage):")
    assert math.isfinite(len(out.stderr)) and "Traceback" not in out.stderr


# joints that say one thing and are another --------------------------------------------------
def _example(name: str) -> dict:
    return yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text())


def test_internal_on_a_wheel_and_its_track_is_refused():
    tree = _example("wheel_rolling")
    roll = next(j for j in tree["joints"] if j["type"] == "rolling")
    roll["internal"] = True
    err = error_of(tree)
    assert err.kind == "schema" and "`internal` tells how two circles touch" in err.message


def test_an_external_mesh_declared_internal_is_a_geometry_error():
    tree = _example("planetary_gears")
    gear = next(j for j in tree["joints"] if j["type"] == "gear" and not j.get("internal"))
    gear["internal"] = True
    err = error_of(tree)
    assert err.kind == "geometry"
    assert "declared internal but its pitch circles touch externally" in err.message


def test_a_point_listed_twice_by_one_body_is_refused():
    tree = four_bar()
    tree["bodies"]["crank"].append("A")
    err = error_of(tree)
    assert (err.kind, err.where, err.message) == ("schema", "bodies.crank", "point 'A' is listed twice")


def test_a_file_that_is_not_a_mapping_names_itself(tmp_path):
    path = tmp_path / "list.yaml"
    path.write_text("- 1\n- 2\n")
    err = error_of(path)
    assert (err.kind, err.where) == ("schema", str(path))
    assert err.message.endswith("this file holds a list")


def test_too_many_questions_are_refused():
    err = error_of(four_bar(ask=[{"velocity": "B@rocker"}] * 10_001))
    assert (err.kind, err.where) == ("schema", "ask")
    assert err.message == "10001 questions: at most 10000 in one model"
