"""The solved motion at the instant: each body's twist and its derivative.

A body's state is (ω, v₀, α, a₀): angular velocity and acceleration, and the velocity and
acceleration of its material point at the reference point `ref`. Every other kinematic
quantity (any point, any frame) follows from these by the rigid-body formulas below.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..algebra.vectors import Space, add, scale, sub


@dataclass(frozen=True)
class BodyState:
    omega: Any
    v0: tuple
    alpha: Any
    a0: tuple


class Motion:
    """Body states relative to the fixed frame, and the same seen from any body."""

    def __init__(self, space: Space, ref: tuple, states: dict[str, BodyState]) -> None:
        self.space = space
        self.ref = ref
        self.states = states

    def state(self, body: str, relative_to: str | None = None) -> BodyState:
        """The motion of `body` as seen by an observer fixed to `relative_to` (default: ground).

        Vectors stay in ground axes at this instant. With F the frame and ω_r = ω − ω_F:
        α_r = α − α_F − ω_F × ω_r, and a₀ gets the Coriolis term −2 ω_F × v₀_r.
        """
        s = self.states[body]
        if relative_to is None:
            return s
        f = self.states[relative_to]
        sp = self.space
        w = sp.rot_sub(s.omega, f.omega)
        v0 = sub(s.v0, f.v0)
        alpha = sp.rot_sub(sp.rot_sub(s.alpha, f.alpha), sp.cross_ww(f.omega, w))
        a0 = sub(sub(s.a0, f.a0), scale(2, sp.cross(f.omega, v0)))
        return BodyState(w, v0, alpha, a0)

    def velocity(self, state: BodyState, point: tuple) -> tuple:
        """v = v₀ + ω × (P − ref)."""
        return add(state.v0, self.space.cross(state.omega, sub(point, self.ref)))

    def acceleration(self, state: BodyState, point: tuple) -> tuple:
        """a = a₀ + α × r + ω × (ω × r), r = P − ref."""
        sp = self.space
        r = sub(point, self.ref)
        return add(add(state.a0, sp.cross(state.alpha, r)), sp.cross(state.omega, sp.cross(state.omega, r)))

    def point_velocity(self, body: str, point: tuple, relative_to: str | None = None) -> tuple:
        return self.velocity(self.state(body, relative_to), point)

    def point_acceleration(self, body: str, point: tuple, relative_to: str | None = None) -> tuple:
        return self.acceleration(self.state(body, relative_to), point)

    def moving_point(self, position: tuple, velocity: tuple, acceleration: tuple,
                     relative_to: str | None) -> tuple[tuple, tuple]:
        """Velocity and acceleration of a geometric (non-material) point seen from a frame."""
        if relative_to is None:
            return velocity, acceleration
        f = self.states[relative_to]
        v_rel = sub(velocity, self.velocity(f, position))
        a_rel = sub(sub(acceleration, self.acceleration(f, position)),
                    scale(2, self.space.cross(f.omega, v_rel)))
        return v_rel, a_rel
