"""The inflection circle and pole tangent (`{inflection: BODY}`) against the classical
constructions done here by hand: Euler–Savary for the four-bar's coupler (its points A and
B move on circles about O2 and O4), the straight paths of the points on the circle, the
instant centre's own motion by finite differences, and a wheel rolling on the ground."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy

import kinematika
from kinematika import KinematikaError
from kinematika.report.json_answer import solution_json

from tests.model.test_constructions import four_bar_tree, freudenstein, norton_rates

LINKS = (2.25, 6.1, 4.35, 5.2)       # crank a, coupler b, rocker c, ground d


def places(theta: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A, B by Freudenstein (open circuit) and the coupler's instant centre I, where the lines
    O2A and O4B meet (Aronhold–Kennedy)."""
    a, b, c, d = LINKS
    _, t4 = freudenstein(a, b, c, d, theta, open_circuit=True)
    A = np.array([a * math.cos(theta), a * math.sin(theta)])
    B = np.array([d + c * math.cos(t4), c * math.sin(t4)])
    O4 = np.array([d, 0.0])
    s = np.linalg.solve(np.column_stack([A, O4 - B]), O4)     # s A = O4 + t (B − O4)
    return A, B, s[0] * A


def euler_savary_point(I: np.ndarray, P: np.ndarray, C: np.ndarray) -> np.ndarray:
    """The inflection circle's point on the ray I→P, P's path having its centre at C:
    1/IP − 1/IC = 1/IJ (distances signed along the ray)."""
    e = (P - I) / np.linalg.norm(P - I)
    return I + e / (1 / np.linalg.norm(P - I) - 1 / ((C - I) @ e))


def circumcircle(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, float]:
    m = 2 * np.array([q - p, r - p])
    centre = np.linalg.solve(m, [q @ q - p @ p, r @ r - p @ p])
    return centre, 2 * float(np.linalg.norm(centre - p))


def coupler_inflection(theta_deg: float, w: float = 9.5, alpha: float = -21.0, extra=None) -> list:
    tree = four_bar_tree(theta=theta_deg, w=w, alpha=alpha)
    tree["ask"] = [{"inflection": "coupler"}]
    for name, (x, y) in (extra or {}).items():
        tree["points"][name] = [float(x), float(y)]
        tree["bodies"]["coupler"].append(name)
        tree["ask"].append({"curvature": f"{name}@coupler"})
    return [x["value"] for x in solution_json(kinematika.solve(tree))["answers"]]


@pytest.mark.parametrize("theta", [52, 140, 300])
def test_the_coupler_circle_is_euler_savarys_through_the_pole(theta):
    t = math.radians(theta)
    A, B, I = places(t)
    centre, diameter = circumcircle(I, euler_savary_point(I, A, np.zeros(2)),
                                    euler_savary_point(I, B, np.array([LINKS[3], 0.0])))
    (got,) = coupler_inflection(theta)
    assert got["pole"] == pytest.approx(list(I), rel=1e-9, abs=1e-9)
    assert got["center"] == pytest.approx(list(centre), rel=1e-8)
    assert got["diameter"] == pytest.approx(diameter, rel=1e-8)
    n, tangent = np.array(got["pole_normal"]), np.array(got["pole_tangent"])
    assert got["inflection_pole"] == pytest.approx(list(I + diameter * n), rel=1e-8)
    assert n @ tangent == pytest.approx(0, abs=1e-12)
    # the circle is geometry: the crank's rate and angular acceleration do not change it
    (other,) = coupler_inflection(theta, w=-3.0, alpha=40.0)
    assert other["center"] == pytest.approx(got["center"], rel=1e-8)


def test_points_on_the_circle_move_straight_and_the_others_as_euler_savary_says():
    t = math.radians(52)
    A, B, I = places(t)
    centre, diameter = circumcircle(I, euler_savary_point(I, A, np.zeros(2)),
                                    euler_savary_point(I, B, np.array([LINKS[3], 0.0])))
    on = {f"K{k}": centre + diameter / 2 * np.array([math.cos(u), math.sin(u)])
          for k, u in enumerate((0.3, 1.9, 4.0))}
    P = np.array([3.0, 2.0])                                  # a coupler point off the circle
    _, *curvatures = coupler_inflection(52, extra={**on, "P": P})
    for value in curvatures[:-1]:
        assert value == {"radius": None, "center": None}
    # Euler–Savary for P: 1/IC = 1/IP − 1/IJ, J the circle's point on the ray I→P
    e = (P - I) / np.linalg.norm(P - I)
    ij = float(np.dot(2 * (centre - I), e))                   # the circle's chord from I along e
    ic = 1 / (1 / np.linalg.norm(P - I) - 1 / ij)
    assert curvatures[-1]["center"] == pytest.approx(list(I + ic * e), rel=1e-7)


def test_the_pole_moves_along_the_pole_tangent_at_the_pole_velocity():
    """u = dI/dt = (dI/dθ) ω₂ by central differences of I(θ), the lines O2A and O4B's
    meeting; and d = |u| / |ω₃|, ω₃ the coupler's rate (Norton's equation 6.18)."""
    t, w, h = math.radians(52), 9.5, 1e-6
    rate = (places(t + h)[2] - places(t - h)[2]) / (2 * h) * w
    (got,) = coupler_inflection(52, w=w)
    assert got["pole_velocity"] == pytest.approx(list(rate), rel=1e-6)
    assert got["pole_tangent"] == pytest.approx(list(rate / np.linalg.norm(rate)), rel=1e-6)
    a, b, c, d = LINKS
    t3, t4 = freudenstein(a, b, c, d, t, open_circuit=True)
    w3 = norton_rates(a, b, c, t, t3, t4, w, 0.0)[0]
    assert got["diameter"] == pytest.approx(np.linalg.norm(rate) / abs(w3), rel=1e-6)


def test_a_wheel_rolling_on_the_ground_has_its_centre_on_the_circle():
    """Radius R, centre C at (0, R) moving at v along x: I is the contact, a_I = R ω² up with
    ω = −v/R, so the circle has diameter R from I to C (C moves straight), and I moves with C."""
    R, v = sympy.symbols("R v", positive=True)
    tree = {"parameters": {"R": None, "v": None},
            "points": {"J": [0, 0], "C": [0, "R"]},
            "bodies": {"ground": {"points": ["J"], "line": {"through": "J", "direction": [1, 0]}},
                       "wheel": {"points": ["J", "C"], "circle": {"center": "C", "radius": "R"}}},
            "joints": [{"type": "rolling", "bodies": ["ground", "wheel"]}],
            "drivers": [{"velocity": "C", "along": [1, 0], "value": "v"}],
            "ask": [{"inflection": "wheel"}]}
    (got,) = [x["value"] for x in solution_json(kinematika.solve(tree))["answers"]]
    names = {"R": R, "v": v}

    def exact(x):
        return [sympy.sympify(c, locals=names) for c in x] if isinstance(x, list) else sympy.sympify(x, locals=names)

    assert exact(got["pole"]) == [0, 0] and exact(got["center"]) == [0, R / 2]
    assert exact(got["diameter"]) == R and exact(got["inflection_pole"]) == [0, R]
    assert exact(got["pole_velocity"]) == [v, 0] and exact(got["pole_tangent"]) == [1, 0]
    assert exact(got["pole_normal"]) == [0, 1]


def test_a_translating_body_has_no_circle_and_3d_asks_for_the_screw_axis():
    tree = {"points": {"O": [0, 0], "C": [1, 0]},
            "bodies": {"ground": ["O"], "slider": ["C"]},
            "joints": [{"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
            "drivers": [{"velocity": "C", "value": [2, 0]}], "ask": [{"inflection": "slider"}]}
    (got,) = [x["value"] for x in solution_json(kinematika.solve(tree))["answers"]]
    assert got == {"pole": None, "center": None, "diameter": None, "translation": True}
    spatial = {"dimension": 3, "points": {"O": [0, 0, 0], "A": [1, 0, 0]},
               "bodies": {"ground": ["O"], "arm": ["O", "A"]},
               "joints": [{"type": "revolute", "bodies": ["ground", "arm"], "at": "O", "axis": [0, 0, 1]}],
               "drivers": [{"omega": "arm", "value": [0, 0, 1]}], "ask": [{"inflection": "arm"}]}
    with pytest.raises(KinematikaError) as info:
        kinematika.solve(spatial)
    assert info.value.where == "ask[0]" and "planar" in info.value.message
