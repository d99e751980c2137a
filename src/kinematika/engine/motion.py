"""The solved motion at the instant: each body's twist and its derivative.

A body's state is (ω, v₀, α, a₀): angular velocity and acceleration, and the velocity and
acceleration of its material point at the reference point `ref`. Every other kinematic
quantity (any point, any frame) follows from these by the rigid-body formulas below.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

from ..algebra.vectors import Space, add, scale, sub
from .terms import MECHANICS, Terms


@dataclass(frozen=True)
class BodyState:
    """A body's twist and its derivative at the instant: angular velocity ω and acceleration α,
    and the velocity v₀ and acceleration a₀ of its material point at the reference point
    (scalars ω, α in the plane, 3-vectors in space)."""

    omega: Any
    v0: tuple
    alpha: Any
    a0: tuple


class Motion:
    """Body states relative to the fixed frame, and the same seen from any body.

    `terms` are the factors of the normal and Coriolis terms (`engine.terms`): mechanics'
    unless the motion was solved as a student with a mistake would solve it."""

    def __init__(self, space: Space, ref: tuple, states: dict[str, BodyState],
                 terms: Terms = MECHANICS) -> None:
        self.space = space
        self.ref = ref
        self.states = states
        self.terms = terms
        self._arrays: tuple[Any, ...] | None = None

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
        a0 = sub(sub(s.a0, f.a0), scale(self.terms.coriolis_factor(), sp.cross(f.omega, v0)))
        return BodyState(w, v0, alpha, a0)

    def velocity(self, state: BodyState, point: tuple) -> tuple:
        """v = v₀ + ω × (P − ref)."""
        return add(state.v0, self.space.cross(state.omega, sub(point, self.ref)))

    def acceleration(self, state: BodyState, point: tuple) -> tuple:
        """a = a₀ + α × r + ω × (ω × r), r = P − ref."""
        sp = self.space
        r = sub(point, self.ref)
        normal = self.terms.normal_part(sp.cross(state.omega, sp.cross(state.omega, r)))
        return add(add(state.a0, sp.cross(state.alpha, r)), normal)

    def arrays(self) -> tuple[Any, ...]:
        """ω, v₀, α, a₀ of every body (the order of `states`) as float arrays of one row per
        body (ω and α with one column in the plane, three in space); numeric motions. Read
        once (a motion's states are not changed after it is solved) and shared, read-only:
        an answer reads them three times (its scales, its points' fields, its tables)."""
        if self._arrays is None:
            self._arrays = self._read_arrays()
        return self._arrays

    def _read_arrays(self) -> tuple[Any, ...]:
        """`arrays`, read from the states."""
        import numpy as np

        sp, n = self.space, len(self.states)
        rot = sp.rot_components
        widths = (sp.rot, sp.dim, sp.rot, sp.dim)
        # one row per body, its four parts side by side, read into floats in one pass (in the
        # plane ω and α are their one component: `rot_components` not called body by body)
        if sp.rot == 1:
            rows = [(s.omega, *s.v0, s.alpha, *s.a0) for s in self.states.values()]
        else:
            rows = [(*rot(s.omega), *s.v0, *rot(s.alpha), *s.a0) for s in self.states.values()]
        table = np.array(rows, dtype=float).reshape(n, sum(widths))
        edges = np.cumsum((0, *widths)).tolist()
        out = tuple(np.ascontiguousarray(table[:, edges[k]:edges[k + 1]]) for k in range(4))
        for part in out:
            part.flags.writeable = False          # shared: read, never written
        return out

    def fields(self, bodies: Sequence[str], points: Any) -> tuple[Any, Any]:
        """Velocities and accelerations of many material points of a numeric motion at once:
        point k of body `bodies[k]` at `points[k]` (an (n, dim) float array). The formulas of
        `velocity` and `acceleration` with numpy, operation for operation, so the numbers
        are the same."""
        import numpy as np

        sp = self.space
        row = {name: i for i, name in enumerate(self.states)}
        take = np.array([row[b] for b in bodies], dtype=np.intp)
        w, v0, alpha, a0 = (column[take] for column in self.arrays())
        r = np.asarray(points, dtype=float).reshape(len(take), sp.dim) - np.asarray(self.ref, dtype=float)
        turn = _cross if sp.dim == 3 else _cross_planar
        velocity = v0 + turn(w, r)
        normal = turn(w, turn(w, r))
        acceleration = (a0 + turn(alpha, r)) + (normal if self.terms.normal == 1 else self.terms.normal * normal)
        return velocity, acceleration

    def point_velocity(self, body: str, point: tuple, relative_to: str | None = None) -> tuple:
        """The velocity of `body`'s material point at `point` seen from `relative_to`: v = v₀ +
        ω × (P − ref) of the relative state."""
        return self.velocity(self.state(body, relative_to), point)

    def point_acceleration(self, body: str, point: tuple, relative_to: str | None = None) -> tuple:
        """The acceleration of `body`'s point at `point` seen from `relative_to`. In a
        mistaken world (`terms` not mechanics' ones) a relative acceleration is the
        composition at the point, a_rel = a_P(b) − a_P(F) − 2c ω_F × v_rel, as the student
        writes it (the relative state's formula assumes the true terms)."""
        if relative_to is None or self.terms.mechanics:
            return self.acceleration(self.state(body, relative_to), point)
        f = self.states[relative_to]
        v_rel = sub(self.velocity(self.states[body], point), self.velocity(f, point))
        coriolis = scale(self.terms.coriolis_factor(), self.space.cross(f.omega, v_rel))
        return sub(sub(self.acceleration(self.states[body], point), self.acceleration(f, point)), coriolis)

    def moving_point(self, position: tuple, velocity: tuple, acceleration: tuple,
                     relative_to: str | None) -> tuple[tuple, tuple]:
        """Velocity and acceleration of a geometric (non-material) point seen from a frame."""
        if relative_to is None:
            return velocity, acceleration
        f = self.states[relative_to]
        v_rel = sub(velocity, self.velocity(f, position))
        a_rel = sub(sub(acceleration, self.acceleration(f, position)),
                    scale(self.terms.coriolis_factor(), self.space.cross(f.omega, v_rel)))
        return v_rel, a_rel


def _cross_planar(w: Any, r: Any) -> Any:
    """Rows of ω k × r, as `Space.cross` computes them: (−ω r_y, ω r_x)."""
    import numpy as np

    return np.stack([-w[:, 0] * r[:, 1], w[:, 0] * r[:, 0]], axis=1)


def _cross(a: Any, b: Any) -> Any:
    """Rows of a × b, as `cross3` computes them."""
    import numpy as np

    return np.stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                     a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]], axis=1)
