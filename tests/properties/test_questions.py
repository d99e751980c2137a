"""The questions on random linkages, checked against the solved motion by hand: an instant
centre has zero relative velocity, drag + relative + Coriolis is the composition of motions
for a random moving frame, the centre of curvature lies on the normal at v²/aₙ, and the
acceleration pole has zero acceleration."""
from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

import kinematika

from .mechanisms import Drawn, add, dot, kcross, linkages, near, sub, times
from .test_fields import scales


def field(sol, body: str, xy, m: Drawn, frame: str | None = None) -> tuple[tuple, tuple]:
    """Velocity and acceleration of body's material point at location `xy` (relative to
    `frame`: v − v_F, a − a_F − 2 ω_F × v_rel), by the rigid-body formulas."""
    q = sol.model.bodies[body].points[0]
    w, al = float(sol.omega(body)), float(sol.alpha(body))
    r = sub(xy, m.points[q])
    v = add(sol.velocity(f"{q}@{body}"), kcross(w, r))
    a = add(sol.acceleration(f"{q}@{body}"), kcross(al, r), times(-w * w, r))
    if frame is None or frame == "ground":
        return v, a
    vf, af = field(sol, frame, xy, m)
    v_rel = sub(v, vf)
    return v_rel, sub(sub(a, af), kcross(2 * float(sol.omega(frame)), v_rel))


def ask(m: Drawn, questions: list) -> tuple[object, list]:
    """Solve the drawn linkage with the questions; the raw answers in order."""
    tree = dict(m.tree, ask=questions)
    sol = kinematika.solve(tree)
    return sol, [value for _, value in kinematika.answers(sol)]


def material_points(m: Drawn) -> list[tuple[str, str]]:
    return [(p, b) for b, pts in m.tree["bodies"].items() for p in pts]


@given(linkages, st.data())
def test_instant_centre_has_zero_relative_velocity(m: Drawn, data):
    bodies = list(m.tree["bodies"])
    body = data.draw(st.sampled_from(bodies[1:]))
    frame = data.draw(st.sampled_from([b for b in bodies if b != body]))
    sol, (centre,) = ask(m, [{"icr": body, "relative_to": frame}])
    size, speed, _ = scales(m, sol)
    w_rel = float(sol.omega(body)) - float(sol.omega(frame))
    if centre.get("point") is not None:
        v, _ = field(sol, body, centre["point"], m, frame)
        # a centre far away (slow relative turning) is fine: judge v against |w_rel|·distance
        far = math.hypot(*centre["point"]) + size
        assert near(v, (0.0, 0.0), speed + abs(w_rel) * far)
    elif centre.get("rest"):
        assert near(field(sol, body, (0.0, 0.0), m, frame)[0], (0.0, 0.0), speed)
    else:            # a relative translation: its velocity is perpendicular to `direction`
        v, _ = field(sol, body, (0.0, 0.0), m, frame)
        assert near(w_rel * size, 0.0, speed) and near(dot(v, centre["direction"]), 0.0, speed)


@given(linkages, st.data())
def test_decomposition_is_the_composition_of_motions(m: Drawn, data):
    point, body = data.draw(st.sampled_from(material_points(m)))
    frame = data.draw(st.sampled_from([b for b in m.tree["bodies"] if b != body]))
    sol, (parts,) = ask(m, [{"decompose": f"{point}@{body}", "moving": frame}])
    _, speed, accel = scales(m, sol)
    xy = m.points[point]
    v_total, a_total = field(sol, body, xy, m)
    v_drag, a_drag = field(sol, frame, xy, m)
    v_rel = sub(v_total, v_drag)
    coriolis = kcross(2 * float(sol.omega(frame)), v_rel)
    a_rel = sub(sub(a_total, a_drag), coriolis)
    vel, acc = parts["velocity"], parts["acceleration"]
    assert near(vel["drag"], v_drag, speed) and near(vel["relative"], v_rel, speed)
    assert near(vel["total"], v_total, speed)
    assert near(acc["drag"], a_drag, accel) and near(acc["relative"], a_rel, accel)
    assert near(acc["coriolis"], coriolis, accel) and near(acc["total"], a_total, accel)
    assert near(add(acc["drag"], acc["relative"], acc["coriolis"]), acc["total"], accel)


@given(linkages, st.data())
def test_centre_of_curvature_lies_on_the_normal_at_v2_over_an(m: Drawn, data):
    point, body = data.draw(st.sampled_from(material_points(m)))
    frame = data.draw(st.sampled_from(list(m.tree["bodies"])))
    sol, (curv,) = ask(m, [{"curvature": f"{point}@{body}", "relative_to": frame}])
    _, speed, accel = scales(m, sol)
    p = m.points[point]
    v, a = field(sol, body, p, m, frame)
    vv = dot(v, v)
    if curv.get("rest"):
        assert near(math.sqrt(vv), 0.0, speed)
        return
    a_n = sub(a, times(dot(a, v) / vv, v))
    if curv["radius"] is None:                       # straight path or inflection
        assert near(math.hypot(*a_n), 0.0, accel)
        return
    radius, centre = float(curv["radius"]), curv["center"]
    to_centre = sub(centre, p)
    assert math.isclose(math.hypot(*to_centre), radius, rel_tol=1e-7)
    assert math.isclose(radius, vv / math.hypot(*a_n), rel_tol=1e-7)
    assert abs(dot(to_centre, v)) <= 1e-7 * radius * math.sqrt(vv)        # on the normal
    assert dot(to_centre, a_n) > 0                                          # on aₙ's side


@given(linkages, st.data())
def test_acceleration_pole_has_zero_acceleration(m: Drawn, data):
    body = data.draw(st.sampled_from(list(m.tree["bodies"])[1:]))
    sol, (pole,) = ask(m, [{"pole": body}])
    size, _, accel = scales(m, sol)
    if pole.get("point") is None:
        assert near(sol.alpha(body), 0.0, accel / size) and near(sol.omega(body), 0.0, accel / size)
        return
    far = math.hypot(*pole["point"]) + size
    assert near(field(sol, body, pole["point"], m)[1], (0.0, 0.0), accel * far / size)
