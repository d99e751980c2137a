"""Every error kind of the contract, from a real bad input, with its message and place."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from kinematika import KinematikaError, solve
from kinematika.commands import solve_data
from kinematika.model.files import parse_text

from .models import four_bar


def error_of(tree) -> KinematikaError:
    with pytest.raises(KinematikaError) as info:
        solve(tree)
    return info.value


def test_syntax_error_names_the_line(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("points:\n  A: [0, 0\n  B: [1, 1]\n")
    with pytest.raises(KinematikaError) as info:
        solve(bad)
    assert info.value.kind == "syntax"
    assert "invalid YAML at line" in info.value.message


def test_syntax_error_in_json_and_toml():
    with pytest.raises(KinematikaError, match="invalid JSON at line 1"):
        parse_text("{points: }", "json")
    with pytest.raises(KinematikaError, match="invalid TOML"):
        parse_text("points = [", "toml")


def test_unknown_key_is_a_schema_error_naming_the_joint():
    tree = four_bar()
    tree["joints"][3]["atx"] = 1
    err = error_of(tree)
    assert (err.kind, err.message) == ("schema", "unknown key 'atx'")
    assert err.where.startswith("joints[3] (j4)")


def test_unknown_body_lists_the_bodies():
    err = error_of(four_bar(drivers=[{"omega": "crankk", "value": 1}]))
    assert err.kind == "schema"
    assert err.where == "drivers[0].omega"
    assert err.message == "unknown body 'crankk' (bodies: ground, crank, coupler, rocker)"


def test_ambiguous_bare_point_lists_the_choices():
    tree = four_bar(ask=[{"velocity": "A"}])
    tree["joints"][1] = {"type": "slot", "bodies": ["coupler", "crank"], "at": "A", "along": [1, 0]}
    err = error_of(tree)
    assert err.kind == "schema"
    assert "write A@crank or A@coupler" in err.message


def test_point_carried_by_no_body():
    tree = four_bar()
    tree["points"]["Q"] = [1, 1]
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "points.Q")
    assert "not carried by any body" in err.message


def test_expressions_are_never_run_as_code(tmp_path):
    marker = tmp_path / "pwned"
    tree = four_bar(drivers=[{"omega": "crank",
                              "value": f"__import__('os').system('touch {marker}')"}])
    err = error_of(tree)
    assert err.kind == "schema" and "unknown function" in err.message
    assert not marker.exists()
    for text in ["(1).__class__", "[1][0]", "lambda: 1", "'a'", "w2 if 1 else 2", "w2.real"]:
        err = error_of(four_bar(drivers=[{"omega": "crank", "value": text}]))
        assert err.kind == "schema", text


def test_revolute_point_not_on_a_body_is_geometry():
    tree = four_bar()
    tree["joints"][2]["at"] = "A"
    err = error_of(tree)
    assert err.kind == "geometry"
    assert err.where == "joints[2] (j3)"
    assert err.message == "the revolute point 'A' is not on body 'rocker': list 'A' in its points"


def test_wheel_that_does_not_touch_its_track_gives_the_gap():
    tree = {"parameters": {"R": 0.5},
            "points": {"G": [0, 0], "C": [0, 0.53]},
            "bodies": {"ground": {"points": ["G"], "line": {"through": "G", "direction": [1, 0]}},
                       "roda": {"points": ["C"], "circle": {"center": "C", "radius": "R"}}},
            "joints": [{"type": "rolling", "bodies": ["ground", "roda"]}],
            "drivers": [{"omega": "roda", "value": -2}]}
    err = error_of(tree)
    assert (err.kind, err.where) == ("geometry", "joints[0] (j1)")
    assert err.message == "'roda' does not touch 'ground': gap 0.03"


def test_slot_point_off_its_line():
    tree = four_bar()
    tree["joints"][1] = {"type": "slot", "bodies": ["coupler", "crank"], "at": "A",
                         "along": ["B", "O4"]}
    tree["bodies"]["coupler"] = ["A", "B", "O4"]
    err = error_of(tree)
    assert err.kind == "geometry" and "slot point 'A' is off the line BO4: gap" in err.message


def test_too_few_drivers_says_the_dof_and_the_free_bodies():
    err = error_of(four_bar(drivers=[]))
    assert err.kind == "mobility"
    assert err.message == ("the mechanism has 1 degree of freedom but the drivers give 0 "
                           "independent conditions; left free: crank, coupler, rocker")


def test_conflicting_drivers_are_named():
    err = error_of(four_bar(drivers=[{"omega": "crank", "value": 10},
                                     {"omega": "rocker", "value": 3}]))
    assert err.kind == "mobility"
    assert "drivers[1] (ω of rocker = 3)" in err.message
    assert "1 degree of freedom" in err.message


def test_consistent_redundant_driver_is_accepted():
    # the rocker's rate and its derivative restated with the values the crank implies
    from .models import four_bar_closed_form

    w3, w4, a3, a4 = four_bar_closed_form()
    sol = solve(four_bar(drivers=[{"omega": "crank", "value": 10},
                                  {"omega": "rocker", "value": repr(w4), "alpha": repr(a4)}]))
    assert sol.omega("coupler") == pytest.approx(w3, rel=1e-9)
    assert sol.alpha("coupler") == pytest.approx(a3, rel=1e-8)


def test_restated_rate_with_a_contradicting_alpha_is_a_conflict():
    # α of the rocker left at its default 0 contradicts the crank's steady turning
    from .models import four_bar_closed_form

    _, w4, _, _ = four_bar_closed_form()
    err = error_of(four_bar(drivers=[{"omega": "crank", "value": 10},
                                     {"omega": "rocker", "value": repr(w4)}]))
    assert err.kind == "mobility" and "α of rocker = 0" in err.message


def _rigid_epicyclic(drivers: list) -> dict:
    """The notes' epicyclic train (C5-1.4: sun r, ring 3r, three planets r on a carrier at 2r)
    in numbers, r = 0.05, with the given drivers."""
    import yaml

    examples = Path(__file__).resolve().parents[2] / "examples"
    tree = yaml.safe_load((examples / "seed_c5_1_4_epicyclic.yaml").read_text())
    tree["parameters"] = {"r": 0.05, "w": 10}
    tree.pop("draw_at")
    tree["drivers"] = drivers
    return tree


@pytest.mark.parametrize("symbolic", [False, True])
def test_a_train_driven_rigidly_is_no_conflict(symbolic):
    """Carrier and ring driven at the same rate w: the planets cannot turn on the carrier, so
    the whole train turns as one body at w (sun and planets too), and A1 = (0, −2r) moves at
    w k × A1 = (2rw, 0), by hand. Redundant (three planets) and consistent: never a conflict
    (the acceleration system's right side is all round-off there)."""
    tree = _rigid_epicyclic([{"omega": "carrier", "value": "w"}, {"omega": "ring", "value": "w"}])
    if symbolic:
        tree["parameters"] = {"r": None, "w": None}
    data = solve_data(tree)
    w = "w" if symbolic else 10.0
    for body in ("carrier", "ring", "sun", "planet1", "planet2", "planet3"):
        assert data["bodies"][body] == {"omega": w, "alpha": "0" if symbolic else 0.0}
    assert data["points"]["A1@carrier"]["velocity"] == (["2*r*w", "0"] if symbolic else [1.0, 0.0])


def test_a_third_consistent_driver_of_a_rigid_train_is_accepted_and_a_contradicting_alpha_is_not():
    rigid = [{"omega": "carrier", "value": "w"}, {"omega": "ring", "value": "w"}]
    sol = solve(_rigid_epicyclic(rigid + [{"omega": "sun", "value": "w", "alpha": 0}]))
    assert sol.omega("planet2") == pytest.approx(10, rel=1e-12)
    err = error_of(_rigid_epicyclic(rigid + [{"omega": "sun", "value": "w", "alpha": 1}]))
    assert err.kind == "mobility" and "α of sun = 1" in err.message


def test_dead_point_is_singular():
    # driven from the rocker while crank and coupler are aligned (O2, A, B collinear)
    tree = {"points": {"O2": [0, 0], "A": [1, 0], "B": [4, 0], "O4": [4, 3]},
            "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"],
                       "rocker": ["B", "O4"]},
            "joints": four_bar()["joints"],
            "drivers": [{"omega": "rocker", "value": 1}]}
    err = error_of(tree)
    assert err.kind == "singular"
    assert "dead point" in err.message and "drivers[0] (ω of rocker = 1) depends" in err.message


@pytest.mark.parametrize("kind,tree_change", [
    ("schema", {"drivers": [{"omega": "nobody", "value": 1}]}),
    ("mobility", {"drivers": []}),
])
def test_cli_reports_one_line_and_json_with_exit_2(tmp_path, kind, tree_change):
    path = tmp_path / "model.json"
    path.write_text(json.dumps(four_bar(**tree_change)))
    cmd = [sys.executable, "-m", "kinematika.cli", "solve", str(path)]
    plain = subprocess.run(cmd, capture_output=True, text=True)
    assert plain.returncode == 2
    assert plain.stdout == "" and plain.stderr.startswith(f"error ({kind}): ")
    assert len(plain.stderr.strip().splitlines()) == 1
    assert "Traceback" not in plain.stderr
    as_json = subprocess.run(cmd + ["--json"], capture_output=True, text=True)
    assert as_json.returncode == 2
    payload = json.loads(as_json.stdout)["error"]
    assert payload["kind"] == kind and payload["message"] and "where" in payload


@pytest.mark.parametrize("symbolic", [False, True], ids=["numeric", "symbolic"])
@pytest.mark.parametrize("text", ["10**10**10", "2**2**2**2**2**2", "(10**300)**1000 / 10**299"])
def test_huge_powers_are_refused_quickly(text, symbolic):
    # 10**10**10 has ten billion digits: evaluating it exactly would never end
    tree = four_bar()
    tree["points"]["A"] = [0, text]
    with pytest.raises(KinematikaError) as info:
        solve(tree, symbolic=symbolic)
    assert info.value.kind == "schema" and info.value.where == "points.A[1]"
    assert "too large" in info.value.message or "too many digits" in info.value.message


@pytest.mark.parametrize("value", [float("inf"), float("nan"), 10 ** 400, "1e400", "1" + "0" * 400])
def test_numbers_must_be_finite(value):
    tree = four_bar()
    tree["points"]["A"] = [0, value]
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "points.A[1]")


@pytest.mark.parametrize("text,problem", [("sqrt(-1)", "not real"), ("(-8)**(1/3)", "not real"),
                                          ("tan(pi/2)", "not finite"), ("exp(1000)", "too large")])
def test_symbolic_constants_must_be_real_and_finite(text, problem):
    # √−1 = i; (−8)^(1/3) is the principal root 1 + i√3; tan is infinite at π/2; e¹⁰⁰⁰ > 1e308
    tree = four_bar()
    tree["points"]["A"] = [0, text]
    with pytest.raises(KinematikaError) as info:
        solve(tree, symbolic=True)
    assert (info.value.kind, info.value.where) == ("schema", "points.A[1]")
    assert problem in info.value.message


def test_a_reader_that_stops_reading_ends_the_command_quietly():
    """`kinematika sweep ... | head`: the output (far more than a pipe holds) meets a closed
    pipe; the command ends with status 141 (128 + SIGPIPE) and no traceback."""
    from tests.conftest import EXAMPLES

    cmd = [sys.executable, "-m", "kinematika.cli", "sweep", str(EXAMPLES / "four_bar.yaml"), "--steps", "5000",
           "--json"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout.read(10)
    proc.stdout.close()                                  # `head -c 10` has what it wanted
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 141 and "Traceback" not in err, err
