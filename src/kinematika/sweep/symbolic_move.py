"""`move` in a model with symbolic parameters: the input carried, the other bodies following.

A sweep needs numbers, but a model written by construction moves exactly: turn the input
body about its pivot by the amount (or shift a slider along its guide) and every point
constructed from it follows through its construction, so the answers stay formulas (a
four-bar moved 30° from a general crank angle θ is the four-bar at θ + 30°). The other
bodies are carried wherever their pose after the move is a closed form of the input's
(`sweep.carried`: rolling ratios, bodies turning as others do, two known places), so a
planet on a fixed sun moved by its arm, or a Geneva wheel's points, stay exact too.

Everything is checked at the symbols' probe values against the numeric sweep of the same
model (`Path`); a point that still does not follow gets a one-line error saying why.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ..engine.instant import Instant, instantiate
from ..engine.turns import turn_for
from ..errors import KinematikaError, Said
from ..expressions import parse
from ..joints.capabilities import Coordinate
from ..model.body_shapes import Line
from ..model.model import Model
from ..model.motion_sections import Turn
from ..model.overrides import with_parameters
from .advance import advanced, swept_to
from .carried import Input, Path, carried_turns, fixture, placed
from .posed import posed_model

Step = tuple[str, float, str]          # joint id, amount (degrees or length), where


def symbolic_moved(model: Model, steps: list[Step]) -> Model:
    """`model` with each joint advanced by its amount (degrees or length), exactly."""
    where = steps[0][2]
    inst = instantiate(model)
    if not _geometry_has_symbols(inst):
        for jid, amount, _ in steps:
            model = _moved_with_numbers(model, jid, amount)
        return model
    if model.dimension != 2:
        raise KinematikaError("schema", "move-symbolic-3d", where)
    if model.turns:
        raise KinematikaError("schema", "move-symbolic-once", where)
    inputs = [_input(model, i, jid, amount, w) for i, (jid, amount, w) in enumerate(steps)]
    if len({i.turn.body for i in inputs}) < len(inputs):
        raise KinematikaError("schema", "move-same-body", where)
    values = {str(s): repr(float(v)) for s, v in inst.probe.items() if s not in inst.names}
    path = _path(model, steps, values, where)
    turns = carried_turns(model, inputs, path, values, inst)
    posed = dataclasses.replace(model, move={}, turns=turns)
    _check(posed, path, values, where)
    return posed


def _input(model: Model, index: int, jid: str, amount: float, where: str) -> Input:
    """The turn (or shift) of the body joint `jid` drives from the frame, by `amount`."""
    joint = model.joint(jid)
    frame = model.frame
    if frame not in (joint.a, joint.b):
        raise KinematikaError("schema", "move-not-input", where, joint=jid)
    body = joint.b if joint.a == frame else joint.a
    sign = 1 if joint.a == frame else -1          # the coordinate is b relative to a
    value = repr(float(sign * amount))
    if joint.kind.coordinate is Coordinate.ANGLE:
        return Input(Turn(body, pivot=joint.at, angle=parse(f"deg({value})")), {index: 1})
    return Input(Turn(body, along=joint.along, shift=parse(value)), {})


def _geometry_has_symbols(inst: Instant) -> bool:
    """Whether the positions depend on the symbols (else only rates do: ω = w, say)."""
    values = [c for p in inst.points.values() for c in p]
    values += [x for shapes in inst.shapes.values() for s in shapes
               for x in (getattr(s, "radius", 0), *getattr(s, "direction", ()), *getattr(s, "axis", ()),
                         *getattr(s, "normal", ()), *getattr(s, "center", ()), *getattr(s, "through", ()))]
    return any(getattr(v, "free_symbols", None) for v in values)


def _moved_with_numbers(model: Model, jid: str, amount: float) -> Model:
    """A model whose symbols are only rates moves as its numeric twin; the symbols stay."""
    symbols = {name: "1" for name, p in model.parameters.items() if p.value is None}
    twin = advanced(with_parameters(dataclasses.replace(model, move={}), symbols), jid, amount, f"move.{jid}")
    return dataclasses.replace(twin, parameters=model.parameters)


def _path(model: Model, steps: list[Step], values: dict[str, str], where: str) -> Path:
    """The move made numerically at the probe values, one sweep per step, rows end to end."""
    current = with_parameters(dataclasses.replace(model, move={}), values)
    angles: dict[str, list] = {b: [] for b in model.bodies}
    places: dict[str, list] = {}
    columns: list[np.ndarray] = []
    reached = np.zeros(len(steps))
    base = dict.fromkeys(model.bodies, 0.0)
    for k, (jid, amount, _) in enumerate(steps):
        try:
            result = swept_to(current, jid, amount)
        except KinematikaError as err:
            raise KinematikaError(err.kind, "move-at-values", where, values=_shown(values), problem=err.said) from None
        joint = model.joint(jid)
        sign = 1.0 if joint.a == model.frame else -1.0
        rows = np.asarray(result.coordinate, dtype=float)
        rows = np.radians(rows) if joint.kind.coordinate is Coordinate.ANGLE else rows
        block = np.tile(reached, (len(rows), 1))
        block[:, k] = sign * rows
        columns.append(block)
        reached[k] = sign * rows[-1]
        for b in model.bodies:
            angles[b].append(base[b] + np.radians(result.bodies[b]["angle"]))
            base[b] = float(angles[b][-1][-1])
        for ref, q in result.points.items():
            places.setdefault(ref, []).append(np.asarray(q["position"], dtype=float))
        current = posed_model(current, result, -1)
    final = {k: np.asarray(v, dtype=float) for k, v in instantiate(current, False).points.items()}
    return Path({b: np.concatenate(v) for b, v in angles.items()},
                {r: np.concatenate(v) for r, v in places.items()}, np.concatenate(columns), final)


def _check(posed: Model, path: Path, values: dict[str, str], where: str) -> None:
    """The exact pose must be where the numeric move takes the model at the probe values;
    else a one-line error naming the first point that is not, and why."""
    inst = instantiate(posed)
    twin = placed(posed, posed.turns, values)
    for name, p in inst.points.items():
        exact = np.asarray(inst.numvec(p))
        if not np.allclose(exact, path.final[name], atol=1e-7 * inst.scale, rtol=0):
            raise KinematikaError("schema", _why(posed, name, twin is not None and np.allclose(
                twin[name], path.final[name], atol=1e-7 * inst.scale, rtol=0)), where)
    _check_fixtures(posed, path, where)


def _why(model: Model, name: str, numerically: bool) -> Said:
    """Why point `name` does not follow the input: one line."""
    if numerically:
        return Said("move-exact-numbers", point=name)
    owner = model.place_owner(name) if model.carriers(name) else None
    turn = turn_for(model, name)
    if turn is None and owner is not None and _rolls_on_a_line(model, owner):
        return Said("move-exact-rolls", point=name, body=owner)
    if turn is None and owner is not None:
        return Said("move-exact-no-form", point=name, body=owner)
    return Said("move-exact-constructed", point=name, body=repr(turn.body if turn else owner))


def _rolls_on_a_line(model: Model, body: str) -> bool:
    """Whether `body` rolls with a circle on a line (either body's), which `carried` does not
    follow: its turn depends on the path of its centre."""
    for j in model.joints:
        if j.kind.rolls and body in (j.a, j.b):
            if any(isinstance(s, Line) for b in (j.a, j.b) for s in model.bodies[b].shapes):
                return True
    return False


def _check_fixtures(model: Model, path: Path, where: str) -> None:
    """A body the move turns but no turn carries must have no shape or direction written in
    numbers (`fixture`: they would stay as drawn)."""
    turned = {t.body for t in model.turns}
    for body in model.moving_bodies:
        if body in turned or np.max(np.abs(path.angles[body])) <= 1e-9:
            continue
        what = fixture(model, body)
        if what:
            raise KinematikaError("schema", "move-exact-fixture", where, body=body, what=what)


def _shown(values: dict[str, str]) -> str:
    text = ", ".join(f"{k} = {float(v):.4g}" for k, v in values.items())
    return text if len(text) <= 80 else text[:77] + "..."
