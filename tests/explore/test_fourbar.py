"""The closed-form four-bar of synthesis against an independent closure: positions by the law
of cosines, derivatives by central differences of that closure, the crank's limit positions
and the transmission angle against their definitions, Grashof's classes by hand."""
from __future__ import annotations

import numpy as np
import pytest

from kinematika.explore.fourbar import (FourBar, crank_range, grashof_class, least_transmission, pose,
                                        transmission_gaps)


def closure(o2, o4, r2, r3, r4, c, side, phi):
    """A, B, P by the law of cosines: the angle γ at A between A→O4 and A→B,
    cos γ = (r3² + |d|² − r4²) / (2 r3 |d|), B on the `side` (+1 left) of A→O4."""
    a = o2 + r2 * np.exp(1j * phi)
    d = o4 - a
    cos = (r3 ** 2 + abs(d) ** 2 - r4 ** 2) / (2 * r3 * abs(d))
    if abs(cos) > 1:
        return None
    theta3 = np.angle(d) + side * np.arccos(cos)
    b = a + r3 * np.exp(1j * theta3)
    return a, b, a + c * np.exp(1j * theta3)


DESIGNS = [(0.3 - 0.2j, 4.1 + 0.7j, 1.1, 3.9, 3.2, 2.1 + 1.3j, 1.0),
           (-1.0 + 2.0j, 2.5 - 1.0j, 1.4, 2.0, 3.1, -0.7 + 0.4j, -1.0),
           (0.0j, 5.0 + 0.0j, 2.0, 3.0, 4.5, 1.5 - 2.0j, 1.0)]


def four_bar(design, phi0=0.0):
    o2, o4, r2, r3, r4, c, side = design
    return FourBar(np.array([[o2]]), np.array([[o4]]), np.array([[r2]]), np.array([[r3]]), np.array([[r4]]),
                   np.array([[c]]), np.array([[side]]), np.array([[phi0]]))


@pytest.mark.parametrize("design", DESIGNS)
def test_positions_are_the_closure_by_the_law_of_cosines(design):
    phi = np.linspace(0, 2 * np.pi, 37)
    at, _ = pose(four_bar(design), phi[None, :])
    for k, angle in enumerate(phi):
        expect = closure(*design, angle)
        if expect is None:
            assert np.isnan(at.p[0, k])
            continue
        assert at.a[0, k] == pytest.approx(expect[0], abs=1e-12)
        assert at.b[0, k] == pytest.approx(expect[1], abs=1e-12)
        assert at.p[0, k] == pytest.approx(expect[2], abs=1e-12)


@pytest.mark.parametrize("design", DESIGNS)
def test_the_tangents_are_the_closures_derivatives(design):
    """Each of the ten variables (O2, O4 components, r2, r3, r4, c components, φ) moved by ±h
    in the independent closure: the central difference is the kernel's tangent."""
    phi = np.array([[0.4, 1.9, 3.3]])
    at, tangent = pose(four_bar(design), phi, tangents=True)
    h = 1e-6
    for k, angle in enumerate(phi[0]):
        if np.isnan(at.p[0, k]):
            continue
        for var in range(10):
            plus, minus = list(design), list(design)
            step = [1, 1j, 1, 1j, 1, 1, 1, 1, 1j, None][var]
            slot = [0, 0, 1, 1, 2, 3, 4, 5, 5, None][var]
            if slot is None:
                up, down = closure(*design, angle + h), closure(*design, angle - h)
            else:
                plus[slot] = design[slot] + step * h
                minus[slot] = design[slot] - step * h
                up, down = closure(*plus, angle), closure(*minus, angle)
            for name, i in (("a", 0), ("b", 1), ("p", 2)):
                fd = (up[i] - down[i]) / (2 * h)
                assert getattr(tangent, name)[0, k, var] == pytest.approx(fd, abs=1e-6)


@pytest.mark.parametrize("design", DESIGNS)
def test_the_crank_range_ends_where_the_dyad_stretches_or_folds(design):
    """A limited crank stops where |A − O4| is r3 + r4 or |r3 − r4| (coupler and rocker in
    line); just inside it assembles, just outside it does not."""
    o2, o4, r2, r3, r4, c, side = design
    for phi0 in np.linspace(0.1, 6.2, 9):
        fb = four_bar(design, phi0)
        reach = crank_range(fb)
        assembles = closure(*design, phi0) is not None
        assert bool(reach.drawn[0, 0]) == assembles
        if not assembles or reach.full[0, 0]:
            continue
        low, high = float(reach.low[0, 0]), float(reach.high[0, 0])
        assert low <= phi0 <= high
        for end, out in ((low, -1), (high, 1)):
            dist = abs(o4 - o2 - r2 * np.exp(1j * end))
            assert min(abs(dist - (r3 + r4)), abs(dist - abs(r3 - r4))) == pytest.approx(0, abs=1e-9)
            assert closure(*design, end - out * 1e-6) is not None
            assert closure(*design, end + out * 1e-6) is None


def transmission_by_sampling(design):
    """min(μ, 180° − μ) over a dense turn of the crank, μ the angle between coupler and rocker."""
    o2, o4, r2, r3, r4, c, side = design
    worst = 90.0
    for phi in np.linspace(0, 2 * np.pi, 721):
        got = closure(*design, phi)
        if got is None:
            return 0.0
        a, b, _ = got
        mu = np.degrees(abs(np.angle((a - b) / (o4 - b))))
        worst = min(worst, mu, 180 - mu)
    return worst


def test_the_least_transmission_angle_is_the_least_over_the_turn():
    crank_rocker = (0.0j, 4.0 + 0.0j, 1.0, 3.5, 3.0, 1.0 + 1.0j, 1.0)
    limited = DESIGNS[1]
    for design in (crank_rocker, limited, DESIGNS[0]):
        got = float(least_transmission(four_bar(design))[0, 0])
        assert got == pytest.approx(transmission_by_sampling(design), abs=0.05)
    # the margins: positive exactly when the least angle is above the bound
    fb = four_bar(crank_rocker)
    least = float(least_transmission(fb)[0, 0])
    assert (transmission_gaps(fb, least - 1)[:, 0, 0] >= 0).all()
    assert (transmission_gaps(fb, least + 1)[:, 0, 0] < 0).any()


@pytest.mark.parametrize("lengths, expect", [
    ((4, 1, 3.5, 3), "crank-rocker"), ((1, 4, 3.5, 3), "double-crank"), ((4, 3.5, 1, 3), "double-rocker"),
    ((4, 3.5, 3, 1), "rocker-crank"), ((4, 1, 2, 2.5), "non-grashof"), ((4, 1, 3, 2), "change-point")])
def test_grashof_classes_by_hand(lengths, expect):
    ground, crank, coupler, rocker = lengths
    fb = FourBar(np.array([0j]), np.array([ground + 0j]), np.array([crank]), np.array([coupler]),
                 np.array([rocker]), np.array([0j]), np.array([1.0]), np.array([0.0]))
    assert grashof_class(fb)[0] == expect
