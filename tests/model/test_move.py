"""`move` and assemblies: against sweep rows, and against independent position analysis
(Freudenstein's equation, the slider-crank's closed form, the limit of a non-Grashof crank)."""
from __future__ import annotations

import functools
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

import kinematika
from kinematika import KinematikaError
from kinematika.api import prepare
from kinematika.report.json_answer import solution_json
from kinematika.sweep import run_sweep
from kinematika.sweep.assemblies import assemblies

from tests.conftest import DEEP
from tests.model.test_cases import kinematika as run_cli

from .test_constructions import four_bar_tree, freudenstein, norton_rates, slider_crank_tree
import itertools

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def moved_json(source, **move) -> dict:
    return solution_json(kinematika.solve(source, move=move))


@pytest.mark.parametrize("delta", [30, -75, 200, 720])
def test_moved_four_bar_is_freudenstein_at_the_new_crank_angle(delta):
    a, b, c, d, t0 = 2.25, 6.1, 4.35, 5.2, 52
    js = moved_json(four_bar_tree(a, b, c, d, t0), j1=delta)
    t2 = math.radians(t0 + delta)
    t3, t4 = freudenstein(a, b, c, d, t2)
    assert js["points"]["A@crank"]["position"] == pytest.approx([a * math.cos(t2), a * math.sin(t2)], abs=1e-9)
    assert js["points"]["B@rocker"]["position"] == pytest.approx(
        [d + c * math.cos(t4), c * math.sin(t4)], abs=1e-9)
    expected = norton_rates(a, b, c, t2, t3, t4, 9.5, -21.0)
    assert [x["value"] for x in js["answers"]] == pytest.approx(list(expected), rel=1e-8, abs=1e-8)


def test_a_file_move_equals_the_option_and_set_reposes_a_constructed_model():
    tree = four_bar_tree()
    tree["move"] = {"j1": "10*3"}                  # an expression: 30 degrees
    by_file = solution_json(kinematika.solve(tree))
    tree.pop("move")
    by_option = moved_json(tree, j1=30)
    reposed = solution_json(kinematika.solve(tree, set={"theta": "deg(82)"}))
    for other in (by_option, reposed):
        for key, values in by_file["points"].items():
            assert values["position"] == pytest.approx(other["points"][key]["position"], abs=1e-9)
        assert [x["value"] for x in by_file["answers"]] == pytest.approx([x["value"] for x in other["answers"]])


@pytest.mark.parametrize("name, amount", [("four_bar", 137.0), ("slider_crank", -50.0),
                                          ("quick_return", 95.0), ("watt_six_bar", 222.0),
                                          ("jansen_leg", 300.0), ("inverted_slider_crank", 40.0),
                                          ("pulley_train", 33.0), ("planetary_gears", 40.0),
                                          ("triad_six_bar", 25.0), ("spherical_four_bar", 30.0)])
def test_move_equals_the_last_row_of_the_sweep(name, amount):
    path = EXAMPLES / f"{name}.yaml"
    model = kinematika.as_model(path)
    joint = next(iter(__import__("kinematika.sweep.plan", fromlist=["x"]).driven_joints(model)))
    row = run_sweep(path, joint=joint, by=amount, steps=max(1, int(abs(amount)))).to_json()
    js = moved_json(path, **{joint: amount})
    for key, values in js["points"].items():
        for q in ("position", "velocity", "acceleration"):
            assert values[q] == pytest.approx(row["points"][key][q][-1], rel=1e-7, abs=1e-7), (key, q)
    for body, values in js["bodies"].items():
        for q in ("omega", "alpha"):
            assert values[q] == pytest.approx(row["bodies"][body][q][-1], rel=1e-7, abs=1e-7), (body, q)


def test_move_of_a_slider():
    # offset slider-crank driven by its slider: move the slider 1.5 back from x_C(40°)
    tree = slider_crank_tree(theta=40)
    tree["drivers"] = [{"velocity": "C", "along": [1, 0], "value": 2}]
    js0 = solution_json(kinematika.solve(tree))
    x0 = js0["points"]["C@slider"]["position"][0]
    js = moved_json(tree, j4=-1.5)
    x = x0 - 1.5
    # the crank angle on the same branch: 3 cos t + sqrt(121 - (3 sin t + 2)^2) = x, near 40°
    t = math.radians(40)
    for _ in range(60):
        f = 3 * math.cos(t) + math.sqrt(121 - (3 * math.sin(t) + 2) ** 2) - x
        df = -3 * math.sin(t) - 3 * math.cos(t) * (3 * math.sin(t) + 2) / math.sqrt(121 - (3 * math.sin(t) + 2) ** 2)
        t -= f / df
    assert js["points"]["C@slider"]["position"] == pytest.approx([x, -2], abs=1e-9)
    assert js["points"]["A@crank"]["position"] == pytest.approx([3 * math.cos(t), 3 * math.sin(t)], abs=1e-9)


def test_a_slot_pin_is_one_place_and_the_rocker_point_there_its_coincident_point():
    js = moved_json(EXAMPLES / "quick_return.yaml", j1=61)
    for point in {k.partition("@")[0] for k in js["points"]}:   # one place per name
        places = [v["position"] for k, v in js["points"].items() if k.partition("@")[0] == point]
        assert all(p == pytest.approx(places[0], abs=1e-9) for p in places), point
    # the rocker's point at the pin moves as the rocker: v = ω × (A − O4)
    (ox, oy), (ax, ay) = js["points"]["O4@rocker"]["position"], js["points"]["A@rocker"]["position"]
    w = js["bodies"]["rocker"]["omega"]
    assert js["points"]["A@rocker"]["velocity"] == pytest.approx([-w * (ay - oy), w * (ax - ox)], abs=1e-9)


def test_move_beyond_reach_says_how_far():
    # a non-Grashof (triple-rocker) four-bar: a = 4, b = 3, c = 3, d = 5; the crank stops when
    # coupler and rocker line up: |A O4| = b + c, cos t = (a² + d² − (b + c)²) / (2 a d)
    tree = four_bar_tree(a=4, b=3, c=3, d=5, theta=60)
    limit = math.degrees(math.acos((16 + 25 - 36) / 40))      # 82.82°
    with pytest.raises(KinematikaError) as info:
        kinematika.solve(tree, move={"j1": 60})
    err = info.value
    assert err.kind == "assembly" and err.where == "move.j1"
    got = float(err.message.rsplit("after ", 1)[1].rstrip("°"))
    assert got == pytest.approx(limit - 60, abs=0.05)


@pytest.mark.parametrize("move, kind, where", [({"j2": 10}, "schema", "move.j2"),
                                               ({"j9": 10}, "schema", "move.j9"),
                                               ({"j1": "q"}, "schema", "move.j1")])
def test_bad_moves(move, kind, where):
    with pytest.raises(KinematikaError) as info:
        kinematika.solve(four_bar_tree(), move=move)
    assert (info.value.kind, info.value.where) == (kind, where)


def test_spatial_move_of_the_rssr():
    path = EXAMPLES / "rssr_spatial_four_bar.yaml"
    js = moved_json(path, crank_pin=-40)
    row = run_sweep(path, joint="crank_pin", by=-40, steps=40).to_json()
    for key, values in js["points"].items():
        assert values["position"] == pytest.approx(row["points"][key]["position"][-1], abs=1e-7)
        assert values["velocity"] == pytest.approx(row["points"][key]["velocity"][-1], abs=1e-7)


# assemblies ----------------------------------------------------------------------------------
def test_four_bar_has_two_assemblies_open_and_crossed():
    found = assemblies(kinematika.as_model(four_bar_tree()))
    assert [a.number for a in found] == [1, 2] and [a.drawn for a in found] == [True, False]
    assert found[0].closures == ["B left of A→O4"] and found[1].closures == ["B right of A→O4"]
    _, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, math.radians(52), open_circuit=False)
    crossed = solution_json(kinematika.solve(four_bar_tree(), assembly=2))
    assert crossed["points"]["B@rocker"]["position"] == pytest.approx(
        [5.2 + 4.35 * math.cos(t4), 4.35 * math.sin(t4)], abs=1e-9)
    # drawn on the other side, the same two are numbered the same way
    other = assemblies(kinematika.as_model(four_bar_tree(side="right")))
    assert [a.drawn for a in other] == [False, True]


def test_watt_six_bar_has_four_and_the_numbers_do_not_depend_on_the_drawing():
    found = assemblies(kinematika.as_model(EXAMPLES / "watt_six_bar.yaml"))
    assert len(found) == 4 and sum(a.drawn for a in found) == 1
    for a in found:
        again = assemblies(a.model)
        assert [b.closures for b in again] == [b.closures for b in found]
        assert [b.drawn for b in again] == [b.number == a.number for b in found]


@pytest.mark.parametrize("name, count", [("jansen_leg", 8), ("quick_return", 2), ("slider_crank", 2)])
def test_every_assembly_keeps_every_body_rigid_and_differs_from_the_others(name, count):
    from kinematika.engine.instant import instantiate

    model = kinematika.as_model(EXAMPLES / f"{name}.yaml")
    drawn = instantiate(model, False).points
    found = assemblies(model)
    assert len(found) == count and sum(a.drawn for a in found) == 1
    places = []
    for a in found:
        pts = instantiate(a.model, False).points
        for body in model.bodies.values():
            own = [p for p in body.points          # the body's own material points, not a pin
                   if any(body.name in c and model.place_owner(p) in c
                          for c in model.motion_classes(p, model.carriers(p)))]
            for p, q in itertools.pairwise(own):
                assert math.dist(pts[p], pts[q]) == pytest.approx(math.dist(drawn[p], drawn[q]), abs=1e-9)
        kinematika.solve(a.model)                  # each is a mechanism the engine accepts
        places.append([c for name in sorted(pts) for c in pts[name]])
    for i in range(len(places)):
        for j in range(i):
            assert max(abs(x - y) for x, y in zip(places[i], places[j])) > 1e-6


def test_assembly_option_on_the_command_line(tmp_path):
    """`assemblies` in a child process, as a user runs it; the options' errors in this
    process (click's runner: the same command and JSON, without an interpreter's start-up)."""
    out = subprocess.run([sys.executable, "-m", "kinematika", "assemblies", str(EXAMPLES / "four_bar.yaml"),
                          "--json"], capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    assert [a["number"] for a in data["assemblies"]] == [1, 2]
    code, out = run_cli("solve", str(EXAMPLES / "four_bar.yaml"), "--assembly", "3", "--json")
    assert code == 2 and out["error"]["kind"] == "usage"
    code, out = run_cli("solve", str(EXAMPLES / "four_bar.yaml"), "--move", "j1", "--json")
    assert code == 2 and out["error"] == {
        "kind": "usage", "message": "--move expects NAME=VALUE, got 'j1'", "where": "--move"}


def test_prepare_reads_text_in_any_format():
    text = json.dumps(four_bar_tree())
    js = solution_json(kinematika.solve(prepare(text, fmt="json", move={"j1": 30})))
    ref = moved_json(four_bar_tree(), j1=30)
    assert js["points"]["B@rocker"]["position"] == pytest.approx(ref["points"]["B@rocker"]["position"])


# moving models with symbolic parameters ----------------------------------------------------
def symbolic_answers(sol) -> list:
    """The answers of `solve --json` to a symbolic solution's questions, as it writes them
    (without the tables of every point's motion as formulas, which no test here reads)."""
    from kinematika.questions import answer
    from kinematika.report.values import plain

    assert sol.symbolic is True
    return [plain(answer(sol, q), True) for q in sol.model.questions]


def test_symbolic_slider_crank_moved_is_the_formula_at_the_advanced_angle():
    import sympy

    th = sympy.Symbol("theta", positive=True)
    tree = slider_crank_tree()
    tree["parameters"] = {"theta": None}
    vc, w_rod = symbolic_answers(kinematika.solve(tree, move={"j1": 30}))
    t = th + sympy.pi / 6                           # the hand derivation at θ + 30°
    root = sympy.sqrt(121 - (3 * sympy.sin(t) + 2) ** 2)
    expected_w = -12 * sympy.cos(t) / root
    formula = sympy.sympify(w_rod, locals={"theta": th})
    for value in (0.2, 1.3, 2.9):
        assert float(formula.subs(th, value)) == pytest.approx(float(expected_w.subs(th, value)), abs=1e-12)


def test_a_model_symbolic_only_in_its_rates_moves_with_numbers():
    import sympy

    tree = four_bar_tree()
    tree["parameters"]["w"] = None
    tree["drivers"] = [{"omega": "crank", "value": "w"}]
    answers = symbolic_answers(kinematika.solve(tree, move={"j1": 40}))
    t2 = math.radians(92)
    t3, t4 = freudenstein(2.25, 6.1, 4.35, 5.2, t2)
    w3, w4, _, _ = norton_rates(2.25, 6.1, 4.35, t2, t3, t4, 1.0, 0.0)
    w = sympy.Symbol("w", positive=True)
    got = sympy.sympify(answers[0], locals={"w": w})
    assert float(got.subs(w, 1)) == pytest.approx(w3, abs=1e-8)


def test_a_symbolic_point_that_does_not_follow_the_input_is_refused():
    tree = four_bar_tree()
    tree["parameters"]["q"] = None                 # the rocker's angle a symbol, B by coordinates:
    tree["points"]["B"] = ["d + c*cos(q)", "c*sin(q)"]      # B cannot follow the crank
    tree["points"]["A"] = {"circles": [["O2", "a"], ["B", "b"]], "side": "right"}
    with pytest.raises(KinematikaError) as info:
        prepare(tree, move={"j1": 10})
    assert info.value.where == "move.j1" and "'B'" in info.value.message


# each search is seconds of work: a planar triad and a spherical group by default, the spatial
# RSSR too in a deep run
@pytest.mark.parametrize("name, count", [("triad_six_bar", 2), ("spherical_four_bar", 2)]
                         + ([("rssr_spatial_four_bar", 2)] if DEEP else []))
def test_assemblies_of_groups_that_are_not_dyads_are_found_and_rigid(name, count):
    from kinematika.engine.instant import instantiate

    model = kinematika.as_model(EXAMPLES / f"{name}.yaml")
    drawn = instantiate(model, False).points
    found = assemblies(model)
    assert len(found) == count and [a.drawn for a in found].count(True) == 1
    for a in found:
        pts = instantiate(a.model, False).points
        for body in model.bodies.values():               # every pair of a body's points
            for i, p in enumerate(body.points):
                for q in body.points[i + 1:]:
                    assert math.dist(pts[p], pts[q]) == pytest.approx(math.dist(drawn[p], drawn[q]), abs=1e-8)
        from kinematika.sweep.plan import driven_joints

        joint = model.joint(next(iter(driven_joints(model))))
        for body in (model.frame, joint.a, joint.b):     # the frame and the input stay
            for p in model.bodies[body].points:
                assert pts[p] == pytest.approx(drawn[p], abs=1e-9)
        kinematika.solve(a.model)                        # the engine accepts every joint there


@pytest.mark.parametrize("name", ["vehicle_upper_wheel", "seed_c5_e4_upper_wheel", "wheel_rolling"])
def test_models_without_a_held_input_or_with_symbols_list_the_drawn_assembly(name):
    found = assemblies(kinematika.as_model(EXAMPLES / f"{name}.yaml"))
    assert [(a.number, a.drawn) for a in found] == [(1, True)]


@functools.lru_cache(maxsize=None)
def _four_bar_with_symbolic_crank() -> dict:
    """`kinematika solve four_bar.yaml --set theta2=null --json`, once (in this process)."""
    code, out = run_cli("solve", str(EXAMPLES / "four_bar.yaml"), "--set", "theta2=null", "--json")
    assert code == 0, out
    return out


@pytest.mark.parametrize("theta", [20.0, 90.0, 200.0, 321.0])
def test_set_null_makes_the_crank_angle_a_symbol(theta):
    """`--set theta2=null` turns a numeric example's crank angle into θ2, as `null` in the
    file would: the coupler's and rocker's ω are formulas that equal Freudenstein and
    Norton's rates wherever they are evaluated (the example: a=1, b=4, c=3, d=4, w=10)."""
    import sympy

    js = _four_bar_with_symbolic_crank()
    assert js["symbolic"] is True
    values = {next(iter(a["ask"].items())): a["value"] for a in js["answers"]}
    t2 = math.radians(theta)
    t3, t4 = freudenstein(1, 4, 3, 4, t2)
    w3, w4, _, _ = norton_rates(1, 4, 3, t2, t3, t4, 10.0, 0.0)
    at = {sympy.Symbol("theta2"): t2}
    assert float(sympy.sympify(values[("omega", "coupler")]).subs(at)) == pytest.approx(w3, rel=1e-9)
    assert float(sympy.sympify(values[("omega", "rocker")]).subs(at)) == pytest.approx(w4, rel=1e-9)


def test_set_null_through_the_api_and_a_bad_set_value():
    """`set` in the API makes a parameter a symbol as `--set NAME=null` does (here the crank's
    speed w2, a formula linear in it: the crank angle's longer formulas are the command
    line's test above); a value that is no number is refused by name."""
    import sympy

    js = solution_json(kinematika.solve(prepare((EXAMPLES / "four_bar.yaml").read_text(), set={"w2": None})))
    assert js["symbolic"] is True
    values = {next(iter(a["ask"].items())): a["value"] for a in js["answers"]}
    t2 = math.radians(90)
    t3, t4 = freudenstein(1, 4, 3, 4, t2)
    w3, w4, _, _ = norton_rates(1, 4, 3, t2, t3, t4, 10.0, 0.0)
    at = {sympy.Symbol("w2"): 10}
    assert float(sympy.sympify(values[("omega", "coupler")]).subs(at)) == pytest.approx(w3, rel=1e-9)
    assert float(sympy.sympify(values[("omega", "rocker")]).subs(at)) == pytest.approx(w4, rel=1e-9)
    with pytest.raises(KinematikaError) as err:
        prepare((EXAMPLES / "four_bar.yaml").read_text(), set={"theta2": "nul"})
    assert "nul" in err.value.message
