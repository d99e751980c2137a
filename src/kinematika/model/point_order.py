"""The order points are placed in: each after the points its construction is drawn from.

Every model is ordered so, but most models' points are all coordinates; the constructions'
records (`model.constructions`) are imported only when a point is constructed (start-up:
a fast command on a model without constructions does not build their classes).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Mapping, Optional, Union

from ..errors import KinematikaError

if TYPE_CHECKING:
    from .constructions import Construction, ExprVector


def construction_order(points: Mapping[str, Union[ExprVector, Construction]],
                       extra: Optional[Mapping[str, list[str]]] = None) -> list[str]:
    """Every point's name, each after the points its construction uses (and the points
    `extra` says it is placed from); a cycle is an error."""
    order: list[str] = []
    state: dict[str, int] = {}             # 1: being visited, 2: done

    def visit(name: str, path: list[str]) -> None:
        if state.get(name) == 2:
            return
        if state.get(name) == 1:
            cycle = path[path.index(name):] + [name]
            raise KinematikaError("schema", "construction-cycle", f"points.{name}", cycle=" → ".join(cycle))
        state[name] = 1
        spec = points[name]
        before = [] if isinstance(spec, tuple) else _uses(spec)
        for used in before + list((extra or {}).get(name, ())):
            visit(used, path + [name])
        state[name] = 2
        order.append(name)

    for name in points:
        visit(name, [])
    return order


def _uses(c: Construction) -> list[str]:
    """The points a construction is drawn from (`constructions.uses`, imported with the first
    constructed point)."""
    from .constructions import uses

    return uses(c)
