"""More textbook problems written by construction (tests/textbook): four-bars (open,
crossed, Grashof or not, a coupler point, a parallelogram), offset and vertical
slider-cranks, inversions, quick-returns, Geneva wheels, pins in slots, six-bars (Watt,
Stephenson, a triad), gear trains, rolling wheels, spatial linkages and vehicles; `move`,
symbolic inputs and error cases among them.

Each NAME.yaml is run by `kinematika solve NAME.yaml --json` (in this process by click's
runner; in a deep run also in a child process, as the contract's outside tests run it, which
tests/model/test_cases.py does on a few cases in a default run), and compared under check-cases' rules with NAME.expect.json, which holds the hand
derivation of tests/textbook/derive.py (never kinematika's numbers). The other commands a
student uses on these problems (centres, assemblies, --set, --move, --symbolic) are
checked against derivations of their own below.
"""
from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import pytest

from tests.conftest import deep_only, sampled
from tests.model.test_cases import (_matches, case_through_the_command_line, every_case_derived,
                                    expectation_is_derivation, kinematika)

HERE = Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("textbook_derive", HERE / "derive.py")
derive = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(derive)
NAMES = sorted(p.stem for p in HERE.glob("*.yaml"))


# a symbolic case whose solve takes seconds; the other symbolic cases are of its kind
SLOW = {"geneva_symbolic_theta"}


def test_every_case_has_its_derivation_and_expectation():
    every_case_derived(HERE, derive)


@pytest.mark.parametrize("name", NAMES)
def test_the_expectation_is_the_hand_derivation(name):
    expectation_is_derivation(HERE, derive, name)


@pytest.mark.parametrize("name", sampled(NAMES, lambda n: n not in SLOW))
def test_case_through_the_command_line(name):
    case_through_the_command_line(HERE, name)


@deep_only
@pytest.mark.parametrize("name", NAMES)
def test_case_through_a_child_process(name):
    case_through_the_command_line(HERE, name, child=True)


# the other commands on these problems --------------------------------------------------------
def _centres(name: str) -> dict:
    code, out = kinematika("centres", str(HERE / f"{name}.yaml"), "--json")
    assert code == 0, out
    return {tuple(sorted(c["bodies"])): c for c in out["centres"]}


def test_centres_of_the_crank_rocker_by_kennedy():
    """The six centres of a four-bar: four pins, then I13 where O2A meets O4B and I24 where
    AB meets O2O4 (Aronhold-Kennedy)."""
    t = math.radians(50)
    a = [2 * math.cos(t), 2 * math.sin(t)]
    b = [float(x) for x in derive.four_bar(8, 2, 7, 6)(t)]
    expected = {("crank", "ground"): [0, 0], ("ground", "rocker"): [8, 0], ("coupler", "crank"): a,
                ("coupler", "rocker"): b,
                ("coupler", "ground"): derive.line_meet([0, 0], a, [8, 0], [b[0] - 8, b[1]]),
                ("crank", "rocker"): derive.line_meet(a, [b[0] - a[0], b[1] - a[1]], [0, 0], [1, 0])}
    got = _centres("fb_crank_rocker_coupler")
    assert got.keys() == expected.keys()
    for pair, point in expected.items():
        assert got[pair]["point"] == pytest.approx([float(x) for x in point], abs=1e-9), pair


def test_centres_of_the_offset_slider_crank():
    """The slider's centre with the frame is at infinity across its guide; the rod's where
    O2A meets the normal to the guide at B; crank-slider where AB meets the normal at O2."""
    t = math.radians(300)
    a = [30 * math.cos(t), 30 * math.sin(t)]
    b = [a[0] + math.sqrt(90 ** 2 - (15 - a[1]) ** 2), 15.0]
    got = _centres("sc_offset_above")
    assert got[("ground", "slider")]["point"] is None
    assert [abs(x) for x in got[("ground", "slider")]["direction"]] == pytest.approx([0, 1], abs=1e-12)
    assert got[("ground", "rod")]["point"] == pytest.approx(derive.line_meet([0, 0], a, b, [0, 1]), abs=1e-9)
    assert got[("crank", "slider")]["point"] == pytest.approx(
        derive.line_meet(a, [b[0] - a[0], b[1] - a[1]], [0, 0], [0, 1]), abs=1e-9)
    assert got[("rod", "slider")]["point"] == pytest.approx(b, abs=1e-9)


def test_set_poses_the_problem_at_another_crank_angle():
    code, out = kinematika("solve", str(HERE / "sc_offset_above.yaml"), "--set", "theta2=deg(100)", "--json")
    assert code == 0, out
    for got, exp in zip((a["value"] for a in out["answers"]), derive.sc_offset_above(100)):
        _matches(got, exp, {"tolerance": 1e-9, "abs": 1e-9}, "answers")


def test_move_on_the_command_line_is_the_move_in_the_file():
    code, out = kinematika("solve", str(HERE / "fb_non_grashof.yaml"), "--move", "j1=-40", "--json")
    assert code == 0, out
    for got, exp in zip((a["value"] for a in out["answers"]), derive.fb_non_grashof_moved()):
        _matches(got, exp, {"tolerance": 1e-9, "abs": 1e-9}, "answers")


def test_symbolic_gear_train_gives_the_train_value():
    """--symbolic makes every parameter a symbol: ω3 = −r1 w1/r2, ω4 = r1 r3 w1/(r2 r4),
    α4 = 10 r1 r3/(r2 r4)."""
    from tests.model.test_cases import _same_function

    code, out = kinematika("solve", str(HERE / "gear_compound_train.yaml"), "--symbolic", "--json")
    assert code == 0, out
    w3, w4, al4 = (a["value"] for a in out["answers"][:3])
    assert _same_function(w3, "-r1*w1/r2")
    assert _same_function(w4, "r1*r3*w1/(r2*r4)")
    assert _same_function(al4, "10*r1*r3/(r2*r4)")


# assemblies --------------------------------------------------------------------------------
def test_the_oscillating_cylinder_closes_two_ways_and_the_drawn_one_is_listed():
    """An RPR dyad closes with its guide either way along the line O4A. Here every point of the
    two closures is in the same place (the piston carries only A); they differ by the
    piston's and cylinder's half turn, and both used to be taken for one: the drawn one was
    dropped and the other listed alone, not marked drawn. The cylinder's rate is the rate of
    the line O4A whichever way it points."""
    code, out = kinematika("assemblies", str(HERE / "isc_oscillating_cylinder.yaml"), "--json")
    assert code == 0, out
    assert [(a["number"], a["drawn"]) for a in out["assemblies"]] == [(1, False), (2, True)]
    assert [a["closures"] for a in out["assemblies"]] == [["O4 ahead of A along j4"], ["O4 behind A along j4"]]
    code, other = kinematika("solve", str(HERE / "isc_oscillating_cylinder.yaml"), "--assembly", "1", "--json")
    assert code == 0, other
    w, al = derive.isc_oscillating_cylinder()[:2]
    assert [a["value"] for a in other["answers"][:2]] == pytest.approx([w, al], rel=1e-9)


def test_the_triad_has_the_assemblies_a_scan_finds():
    """A triad's closures by a scan over the direction of AB (derive.triad_assemblies); the
    tool finds them by least squares from random poses."""
    code, out = kinematika("assemblies", str(HERE / "stephenson_triad.yaml"), "--json")
    assert code == 0, out
    a = [math.cos(math.radians(30)), math.sin(math.radians(30))]
    found = sorted(out["assemblies"], key=lambda x: x["points"]["B@link1"][1])
    closures = derive.triad_assemblies()
    assert len(found) == len(closures) == 2
    for got, (f1, psi) in zip(found, sorted(closures, key=lambda c: math.sin(math.radians(c[0])))):
        b = [a[0] + 3 * math.cos(math.radians(f1)), a[1] + 3 * math.sin(math.radians(f1))]
        c = [b[0] + 2.5 * math.cos(math.radians(psi)), b[1] + 2.5 * math.sin(math.radians(psi))]
        assert got["points"]["B@ternary"] == pytest.approx(b, abs=1e-9)
        assert got["points"]["C@ternary"] == pytest.approx(c, abs=1e-9)
    assert [x["drawn"] for x in found] == [True, False]
