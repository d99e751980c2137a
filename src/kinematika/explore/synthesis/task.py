"""A synthesis task as posed: the targets, their timing, the objective and the requirements.

Path generation: a point passes through target points `x,y`; with `--timing JOINT` each
row also gives `input`, how far the driven joint has moved since the first target (degrees
for a revolute; the first row 0), the first target met START from the drawn configuration
(`--timing JOINT=START`) or wherever the design chooses (`--timing JOINT`). Function
generation: the output body's rotation `y` (degrees) at the input's travel `x` (degrees),
both from their zeros: the input's zero is the drawn configuration, or START from it, or
free (`--timing`); the output's zero is its drawn position, a free angle
(`--output-zero free`) or the absolute direction of its line (`--output-zero DEG`, degrees
from the x axis; a body's line runs from its first point to its second). Motion
generation: poses `x,y,angle` of the point's body (its line's direction, degrees), with an
`input` column under `--timing` as for a path.

Each target's error is a length (path: the distance; motion: √(|ΔP|² + (ρ Δφ)²), ρ the
body's size, Δφ in radians) or an angle (function, degrees); its residual is √w times it,
w the row's `weight` (1 unless the file has a weight column). `--objective sse` minimises
the sum of the squared residuals, `max` (the default) the largest residual.

A target file is CSV: a first line of column names may stand first (`x,y,input,weight`
…, in any order); without it the columns are, in order, those of the task (x, y, then
`angle` for a motion, `input` under `--timing`, then an optional `weight`). A column the task
does not read is an error, never ignored.
"""
from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ...errors import KinematikaError

OBJECTIVES = ("max", "sse")
REQUIREMENTS = ("crank-rocker", "ordered", "transmission=DEG")
MIN_TARGETS = 2


@dataclass(frozen=True)
class Timing:
    """`--timing JOINT[=START]`: the driven joint, and where the first target is met (sweep
    units from the drawn configuration), None when the design chooses it."""

    joint: str
    start: Optional[float] = None


@dataclass(frozen=True)
class Requirements:
    """`--require`: a crank-rocker, targets met in order, a least transmission angle (degrees)."""

    crank_rocker: bool = False
    ordered: bool = False
    transmission: Optional[float] = None

    def __bool__(self) -> bool:
        return self.crank_rocker or self.ordered or self.transmission is not None

    def names(self) -> list[str]:
        """As written on the command line."""
        out = ["crank-rocker"] if self.crank_rocker else []
        out += ["ordered"] if self.ordered else []
        out += [f"transmission={self.transmission:g}"] if self.transmission is not None else []
        return out


@dataclass
class Task:
    """What the synthesis must do; arrays have one entry per target."""

    kind: str                               # "path", "function" or "motion"
    file: str                               # the target file's name (for messages)
    xy: np.ndarray                          # path and motion: target points (complex); function: empty
    angle: np.ndarray                       # motion: target angles; function: the output's rotation (deg)
    inputs: Optional[np.ndarray]            # the input's travel from the first (or the zero), sweep units
    weights: np.ndarray
    objective: str = "max"
    timing: Optional[Timing] = None
    requires: Requirements = field(default_factory=Requirements)
    point: Optional[str] = None             # path and motion
    body: Optional[str] = None              # function: the output body
    output_zero: Optional[str | float] = None   # function: None (drawn), "free", or degrees

    @property
    def count(self) -> int:
        """How many targets."""
        return len(self.weights)

    @property
    def free_timing(self) -> bool:
        """Path or motion targets met anywhere along the motion (no `input` column)."""
        return self.kind != "function" and self.inputs is None

    @property
    def label(self) -> str:
        """The objective's column name: `sse` or `max`."""
        return self.objective


def parse_objective(text: str) -> str:
    """`--objective`: sse or max."""
    if text not in OBJECTIVES:
        raise KinematikaError("usage", "objective-form", "--objective", got=repr(text))
    return text


def parse_timing(text: Optional[str]) -> Optional[Timing]:
    """`--timing JOINT` or `JOINT=START`."""
    if text is None:
        return None
    joint, eq, start = text.partition("=")
    joint = joint.strip()
    if not joint:
        raise KinematikaError("usage", "timing-form", "--timing", got=repr(text))
    if not eq:
        return Timing(joint)
    try:
        value = float(start)
    except ValueError:
        raise KinematikaError("usage", "timing-start-number", "--timing", joint=joint, got=repr(start)) from None
    if not math.isfinite(value):
        raise KinematikaError("usage", "timing-start-finite", "--timing", joint=joint)
    return Timing(joint, value)


def parse_requirements(texts: list[str]) -> Requirements:
    """`--require crank-rocker`, `--require ordered`, `--require transmission=DEG`."""
    crank_rocker = ordered = False
    transmission: Optional[float] = None
    for text in texts:
        name, eq, value = (t.strip() for t in text.partition("="))
        if name == "crank-rocker" and not eq:
            crank_rocker = True
        elif name == "ordered" and not eq:
            ordered = True
        elif name == "transmission" and eq:
            try:
                deg = float(value)
            except ValueError:
                deg = math.nan
            if not 0 < deg < 90:
                raise KinematikaError("usage", "require-transmission-angle", "--require", got=repr(value))
            transmission = deg
        else:
            raise KinematikaError("usage", "requirement-unknown", "--require", requirement=text,
                                  requirements=list(REQUIREMENTS))
    return Requirements(crank_rocker, ordered, transmission)


def parse_output_zero(text: Optional[str]) -> Optional[str | float]:
    """`--output-zero free` or an angle in degrees."""
    if text is None or text == "free":
        return text
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise KinematikaError("usage", "output-zero-form", "--output-zero", got=repr(text))
    return value


# the target file ------------------------------------------------------------------------------
def columns_of(kind: str, timed: bool) -> tuple[list[str], list[str]]:
    """The columns a task reads, in their order without a header: (required, optional)."""
    if kind == "function":
        return ["x", "y"], ["weight"]
    need = ["x", "y"] + (["angle"] if kind == "motion" else []) + (["input"] if timed else [])
    return need, ["weight"]


def read_targets(kind: str, name: str, text: str, timing: Optional[Timing], option: str) -> dict[str, np.ndarray]:
    """The target file's columns by name, checked: numbers, the task's columns and no other,
    at least MIN_TARGETS rows, inputs that start at 0 (path, motion) and increase, positive
    weights. Each bad input is one line naming the file, and the line when there is one."""
    need, optional = columns_of(kind, timing is not None)
    header, rows, lines = _rows(name, text, option)
    width = len(rows[0]) if rows else 0
    reads = f"{','.join(need)}[,{','.join(optional)}]"         # the task's columns, as a header writes them
    if header is None:
        allowed = need + optional
        if width < len(need) or width > len(allowed):
            raise KinematikaError("usage", "target-columns-count", option, name=name, count=width, reads=reads)
        header = allowed[:width]
    else:
        unknown = [h for h in header if h not in need + optional]
        if unknown:
            raise KinematikaError("usage", "target-column-unread", option, name=name, column=unknown[0],
                                  timing=unknown[0] == "input", reads=reads)
        missing = [h for h in need if h not in header]
        if missing:
            raise KinematikaError("usage", "target-column-missing", option, name=name, column=missing[0], reads=reads)
    table = np.array(rows, dtype=float)
    out = {h: table[:, i] for i, h in enumerate(header)}
    if len(table) < MIN_TARGETS:
        raise KinematikaError("usage", "targets-too-few", option, name=name, count=len(table), least=MIN_TARGETS)
    weights = out.get("weight")
    if weights is not None and not (weights > 0).all():
        k = int(np.argmin(weights > 0))
        raise KinematikaError("usage", "target-weight-positive", option, name=name, line=lines[k])
    series = out.get("input") if kind != "function" else out["x"]
    what = "input" if kind != "function" else "x"
    if series is not None:
        if kind != "function" and series[0] != 0:
            raise KinematikaError("usage", "target-first-input", option, name=name, line=lines[0])
        steps = np.diff(series)
        if (steps <= 0).any():
            k = int(np.argmax(steps <= 0)) + 1
            raise KinematikaError("usage", "target-inputs-increase", option, name=name, line=lines[k], column=what,
                                  before=float(series[k - 1]), after=float(series[k]))
    return out


def _rows(name: str, text: str, option: str) -> tuple[Optional[list[str]], list[list[float]], list[int]]:
    """A header (lowercased names) if the first line is one, the numeric rows, their line numbers."""
    header: Optional[list[str]] = None
    rows: list[list[float]] = []
    lines: list[int] = []
    for i, row in enumerate(csv.reader(io.StringIO(text))):
        cells = [c.strip() for c in row]
        if not any(cells):
            continue
        try:
            numbers = [float(c) for c in cells]
        except ValueError:
            if not rows and header is None:
                header = [c.lower() for c in cells]
                if len(set(header)) != len(header) or not all(header):
                    raise KinematikaError("usage", "target-header-twice", option, name=name, line=i + 1) from None
                continue
            raise KinematikaError("usage", "table-not-numbers", option, name=name, line=i + 1, got=repr(row)) from None
        if not all(map(math.isfinite, numbers)):
            raise KinematikaError("usage", "target-not-finite", option, name=name, line=i + 1)
        width = len(header) if header is not None else (len(rows[0]) if rows else len(numbers))
        if len(numbers) != width:
            raise KinematikaError("usage", "target-row-width", option, name=name, line=i + 1, count=len(numbers),
                                  columns=width)
        rows.append(numbers)
        lines.append(i + 1)
    if not rows:
        raise KinematikaError("usage", "table-empty", option, name=name)
    return header, rows, lines


def make_task(kind: str, name: str, text: str, option: str, objective: str = "max",
              timing: Optional[Timing] = None, requires: Requirements = Requirements(),
              point: Optional[str] = None, body: Optional[str] = None,
              output_zero: Optional[str | float] = None) -> Task:
    """A task from its target file's text and the command line's choices."""
    columns = read_targets(kind, name, text, timing, option)
    n = len(columns["x"])
    weights = columns.get("weight", np.ones(n))
    if kind == "function":
        return Task(kind, name, np.zeros(0, dtype=complex), columns["y"], columns["x"], weights, objective,
                    timing, requires, point, body, output_zero)
    xy = columns["x"] + 1j * columns["y"]
    angle = columns.get("angle", np.zeros(0))
    return Task(kind, name, xy, angle, columns.get("input"), weights, objective, timing, requires, point, body)
