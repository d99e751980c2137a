"""Instant centres of rotation (planar): where the relative velocity field vanishes.

With the relative twist (ω, v₀ at ref): v(P) = v₀ + ω k × (P − ref) = 0 gives
P = ref + k × v₀ / ω. With ω = 0 the motion is a translation: the centre is at infinity,
perpendicular to v₀; with v₀ = 0 too, the body is at rest relative to the frame.
"""
from __future__ import annotations

from typing import Any

from ..algebra.vectors import add
from .base import Asked, Figure, QuestionKind, Solved, Steps


def instant_centre(sol: Solved, body: str, relative_to: str | None,
                   pin: str | None = None) -> dict[str, Any]:
    """The centre of `body`'s motion relative to `relative_to`; `pin` names the point of a
    revolute joint between them (their centre whenever they turn relative to each other)."""
    if sol.exact is not None and sol.inst.names:
        found = _in_stand_ins(sol, body, relative_to, pin)
        if found is not None:
            return found
    state = sol.state(body, relative_to)
    w, v0 = state.omega, state.v0
    if sol.is_zero(w, sol.rate_scale()):
        if sol.is_zero(v0, sol.speed_scale()):
            return {"point": None, "rest": True}
        speed = sol.norm(v0)
        return {"point": None, "direction": (-v0[1] / speed, v0[0] / speed)}
    return {"point": add(sol.motion.ref, (-v0[1] / w, v0[0] / w))}


def _in_stand_ins(sol: Solved, body: str, relative_to: str | None,
                  pin: str | None = None) -> dict[str, Any] | None:
    """The centre of a model with named coordinates (formulas past reading written out):
    the pin of a revolute joint between the two bodies as it stands, else k × v₀ / ω
    formed in stand-ins and revealed once, not formed from the revealed ω and v₀. None
    when ω is zero at the probe (the general rules decide then)."""
    world = sol.exact
    sol.state(body, relative_to)                          # the names checked
    state = world.motion.state(body, sol.frame_of(relative_to))
    w, v0 = state.omega, state.v0
    if abs(world.inst.num(w)) <= 1e-9 * sol.rate_scale():
        return None
    if pin is not None:
        return {"point": sol.position(pin)}
    return {"point": add(sol.motion.ref, world.reveal.vector((-v0[1] / w, v0[0] / w)))}


def icr(sol: Solved, q: Asked) -> dict[str, Any]:
    """The instant centre of body `q.name` relative to `q.relative_to`: P = ref + k × v₀ / ω, at
    infinity perpendicular to v₀ when ω = 0 (`instant_centre`)."""
    return instant_centre(sol, q.name, q.relative_to)


class Icr(QuestionKind):
    """A body's instant centre of rotation relative to another (planar)."""

    name = "icr"
    summary = "the instant centre of rotation of a body (planar)"
    dimensions = (2,)
    fields = {"point": "position", "direction": None}
    page = True
    needs_rate = False          # the centres section places it from the joints (Aronhold–Kennedy)
    placed = True               # and its answer says its distance from the point it was placed from

    def answer(self, sol: Solved, q: Asked) -> Any:
        """P = ref + k × v₀ / ω, at infinity perpendicular to v₀ when ω = 0 (`icr`)."""
        return icr(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """A centre's mark, with the lines it lies on."""
        figure.instant_centre(q)

    def explain(self, steps: Steps, q: Asked) -> None:
        """The instant centres' section finds it (Kennedy, a pin, the velocities) and checks it."""
        steps.instant_centre(q)


KIND = Icr()
