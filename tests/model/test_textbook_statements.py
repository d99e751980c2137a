"""Data as textbook statements give them: a velocity driver relative to a turning body ("the
collar slides at u relative to the bar"), and a 3D joint's axis through two points. Every
expected value is derived here by hand or with sympy.physics.vector."""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
import sympy
from sympy.physics.vector import Point, ReferenceFrame, dynamicsymbols

import kinematika
from kinematika.report.json_answer import solution_json
from kinematika.sweep import run_sweep

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def collar(r="r", w="w", u="u", th="th", along=("O", "E")) -> dict:
    """A bar turning about O at ω (steady), a collar C on it at r from O, sliding along it at
    u relative to the bar (steady)."""
    return {"name": "collar on a turning bar",
            "parameters": {"r": r, "w": w, "u": u, "th": th},
            "points": {"O": [0, 0], "C": {"from": "O", "distance": "r", "angle": "th"},
                       "E": {"from": "O", "distance": "2*r", "angle": "th"}},
            "bodies": {"ground": ["O"], "bar": ["O", "E"], "collar": ["C"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "bar"], "at": "O"},
                       {"type": "prismatic", "bodies": ["bar", "collar"], "along": ["O", "E"]}],
            "drivers": [{"omega": "bar", "value": "w", "alpha": 0},
                        {"velocity": "C@collar", "relative_to": "bar", "along": list(along),
                         "value": "u", "acceleration": 0}],
            "ask": [{"velocity": "C@collar"}, {"acceleration": "C@collar"}]}


def polar_motion(r, w, u, th):
    """By hand in polar coordinates (ṙ = u, r̈ = 0, θ̇ = ω, θ̈ = 0): v = ṙ e_r + r θ̇ e_θ,
    a = (r̈ − r θ̇²) e_r + (r θ̈ + 2 ṙ θ̇) e_θ."""
    er = np.array([math.cos(th), math.sin(th)])
    et = np.array([-math.sin(th), math.cos(th)])
    return u * er + r * w * et, -r * w * w * er + 2 * u * w * et


def test_a_velocity_driver_relative_to_a_turning_bar_gives_the_coriolis_term():
    r, w, u, th = sympy.symbols("r w u th", positive=True)
    js = solution_json(kinematika.solve(collar(None, None, None, None)))
    v, a = (x["value"] for x in js["answers"])
    # sympy.physics.vector: C = s(t) B.x in the bar's frame B, turned by q(t)
    q, s = dynamicsymbols("q s")
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", [q, N.z])
    O = Point("O")
    C = O.locatenew("C", s * B.x)
    vel = C.pos_from(O).dt(N)
    acc = vel.dt(N)
    values = {s.diff().diff(): 0, q.diff().diff(): 0, s.diff(): u, q.diff(): w, s: r, q: th}
    expected_v = [sympy.simplify(vel.dot(e).subs(_order(values))) for e in (N.x, N.y)]
    expected_a = [sympy.simplify(acc.dot(e).subs(_order(values))) for e in (N.x, N.y)]
    names = {"r": r, "w": w, "u": u, "th": th}
    assert [sympy.simplify(sympy.sympify(g, locals=names) - e) for g, e in zip(v, expected_v)] == [0, 0]
    assert [sympy.simplify(sympy.sympify(g, locals=names) - e) for g, e in zip(a, expected_a)] == [0, 0]


def _order(values: dict) -> list:
    """Substitutions highest derivative first (so that ṡ is not replaced inside s̈)."""
    return sorted(values.items(), key=lambda kv: -sympy.count_ops(kv[0]))


@pytest.mark.parametrize("along", [("O", "E"), ("0.955336489125606", "0.29552020666134")])
def test_the_relative_direction_turns_with_the_bar_in_a_sweep_and_a_move(along):
    """Numbers r = 1, ω = 2, u = 0.5, θ₀ = 0.3 rad; `along` as two points of the bar or as the
    bar's drawn direction in numbers (fixed in the bar). The other driver keeps its coordinate
    (the collar stays at r = 1), and every row has the polar-coordinate motion at θ₀ + q."""
    tree = collar(1, 2, 0.5, 0.3, along)
    result = run_sweep(kinematika.api.as_model(tree), joint="j1", by=180, steps=18)
    for k, q in enumerate(np.radians(result.coordinate)):
        v, a = polar_motion(1.0, 2.0, 0.5, 0.3 + q)
        assert result.points["C@collar"]["position"][k] == pytest.approx(
            [math.cos(0.3 + q), math.sin(0.3 + q)], abs=1e-9)
        assert result.points["C@collar"]["velocity"][k] == pytest.approx(v, abs=1e-9)
        assert result.points["C@collar"]["acceleration"][k] == pytest.approx(a, abs=1e-9)
    moved = solution_json(kinematika.solve(tree, move={"j1": 90}))
    v, a = polar_motion(1.0, 2.0, 0.5, 0.3 + math.pi / 2)
    assert moved["answers"][0]["value"] == pytest.approx(list(v), abs=1e-9)
    assert moved["answers"][1]["value"] == pytest.approx(list(a), abs=1e-9)


def arm_with_axes_by_points() -> dict:
    """The two-axis robot arm of examples/robot_arm_3d.yaml with both axes given by points:
    the yaw axis through O and S (vertical), the pitch axis through S and T, T on the base
    at h from S along (sin ψ, −cos ψ, 0)."""
    import yaml

    tree = yaml.safe_load((EXAMPLES / "robot_arm_3d.yaml").read_text())
    tree = copy.deepcopy(tree)
    tree["points"]["T"] = ["h*sin(psi)", "-h*cos(psi)", "h"]
    tree["bodies"]["base"] = ["O", "S", "T"]
    tree["joints"][0]["axis"] = ["O", "S"]
    tree["joints"][1]["axis"] = ["S", "T"]
    tree["ask"] = [{"omega": "arm"}, {"velocity": "E"}, {"acceleration": "E"}]
    return tree


def arm_by_hand(psi0, th0, yaw, pitch, rates=(0.5, 1.0), accels=(0.2, -0.5)):
    """sympy.physics.vector: the base turned by ψ about z, the arm by θ about the base's
    horizontal axis (sin ψ₀, −cos ψ₀, 0) turned with it; E = S + L (the arm's direction)."""
    L = 0.8
    p, t = dynamicsymbols("p t")
    N = ReferenceFrame("N")
    base = N.orientnew("base", "Axis", [p, N.z])
    axis = math.sin(psi0) * base.x - math.cos(psi0) * base.y
    arm = base.orientnew("arm", "Axis", [t, axis])
    S = Point("S")
    # E drawn at L (cos θ₀ cos ψ₀, cos θ₀ sin ψ₀, sin θ₀) from S: the same components in the arm's frame
    d = (math.cos(th0) * math.cos(psi0) * arm.x + math.cos(th0) * math.sin(psi0) * arm.y
         + math.sin(th0) * arm.z)
    E = S.locatenew("E", L * d)
    values = {p.diff().diff(): accels[0], t.diff().diff(): accels[1], p.diff(): rates[0],
              t.diff(): rates[1], p: yaw, t: pitch}
    pos = E.pos_from(S)
    v, a = pos.dt(N), pos.dt(N).dt(N)

    def num(vec):
        return [float(vec.dot(e).subs(_order(values))) for e in (N.x, N.y, N.z)]

    w = arm.ang_vel_in(N)
    return num(w), num(v), num(a)


def test_a_3d_axis_given_by_two_points():
    got = [x["value"] for x in solution_json(kinematika.solve(arm_with_axes_by_points()))["answers"]]
    w, v, a = arm_by_hand(math.radians(30), math.radians(45), 0.0, 0.0)
    assert got[0] == pytest.approx(w, abs=1e-9)
    assert got[1] == pytest.approx(v, abs=1e-9)
    assert got[2] == pytest.approx(a, abs=1e-9)


def test_a_3d_axis_given_by_two_points_turns_with_its_body_when_moved():
    """Yaw moved 60° then pitch 20°: the pitch axis, two points of the base, has turned with it."""
    moved = solution_json(kinematika.solve(arm_with_axes_by_points(), move={"yaw": 60, "pitch": 20}))
    got = [x["value"] for x in moved["answers"]]
    w, v, a = arm_by_hand(math.radians(30), math.radians(45), math.radians(60), math.radians(20))
    assert got[0] == pytest.approx(w, abs=1e-9)
    assert got[1] == pytest.approx(v, abs=1e-9)
    assert got[2] == pytest.approx(a, abs=1e-9)
