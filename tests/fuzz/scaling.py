"""A model scaled in length and time, and the dimensions of its answers.

Kinematics has no preferred unit: the same mechanism drawn 10²⁰⁰ times larger moves with
velocities 10²⁰⁰ times larger, and turned 10¹⁰⁰ times faster has velocities 10¹⁰⁰ times and
accelerations 10²⁰⁰ times larger. `scaled` rewrites a model tree so (every length field
multiplied by `length`, every rate by `rate` and its square); `expected` scales an answer
the same way, so that a test compares the scaled model's answers with the original's.
"""
from __future__ import annotations

import copy
import math
from typing import Any

# the dimension of each kind of answer as (length power, time power): v = L T⁻¹
POSITION, VELOCITY, ACCELERATION = (1, 0), (1, -1), (1, -2)
OMEGA, ALPHA, NONE = (0, -1), (0, -2), (0, 0)

ANSWER = {"velocity": VELOCITY, "acceleration": ACCELERATION, "omega": OMEGA, "alpha": ALPHA}
FIELDS = {   # the fields of compound answers
    "point": POSITION, "direction": NONE, "rest": NONE, "uniform": NONE, "radius": POSITION,
    "center": POSITION, "drag": None, "relative": None, "coriolis": ACCELERATION, "total": None,
    "speed": VELOCITY, "tangent": NONE, "tangential": ACCELERATION, "normal": ACCELERATION,
    "tangential_vector": ACCELERATION, "normal_vector": ACCELERATION, "slide": VELOCITY,
    "omega": OMEGA, "velocity": VELOCITY, "acceleration": ACCELERATION,
}


def _times(value: Any, factor: float | tuple) -> Any:
    """An expression (or number) multiplied by `factor` (or by the product of a tuple of
    factors, written out so that a product beyond floats is the model's to refuse)."""
    factors = [f for f in (factor if isinstance(factor, tuple) else (factor,)) if f != 1]
    if not factors:
        return value
    return f"({value})" + "".join(f"*({f!r})" for f in factors)


def _vec(values: Any, factor: float) -> Any:
    if isinstance(values, list):
        return [_times(v, factor) for v in values]
    return _times(values, factor)


def _location(value: Any, factor: float) -> Any:
    """A point name stays; coordinates scale."""
    return value if isinstance(value, str) else _vec(value, factor)


def numeric(tree: dict) -> dict:
    """The model with every parameter given a number (the `draw_at` values when it has them,
    else generic values), so that it can be solved with floats."""
    tree = copy.deepcopy(tree)
    given = tree.pop("draw_at", None) or {}
    for i, (name, raw) in enumerate(list((tree.get("parameters") or {}).items())):
        value = raw.get("value") if isinstance(raw, dict) else raw
        if isinstance(raw, dict) and raw.get("symbolic"):
            value = None
        if value is None:
            tree["parameters"][name] = given.get(name, 0.7 + 0.37 * ((i * 7) % 11) / 11)
    return tree


def scaled(tree: dict, length: float = 1.0, rate: float = 1.0) -> dict:
    """`tree` with lengths multiplied by `length` and times divided by `rate`."""
    tree = copy.deepcopy(tree)
    speed, accel = (length, rate), (length, rate, rate)
    for name, raw in tree.get("points", {}).items():
        tree["points"][name] = _point(raw, length)
    for body in tree.get("bodies", {}).values():
        if not isinstance(body, dict):
            continue
        for shape, fields in (("circle", ("center", "radius")), ("line", ("through",)),
                              ("disc", ("center", "radius")), ("plane", ("through",))):
            spec = body.get(shape)
            if isinstance(spec, dict):
                for key in fields:
                    if key in spec:
                        spec[key] = _location(spec[key], length) if key != "radius" else _times(spec[key], length)
    sliding = {j.get("id") or f"j{i + 1}" for i, j in enumerate(tree.get("joints", []))
               if j.get("type") in ("prismatic", "slot", "cylindrical")}
    for d in tree.get("drivers", []):
        if "omega" in d:
            d["value"] = _vec(d["value"], rate)
            if "alpha" in d:
                d["alpha"] = _vec(d["alpha"], (rate, rate))
        elif "velocity" in d:
            d["value"] = _vec(d["value"], speed)
            if "acceleration" in d:
                d["acceleration"] = _vec(d["acceleration"], accel)
        elif "joint" in d:
            unit = length if d["joint"] in sliding else 1.0
            d["rate"] = _times(d["rate"], (unit, rate))
            if "accel" in d:
                d["accel"] = _times(d["accel"], (unit, rate, rate))
    sweep = tree.get("sweep")
    if isinstance(sweep, dict) and sweep.get("joint") in sliding and "by" in sweep:
        sweep["by"] = _times(sweep["by"], length)
    tree.pop("draw_at", None)
    return tree


def _point(raw: Any, length: float) -> Any:
    if isinstance(raw, list):
        return _vec(raw, length)
    raw = dict(raw)           # a construction
    for key in ("distance",):
        if key in raw:
            raw[key] = _times(raw[key], length)
    for key in ("at", "near"):
        if key in raw:
            raw[key] = _vec(raw[key], length)
    if "circles" in raw:
        raw["circles"] = [[c[0], _times(c[1], length)] for c in raw["circles"]]
    if "circle" in raw:
        raw["circle"] = [raw["circle"][0], _times(raw["circle"][1], length)]
    for key in ("line",):
        if isinstance(raw.get(key), dict):
            raw[key] = {**raw[key], "through": _location(raw[key]["through"], length)}
    if "lines" in raw:
        raw["lines"] = [{**ln, "through": _location(ln["through"], length)} if isinstance(ln, dict)
                        else ln for ln in raw["lines"]]
    return raw


def factor(dim: tuple[int, int] | None, length: float, rate: float) -> float:
    return 1.0 if dim is None else length ** dim[0] * rate ** (-dim[1])


def expected(value: Any, kind: str, length: float, rate: float, dim: Any = None) -> Any:
    """An answer of the unscaled model, scaled as the scaled model's should be."""
    dim = ANSWER.get(kind, POSITION) if dim is None else dim
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, dict):
        out = {}
        for key, v in value.items():
            sub = FIELDS.get(key, dim)
            if key in ("velocity", "acceleration") and isinstance(v, dict):
                sub = VELOCITY if key == "velocity" else ACCELERATION
            if key in ("drag", "relative", "total"):
                sub = dim
            out[key] = expected(v, kind, length, rate, sub)
        return out
    if isinstance(value, list):
        return [expected(v, kind, length, rate, dim) for v in value]
    return value * factor(dim, length, rate)


def is_close(got: Any, want: Any, scale: float, rel: float = 1e-6) -> bool:
    """Whether two answers agree: numbers within `rel` of the scale of their kind."""
    if isinstance(want, dict):
        return isinstance(got, dict) and set(got) == set(want) and all(
            is_close(got[k], want[k], scale, rel) for k in want)
    if isinstance(want, list):
        return isinstance(got, list) and len(got) == len(want) and all(
            is_close(g, w, scale, rel) for g, w in zip(got, want))
    if isinstance(want, float) or isinstance(got, float):
        if not isinstance(got, (int, float)) or not isinstance(want, (int, float)):
            return False
        if not (math.isfinite(got) and math.isfinite(want)):
            return False
        return abs(got - want) <= rel * max(abs(want), scale)
    return got == want
