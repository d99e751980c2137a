"""`move` in a model with symbolic parameters: the input carried, the constructions following.

A sweep needs numbers, but a model written by construction moves exactly: turn the input
body about its pivot by the amount (or shift a slider along its guide) and every point
constructed from it follows through its construction, so the answers stay formulas (a
four-bar moved 30° from a general crank angle θ is the four-bar at θ + 30°). This holds only
when the other moving bodies' points are constructed from the input's; it is checked at
the symbols' probe values against the numeric sweep of the same model, and a model for
which it does not hold gets an error saying which point to write by construction.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import KinematikaError
from ..expressions import parse
from ..model.model import Model, Turn


def symbolic_moved(model: Model, jid: str, amount: float, where: str) -> Model:
    """`model` with joint `jid` advanced by `amount` (degrees or length), exactly."""
    if not _geometry_has_symbols(model):
        return _moved_with_numbers(model, jid, amount)
    if model.dimension != 2:
        raise KinematikaError("schema", "a 3D model with symbolic parameters cannot be moved: "
                              "give its parameters values (--set NAME=VALUE)", where)
    joint = model.joint(jid)
    frame = model.frame
    body = joint.b if joint.a == frame else joint.a
    if frame not in (joint.a, joint.b):
        raise KinematikaError("schema", f"joint {jid!r} does not join a body to the frame: move a "
                              "model with symbolic parameters by its input joint", where)
    sign = 1 if joint.a == frame else -1          # the coordinate is b relative to a
    value = repr(float(sign * amount))
    if joint.kind.coordinate == "angle":
        turn = Turn(body, pivot=joint.at, angle=parse(f"deg({value})"))
    else:
        turn = Turn(body, along=joint.along, shift=parse(value))
    posed = dataclasses.replace(model, move={}, turns=[*model.turns, turn])
    _check(model, posed, jid, amount, where)
    return posed


def _geometry_has_symbols(model: Model) -> bool:
    """Whether the positions depend on the symbols (else only rates do: ω = w, say)."""
    from ..engine.instant import instantiate

    inst = instantiate(model)
    values = [c for p in inst.points.values() for c in p]
    values += [x for shapes in inst.shapes.values() for s in shapes
               for x in (getattr(s, "radius", 0), *getattr(s, "direction", ()), *getattr(s, "axis", ()),
                         *getattr(s, "normal", ()), *getattr(s, "center", ()), *getattr(s, "through", ()))]
    return any(getattr(v, "free_symbols", None) for v in values)


def _moved_with_numbers(model: Model, jid: str, amount: float) -> Model:
    """A model whose symbols are only rates moves as its numeric twin; the symbols stay."""
    from ..model.overrides import with_parameters
    from .move import moved

    symbols = {name: "1" for name, p in model.parameters.items() if p.value is None}
    twin = moved(with_parameters(dataclasses.replace(model, move={}), symbols), {jid: amount})
    return dataclasses.replace(twin, parameters=model.parameters)


def _check(model: Model, posed: Model, jid: str, amount: float, where: str) -> None:
    """The exact pose must be where the numeric sweep takes the model at the probe values."""
    from ..engine.instant import instantiate
    from ..model.overrides import with_parameters
    from .move import moved

    inst = instantiate(posed)
    values = {str(s): repr(float(v)) for s, v in inst.probe.items() if s not in inst.names}
    numeric = with_parameters(dataclasses.replace(model, move={}), values)
    try:
        reached = instantiate(moved(numeric, {jid: amount}), False).points
    except KinematikaError as err:
        raise KinematikaError(err.kind, f"cannot move: at values of the symbols where the model "
                              f"holds ({_shown(values)}), {err.message}", where) from None
    for name, p in inst.points.items():
        exact = np.asarray(inst.numvec(p))
        if not np.allclose(exact, reached[name], atol=1e-7 * inst.scale, rtol=0):
            raise KinematikaError("schema", f"cannot move exactly: point {name!r} does not follow "
                                  f"the input; write it by construction from the points it is "
                                  "joined to (or give the parameters values)", where)


def _shown(values: dict[str, str]) -> str:
    text = ", ".join(f"{k} = {float(v):.4g}" for k, v in values.items())
    return text if len(text) <= 80 else text[:77] + "..."
