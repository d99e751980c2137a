"""Motion through limit positions: where the input cannot go further it runs back, and the
mechanism passes to its other branch, as the real mechanism moves.

Every expected number is derived by hand from the geometry, independently of the code:

- a crank-rocker driven from its rocker (ground 4, crank 1, coupler 4, rocker 3): the rocker
  stops where crank and coupler are in line, |O2B| = 4 ± 1, so with B on the circle of 3
  about O4 = (4, 0), |O2B|² = 25 + 24 cos φ gives φ = 90° (extended) and acos(−2/3) =
  131.81° (folded); its range is their difference;
- the notes' guide M driving a rocker (P pair with Coriolis): the guide's line through A
  can carry the block B only while it passes within |EB| of E: E × u(θ) = ±|EB|;
- the pin in a circular slot is the four-bar O2-A-C-B with coupler AC = the slot's radius R
  and rocker BC = L: the crank stops where |AB| = R + L, 10 − 6 cos θ = (R + L)²;
- a Grashof double rocker (ground 4, input 3, coupler 1, output 3.5): the input stops where
  coupler and output are in line, |AO4| = 3.5 ± 1, 25 − 24 cos θ = 4.5² or 2.5².
"""
from __future__ import annotations

import csv
import functools
import itertools
import io
import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from kinematika import KinematikaError
from kinematika.cli import app
from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper
from tests.conftest import EXAMPLES

from .models import circle_meet, four_bar_tree, rocker_driven_tree

PATHS = ["closed-form", "newton"]


def _sweeper(tree_or_path, general: bool) -> Sweeper:
    sweeper = Sweeper(tree_or_path)
    if general:
        sweeper.closed = None                       # Newton's path, by arclength near the limits
    return sweeper


def _side(p, q, r) -> float:
    """+1 when r is left of the line p→q."""
    return math.copysign(1.0, (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))


# a crank-rocker driven from its rocker ---------------------------------------------------------
SWING = (90.0, math.degrees(math.acos(-2 / 3)))          # the rocker's limits, absolute


@functools.cache
def _rocker_cycle(general: bool):
    """The rocker-driven crank-rocker's whole cycle, swept once for the tests that read it."""
    return _sweeper(rocker_driven_tree(rocker_deg=120.0), general).run()


@pytest.mark.parametrize("general", [False, True], ids=PATHS)
def test_a_rocker_driven_crank_rocker_swings_between_its_limits_and_closes_its_cycle(general):
    result = _rocker_cycle(general)
    low, high = (x - 120.0 for x in SWING)
    # up first (by > 0) to the folded limit, back to the extended one, then up to the drawing
    assert result.limits == pytest.approx([high, low], abs=1e-9)
    assert max(*result.limits, *result.coordinate) - min(*result.limits, *result.coordinate) == \
        pytest.approx(SWING[1] - SWING[0], abs=1e-9)                       # the rocker's swing
    cycle = 2 * (SWING[1] - SWING[0])
    assert result.closed and result.travel[-1] == pytest.approx(cycle, abs=1e-9)
    assert len(result) == math.floor(cycle) + 2             # a row a degree, and the drawing again
    assert result.coordinate[-1] == 0.0
    for values in result.points.values():                   # the last row is the drawn one
        np.testing.assert_allclose(values["position"][-1], values["position"][0], atol=1e-9)
    # the real motion: the crank turns on, one way, a whole turn over the rocker's cycle
    a = result.points["A@crank"]["position"]
    turn = np.unwrap(np.arctan2(a[:, 1], a[:, 0]))
    steps = np.diff(turn)
    assert (steps > 0).all() or (steps < 0).all()
    assert abs(turn[-1] - turn[0]) == pytest.approx(2 * math.pi, abs=1e-9)
    assert abs(result.bodies["crank"]["angle"][-1]) == pytest.approx(360.0, abs=1e-9)


@pytest.mark.parametrize("general", [False, True], ids=PATHS)
def test_past_each_limit_the_crank_is_on_the_other_side_and_its_rates_are_the_loop_closures(general):
    result = _rocker_cycle(general)
    o4 = np.array([4.0, 0.0])
    # the rows of each run: up to the first limit, back to the second, then up again
    runs = np.searchsorted(result.travel, result.limit_travel)
    drawn_side = None
    for k, q in enumerate(result.coordinate):
        phi = math.radians(120.0 + q)
        b = o4 + 3 * np.array([math.cos(phi), math.sin(phi)])
        a = result.points["A@crank"]["position"][k]
        assert np.linalg.norm(a) == pytest.approx(1.0, abs=1e-9)
        assert np.linalg.norm(b - a) == pytest.approx(4.0, abs=1e-9)
        np.testing.assert_allclose(result.points["B@coupler"]["position"][k], b, atol=1e-9)
        side = _side((0, 0), b, a)
        run = int(np.searchsorted(runs, k, side="right"))      # 0, 1, 2: limits passed
        drawn_side = side if k == 0 else drawn_side
        assert side == (drawn_side if run % 2 == 0 else -drawn_side), k
        # rates as written (ω4 = 1): v_B = ω4 k×(B − O4) = ω2 k×A + ω3 k×(B − A)
        vb = np.array([-(b - o4)[1], (b - o4)[0]])
        m = np.array([[-a[1], -(b - a)[1]], [a[0], (b - a)[0]]])
        w2, w3 = np.linalg.solve(m, vb)
        assert result.bodies["crank"]["omega"][k] == pytest.approx(w2, rel=1e-7)
        assert result.bodies["coupler"]["omega"][k] == pytest.approx(w3, rel=1e-7)


def test_a_sweep_shorter_than_the_cycle_ends_where_its_travel_ends():
    # down first, 5.5° a row: 30° down to the extended limit, 41.81° up to the folded one,
    # then 5.19° down again: 77° of travel in all
    result = run_sweep(rocker_driven_tree(rocker_deg=120.0), by=-77, steps=14)
    low, high = (x - 120.0 for x in SWING)
    assert result.limits == pytest.approx([low, high], abs=1e-9)
    assert not result.closed and len(result) == 15 and result.travel[-1] == pytest.approx(77.0)
    assert result.coordinate[5] == pytest.approx(-27.5, abs=1e-9)
    assert result.coordinate[6] == pytest.approx(-30.0 + 3.0, abs=1e-9)        # back up
    assert result.coordinate[-1] == pytest.approx(high - (77 - 30 - (high - low)), abs=1e-9)


# the notes' P pair with Coriolis --------------------------------------------------------------
def _guide_limits() -> list[float]:
    """Increments of the guide (drawn at 30°) where its line through A = (0, 0) touches the
    circle of radius |EB| about E: Ex sin θ − Ey cos θ = ±|EB|, i.e. R sin(θ − φ) = ±|EB| with
    R = |E|, φ = atan2(−Ey, Ex)... written as a sine: Ex sin θ − Ey cos θ = R sin(θ − ψ),
    ψ = atan2(Ey, Ex)."""
    e = (0.1, 0.4)
    b = (0.4 * math.cos(math.radians(30)), 0.4 * math.sin(math.radians(30)))
    length = math.dist(e, b)
    r, psi = math.hypot(*e), math.atan2(e[1], e[0])
    out = []
    for sign in (1, -1):
        base = math.asin(sign * length / r)
        for theta in (psi + base, psi + math.pi - base):
            out.append((math.degrees(theta) - 30 + 180) % 360 - 180)
    return out


@pytest.mark.parametrize("general", [False, True], ids=PATHS)
def test_the_notes_guide_driving_a_rocker_reverses_where_its_line_touches_the_rockers_circle(general):
    result = _sweeper(EXAMPLES / "seed_001_p_pair_coriolis.yaml", general).run()
    candidates = _guide_limits()
    high = min(x for x in candidates if x > 0)          # the first met going up from the drawing
    low = max(x for x in candidates if x < 0)
    assert result.limits == pytest.approx([high, low], abs=1e-9)
    assert result.closed and result.travel[-1] == pytest.approx(2 * (high - low), abs=1e-9)
    assert abs(result.bodies["rocker"]["angle"][-1]) == pytest.approx(360.0, abs=1e-7)   # it turns fully


# the pin in a circular slot (Newton's path) -----------------------------------------------------
def test_the_pin_in_a_circular_slot_stops_where_its_equivalent_four_bar_does():
    r = math.hypot(2.2 - 0.5, 1.6 - math.sqrt(3) / 2)
    l = math.hypot(3 - 2.2, 1.6)
    theta = math.degrees(math.acos((10 - (r + l) ** 2) / 6))      # |AB| = R + L, both ways
    high, low = theta - 60, -theta - 60
    result = run_sweep(EXAMPLES / "pin_in_circular_slot.yaml")
    assert result.method == "newton"
    assert result.limits == pytest.approx([high, low], abs=1e-9)
    assert not result.closed and len(result) == 361              # its cycle is longer than 360°
    end = low + (360 - high - (high - low))                       # travelled: up, down, then up
    assert result.coordinate[-1] == pytest.approx(end, abs=1e-9)
    np.testing.assert_allclose(result.travel, np.arange(361.0), atol=1e-9)
    # on both branches the pin A is on the crank's circle and on the slot's, about C
    a = result.points["A@crank"]["position"]
    c = result.points["C@rocker"]["position"]
    np.testing.assert_allclose(np.linalg.norm(a, axis=1), 1.0, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(a - c, axis=1), r, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(c - [3.0, 0.0], axis=1), l, atol=1e-9)


# a double rocker ------------------------------------------------------------------------------------
@pytest.mark.parametrize("general", [False, True], ids=PATHS)
def test_a_double_rockers_input_swings_over_its_range(general):
    tree = four_bar_tree(ground=4.0, crank=3.0, coupler=1.0, rocker=3.5, crank_deg=60.0)
    high = math.degrees(math.acos((25 - 4.5 ** 2) / 24))          # coupler and output extended
    low = math.degrees(math.acos((25 - 2.5 ** 2) / 24))           # folded
    result = _sweeper(tree, general).run()
    assert result.limits == pytest.approx([high - 60, low - 60], abs=1e-9)
    assert result.closed and result.travel[-1] == pytest.approx(2 * (high - low), abs=1e-9)
    span = np.ptp(np.concatenate([result.coordinate, result.limits]))
    assert span == pytest.approx(high - low, abs=1e-9)
    # the coupler, the shortest link, turns a whole turn relative to the input in a cycle
    relative = result.bodies["coupler"]["angle"] - result.bodies["crank"]["angle"]
    assert abs(relative[-1] - relative[0]) == pytest.approx(360.0, abs=1e-7)


# the examples that stopped at their limit positions now move -----------------------------------------
@pytest.mark.parametrize("name", ["seed_001_p_pair_coriolis.yaml", "triad_six_bar.yaml"])
def test_the_examples_that_stopped_at_a_limit_move_through_it(name):
    """(The pin in a circular slot, the third, has a test of its own above.)"""
    from kinematika import load_model

    result = run_sweep(EXAMPLES / name)
    assert result.ok.all() and len(result.limits) == 2
    # every row still holds the mechanism together: the points of each body (those whose name
    # is not also the place of another body's point) keep their distances
    model = load_model(EXAMPLES / name)
    single = {n for n in model.points if len(model.motion_classes(n, model.carriers(n))) == 1}
    for body, names in _bodies(result).items():
        names = [n for n in names if n in single]
        for p, q in itertools.pairwise(names):
            d = np.linalg.norm(result.points[f"{p}@{body}"]["position"] -
                               result.points[f"{q}@{body}"]["position"], axis=1)
            np.testing.assert_allclose(d, d[0], rtol=0, atol=1e-9 * max(d[0], 1.0))


def _bodies(result) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for key in result.points:
        point, _, body = key.partition("@")
        out.setdefault(body, []).append(point)
    return out


# what is written ---------------------------------------------------------------------------------
def test_the_json_gains_the_limits_and_the_csv_the_travel_and_the_limit_passed(tmp_path):
    result = run_sweep(rocker_driven_tree(rocker_deg=120.0), by=-77, steps=14)
    limits = [SWING[0] - 120.0, SWING[1] - 120.0]
    data = json.loads(b"".join(result.json_chunks()))
    assert data == result.to_json()
    assert set(data) == {"coordinate", "bodies", "points", "limits"}
    assert data["limits"] == pytest.approx(limits, abs=1e-9)
    assert len(data["coordinate"]) == 15
    assert set(run_sweep(four_bar_tree(), steps=8).to_json()) == {"coordinate", "bodies", "points"}
    result.to_csv(tmp_path / "rows.csv")
    rows = list(csv.DictReader(io.StringIO((tmp_path / "rows.csv").read_text())))
    assert list(rows[0])[:3] == ["coordinate_deg", "travel_deg", "limit_deg"]
    assert [float(r["travel_deg"]) for r in rows] == pytest.approx([5.5 * k for k in range(15)])
    # each limit is written on the first row after it: 30° (row 6: 33°) and 71.81° (row 14: 77°)
    passed = {k: float(r["limit_deg"]) for k, r in enumerate(rows) if r["limit_deg"]}
    assert list(passed) == [6, 14] and list(passed.values()) == pytest.approx(limits, abs=1e-9)
    stored = np.load(_npz(result, tmp_path))
    assert np.isnan(stored["limit_deg"]).sum() == 13 and stored["travel_deg"][-1] == 77.0


def _npz(result, tmp_path):
    path = tmp_path / "rows.npz"
    result.to_npz(path)
    return path


def test_the_command_line_reports_the_limit_positions_range_and_cycle(tmp_path):
    import yaml

    model = tmp_path / "rocker.yaml"
    model.write_text(yaml.safe_dump(rocker_driven_tree(rocker_deg=120.0)))
    out = CliRunner().invoke(app, ["sweep", str(model), "--plot", str(tmp_path / "c.svg")])
    assert out.exit_code == 0, out.output
    text = out.stdout
    assert f"limit positions of j4: {SWING[1] - 120:.6g}, -30 deg" in text
    assert f"range of j4: -30 .. {SWING[1] - 120:.6g} deg" in text
    assert f"back at the drawn configuration after {2 * (SWING[1] - SWING[0]):.6g} deg" in text
    svg = (tmp_path / "c.svg").read_text()
    assert 'id="limit:-30"' in svg                                   # a dotted line at each


# a motion that cannot be followed ------------------------------------------------------------------
RUN_OFF = {
    "name": "A slotted crank pushing a block to infinity",
    "points": {"O": [0, 0], "B": [0, 1], "G": [1, 1], "H": [0, 2], "S": [0.5, 1]},
    "bodies": {"ground": ["O", "G"], "crank": ["O", "B"], "block": ["B"], "shoe": ["B", "S"],
               "arm": ["O", "H"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
               {"type": "prismatic", "bodies": ["crank", "block"], "along": ["O", "B"]},
               {"type": "revolute", "bodies": ["block", "shoe"], "at": "B"},
               {"type": "prismatic", "bodies": ["ground", "shoe"], "along": ["B", "G"]},
               {"type": "weld", "bodies": ["crank", "arm"]}],
    "drivers": [{"omega": "crank", "value": 1}],
}


def test_a_motion_that_runs_off_to_infinity_is_one_clear_error_with_the_rows_so_far(tmp_path):
    # the block slides where the crank's line meets y = 1: x = cot θ, infinite as θ → 0
    sweeper = Sweeper(RUN_OFF)
    assert sweeper.method == "newton"
    with pytest.raises(KinematikaError) as err:
        sweeper.run(by=-100, steps=100)
    assert err.value.kind == "assembly"
    assert "cannot be followed past j1 = -89.9" in err.value.message
    assert "runs off to infinity" in err.value.message
    partial = err.value.partial
    assert len(partial) == 90 and partial.ok.all() and partial.coordinate[-1] == -89.0
    # the shoe's pin where the crank (at 90° − 89° = 1°) meets the line y = 1; S half a unit on
    assert partial.points["S@shoe"]["position"][-1] == pytest.approx(
        [1 / math.tan(math.radians(1)) + 0.5, 1.0], rel=1e-9)
    import yaml

    model = tmp_path / "off.yaml"
    model.write_text(yaml.safe_dump(RUN_OFF))
    out = CliRunner().invoke(app, ["sweep", str(model), "--by", "-100", "--steps", "100",
                                   "--csv", str(tmp_path / "rows.csv")])
    assert out.exit_code == 2
    assert out.stderr.count("\n") == 1 and out.stderr.startswith("error (assembly): sweep: the motion")
    assert len((tmp_path / "rows.csv").read_text().splitlines()) == 91        # header + 90 rows
    out = CliRunner().invoke(app, ["sweep", str(model), "--by", "-100", "--steps", "100", "--json"])
    data = json.loads(out.stdout)
    assert out.exit_code == 2 and data["error"]["kind"] == "assembly"
    assert len(data["partial"]["coordinate"]) == 90


def test_move_still_stops_at_a_limit_position():
    from kinematika.api import prepare

    with pytest.raises(KinematikaError) as err:
        prepare(rocker_driven_tree(rocker_deg=120.0), move={"j4": 20})
    assert err.value.kind == "assembly" and err.value.where == "move.j4"
    assert f"after {SWING[1] - 120:.6g}°" in err.value.message


def test_a_row_of_the_sweep_past_a_limit_is_posed_on_the_other_branch():
    """The page's slider at rest solves its row exactly (the API's `row`): past a limit
    position the coordinate is one the drawn branch reaches too, but the row is on the
    other branch."""
    from kinematika.commands import How, solve_data

    tree = rocker_driven_tree(rocker_deg=120.0)
    rows = run_sweep(tree)
    k = 40                                                    # after the limit at 11.81°
    assert rows.limit_travel[0] < rows.travel[k] < rows.limit_travel[1]
    q = math.radians(120 + rows.coordinate[k])
    b = (4.0 + 3 * math.cos(q), 3 * math.sin(q))
    drawn = _side((0, 0), tree["points"]["B"], tree["points"]["A"])
    expected = circle_meet((0.0, 0.0), 1.0, b, 4.0, -drawn)   # A on the other side of O2→B
    solved = solve_data(tree, how=How(row=k))
    assert solved["points"]["A@crank"]["position"] == pytest.approx(list(expected), abs=1e-9)
    np.testing.assert_allclose(rows.points["A@crank"]["position"][k], expected, atol=1e-9)
    assert solved["bodies"]["crank"]["omega"] == pytest.approx(rows.bodies["crank"]["omega"][k], rel=1e-8)
    moved = solve_data(tree, how=How(move={"j4": str(rows.coordinate[k])}))   # the drawn branch
    assert moved["points"]["A@crank"]["position"] == pytest.approx(
        list(circle_meet((0.0, 0.0), 1.0, b, 4.0, drawn)), abs=1e-9)


# a spatial linkage (Newton's path in 3D) ------------------------------------------------------------
def test_a_spatial_four_bar_driven_from_its_rocker_reverses_at_its_limit():
    """The RSSR example driven from its rocker (about x at D = (2, 0, 1), B drawn 1.5 from D
    along y): B = D + 1.5 (0, cos t, sin t), the crank's pin A = (−sin s, cos s, 0), the
    coupler |AB|² = 5.25. |AB|² = 5 + 2.25 cos² t + (1 + 1.5 sin t)² + 4 sin s − 3 cos t cos s,
    whose least over s is with 4 sin s − 3 cos t cos s = −√(16 + 9 cos² t): the rocker can go
    on while that least is at most 5.25."""
    import yaml
    from scipy.optimize import brentq

    tree = yaml.safe_load((EXAMPLES / "rssr_spatial_four_bar.yaml").read_text())
    tree["points"]["B"] = [2, 1.5, 1]
    tree["drivers"] = [{"joint": "rocker_pin", "rate": 1}]
    tree.pop("sweep"), tree.pop("ask")

    def least(t: float) -> float:
        c = math.cos(t)
        return 5 + 2.25 * c * c + (1 + 1.5 * math.sin(t)) ** 2 - math.sqrt(16 + 9 * c * c) - 5.25

    limit = math.degrees(brentq(least, math.radians(10), math.radians(80), xtol=1e-15))
    result = run_sweep(tree, by=40, steps=5)
    assert result.method == "newton"
    assert result.limits == pytest.approx([limit], abs=1e-8)
    assert result.coordinate[-1] == pytest.approx(limit - (40 - limit), abs=1e-8)
    b = result.points["B@rocker"]["position"]
    a = result.points["A@crank"]["position"]
    np.testing.assert_allclose(np.linalg.norm(a - b, axis=1), math.sqrt(5.25), atol=1e-9)
