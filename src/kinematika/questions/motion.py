"""Velocity, acceleration, angular velocity and acceleration, relative to any body."""
from __future__ import annotations

from typing import Any

from ..model.model import Question
from ..solution import Solution


def velocity(sol: Solution, q: Question) -> tuple:
    """The velocity of material point `q.target` relative to body `q.relative_to` (default: the
    frame): v_P = v₀ + ω × (P − O)."""
    return sol.velocity(q.target, q.relative_to)


def acceleration(sol: Solution, q: Question) -> tuple:
    """The acceleration of material point `q.target` relative to body `q.relative_to`: a_P = a₀
    + α × (P − O) + ω × (ω × (P − O)), drag and Coriolis taken out for a moving observer."""
    return sol.acceleration(q.target, q.relative_to)


def omega(sol: Solution, q: Question) -> Any:
    """The angular velocity of body `q.name` relative to body `q.relative_to`: ω − ω_F."""
    return sol.omega(q.name, q.relative_to)


def alpha(sol: Solution, q: Question) -> Any:
    """The angular acceleration of body `q.name` relative to body `q.relative_to`, as seen from
    it: α − α_F − ω_F × (ω − ω_F)."""
    return sol.alpha(q.name, q.relative_to)
