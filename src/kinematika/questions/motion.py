"""Velocity, acceleration, angular velocity and acceleration, relative to any body."""
from __future__ import annotations

from typing import Any

from ..model.model import Question
from ..solution import Solution


def velocity(sol: Solution, q: Question) -> tuple:
    return sol.velocity(q.target, q.relative_to)


def acceleration(sol: Solution, q: Question) -> tuple:
    return sol.acceleration(q.target, q.relative_to)


def omega(sol: Solution, q: Question) -> Any:
    return sol.omega(q.name, q.relative_to)


def alpha(sol: Solution, q: Question) -> Any:
    return sol.alpha(q.name, q.relative_to)
