"""Every assembly of a mechanism at its drawn input, numbered, and the model on any of them.

With the input where it is drawn, a dyad closes in two ways (its middle pin on either side
of the line through its end pins; a pin ahead of or behind its pivot along a guide), so a
mechanism of k such dyads has up to 2^k assemblies, fewer where a dyad cannot close. They
are numbered from 1 by their closures in solving order, the first closure (left, ahead)
before the second, so the numbers do not depend on which one the model happens to draw.
Mechanisms that are not made of dyads (a triad, a spatial loop) are assembled numerically
from many starting poses, and the distinct real solutions found are listed.
"""
from __future__ import annotations

import itertools
from typing import Any, Optional

import numpy as np

from ..engine.instant import instantiate
from ..errors import KinematikaError
from ..model.model import Model
from .assembly import Assembly
from .move import as_written
from .plan import driven_joints
from .posed import posed_model
from .run import Sweeper
from .search import searched_assemblies

MAX_DYADS = 12               # 4096 closures: beyond this, listing them helps nobody


def assemblies(model: Model) -> list[Assembly]:
    """Every assembly of `model` at its drawn input; the drawn one is marked. A model whose
    position analysis needs numbers it does not have (symbols), or that has no driven joint
    to hold at its input (a vehicle driven by a speed), lists the drawn assembly only."""
    if any(p.value is None for p in model.parameters.values()) or not driven_joints(model):
        return [_drawn_only(model)]
    sweeper = Sweeper(as_written(model))           # on its own `move:`, as a file is posed
    if sweeper.closed is not None:
        return _dyad_assemblies(model, sweeper)
    return searched_assemblies(model, sweeper)


def _drawn_only(model: Model) -> Assembly:
    """The drawn assembly, its points at the probe values when symbolic (for the listing)."""
    inst = instantiate(model)
    points = {str(r): inst.numvec(inst.points[r.point]) for r in model.material_points()}
    return Assembly(1, True, [], model, points)


def with_assembly(model: Model, number: Any) -> Model:
    """`model` posed on its assembly `number` (as `kinematika assemblies` numbers them)."""
    if isinstance(number, bool) or not isinstance(number, int):
        raise KinematikaError("usage", "assembly-not-whole", "--assembly", got=repr(number))
    found = assemblies(model)
    if not 1 <= number <= len(found):
        raise KinematikaError("usage", "assembly-missing", "--assembly", number=number, count=len(found))
    chosen = found[number - 1]
    return model if chosen.drawn else chosen.model


def _dyad_assemblies(model: Model, sweeper: Any) -> list[Assembly]:
    branches = sweeper.closed.branches()
    if len(branches) > MAX_DYADS:
        raise KinematikaError("schema", "assemblies-too-many", "", dyads=len(branches), limit=MAX_DYADS)
    out: list[Assembly] = []
    turns: list[dict[str, float]] = []
    for sides in itertools.product((1.0, -1.0), repeat=len(branches)):
        flips = {i: side * drawn for (i, _, drawn), side in zip(branches, sides)}
        sweeper.closed = sweeper._closed_form(flips)
        result = sweeper.run(0.0, 1, skip_bad=True)
        if not result.ok[0]:
            continue
        points, turn = _places(model, result), _turns(result)
        if any(_same(points, a.points, sweeper.inst.scale) and _same_turns(turn, t)
               for a, t in zip(out, turns)):
            continue                          # a dyad at its limit closes one way only
        turns.append(turn)
        drawn = all(f == 1.0 for f in flips.values())
        posed = model if drawn else posed_model(model, result, 0)
        words = [_closure(model, g, side) for (_, g, _), side in zip(branches, sides)]
        out.append(Assembly(len(out) + 1, drawn, words, posed, points))
    sweeper.closed = sweeper._closed_form()
    return out


def _places(model: Model, result: Any) -> dict[str, tuple]:
    """Every material point's place at row 0."""
    return {name: tuple(float(c) for c in values["position"][0]) for name, values in result.points.items()}


def _same(a: dict[str, tuple], b: dict[str, tuple], scale: float) -> bool:
    return all(np.allclose(a[k], b[k], atol=1e-7 * scale, rtol=0) for k in a)


def _turns(result: Any) -> dict[str, float]:
    """Each body's turn from the drawn pose at row 0, degrees. Two closures may put every
    point in the same place and still differ: the block of an inverted slider-crank turned
    half a turn on its pin (its only point) carries its guide the other way."""
    return {name: float(values["angle"][0]) for name, values in result.bodies.items()}


def _same_turns(a: dict[str, float], b: dict[str, float]) -> bool:
    return all(abs((a[k] - b[k] + 180.0) % 360.0 - 180.0) < 1e-6 for k in a)


def _closure(model: Model, g: Any, side: float) -> str:
    """How a dyad closes, in words: `B left of A→C`, `B ahead of A along j4`."""
    joints = [model.joint(j) for j in g.joints]
    first, last = joints[0], joints[-1]
    middle = joints[1] if len(joints) == 3 else last
    if g.kind == "RRR":
        return f"{middle.at} {'left' if side > 0 else 'right'} of {first.at}→{last.at}"
    if g.kind == "RRP":
        return f"{middle.at} {'ahead of' if side > 0 else 'behind'} {first.at} along {last.id}"
    return f"{last.at} {'ahead of' if side > 0 else 'behind'} {first.at} along {middle.id}"


def assemblies_json(found: list[Assembly]) -> dict:
    """The `assemblies --json` answer: each assembly's number, closures and point places."""
    return {"assemblies": [{"number": a.number, "drawn": a.drawn, "closures": a.closures,
                            "points": {k: list(v) for k, v in a.points.items()}} for a in found]}


def drawn_number(found: list[Assembly]) -> Optional[int]:
    """The number of the assembly the drawing shows, or None when none of `found` is the drawn
    one."""
    return next((a.number for a in found if a.drawn), None)
