"""The three coincident points of a rolling contact: each body's material point and the
geometric contact point, which moves along both profiles."""
from __future__ import annotations

from typing import Any

from ..model.model import Question
from ..solution import Solution


def contact(sol: Solution, q: Question) -> dict[str, Any]:
    """The three coincident points of joint `q.name`'s contact, seen from `q.relative_to`:
    velocity and acceleration of each body's material point at J (`body_a`, `body_b`) and of the
    geometric contact point J itself, which moves along both profiles (`geometric`)."""
    joint = sol.model.joint(q.name)
    c = sol.geometry(joint.id).contact
    if c is None:
        raise TypeError(f"{q.where}: joint {joint.id} has no contact")
    rel = None if q.relative_to in (None, sol.model.frame) else q.relative_to
    out: dict[str, Any] = {}
    for key, body in (("body_a", joint.a), ("body_b", joint.b)):
        state = sol.state(body, rel)
        out[key] = {"velocity": sol.motion.velocity(state, c.point),
                    "acceleration": sol.motion.acceleration(state, c.point)}
    v, a = sol.motion.moving_point(c.point, c.jdot(sol.motion), c.jddot(sol.motion), rel)
    out["geometric"] = {"velocity": v, "acceleration": a}
    out["point"] = c.point
    return out
