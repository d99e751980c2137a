"""The three coincident points of a rolling contact: each body's material point and the
geometric contact point, which moves along both profiles."""
from __future__ import annotations

from typing import Any, Optional

from ..errors import KinematikaError, Names
from ..joints import KINDS
from .base import Asked, Figure, QuestionKind, Solved, Steps, Words


def contact(sol: Solved, q: Asked) -> dict[str, Any]:
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


class Contact(QuestionKind):
    """The three coincident points of a touching pair's contact."""

    name = "contact"
    summary = "the velocities and accelerations of the three coincident points at a contact"
    about = "joint"
    level = "acceleration"
    unit_kind = "velocity"
    fields = {"velocity": "velocity", "acceleration": "acceleration", "point": "position"}
    rows_by_part = True                     # v_J∈a, a_J∈a, …, v_J^geom: one row each, as the notes list them

    def answer(self, sol: Solved, q: Asked) -> Any:
        """Each body's material point at J and the geometric contact point (`contact`)."""
        return contact(sol, q)

    def target_joint(self, text: str, joints: list, where: str) -> str:
        """A joint whose bodies touch (its kind `touches`), else a `schema` error listing them."""
        joint = next((j for j in joints if j.id == text), None)
        if joint is None or not joint.kind.touches:
            touching = [j.id for j in joints if j.kind.touches]
            kinds = Names(sorted(k.name for k in KINDS.values() if k.touches), joined="or")
            raise KinematikaError("schema", "contact-not-touching", where, text=text, kinds=kinds, joints=touching)
        return text

    def draw(self, figure: Figure, q: Asked) -> None:
        """A marked point J."""
        figure.contact_point(q)

    def explain(self, steps: Steps, q: Asked) -> None:
        """Its section: each point's motion from an equation (a rolling pair's, planar)."""
        steps.contact_points(q)

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """v_J∈a, a_J∈b, v_J^geom: the point of each body at J, and the geometric one."""
        name, a, b = words.contact(q)
        level = "v" if sub == "velocity" else "a"
        if key == "body_a":
            return words.sym(level, f"{name}∈{a}")
        if key == "body_b":
            return words.sym(level, f"{name}∈{b}")
        if key == "geometric":
            return words.geometric(level, name)
        return None


KIND = Contact()
