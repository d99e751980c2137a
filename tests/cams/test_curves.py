"""Curves: exact geometry of circles, a spline through a circle's points, nearest points
against brute force, derivatives against finite differences."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from kinematika.curves import Arc, CamProfile, Circle, Line, Spline, jet

R = 3.0
CENTRE = np.array([1.0, -2.0])


def ellipse() -> CamProfile:
    """x = 4 cos u + 0.5 cos 3u, y = 2 sin u: a closed, non-circular curve written on jets."""
    return CamProfile(lambda u: (4 * jet.cos(u) + 0.5 * jet.cos(3 * u), 2 * jet.sin(u)))


def circle_spline(n: int = 24) -> Spline:
    t = np.linspace(0, 2 * math.pi, n, endpoint=False)
    return Spline(CENTRE + R * np.c_[np.cos(t), np.sin(t)], closed=True)


def wave() -> Spline:
    x = np.linspace(0, 6, 13)
    return Spline(np.c_[x, np.sin(x)], closed=False)


CURVES = {"circle": Circle(CENTRE, R), "arc": Arc(CENTRE, R, 0.3, 2.5), "closed spline": circle_spline(),
          "open spline": wave(), "cam profile": ellipse(), "line": Line([1, 1], [3, 4], (-2.0, 5.0))}


def test_a_circles_curvature_is_one_over_its_radius_everywhere():
    u = np.linspace(0, 2 * math.pi, 50)
    c = Circle(CENTRE, R)
    assert np.allclose(c.curvature(u), 1 / R, rtol=1e-14)
    assert np.allclose(np.linalg.norm(c.point(u) - CENTRE, axis=1), R)
    assert np.allclose(c.normal(u), -(c.point(u) - CENTRE) / R)      # t turned +90° points in
    assert c.length == pytest.approx(2 * math.pi * R)


def test_a_spline_through_a_circles_points_has_nearly_its_curvature():
    """24 points: curvature within 1 % of 1/R everywhere (a periodic cubic spline's error is
    O(h²) in curvature: h = 2πR/24), length within 1e-4 relative; 96 points: 0.1 %."""
    for n, tol in ((24, 1e-2), (96, 1e-3)):
        s = circle_spline(n)
        u = np.linspace(*s.domain, 1000)
        assert np.max(np.abs(s.curvature(u) * R - 1)) < tol
        assert np.max(np.abs(np.linalg.norm(s.point(u) - CENTRE, axis=1) - R)) < tol * R
    assert circle_spline(24).length == pytest.approx(2 * math.pi * R, rel=1e-4)


def test_a_closed_spline_is_periodic_and_smooth_at_its_seam():
    s = circle_spline(7)
    a, b = s.domain
    for d in (s.point, s.d1, s.d2):
        assert np.allclose(d(a), d(b)) and np.allclose(d(a - 0.1), d(b - 0.1))


@pytest.mark.parametrize("name", list(CURVES))
@given(x=st.floats(-8, 8), y=st.floats(-8, 8))
def test_nearest_finds_the_closest_point_found_by_brute_force(name, x, y):
    curve = CURVES[name]
    p = np.array([x, y])
    u = curve.nearest(p)
    a, b = curve.domain
    assert a - 1e-12 <= u <= b + 1e-12
    brute = np.min(np.linalg.norm(curve.point(np.linspace(a, b, 20_001)) - p, axis=1))
    assert np.linalg.norm(curve.point(u) - p) <= brute + 1e-9


@pytest.mark.parametrize("name", list(CURVES))
@given(t=st.floats(0.02, 0.98))
def test_derivatives_match_finite_differences(name, t):
    curve = CURVES[name]
    a, b = curve.domain
    u, h = a + t * (b - a), 1e-5 * (b - a)
    central = (curve.point(u + h) - curve.point(u - h)) / (2 * h)
    second = (curve.point(u + h) - 2 * curve.point(u) + curve.point(u - h)) / h**2
    scale = 1 + np.max(np.abs(curve.point(u)))
    assert np.allclose(curve.d1(u), central, atol=1e-6 * scale)
    assert np.allclose(curve.d2(u), second, atol=1e-3 * scale)
    assert np.linalg.norm(curve.tangent(u)) == pytest.approx(1)
    assert float(np.dot(curve.tangent(u), curve.normal(u))) == pytest.approx(0, abs=1e-12)


def test_curvature_of_the_jet_curve_matches_its_hand_formula():
    """x = 4cos u + ½cos 3u, y = 2 sin u: κ = (x'y'' − y'x'')/(x'² + y'²)^{3/2} by hand."""
    u = np.linspace(0, 2 * math.pi, 37)
    x1, x2 = -4 * np.sin(u) - 1.5 * np.sin(3 * u), -4 * np.cos(u) - 4.5 * np.cos(3 * u)
    y1, y2 = 2 * np.cos(u), -2 * np.sin(u)
    kappa = (x1 * y2 - y1 * x2) / (x1**2 + y1**2) ** 1.5
    assert np.allclose(ellipse().curvature(u), kappa, rtol=1e-12)


def test_vectorised_calls_give_what_single_calls_give():
    c = CURVES["cam profile"]
    u = np.array([0.1, 1.0, 4.0])
    assert np.allclose(c.point(u), np.array([c.point(v) for v in u]))
    pts = np.array([[5.0, 1.0], [-3.0, -3.0]])
    assert np.allclose(c.nearest(pts), [c.nearest(p) for p in pts])


def test_a_line_is_straight_and_its_nearest_point_is_the_foot_of_the_perpendicular():
    line = Line([0, 1], [2, 0])
    assert line.nearest([3.5, 7]) == pytest.approx(3.5)
    assert np.all(line.curvature(np.array([0.0, 2.0])) == 0)
    assert line.length == math.inf
    with pytest.raises(ValueError):
        line.points(5)


def test_bad_curves_are_refused():
    with pytest.raises(ValueError):
        Circle([0, 0], 0)
    with pytest.raises(ValueError):
        Arc([0, 0], 1, 1.0, 0.5)
    with pytest.raises(ValueError):
        Spline([[0, 0], [0, 0], [1, 1]])
    with pytest.raises(ValueError):
        Line([0, 0], [0, 0])
