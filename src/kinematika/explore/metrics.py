"""The metrics of a design study: one number (or class) per design, named as written.

Each metric reads the designs' motion over the sweep (`cycle.Cycle`, (D, N) arrays) and
gives one value per design. A metric that needs the whole cycle is null (NaN) for a design
whose sweep meets a position it cannot assemble. Definitions (docs/explore.md lists them):

| metric | value |
| --- | --- |
| `grashof` | the four-bar's class from its drawn link lengths (contract) |
| `transmission` | over the cycle, the least of μ and 180° − μ (degrees), μ the angle at B between coupler and rocker; a slider-crank: the least angle between rod and the normal to the slider's path |
| `range:BODY` | the body's angle range over the cycle (degrees) |
| `peak_omega:BODY`, `peak_alpha:BODY` | the largest \\|ω\\|, \\|α\\| over the cycle |
| `peak_speed:POINT`, `peak_accel:POINT` | the largest \\|v\\|, \\|a\\| over the cycle |
| `path_error:POINT=FILE.csv` | the largest distance from a target point of the file to the point's path |
| `motion_error:POINT=FILE.csv` | the largest distance from a target pose (x, y, angle) to the poses of the body carrying POINT |
| `time_ratio[:BODY]` | the output's slower stroke over its quicker one, in input travel (a full turn) |
| `dead_points` | the number of dead points met over the sweep |
| `structural_error:BODY=FILE.csv` | the largest \\|rotation − target\\| over the file's (input, rotation) rows |
| `angle:BODY=X`, `omega:BODY=X`, `alpha:BODY=X` | the body's value at the input X (sweep units) |
| `speed:POINT=X`, `accel:POINT=X`, `x:POINT=X`, `y:POINT=X` | the point's value at the input X |
"""
from __future__ import annotations

import csv
import io
import math
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

import numpy as np

from ..errors import KinematikaError
from ..model.model import Model, PointRef
from ..structure.assur import Group
from .cycle import Cycle
from .fourbar import grashof_of

CLASSES = ("crank-rocker", "double-crank", "double-rocker", "rocker-crank", "change-point", "non-grashof")
AT_INPUT = {"angle": "body", "omega": "body", "alpha": "body",
            "speed": "point", "accel": "point", "x": "point", "y": "point"}
PEAKS = {"peak_omega": "body", "peak_alpha": "body", "peak_speed": "point", "peak_accel": "point"}


@dataclass
class Context:
    """What metrics need to know about the study's model: its structure and its sweep."""

    model: Model
    groups: Optional[list[Group]]
    coordinate: np.ndarray          # the sweep's increments (sweep units)
    unit: str                       # "deg" or "length"


@dataclass
class Metric:
    """A metric as written (`name`) and how to compute it over a cycle (one value per design)."""

    name: str
    compute: Callable[[Cycle], np.ndarray]
    full_cycle: bool = True
    kind: str = "number"            # "number", "count" or "class"
    data: Any = field(default=None, repr=False)

    def values(self, cycle: Cycle) -> np.ndarray:
        """The metric over `cycle`, one value per design; floating-point warnings are silenced
        (a design that stops gives NaN), and a number that needs the full cycle is NaN for a
        design not assembled all the way."""
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)      # all-NaN rows: designs that stop
            out = self.compute(cycle)
        if self.full_cycle and self.kind == "number":
            out = np.where(cycle.complete, out, np.nan)
        return out


def parse_metric(text: str, ctx: Context, files: Optional[dict[str, str]] = None) -> Metric:
    """A metric from its name as written after `--metric`; a bad one is a usage error.
    `files` holds the text of the target files it names (read where the study starts)."""
    files = files or {}
    head, _, arg = text.partition("=")
    kind, colon, target = head.partition(":")
    kind, target = kind.strip(), target.strip()
    where = f"--metric {text}"
    if kind == "grashof" and not colon and not arg:
        roles = four_bar_roles(ctx)
        return Metric(text, lambda c: grashof(c, roles), full_cycle=False, kind="class")
    if kind == "transmission" and not colon and not arg:
        return Metric(text, _transmission(ctx, where))
    if kind == "dead_points" and not colon and not arg:
        return Metric(text, lambda c: c.dead.astype(float), full_cycle=False, kind="count")
    if kind == "time_ratio" and not arg:
        _full_turn(ctx, where)
        output = _body(ctx, target, where) if colon else _linkage_output(ctx, where)
        refs = [PointRef(p, output) for p in ctx.model.bodies[output].points]
        return Metric(text, lambda c: time_ratio(c, output, refs))
    if kind == "range" and colon and not arg:
        body = _body(ctx, target, where)
        return Metric(text, lambda c: np.nanmax(c.angle(body), axis=1) - np.nanmin(c.angle(body), axis=1))
    if kind in PEAKS and colon and not arg:
        return Metric(text, _peak(kind, ctx, target, where))
    if kind == "path_error" and colon and arg:
        ref = _point(ctx, target, where)
        targets = read_points(arg.strip(), files, where)
        return Metric(text, lambda c: path_error(c.motion(ref)[0], targets), data=targets)
    if kind == "motion_error" and colon and arg:
        ref = _point(ctx, target, where)
        points = ctx.model.bodies[ref.body].points
        if len(points) < 2:
            raise KinematikaError("usage", "motion-error-two-points", where, body=ref.body)
        poses = read_table(arg.strip(), files, where, 3)
        return Metric(text, lambda c: motion_error(c, ref, points, poses), data=poses)
    if kind == "structural_error" and colon and arg:
        body = _body(ctx, target, where)
        table = read_table(arg.strip(), files, where, 2)
        _inside(ctx, table[:, 0], where)
        return Metric(text, lambda c: structural_error(c, body, table), data=table)
    if kind in AT_INPUT and colon and arg:
        return _at_input(text, kind, ctx, target, arg, where)
    raise KinematikaError("usage", "metric-unknown", "--metric", metric=text)


# names ---------------------------------------------------------------------------------------
def _body(ctx: Context, name: str, where: str) -> str:
    if name not in ctx.model.bodies:
        raise KinematikaError("usage", "unknown-body", where, body=name, bodies=list(ctx.model.bodies))
    return name


def _point(ctx: Context, name: str, where: str) -> PointRef:
    try:
        return ctx.model.resolve_point(name, where)
    except KinematikaError as err:
        raise KinematikaError("usage", err.said, where) from None


# linkages ------------------------------------------------------------------------------------
def four_bar_roles(ctx: Context, where: str = "--metric grashof") -> dict[str, str]:
    """The point names O2, A, B, O4 of a four-bar driven at its crank (structure only)."""
    roles = _linkage(ctx)
    if roles is None or roles["kind"] != "four-bar":
        raise KinematikaError("usage", "grashof-four-bar", where)
    return roles


def _linkage(ctx: Context) -> Optional[dict[str, Any]]:
    """Four-bar (input crank + RRR closing on the frame) or slider-crank (+ RRP on the frame)."""
    return linkage_roles(ctx.model, ctx.groups)


def linkage_roles(model: Model, groups: Optional[list[Group]]) -> Optional[dict[str, Any]]:
    """The roles of a four-bar (an input crank and an RRR dyad closing on the frame) or a
    slider-crank (an RRP dyad): the points O2, A, B (and O4), the crank, coupler and output
    bodies, `kind`; None for any other mechanism."""
    if not groups or len(groups) != 2 or groups[0].kind != "input":
        return None
    first, dyad = groups
    crank = model.joint(first.joints[0])
    if first.letters != "R" or dyad.kind not in ("RRR", "RRP") or len(dyad.bodies) != 2 \
            or dyad.known != [first.bodies[0], model.frame]:
        return None
    j1, j2, j3 = (model.joint(j) for j in dyad.joints)
    roles = {"O2": crank.at, "A": j1.at, "B": j2.at, "crank": first.bodies[0],
             "coupler": dyad.bodies[0], "output": dyad.bodies[1]}
    if dyad.kind == "RRR":
        return {**roles, "kind": "four-bar", "O4": j3.at}
    return {**roles, "kind": "slider-crank", "guide": j3.id}


def _linkage_output(ctx: Context, where: str) -> str:
    roles = _linkage(ctx)
    if roles is None:
        raise KinematikaError("usage", "time-ratio-linkage", where)
    return roles["output"]


def grashof(c: Cycle, roles: dict[str, Any]) -> np.ndarray:
    """Grashof's class from the drawn lengths (s + l against p + q, then the shortest link)."""
    o2, a, b, o4 = (c.drawn(roles[k]) for k in ("O2", "A", "B", "O4"))
    return grashof_of(np.stack([np.abs(o4 - o2), np.abs(a - o2), np.abs(b - a), np.abs(o4 - b)]))


def _transmission(ctx: Context, where: str) -> Callable[[Cycle], np.ndarray]:
    roles = _linkage(ctx)
    if roles is None:
        raise KinematikaError("usage", "transmission-linkage", where)
    coupler = roles["coupler"]
    a_ref, b_ref = PointRef(roles["A"], coupler), PointRef(roles["B"], coupler)
    if roles["kind"] == "four-bar":
        o4 = roles["O4"]

        def four_bar(c: Cycle) -> np.ndarray:
            ba = c.motion(a_ref)[0] - c.motion(b_ref)[0]
            bo = c.drawn(o4)[:, None] - c.motion(b_ref)[0]
            mu = np.degrees(np.abs(np.angle(bo * np.conj(ba))))        # 0..180
            return np.nanmin(np.minimum(mu, 180.0 - mu), axis=1)
        return four_bar
    guide = ctx.model.joint(roles["guide"])

    def slider_crank(c: Cycle) -> np.ndarray:
        ba = c.motion(a_ref)[0] - c.motion(b_ref)[0]
        n = 1j * c.direction(guide.id)[:, None]          # the normal to the slider's path
        cos = np.abs((ba * np.conj(n)).real) / np.abs(ba)
        return np.nanmin(np.degrees(np.arccos(np.clip(cos, 0.0, 1.0))), axis=1)
    return slider_crank


# over the cycle ------------------------------------------------------------------------------
def _peak(kind: str, ctx: Context, target: str, where: str) -> Callable[[Cycle], np.ndarray]:
    if PEAKS[kind] == "body":
        body = _body(ctx, target, where)
        read = (lambda c: c.omega(body)) if kind == "peak_omega" else (lambda c: c.alpha(body))
    else:
        ref = _point(ctx, target, where)
        index = 1 if kind == "peak_speed" else 2
        read = lambda c: c.motion(ref)[index]
    return lambda c: np.nanmax(np.abs(read(c)), axis=1)


def path_error(path: np.ndarray, targets: np.ndarray) -> np.ndarray:
    """The largest distance from a target to the polyline through the path's rows (D, N)."""
    return path_distances(path, targets).max(axis=1)


def path_distances(path: np.ndarray, targets: np.ndarray) -> np.ndarray:
    """Each target's distance to the polyline through the path's rows (D, N): (D, K)."""
    start, end = path[:, :-1], path[:, 1:]
    seg = end - start
    length2 = (seg * np.conj(seg)).real
    out = np.zeros((len(path), len(targets)))
    for i, t in enumerate(targets):
        rel = t - start
        along = np.clip(np.where(length2 > 0, (rel * np.conj(seg)).real / length2, 0.0), 0.0, 1.0)
        out[:, i] = np.nanmin(np.abs(rel - along * seg), axis=1)
    return out


def motion_error(c: Cycle, ref: PointRef, points: list[str], poses: np.ndarray) -> np.ndarray:
    """The largest, over target poses (x, y, angle in degrees), of the distance to the nearest pose
    over the cycle: √(|ΔP|² + (ρ Δφ)²), φ the direction of the body's line from its first point to
    its second, ρ the body's size (its largest distance between two points): an angle error
    counts as the displacement it gives the body's far end."""
    return pose_distances(c, ref, points, poses).max(axis=1)


def pose_distances(c: Cycle, ref: PointRef, points: list[str], poses: np.ndarray) -> np.ndarray:
    """Each target pose's distance to the nearest pose over the cycle (as `motion_error`): (D, K)."""
    pos = c.motion(ref)[0]
    drawn = [c.drawn(p) for p in points]
    phi = np.angle(drawn[1] - drawn[0])[:, None] + np.radians(c.angle(ref.body))
    size = np.max([np.abs(p - q) for p in drawn for q in drawn], axis=0)[:, None]
    out = np.zeros((len(pos), len(poses)))
    for i, (x, y, angle) in enumerate(poses):
        turn = np.angle(np.exp(1j * (phi - math.radians(angle))))
        out[:, i] = np.nanmin(np.sqrt(np.abs(pos - complex(x, y)) ** 2 + (size * turn) ** 2), axis=1)
    return out


def time_ratio(c: Cycle, body: str, refs: list[PointRef]) -> np.ndarray:
    """Over a full turn of the input at constant speed: the output's slower stroke (between its
    extreme positions) over its quicker one, each measured in input travel. The extremes are
    located between rows by the quartic through the five nearest rows."""
    series = _output_series(c, body, refs)[:, :-1]                # the last row repeats the first
    n = series.shape[1]
    step = 360.0 / n
    at_max = _vertex(series, np.nanargmax(series, axis=1))
    at_min = _vertex(series, np.nanargmin(series, axis=1))
    a = ((at_max - at_min) * step) % 360.0
    quick = np.minimum(a, 360.0 - a)
    return np.where(quick > 0, np.maximum(a, 360.0 - a) / quick, np.nan)


def _output_series(c: Cycle, body: str, refs: list[PointRef]) -> np.ndarray:
    """The body's angle where it turns; a body that only translates: its displacement along the
    direction of its largest travel."""
    angle = c.angle(body)
    turns = np.nanmax(angle, axis=1) - np.nanmin(angle, axis=1) > 1e-9
    if turns.all() or not refs:
        return angle
    pos = c.motion(refs[0])[0]
    d = pos - pos[:, :1]
    far = np.take_along_axis(d, np.nanargmax(np.abs(d), axis=1)[:, None], axis=1)
    u = np.where(np.abs(far) > 0, far / np.abs(far), 1.0)
    travel = (d * np.conj(u)).real
    return np.where(turns[:, None], angle, travel)


def _vertex(series: np.ndarray, k: np.ndarray) -> np.ndarray:
    """The extreme's row, refined between rows: the quartic through rows k-2 .. k+2 (cyclic),
    its slope's zero found by Newton's method from the parabola's vertex."""
    n = series.shape[1]
    rows = np.arange(len(series))[:, None]
    y = series[rows, (k[:, None] + np.arange(-2, 3)) % n]
    c = y @ _QUARTIC.T                                  # c0 + c1 x + ... + c4 x^4, x in rows from k
    x = np.where(c[:, 2] != 0, -c[:, 1] / (2 * np.where(c[:, 2] != 0, c[:, 2], 1.0)), 0.0)
    for _ in range(4):
        slope = c[:, 1] + 2 * c[:, 2] * x + 3 * c[:, 3] * x * x + 4 * c[:, 4] * x ** 3
        curve = 2 * c[:, 2] + 6 * c[:, 3] * x + 12 * c[:, 4] * x * x
        x = np.clip(x - np.where(curve != 0, slope / np.where(curve != 0, curve, 1.0), 0.0), -1.0, 1.0)
    return k + x


_QUARTIC = np.linalg.inv(np.vander(np.arange(-2.0, 3.0), 5, increasing=True))


def structural_error(c: Cycle, body: str, table: np.ndarray) -> np.ndarray:
    """The largest |rotation(x) − target| over the table's (x, target) rows (degrees), the
    rotation interpolated linearly between the sweep's rows."""
    return rotation_errors(c, body, table).max(axis=1)


def rotation_errors(c: Cycle, body: str, table: np.ndarray) -> np.ndarray:
    """Each row's |rotation(x) − target| (degrees; as `structural_error`): (D, K)."""
    return np.abs(_interpolate(c.coordinate, c.angle(body), table[:, 0]) - table[None, :, 1])


def _interpolate(coordinate: np.ndarray, values: np.ndarray, x: np.ndarray) -> np.ndarray:
    """(D, N) values at the inputs x (K,): linear between rows (exact at a row)."""
    n = len(coordinate)
    h = (coordinate[-1] - coordinate[0]) / (n - 1) if n > 1 else 1.0
    pos = (np.asarray(x, dtype=float) - coordinate[0]) / h
    k = np.clip(np.floor(pos).astype(int), 0, max(n - 2, 0))
    t = pos - k
    left = values[:, k]
    right = values[:, np.minimum(k + 1, n - 1)]
    return np.where(t == 0, left, left + t * (right - left))


def _at_input(text: str, kind: str, ctx: Context, target: str, arg: str, where: str) -> Metric:
    try:
        x = float(arg)
    except ValueError:
        raise KinematikaError("usage", "metric-at-input", where, metric=f"{kind}:{target}", unit=ctx.unit,
                              got=repr(arg)) from None
    _inside(ctx, np.array([x]), where)
    if AT_INPUT[kind] == "body":
        body = _body(ctx, target, where)
        read = {"angle": lambda c: c.angle(body), "omega": lambda c: c.omega(body),
                "alpha": lambda c: c.alpha(body)}[kind]
    else:
        ref = _point(ctx, target, where)
        read = {"speed": lambda c: np.abs(c.motion(ref)[1]), "accel": lambda c: np.abs(c.motion(ref)[2]),
                "x": lambda c: c.motion(ref)[0].real, "y": lambda c: c.motion(ref)[0].imag}[kind]

    def compute(c: Cycle) -> np.ndarray:
        values = np.where(c.ok, read(c), np.nan)
        return _interpolate(c.coordinate, values, np.array([x]))[:, 0]
    return Metric(text, compute, full_cycle=False)


def _inside(ctx: Context, x: np.ndarray, where: str) -> None:
    low, high = sorted((ctx.coordinate[0], ctx.coordinate[-1]))
    if (x < low - 1e-9).any() or (x > high + 1e-9).any():
        raise KinematikaError("usage", "input-outside-sweep", where, low=float(low), high=float(high), unit=ctx.unit)


def _full_turn(ctx: Context, where: str) -> None:
    if ctx.unit != "deg" or abs(abs(ctx.coordinate[-1]) - 360.0) > 1e-9:
        raise KinematikaError("usage", "time-ratio-full-turn", where)


# target files --------------------------------------------------------------------------------
def read_table(name: str, files: dict[str, str], where: str, columns: int) -> np.ndarray:
    """The numeric rows of a CSV file's text (a header line is skipped), `columns` numbers each."""
    if name not in files:
        raise KinematikaError("usage", "target-csv", where, name=name)
    rows: list[list[float]] = []
    for i, row in enumerate(csv.reader(io.StringIO(files[name]))):
        cells = [c.strip() for c in row if c.strip()]
        if not cells:
            continue
        try:
            numbers = [float(c) for c in cells]
        except ValueError:
            if not rows and i == 0:
                continue                                # a header
            raise KinematikaError("usage", "table-not-numbers", where, name=name, line=i + 1, got=repr(row)) from None
        if len(numbers) < columns or not all(map(math.isfinite, numbers)):
            raise KinematikaError("usage", "table-columns", where, name=name, line=i + 1, columns=columns)
        rows.append(numbers[:columns])
    if not rows:
        raise KinematikaError("usage", "table-empty", where, name=name)
    return np.array(rows, dtype=float)


def read_points(name: str, files: dict[str, str], where: str) -> np.ndarray:
    """Target points (x, y) of a CSV file as complex numbers."""
    table = read_table(name, files, where, 2)
    return table[:, 0] + 1j * table[:, 1]
