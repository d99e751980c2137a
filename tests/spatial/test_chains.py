"""Property tests on random serial chains in space (hypothesis).

Each chain ground → b1 → … → bn has joints with random axes, points and rates: revolutes
(driven by their joint rate or by a relative omega vector), prismatic and cylindrical
joints (a relative point velocity along the axis) and spherical joints (a relative omega
vector). The expected motion is derived independently as a product of exponentials: joint i
moves body i relative to body i-1 by exp(M_i(t)), M_i = V_i t + A_i t²/2 with V_i, A_i the
4×4 twist matrices of the joint's relative motion in the drawn configuration, so that the
pose of body k is T_k = exp(M_1)…exp(M_k) and, at t = 0,

    T'_k = Σ V_i,     T''_k = Σ (A_i + V_i²) + 2 Σ_{i<j} V_i V_j;
    [ω] = R',  [α] = R'' − R'²   (R the rotation block of T_k, R = I at t = 0).
"""
from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from kinematika import solve
from kinematika.report.json_answer import solution_json

from .derive import assert_close, cross, minus, plus
import itertools

TYPES = ["revolute", "revolute", "revolute", "prismatic", "cylindrical", "spherical"]
# on a grid of 0.01: a model's length scale comes from its points, so no subnormal spreads
coord = st.integers(-100, 100).map(lambda k: k / 100)
rate = st.integers(-300, 300).map(lambda k: k / 100)
vector = st.tuples(coord, coord, coord)
direction = vector.filter(lambda v: np.linalg.norm(v) > 0.3)


def skew(w) -> np.ndarray:
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=float)


def twist(w, p, slide) -> np.ndarray:
    """The 4×4 twist of a turning w about point p plus a translation `slide`."""
    m = np.zeros((4, 4))
    m[:3, :3] = skew(w)
    m[:3, 3] = np.asarray(slide, dtype=float) - skew(w) @ np.asarray(p, dtype=float)
    return m


def unskew(m: np.ndarray) -> np.ndarray:
    return np.array([m[2, 1], m[0, 2], m[1, 0]])


@st.composite
def chains(draw, types=TYPES):
    """Joints with their relative motion: (type, point, axis, w, w', slide, slide', driver)."""
    n = draw(st.integers(2, 4))
    joints = []
    for _ in range(n):
        kind = draw(st.sampled_from(types))
        p = np.array(draw(vector))
        u = np.array(draw(direction))
        u = u / np.linalg.norm(u)
        q1, q2, s1, s2 = (draw(rate) for _ in range(4))
        if kind == "spherical":
            w, dw = np.array(draw(vector)) * 3, np.array(draw(vector)) * 3
        else:
            w, dw = (q1 * u, q2 * u) if kind != "prismatic" else (0 * u, 0 * u)
        slide, dslide = (s1 * u, s2 * u) if kind in ("prismatic", "cylindrical") else (0 * u, 0 * u)
        driver = draw(st.sampled_from(["rate", "omega"])) if kind == "revolute" else None
        joints.append(dict(kind=kind, p=p, u=u, q1=q1, q2=q2, s1=s1, s2=s2, w=w, dw=dw,
                           slide=slide, dslide=dslide, driver=driver))
    tips = [np.array(draw(vector)) for _ in range(n)]
    return joints, tips


def chain_tree(joints, tips) -> dict:
    """The chain as a model: body i carries its joint point, the next one and a tip point."""
    n = len(joints)
    points = {f"P{i}": list(j["p"]) for i, j in enumerate(joints)}
    points.update({f"E{i}": list(e) for i, e in enumerate(tips)})
    bodies = {"ground": ["P0"]}
    for i in range(n):
        bodies[f"b{i}"] = [f"P{i}", f"E{i}"] + ([f"P{i + 1}"] if i + 1 < n else [])
    tree_joints, drivers = [], []
    for i, j in enumerate(joints):
        parent, child = ("ground" if i == 0 else f"b{i - 1}"), f"b{i}"
        spec = {"id": f"k{i}", "type": j["kind"], "bodies": [parent, child], "at": f"P{i}"}
        if j["kind"] in ("revolute", "cylindrical"):
            spec["axis"] = list(j["u"])
        if j["kind"] == "prismatic":
            spec = {"id": f"k{i}", "type": "prismatic", "bodies": [parent, child], "along": list(j["u"])}
        tree_joints.append(spec)
        if j["driver"] == "rate":
            drivers.append({"joint": f"k{i}", "rate": j["q1"], "accel": j["q2"]})
        elif j["kind"] != "prismatic":
            drivers.append({"omega": child, "relative_to": parent, "value": list(j["w"]),
                            "alpha": list(j["dw"])})
        if j["kind"] in ("prismatic", "cylindrical"):
            drivers.append({"velocity": f"P{i}@{child}", "relative_to": parent, "along": list(j["u"]),
                            "value": j["s1"], "acceleration": j["s2"]})
    return {"dimension": 3, "points": points, "bodies": bodies, "joints": tree_joints,
            "drivers": drivers}


def expected_motion(joints):
    """(ω, α, T', T'') of each body, from the product of exponentials."""
    out = []
    first, second = np.zeros((4, 4)), np.zeros((4, 4))
    for j in joints:
        v = twist(j["w"], j["p"], j["slide"])
        a = twist(j["dw"], j["p"], j["dslide"])
        second = second + a + v @ v + 2 * first @ v
        first = first + v
        r1, r2 = first[:3, :3], second[:3, :3]
        out.append((unskew(r1), unskew(r2 - r1 @ r1), first.copy(), second.copy()))
    return out


def point_motion(first, second, p):
    h = np.append(np.asarray(p, dtype=float), 1.0)
    return (first @ h)[:3], (second @ h)[:3]


@given(chains())
def test_random_chain_matches_the_product_of_exponentials(chain):
    joints, tips = chain
    sol = solve(chain_tree(joints, tips))
    out = solution_json(sol)
    for i, (w, al, first, second) in enumerate(expected_motion(joints)):
        body = f"b{i}"
        assert_close(sol.omega(body), w, 1e-7)
        assert_close(sol.alpha(body), al, 1e-7)
        for name in sol.model.bodies[body].points:
            v, a = point_motion(first, second, sol.inst.points[name])
            assert_close(sol.velocity(f"{name}@{body}"), v, 1e-7)
            assert_close(sol.acceleration(f"{name}@{body}"), a, 1e-7)
            assert_close(out["points"][f"{name}@{body}"]["acceleration"], a, 1e-7)


@given(chains())
def test_rigid_body_fields_hold_for_every_body(chain):
    joints, tips = chain
    sol = solve(chain_tree(joints, tips))
    for body in sol.model.moving_bodies:
        w, al = sol.omega(body), sol.alpha(body)
        names = sol.model.bodies[body].points
        for a_name, b_name in itertools.pairwise(names):
            pa, pb = sol.inst.points[a_name], sol.inst.points[b_name]
            ab = minus(pb, pa)
            va, vb = sol.velocity(f"{a_name}@{body}"), sol.velocity(f"{b_name}@{body}")
            aa, ab_ = sol.acceleration(f"{a_name}@{body}"), sol.acceleration(f"{b_name}@{body}")
            assert_close(minus(vb, va), cross(w, ab), 1e-7)
            assert_close(minus(ab_, aa), plus(cross(al, ab), cross(w, cross(w, ab))), 1e-7)


@given(chains())
def test_omega_is_the_sum_of_relative_omegas_and_alpha_composes(chain):
    joints, tips = chain
    sol = solve(chain_tree(joints, tips))
    total = (0.0, 0.0, 0.0)
    for i, j in enumerate(joints):
        body, parent = f"b{i}", ("ground" if i == 0 else f"b{i - 1}")
        w_rel, al_rel = sol.omega(body, parent), sol.alpha(body, parent)
        # the relative motion is the joint's own: rate about its axis, derivative seen from the parent
        assert_close(w_rel, j["w"], 1e-7)
        assert_close(al_rel, j["dw"], 1e-7)
        total = plus(total, w_rel)
        assert_close(sol.omega(body), total, 1e-7)
        # α = α_parent + α_rel + ω_parent × ω_rel
        assert_close(sol.alpha(body), plus(sol.alpha(parent), al_rel, cross(sol.omega(parent), w_rel)), 1e-7)


@given(chains(types=["revolute"]))
def test_relative_point_motion_of_the_tip_composes(chain):
    """v = v_drag + v_rel, a = a_drag + a_rel + 2 ω_F × v_rel, the last body seen from the first."""
    joints, tips = chain
    sol = solve(chain_tree(joints, tips))
    n = len(joints)
    tip, frame = f"E{n - 1}@b{n - 1}", "b0"
    p = sol.inst.points[f"E{n - 1}"]
    motion = expected_motion(joints)
    # the tip seen from b0: the chain b1..b(n-1) with b0 held still (joint 0 removed)
    rel = expected_motion(joints[1:])[-1]
    v_rel, a_rel = point_motion(rel[2], rel[3], p)
    # the frame's material point at the tip: drag
    v_drag, a_drag = point_motion(motion[0][2], motion[0][3], p)
    coriolis = 2 * np.cross(motion[0][0], v_rel)
    assert_close(sol.velocity(tip, frame), v_rel, 1e-7)
    assert_close(sol.acceleration(tip, frame), a_rel, 1e-7)
    assert_close(sol.velocity(tip), v_drag + v_rel, 1e-7)
    assert_close(sol.acceleration(tip), a_drag + a_rel + coriolis, 1e-7)
