"""Random four-bars, slider-cranks and inverted slider-cranks: the solved motion matches the
loop equations differentiated by hand, every body's velocity and acceleration fields are
rigid, and every joint's velocity and acceleration conditions hold."""
from __future__ import annotations

from itertools import combinations

from hypothesis import given

import kinematika

from .mechanisms import (Drawn, add, dot, kcross, linkages, loop_closure, near, sub, times, unit)


def scales(m: Drawn, sol) -> tuple[float, float, float]:
    """Sizes of lengths, speeds and accelerations of this draw, for tolerances."""
    size = max(max(abs(c) for c in p) for p in m.points.values()) + 1.0
    rate = max(abs(float(sol.omega(b))) for b in sol.model.bodies) + abs(m.rate) + 1.0
    accel = max(abs(float(sol.alpha(b))) for b in sol.model.bodies) + abs(m.accel) + rate ** 2
    return size, rate * size, accel * size


def field_at(sol, body: str, point: str, m: Drawn) -> tuple[tuple, tuple]:
    """Velocity and acceleration of body's material point at `point`, from one of its own
    listed points by the rigid-body formulas (the body need not list `point`)."""
    q = sol.model.bodies[body].points[0]
    w, al = float(sol.omega(body)), float(sol.alpha(body))
    r = sub(m.points[point], m.points[q])
    v = add(sol.velocity(f"{q}@{body}"), kcross(w, r))
    a = add(sol.acceleration(f"{q}@{body}"), kcross(al, r), times(-w * w, r))
    return v, a


@given(linkages)
def test_angular_motion_matches_the_loop_equations(m: Drawn):
    sol = kinematika.solve(m.tree)
    _, speed, accel = scales(m, sol)
    size = speed / max(abs(m.rate), 1.0)
    for body, (w, al) in loop_closure(m).items():
        assert near(sol.omega(body), w, speed / size)
        assert near(sol.alpha(body), al, accel / size)


@given(linkages)
def test_every_body_moves_rigidly(m: Drawn):
    sol = kinematika.solve(m.tree)
    _, speed, accel = scales(m, sol)
    for body, spec in sol.model.bodies.items():
        w, al = float(sol.omega(body)), float(sol.alpha(body))
        for p, q in combinations(spec.points, 2):
            pq = sub(m.points[q], m.points[p])
            dv = sub(sol.velocity(f"{q}@{body}"), sol.velocity(f"{p}@{body}"))
            da = sub(sol.acceleration(f"{q}@{body}"), sol.acceleration(f"{p}@{body}"))
            assert near(dv, kcross(w, pq), speed)
            assert near(da, add(kcross(al, pq), times(-w * w, pq)), accel)


@given(linkages)
def test_every_joint_condition_holds(m: Drawn):
    sol = kinematika.solve(m.tree)
    _, speed, accel = scales(m, sol)
    for joint in m.tree["joints"]:
        a, b = joint["bodies"]
        if joint["type"] == "revolute":
            at = joint["at"]
            assert near(sol.velocity(f"{at}@{a}"), sol.velocity(f"{at}@{b}"), speed)
            assert near(sol.acceleration(f"{at}@{a}"), sol.acceleration(f"{at}@{b}"), accel)
            continue
        # prismatic: same rotation; the block's point moves relative to the guide only along
        # it, and its relative acceleration (less Coriolis 2 w_guide × v_rel) too
        along = joint["along"]
        e = unit(sub(m.points[along[1]], m.points[along[0]]) if isinstance(along[0], str) else along)
        n = kcross(1, e)
        assert near(sol.omega(a), sol.omega(b), speed) and near(sol.alpha(a), sol.alpha(b), accel)
        p = sol.model.bodies[b].points[0]
        v_guide, a_guide = field_at(sol, a, p, m)
        v_rel = sub(sol.velocity(f"{p}@{b}"), v_guide)
        coriolis = kcross(2 * float(sol.omega(a)), v_rel)
        a_rel = sub(sub(sol.acceleration(f"{p}@{b}"), a_guide), coriolis)
        assert near(dot(v_rel, n), 0.0, speed)
        assert near(dot(a_rel, n), 0.0, accel)
