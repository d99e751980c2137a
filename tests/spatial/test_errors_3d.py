"""Bad spatial input: each error kind with its message and place, never a traceback."""
from __future__ import annotations

import copy
import json
import subprocess
import sys

import pytest
import yaml

from kinematika import KinematikaError, solve

from .derive import EXAMPLES


def example(name: str) -> dict:
    return yaml.safe_load((EXAMPLES / name).read_text())


def error_of(tree: dict) -> KinematikaError:
    with pytest.raises(KinematikaError) as info:
        solve(tree)
    return info.value


COIN = {"dimension": 3,
        "points": {"O": [0, 0, 0], "C": [0.5, 0, 0.1]},
        "bodies": {"ground": {"points": ["O"], "plane": {"through": "O", "normal": [0, 0, 1]}},
                   "coin": {"points": ["C"], "disc": {"center": "C", "radius": 0.1, "axis": [1, 0, 0]}}},
        "joints": [{"id": "roll", "type": "rolling", "bodies": ["ground", "coin"]}],
        "drivers": [{"omega": "coin", "value": [-10, 0, 2], "alpha": [0, -20, 0]}]}


def coin(**disc) -> dict:
    tree = copy.deepcopy(COIN)
    tree["bodies"]["coin"]["disc"].update(disc)
    return tree


def test_the_coin_itself_solves():
    # the base model of this file is valid: v_C = -omega x CJ, CJ = (0, 0, -0.1)
    assert solve(COIN).velocity("C") == pytest.approx((0, 1, 0), abs=1e-12)


def test_revolute_without_axis():
    tree = example("gyroscope.yaml")
    del tree["joints"][1]["axis"]
    err = error_of(tree)
    assert (err.kind, err.message, err.where) == ("schema", "a revolute joint needs `axis`",
                                                  "joints[1] (nutation)")


def test_zero_axis():
    tree = example("gyroscope.yaml")
    tree["joints"][0]["axis"] = [0, 0, 0]
    err = error_of(tree)
    assert (err.kind, err.message, err.where) == ("schema", "a direction cannot be the zero vector",
                                                  "joints[0] (precession).axis")


def test_disc_not_touching_its_plane():
    tree = coin()
    tree["points"]["C"] = [0.5, 0, 0.13]
    err = error_of(tree)
    assert (err.kind, err.where) == ("geometry", "joints[0] (roll)")
    assert err.message == "'coin' does not touch 'ground': gap 0.03"


def test_leaning_disc_at_the_upright_height_does_not_touch():
    # leaning by 30 deg, its lowest point is R cos 30 below the centre, not R
    err = error_of(coin(axis=[0.8660254037844386, 0, 0.5]))
    assert err.kind == "geometry" and "gap 0.0133975" in err.message


def test_disc_lying_flat():
    err = error_of(coin(axis=[0, 0, 1]))
    assert (err.kind, err.where) == ("geometry", "joints[0] (roll)")
    assert err.message == ("disc 'coin' lies flat on the plane of 'ground': it touches along its "
                           "face, not at a point")


def test_circles_cannot_roll_in_space():
    tree = copy.deepcopy(COIN)
    tree["bodies"]["coin"] = {"points": ["C"], "circle": {"center": "C", "radius": 0.1}}
    err = error_of(tree)
    assert (err.kind, err.message) == ("geometry", "rolling between 'ground' and 'coin': these shapes "
                                       "cannot roll on each other")


def test_too_few_drivers():
    tree = copy.deepcopy(COIN)
    tree["drivers"] = []
    err = error_of(tree)
    assert (err.kind, err.where) == ("mobility", "drivers")
    assert err.message == ("the mechanism has 3 degrees of freedom but the drivers give 0 independent "
                           "conditions; left free: coin")
    tree = example("gyroscope.yaml")
    tree["drivers"] = tree["drivers"][:2]
    err = error_of(tree)
    assert err.kind == "mobility"
    assert err.message == ("the mechanism has 3 degrees of freedom but the drivers give 2 independent "
                           "conditions; left free: rotor")


def test_gimbal_lock_is_singular_for_an_absolute_omega():
    """With the nutation at 0 the spin axis lies along the precession axis: the rotor's three
    components of ω cannot be given through the gimbal (one of them depends on the joints)."""
    tree = example("gyroscope.yaml")
    tree["parameters"]["th"] = 0
    tree["drivers"] = [{"omega": "rotor", "value": [0.5, 0, 3]}]
    err = error_of(tree)
    assert err.kind == "singular"
    assert "dead point" in err.message and "drivers[0] (ω of rotor (y) = 0) depends" in err.message
    # away from the lock the same driver is accepted
    tree["parameters"]["th"] = "deg(30)"
    assert solve(tree).omega("rotor") == pytest.approx((0.5, 0, 3))


def test_conflicting_vector_drivers():
    tree = copy.deepcopy(COIN)
    tree["drivers"].append({"omega": "coin", "value": [-10, 1, 2]})
    err = error_of(tree)
    assert err.kind == "mobility"
    assert "drivers[1] (ω of coin (y) = 1)" in err.message and "do not agree" in err.message


def test_vector_driver_needs_three_components():
    tree = copy.deepcopy(COIN)
    tree["drivers"][0]["value"] = [1, 2]
    err = error_of(tree)
    assert (err.kind, err.message, err.where) == ("schema", "expected 3 components, got 2",
                                                  "drivers[0].value")


def test_cylindrical_joint_has_no_single_rate():
    tree = {"dimension": 3, "points": {"A": [0, 0, 0]},
            "bodies": {"ground": ["A"], "collar": ["A"]},
            "joints": [{"type": "cylindrical", "bodies": ["ground", "collar"], "at": "A", "axis": [1, 0, 0]}],
            "drivers": [{"joint": "j1", "rate": 1}]}
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "drivers[0]")
    assert "two rates" in err.message


@pytest.mark.parametrize("change,message,where", [
    ({"joints": [{"type": "spherical", "bodies": ["ground", "crank"], "at": "O2"}]},
     "a spherical joint belongs to a 3D model", "joints[0] (j1)"),
    ({"ask": [{"axis": "crank"}]},
     "the screw axis is a 3D question; ask for `icr` in a planar model", "ask[0]"),
])
def test_spatial_things_in_a_planar_model(change, message, where):
    tree = example("four_bar.yaml")
    for key, value in change.items():
        tree[key] = value + tree[key][1:] if key == "joints" else value
    err = error_of(tree)
    assert (err.kind, err.message, err.where) == ("schema", message, where)


def test_planar_things_in_a_spatial_model():
    tree = example("gyroscope.yaml")
    tree["ask"] = [{"icr": "rotor"}]
    err = error_of(tree)
    assert (err.kind, err.message) == ("schema", "icr is a planar question; ask for the screw `axis` in 3D")
    tree = example("gyroscope.yaml")
    tree["joints"][0] = {"type": "wheel", "bodies": ["ground", "outer"], "at": "O", "along": [1, 0, 0]}
    err = error_of(tree)
    assert (err.kind, err.message) == ("schema", "a wheel joint belongs to a planar model")


def test_command_line_gives_one_line_and_status_2(tmp_path):
    bad = tmp_path / "flat.yaml"
    bad.write_text(yaml.safe_dump(coin(axis=[0, 0, 1])))
    run = subprocess.run([sys.executable, "-m", "kinematika", "solve", str(bad), "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 2
    assert "Traceback" not in run.stderr + run.stdout
    assert json.loads(run.stdout)["error"] == {
        "kind": "geometry", "where": "joints[0] (roll)",
        "message": "disc 'coin' lies flat on the plane of 'ground': it touches along its face, not at a point"}
