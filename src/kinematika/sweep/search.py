"""Assemblies of mechanisms that are not made of dyads: found numerically (to come)."""
from __future__ import annotations

from typing import Any

from ..model.model import Model


def searched_assemblies(model: Model, sweeper: Any) -> list:
    from .assemblies import Assembly

    points = {str(r): tuple(float(c) for c in sweeper.inst.points[r.point]) for r in model.material_points()}
    return [Assembly(1, True, [], model, points)]
