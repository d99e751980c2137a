"""Velocity, acceleration, angular velocity and acceleration, relative to any body."""
from __future__ import annotations

from typing import Any

from .base import Asked, Solved


def velocity(sol: Solved, q: Asked) -> tuple:
    """The velocity of material point `q.target` relative to body `q.relative_to` (default: the
    frame): v_P = v₀ + ω × (P − O)."""
    return sol.velocity(q.target, q.relative_to)


def acceleration(sol: Solved, q: Asked) -> tuple:
    """The acceleration of material point `q.target` relative to body `q.relative_to`: a_P = a₀
    + α × (P − O) + ω × (ω × (P − O)), drag and Coriolis taken out for a moving observer."""
    return sol.acceleration(q.target, q.relative_to)


def omega(sol: Solved, q: Asked) -> Any:
    """The angular velocity of body `q.name` relative to body `q.relative_to`: ω − ω_F."""
    return sol.omega(q.name, q.relative_to)


def alpha(sol: Solved, q: Asked) -> Any:
    """The angular acceleration of body `q.name` relative to body `q.relative_to`, as seen from
    it: α − α_F − ω_F × (ω − ω_F)."""
    return sol.alpha(q.name, q.relative_to)
