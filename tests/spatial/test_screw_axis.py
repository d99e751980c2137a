"""The instantaneous screw axis (`axis` question): a helical motion with sliding, a
translation, rest, and its defining properties on random chains against the exact
velocity field (the product of exponentials of test_chains)."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given

from kinematika import solve
from kinematika.api import answers

from .derive import EXAMPLES, assert_close
from .test_chains import chain_tree, chains, expected_motion, point_motion


def nut_on_a_screw(turn: float, advance: float) -> dict:
    """A nut on a fixed screw whose axis passes through A = (1, 2, 0.5) along d = (1, 2, 2)/3:
    a cylindrical joint, the nut's ω = turn d and the advance of its point A along d."""
    return {"dimension": 3,
            "points": {"A": [1, 2, 0.5], "B": [0, 0, 0], "Q": [2, 1, 0]},
            "bodies": {"ground": ["A", "B"], "nut": ["A", "Q"]},
            "joints": [{"type": "cylindrical", "bodies": ["ground", "nut"], "at": "A", "axis": [1, 2, 2]}],
            "drivers": [{"omega": "nut", "value": [turn / 3, 2 * turn / 3, 2 * turn / 3]},
                        {"velocity": "A@nut", "along": [1, 2, 2], "value": advance}],
            "ask": [{"axis": "nut"}, {"velocity": "Q"}]}


@pytest.mark.parametrize("turn,advance", [(2.0, 0.3), (-2.0, 0.3), (1.5, 0.0), (0.5, -1.0)])
def test_helical_motion_of_a_nut(turn, advance):
    d = np.array([1, 2, 2]) / 3
    a = np.array([1, 2, 0.5])
    (_, ax), (_, v_q) = answers(solve(nut_on_a_screw(turn, advance)))
    # the screw's axis itself: its point nearest the origin, ω̂ = sign(turn) d
    assert_close(ax["point"], a - (a @ d) * d)
    assert_close(ax["direction"], np.sign(turn) * d)
    assert ax["omega"] == pytest.approx(abs(turn))
    assert ax["slide"] == pytest.approx(np.sign(turn) * advance)
    # by hand: v_Q = advance d + turn d × (Q − A)
    assert_close(v_q, advance * d + turn * np.cross(d, np.array([2, 1, 0]) - a))


def test_translating_and_resting_bodies():
    tree = {"dimension": 3, "points": {"O": [0, 0, 0], "P": [1, 1, 1]},
            "bodies": {"ground": ["O"], "slider": ["P"], "still": ["O"]},
            "joints": [{"type": "prismatic", "bodies": ["ground", "slider"], "along": [0, 3, 4]},
                       {"type": "weld", "bodies": ["ground", "still"]}],
            "drivers": [{"velocity": "P", "along": [0, 3, 4], "value": -2}],
            "ask": [{"axis": "slider"}, {"axis": "still"}]}
    (_, moving), (_, still) = answers(solve(tree))
    assert moving["point"] is None and moving["omega"] == 0
    assert_close(moving["direction"], (0, -0.6, -0.8))
    assert moving["slide"] == pytest.approx(2)
    assert still == {"point": None, "direction": None, "omega": 0, "slide": 0, "rest": True}


def test_relative_screw_axis_of_the_fan_blades():
    """Seen from the motor block the blades turn about the hub axis BC (+x through B)."""
    sol = solve(EXAMPLES / "fan_composition.yaml")
    ax = answers(sol)[5][1]
    assert_close(ax["point"], (0, 0, 0))
    assert_close(ax["direction"], (1, 0, 0))
    assert ax["omega"] == pytest.approx(0.5)
    assert ax["slide"] == pytest.approx(0, abs=1e-12)


@given(chains())
def test_screw_axis_properties_on_random_chains(chain):
    """For every body: the axis point p is the one nearest the origin (p ⟂ ω), the exact
    velocity at p is along ω, and the slide is v·ω̂ for any point of the body."""
    joints, tips = chain
    sol = solve(chain_tree(joints, tips))
    for i, (w, _, first, second) in enumerate(expected_motion(joints)):
        ax = answers_axis(sol, f"b{i}")
        size = np.linalg.norm(w)
        v_origin, _ = point_motion(first, second, (0, 0, 0))
        if size < 1e-9:
            continue
        p = np.array(ax["point"], dtype=float)
        u = np.array(ax["direction"], dtype=float)
        assert_close(u, w / size, 1e-7)
        assert float(ax["omega"]) == pytest.approx(size, rel=1e-7)
        assert abs(p @ u) < 1e-7 * max(1.0, np.linalg.norm(p))
        v_p, _ = point_motion(first, second, p)
        assert_close(np.cross(v_p, u), (0, 0, 0), 1e-7)
        assert float(ax["slide"]) == pytest.approx(v_origin @ u, rel=1e-7, abs=1e-9)
        tip = tips[i]
        assert float(ax["slide"]) == pytest.approx(point_motion(first, second, tip)[0] @ u,
                                                   rel=1e-7, abs=1e-9)


def answers_axis(sol, body: str) -> dict:
    from kinematika.model.question import Question
    from kinematika.questions import answer

    return answer(sol, Question("axis", 0, body, {"axis": body}))


def test_a_point_of_the_nut_runs_on_a_helix():
    """Q at distance ρ from the screw's axis, steady turn ω and advance u: its path is a helix
    of radius of curvature (ω²ρ² + u²)/(ω²ρ), centred on the line from Q towards the axis."""
    turn, advance = 2.0, 0.3
    tree = nut_on_a_screw(turn, advance)
    tree["ask"] = [{"curvature": "Q"}]
    d = np.array([1, 2, 2]) / 3
    a, q = np.array([1, 2, 0.5]), np.array([2, 1, 0])
    radial = (q - a) - ((q - a) @ d) * d
    rho = np.linalg.norm(radial)
    expected = (turn ** 2 * rho ** 2 + advance ** 2) / (turn ** 2 * rho)
    curv = answers(solve(tree))[0][1]
    assert curv["radius"] == pytest.approx(expected)
    assert_close(curv["center"], q - expected * radial / rho)
