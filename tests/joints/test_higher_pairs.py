"""Higher pairs — cams and followers, a pin in a curved slot, curves that slide — against
independent derivations: the motion laws' closed forms (a follower moves as its program
says: v = s'θ̇, a = s''θ̇²), the eccentric cam's y = e sin θ + R, and the equivalent
linkage of a circular slot (a four-bar through the slot's centre), solved here by hand."""
from __future__ import annotations

import copy
import math

import numpy as np
import pytest
import sympy

from kinematika.commands import solve_data, sweep_run
from kinematika.errors import KinematikaError
from tests.conftest import DEEP

W = 2 * math.pi                     # the cam's speed, rad/s (60 rev/min)
H, BETA = 25.0, math.pi / 2         # rise (mm) and its span (90°)


def cycloidal(theta_deg: float) -> tuple[float, float, float]:
    """s, s', s'' of the cycloidal rise over 90°-180° (Norton's eq. 8.6): s = h(x − sin 2πx/2π),
    s' = (h/β)(1 − cos 2πx), s'' = (2πh/β²) sin 2πx, x = (θ − 90°)/β."""
    x = (theta_deg - 90) / 90
    return (H * (x - math.sin(2 * math.pi * x) / (2 * math.pi)), H / BETA * (1 - math.cos(2 * math.pi * x)),
            2 * math.pi * H / BETA ** 2 * math.sin(2 * math.pi * x))


def return_345(theta_deg: float) -> tuple[float, float, float]:
    """s, s', s'' of the 3-4-5 return over 270°-360°: s = h(1 − (10x³ − 15x⁴ + 6x⁵))."""
    x = (theta_deg - 270) / 90
    return (H * (1 - (10 * x**3 - 15 * x**4 + 6 * x**5)), -H / BETA * (30 * x**2 - 60 * x**3 + 30 * x**4),
            -H / BETA ** 2 * (60 * x - 180 * x**2 + 120 * x**3))


PROGRAM = [{"law": "dwell", "over": 90}, {"law": "cycloidal", "over": 90, "to": 25},
           {"law": "dwell", "over": 90}, {"law": "3-4-5", "over": 90, "to": 0}]


def cam_model(theta: float, contact: str, offset: float = 0.0, s: float = 0.0) -> dict:
    """A disc cam (ccw) and a translating follower along x = offset: base circle 40 mm (80
    for a flat face, whose profile would be undercut on 40: R_b + s + s'' < 0 late in the rise)."""
    follower = {"motion": "translating", "contact": contact, "offset": offset}
    if contact == "roller":
        follower["radius"] = 10
    base = 80 if contact == "flat" else 40
    prime = 50.0 if contact == "roller" else 40.0
    height = math.sqrt(prime**2 - offset**2) + s if contact != "flat" else base + s
    body: dict = {"points": ["F"]}
    if contact == "flat":
        body["line"] = {"through": "F", "direction": [1, 0]}
    return {"name": "cam", "parameters": {"w": W},
            "points": {"O": [0, 0], "F": [offset, height]},
            "bodies": {"ground": ["O"],
                       "cam": {"points": ["O"], "cam": {"center": "O", "angle": f"deg({theta})", "base": base,
                                                        "follower": follower, "program": PROGRAM}},
                       "follower": body},
            "joints": [{"type": "revolute", "bodies": ["ground", "cam"], "at": "O"},
                       {"type": "prismatic", "bodies": ["ground", "follower"], "along": [0, 1]},
                       {"type": "cam", "bodies": ["cam", "follower"], **({} if contact == "flat" else {"at": "F"})}],
            "drivers": [{"omega": "cam", "value": "w"}],
            "ask": [{"velocity": "F"}, {"acceleration": "F"}]}


@pytest.mark.parametrize("contact", ["roller", "knife", "flat"])
@pytest.mark.parametrize("theta, law", [(112.5, cycloidal), (150.0, cycloidal), (300.0, return_345)])
def test_a_translating_follower_moves_as_its_program_says(contact, theta, law):
    s, ds, dds = law(theta)
    data = solve_data(cam_model(theta, contact, s=s))
    v, a = (x["value"] for x in data["answers"])
    assert v == pytest.approx([0.0, ds * W], abs=1e-7)
    assert a == pytest.approx([0.0, dds * W * W], abs=1e-5)


def test_an_offset_knife_edge_moves_as_its_program_says():
    s, ds, dds = cycloidal(130.0)
    data = solve_data(cam_model(130.0, "knife", offset=12.0, s=s))
    v, a = (x["value"] for x in data["answers"])
    assert v == pytest.approx([0.0, ds * W], abs=1e-7)
    assert a == pytest.approx([0.0, dds * W * W], abs=1e-5)


def test_an_oscillating_roller_follower_turns_as_its_program_says():
    """Pivot A = (80, 0), arm 50, roller 10 on a 40 mm base circle: B = (a − ℓ cos ψ, ℓ sin ψ),
    ψ = ψ₀ + s with cos ψ₀ = (a² + ℓ² − R_p²)/(2aℓ); the arm's angle from x is π − ψ, so
    ω_arm = −s'θ̇ and α_arm = −s''θ̇² (program in degrees of arm swing: 20°)."""
    theta, swing = 120.0, math.radians(20)
    x = (theta - 90) / 90
    s = swing * (x - math.sin(2 * math.pi * x) / (2 * math.pi))
    ds = swing / BETA * (1 - math.cos(2 * math.pi * x))
    dds = 2 * math.pi * swing / BETA**2 * math.sin(2 * math.pi * x)
    a, arm, rp = 80.0, 50.0, 50.0
    psi = math.acos((a * a + arm * arm - rp * rp) / (2 * a * arm)) + s
    program = [{"law": "dwell", "over": 90}, {"law": "cycloidal", "over": 90, "to": 20},
               {"law": "dwell", "over": 90}, {"law": "cycloidal", "over": 90, "to": 0}]
    tree = {"parameters": {"w": W},
            "points": {"O": [0, 0], "A": [a, 0], "B": [a - arm * math.cos(psi), arm * math.sin(psi)]},
            "bodies": {"ground": ["O", "A"],
                       "cam": {"points": ["O"], "cam": {"center": "O", "angle": f"deg({theta})", "base": 40,
                                                        "follower": {"motion": "oscillating", "contact": "roller",
                                                                     "radius": 10, "pivot": a, "arm": arm},
                                                        "program": program}},
                       "arm": ["A", "B"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "cam"], "at": "O"},
                       {"type": "revolute", "bodies": ["ground", "arm"], "at": "A"},
                       {"type": "cam", "bodies": ["cam", "arm"], "at": "B"}],
            "drivers": [{"omega": "cam", "value": "w"}], "ask": [{"omega": "arm"}, {"alpha": "arm"}]}
    omega, alpha = (x["value"] for x in solve_data(tree)["answers"])
    assert omega == pytest.approx(-ds * W, abs=1e-9)
    assert alpha == pytest.approx(-dds * W * W, abs=1e-7)


@pytest.mark.parametrize("contact, lowest", [("roller", 50), ("knife", 40), ("flat", 80)])
def test_a_sweep_of_the_cam_follows_the_program_over_a_turn(contact, lowest):
    """The follower's height over a turn: its lowest (the prime or base circle) + s(θ)."""
    s0 = cycloidal(112.5)[0]
    # a row every 30° (7.5° deep): three in each of the program's four segments
    _, result = sweep_run(cam_model(112.5, contact, s=s0), steps=48 if DEEP else 12)
    y = np.asarray(result.points["F@follower"]["position"])[:, 1]
    expected = []
    for c in np.asarray(result.coordinate):
        th = (112.5 + c) % 360
        s = 0.0 if th < 90 else cycloidal(th)[0] if th < 180 else H if th < 270 else return_345(th)[0]
        expected.append(lowest + s)
    assert y == pytest.approx(expected, abs=1e-7)


ECCENTRIC = {"parameters": {"e": 0.02, "R": 0.05, "th": "deg(30)", "w": 10},
             "points": {"O": [0, 0], "C": {"from": "O", "distance": "e", "angle": "th"}, "F": [0, "e*sin(th) + R"]},
             "bodies": {"ground": ["O"], "cam": {"points": ["O", "C"], "circle": {"center": "C", "radius": "R"}},
                        "follower": {"points": ["F"], "line": {"through": "F", "direction": [1, 0]}}},
             "joints": [{"type": "revolute", "bodies": ["ground", "cam"], "at": "O"},
                        {"type": "prismatic", "bodies": ["ground", "follower"], "along": [0, 1]},
                        {"type": "contact", "bodies": ["cam", "follower"]}],
             "drivers": [{"omega": "cam", "value": "w", "alpha": 0}],
             "ask": [{"velocity": "F"}, {"acceleration": "F"}]}


def test_an_eccentric_cam_drives_a_flat_follower_as_y_is_e_sin_theta_plus_R():
    """The face's height y = e sin θ + R: v = e ω cos θ, a = −e ω² sin θ."""
    v, a = (x["value"] for x in solve_data(ECCENTRIC)["answers"])
    e, w, t = 0.02, 10, math.radians(30)
    assert v == pytest.approx([0, e * w * math.cos(t)], abs=1e-12)
    assert a == pytest.approx([0, -e * w * w * math.sin(t)], abs=1e-12)


def test_the_eccentric_cam_in_symbols():
    tree = copy.deepcopy(ECCENTRIC)
    tree["parameters"] = dict.fromkeys(("e", "R", "th", "w"))
    v, a = (x["value"] for x in solve_data(tree)["answers"])
    e, w, th = sympy.symbols("e w th", positive=True)
    assert sympy.simplify(sympy.sympify(v[1], locals={"e": e, "w": w, "th": th}) - e * w * sympy.cos(th)) == 0
    assert sympy.simplify(sympy.sympify(a[1], locals={"e": e, "w": w, "th": th}) + e * w**2 * sympy.sin(th)) == 0


def test_a_knife_edge_on_the_eccentric_circle():
    """An in-line knife edge on the eccentric circle: y = e sin θ + √(R² − e² cos² θ),
    differentiated by sympy."""
    th = sympy.Symbol("th")
    e, r, w = sympy.Rational(1, 50), sympy.Rational(1, 20), 10
    y = e * sympy.sin(th) + sympy.sqrt(r**2 - e**2 * sympy.cos(th) ** 2)
    at = {th: sympy.pi / 6}
    tree = copy.deepcopy(ECCENTRIC)
    tree["points"]["F"] = [0, float(y.subs(at))]
    tree["bodies"]["follower"] = ["F"]
    tree["joints"][2] = {"type": "contact", "bodies": ["cam", "follower"], "at": "F"}
    v, a = (x["value"] for x in solve_data(tree)["answers"])
    assert v[1] == pytest.approx(float((y.diff(th) * w).subs(at)), abs=1e-12)
    assert a[1] == pytest.approx(float((y.diff(th, 2) * w * w).subs(at)), abs=1e-10)


def _four_bar_by_hand(o, a, c, b, w2):
    """The equivalent four-bar O-A-C-B (crank OA at ω₂, α₂ = 0): v_C = v_A + ω₃ × AC =
    ω₄ × BC, a_C = a_A + α₃ × AC − ω₃² AC = α₄ × BC − ω₄² BC; returns ω₄, α₄."""
    def perp(v):
        return np.array([-v[1], v[0]])
    oa, ac, bc = a - o, c - a, c - b
    va = w2 * perp(oa)
    w3, w4 = np.linalg.solve(np.column_stack([perp(ac), -perp(bc)]), -va)
    aa = -w2 * w2 * oa
    rhs = -aa + w3 * w3 * ac - w4 * w4 * bc
    _, a4 = np.linalg.solve(np.column_stack([perp(ac), -perp(bc)]), rhs)
    return w4, a4


def test_a_pin_in_a_circular_slot_moves_the_rocker_as_its_equivalent_four_bar():
    """Crank OA (1 at 60°, 2 rad/s) whose pin A slides in a circular slot of the rocker
    (pivot B, slot centre C): the rocker turns as the four-bar O-A-C-B, whose coupler AC is
    the slot's radius (Norton §2.14)."""
    o, b, c = np.array([0.0, 0.0]), np.array([3.0, 0.0]), np.array([2.2, 1.6])
    a = np.array([math.cos(math.pi / 3), math.sin(math.pi / 3)])
    tree = {"points": {"O": [0, 0], "A": {"from": "O", "distance": 1, "angle": "deg(60)"}, "B": [3, 0],
                       "C": [2.2, 1.6]},
            "bodies": {"ground": ["O", "B"], "crank": ["O", "A"],
                       "rocker": {"points": ["B", "C"],
                                  "circle": {"center": "C", "radius": float(np.linalg.norm(c - a))}}},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "revolute", "bodies": ["ground", "rocker"], "at": "B"},
                       {"type": "curved_slot", "bodies": ["rocker", "crank"], "at": "A"}],
            "drivers": [{"omega": "crank", "value": 2}],
            "ask": [{"omega": "rocker"}, {"alpha": "rocker"}]}
    w4, a4 = _four_bar_by_hand(o, a, c, b, 2.0)
    omega, alpha = (x["value"] for x in solve_data(tree)["answers"])
    assert omega == pytest.approx(w4, abs=1e-12)
    assert alpha == pytest.approx(a4, abs=1e-10)


def test_a_follower_off_its_cam_is_a_geometry_error_naming_the_joint():
    tree = cam_model(112.5, "roller", s=cycloidal(112.5)[0] + 0.5)
    with pytest.raises(KinematikaError) as info:
        solve_data(tree)
    assert info.value.kind == "geometry" and info.value.where == "joints[2] (j3)"
    gap = float(info.value.message.rsplit("gap ", 1)[1])       # along the normal: 0.5 cos φ
    s, ds, _ = cycloidal(112.5)
    assert gap == pytest.approx(0.5 * math.cos(math.atan(ds / (50 + s))), rel=2e-2)


def test_a_cam_joint_needs_a_cam():
    tree = cam_model(112.5, "roller")
    del tree["bodies"]["cam"]["cam"]
    with pytest.raises(KinematikaError) as info:
        solve_data(tree)
    assert info.value.kind == "schema" and "give 'cam' a `cam:` shape" in info.value.message
