"""What a model says about the exercises made from it, and nothing else reads: the `exercise`
section (`kinematika exercise`, docs/exercises.md), checked here, and the units a
statement gives its data in.

    exercise:
      title: {en: "P pair with Coriolis", eu: "P bikotea Coriolisekin"}   # default: the model's name
      statement: {en: "The guide M turns about A at ω = {w} …", eu: "…"}
      units: {s: mm, beta: deg, w: rad/s}       # how the statement states each parameter
      length: m                                 # the model's length unit (default m)
      ask: [1, 2, 4]                            # the graded questions, 1-based (default: all)
      tolerance: 0.01                           # relative (default 0.01)
      weights: [1, 1, 2]                        # each graded question's weight (default: equal)
      dimensions: [{between: [A, E], along: x, label: ex}]    # more marks on the figure

A statement's `{name}` is the parameter's value as stated (`400 mm`, `30°`).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Collection, Optional

from ..errors import KinematikaError
from ..languages import known

PLACEHOLDER = re.compile(r"\{(\w+)\}")


@dataclass(frozen=True)
class Unit:
    """A unit a statement may give a value in: its kind and its size in the kind's base
    (metre, radian, second), exactly: `ratio` · π^`pi`."""

    name: str
    kind: str                     # length, angle, rate, rate2, speed, accel
    ratio: Fraction
    pi: int = 0
    text: str = ""                # as printed after a number ("mm", "°")

    @property
    def size(self) -> float:
        """The unit's size in its kind's base unit (metre, radian, second), ratio·π^pi: 0.001
        for mm, π/180 for deg."""
        return float(self.ratio) * math.pi ** self.pi

    @property
    def shown(self) -> str:
        """How the unit is printed after a number ("°" for deg, else its name)."""
        return self.text or self.name


def _units() -> dict[str, Unit]:
    rows = [("m", "length", Fraction(1), 0, ""), ("cm", "length", Fraction(1, 100), 0, ""),
            ("mm", "length", Fraction(1, 1000), 0, ""),
            ("rad", "angle", Fraction(1), 0, ""), ("deg", "angle", Fraction(1, 180), 1, "°"),
            ("rad/s", "rate", Fraction(1), 0, ""), ("rpm", "rate", Fraction(1, 30), 1, "rpm"),
            ("deg/s", "rate", Fraction(1, 180), 1, "°/s"),
            ("rad/s^2", "rate2", Fraction(1), 0, "rad/s²"), ("deg/s^2", "rate2", Fraction(1, 180), 1, "°/s²"),
            ("m/s", "speed", Fraction(1), 0, ""), ("cm/s", "speed", Fraction(1, 100), 0, ""),
            ("mm/s", "speed", Fraction(1, 1000), 0, ""), ("km/h", "speed", Fraction(5, 18), 0, ""),
            ("m/s^2", "accel", Fraction(1), 0, "m/s²"), ("cm/s^2", "accel", Fraction(1, 100), 0, "cm/s²"),
            ("mm/s^2", "accel", Fraction(1, 1000), 0, "mm/s²")]
    table = {name: Unit(name, kind, ratio, pi, text) for name, kind, ratio, pi, text in rows}
    for name in list(table):              # rad/s² and rad/s2 as well as rad/s^2
        if name.endswith("^2"):
            table[name[:-2] + "²"] = table[name]
            table[name[:-2] + "2"] = table[name]
    table["°"] = table["deg"]
    return table


UNITS = _units()
NAMES = ("m", "cm", "mm", "rad", "deg", "rad/s", "rpm", "deg/s", "rad/s^2", "deg/s^2", "m/s", "cm/s",
         "mm/s", "km/h", "m/s^2", "cm/s^2", "mm/s^2")

LENGTHS = {name: u for name, u in UNITS.items() if u.kind == "length"}


@dataclass(frozen=True)
class DimensionMark:
    """A dimension to draw: the distance between two points along x, y or aligned."""

    between: tuple[str, str]
    along: str = "aligned"
    label: Optional[str] = None        # a parameter's name, or a text


@dataclass(frozen=True)
class ExerciseSection:
    """The checked `exercise` section (every field has its default when absent)."""

    statement: dict[str, str] = field(default_factory=dict)
    units: dict[str, Unit] = field(default_factory=dict)
    title: dict[str, str] = field(default_factory=dict)
    length: Unit = UNITS["m"]
    ask: Optional[tuple[int, ...]] = None          # 1-based positions in the model's `ask`
    tolerance: float = 0.01
    dimensions: tuple[DimensionMark, ...] = ()
    weights: dict[int, float] = field(default_factory=dict)     # 1-based question -> its weight

    def unit(self, name: str) -> Optional[Unit]:
        """The unit parameter `name` is stated in (None: a plain number in the model's units)."""
        return self.units.get(name)


def exercise_section(raw: Any, params: Collection[str], questions: int,
                     points: Any) -> Optional[ExerciseSection]:
    """The section checked against the model: known parameters (`params`, their names),
    languages, units, questions and points; None when the model has none."""
    if raw is None:
        return None
    for lang in raw.title:
        known(lang, f"exercise.title.{lang}")
    statement = {}
    for lang, text in raw.statement.items():
        where = f"exercise.statement.{lang}"
        known(lang, where)
        for name in PLACEHOLDER.findall(text):
            if name not in params:
                raise KinematikaError("schema", "statement-placeholder", where, name=name, parameters=list(params))
        statement[lang] = text
    units = {name: _unit(text, f"exercise.units.{name}") for name, text in raw.units.items()}
    for name in units:
        if name not in params:
            raise KinematikaError("schema", "unknown-parameter", f"exercise.units.{name}", name=name,
                                  parameters=list(params))
    length = _unit(raw.length, "exercise.length")
    if length.kind != "length":
        raise KinematikaError("schema", "unit-not-length", "exercise.length", unit=raw.length, units=list(LENGTHS))
    ask = None if raw.ask is None else tuple(raw.ask)
    for i, k in enumerate(ask or ()):
        if not 1 <= k <= questions:
            raise KinematikaError("schema", "question-missing", f"exercise.ask[{i}]", number=k, count=questions)
    if ask is not None and (not ask or len(set(ask)) != len(ask)):
        raise KinematikaError("schema", "graded-once", "exercise.ask")
    tolerance = float(raw.tolerance)
    if not 0 < tolerance < 1:
        raise KinematikaError("schema", "tolerance-relative", "exercise.tolerance", tolerance=tolerance)
    weights = _weights(raw.weights, ask or tuple(range(1, questions + 1)))
    marks = []
    for i, d in enumerate(raw.dimensions):
        where = f"exercise.dimensions[{i}]"
        for name in d.between:
            if name not in points:
                raise KinematikaError("schema", "unknown-point-bare", f"{where}.between", point=name)
        marks.append(DimensionMark(tuple(d.between), d.along or "aligned", d.label))
    return ExerciseSection(statement, units, dict(raw.title), length, ask, tolerance, tuple(marks), weights)


def _weights(raw: Any, graded: tuple[int, ...]) -> dict[int, float]:
    """Each graded question's weight, by its number: one positive number per graded question,
    in order."""
    if raw is None:
        return {}
    if len(raw) != len(graded):
        raise KinematikaError("schema", "weights-count", "exercise.weights", count=len(graded), got=len(raw))
    for i, w in enumerate(raw):
        if not (w > 0 and math.isfinite(w)):
            raise KinematikaError("schema", "weight-positive", f"exercise.weights[{i}]", got=w)
    return {k: float(w) for k, w in zip(graded, raw)}


def _unit(text: str, where: str) -> Unit:
    unit = UNITS.get(text.strip())
    if unit is None:
        raise KinematikaError("schema", "unknown-unit", where, unit=text, units=list(NAMES))
    return unit
