"""Motion through limit positions: the input runs back where it cannot go further.

A mechanism whose driven coordinate q reaches a limit position (a rocker's end of swing: the
input cannot go further) moves on as the real mechanism does: q turns back there and the
mechanism passes to the other branch of its configuration curve. The sweep's rows are taken
at equal steps of the input's *travel* t (the length of the path run by q, |by|/steps a
row), so q(t) is a zigzag between the limit positions met; the motion stops when `by` has
been travelled, or when it is back at the drawn configuration (the cycle is complete: a
last row is added there, as a crank's sweep ends at 360°).

`Zigzag` keeps that bookkeeping. Two paths find the limit positions:

- the closed form (dyads, `closed_form`): a limit position is where one dyad's two links
  fall in line (its circle–circle, circle–line or line–line discriminant reaches 0); found
  between two rows by bisection on "can it be assembled", the dyad then closes the other
  way (its side flipped) and q runs back (`follow_closed`);
- Newton's path (`continuation`): the configuration curve followed by pseudo-arclength
  continuation where stepping q fails; a limit position is where the curve's tangent has
  no q component.

Every loop is bounded by counts (`kinematika.limits`): limit positions a sweep may pass,
continuation steps, refinements; never by time.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from .. import limits as bounds
from ..errors import KinematikaError, Names, Num, Said
from .closed_form import series
from .plan import Plan
from .result import SweepResult, dead_points
from .swept import Swept

EDGE_LEVELS = 8          # bisection levels of 64 between a row that assembles and one that does not:
                         # 64⁻⁸ ≈ 3e-15 of a step


@dataclass
class Zigzag:
    """The input's path through its limit positions: where it is after a travel t.

    q runs from 0 in the direction of `by` (d = ±1); at each limit position it turns back.
    `start`/`travel0` are the coordinate and travel where the current run began.
    """

    plan: Plan
    d: float = 1.0
    start: float = 0.0
    travel0: float = 0.0
    limits: list[float] = field(default_factory=list)
    at: list[float] = field(default_factory=list)          # the travel at each limit

    def __post_init__(self) -> None:
        self.d = -1.0 if self.plan.by < 0 else 1.0
        self.h = abs(self.plan.by) / self.plan.steps       # the travel of a row

    def travel(self, k: Any) -> Any:
        """The travel at row k (rows at equal steps of travel)."""
        return np.asarray(k) * self.h

    def coordinate(self, t: Any) -> Any:
        """The coordinate after a travel t ≥ `travel0`, on the current run."""
        return self.start + self.d * (np.asarray(t, dtype=float) - self.travel0)

    def turn(self, q: float) -> None:
        """A limit position at q: the run ends there and the next one goes back."""
        if len(self.limits) >= bounds.SWEEP_LIMITS:
            raise KinematikaError("limit", "sweep-too-many-limits", "sweep", limit=bounds.SWEEP_LIMITS)
        self.travel0 += abs(q - self.start)
        self.limits.append(float(q))
        self.at.append(self.travel0)
        self.start, self.d = float(q), -self.d

    def period(self) -> float:
        """The input coordinate's period: 360 (degrees) for a revolute, none for a slider."""
        return 360.0 if self.plan.turns else math.inf

    def drawn_between(self, a: float, b: float) -> Optional[float]:
        """The first coordinate after a and up to b (along the run) where the input is as drawn
        (a multiple of its period), or None."""
        period = self.period()
        lo, hi = min(a, b), max(a, b)
        if not math.isfinite(period):
            values = [0.0] if lo < 0.0 <= hi or lo <= 0.0 < hi else []
        else:
            first, last = math.ceil(lo / period), math.floor(hi / period)
            values = [m * period for m in range(first, last + 1)]
        values = [v for v in values if (v - a) * self.d > 1e-12 * max(1.0, abs(a))]
        if not values:
            return None
        return min(values, key=lambda v: abs(v - a))


def not_followed(plan: Plan, q: float, travel: float, why: Said, kind: str = "assembly") -> KinematikaError:
    """The error of a motion that cannot be followed further (not a limit position)."""
    return KinematikaError(kind, "sweep-not-followed", "sweep", joint=plan.joint.id, value=Num(q, ".6g"),
                           unit=plan.unit, travel=Num(travel, ".6g"), why=why)


def with_rows(err: KinematikaError, partial: Optional[SweepResult]) -> KinematikaError:
    """`err` carrying the rows computed so far (`partial`): the command line writes them."""
    err.partial = partial                     # type: ignore[attr-defined]  # the rows ride on this one error to the command line (`cli.run`)
    return err


# the closed form ----------------------------------------------------------------------------
@dataclass
class _Run:
    """One run of the closed form between limit positions: its rows, coordinates and sides."""

    rows: np.ndarray                # row numbers
    q: np.ndarray                   # coordinates of those rows (user units)
    flips: dict[int, float]
    begin: Optional[float]          # the limit position it starts from (None: the drawing)
    end: Optional[float]            # the limit position (or the drawing) it ends at


def follow_closed(sweeper: Swept, plan: Plan, skip_bad: bool) -> SweepResult:
    """The sweep of a dyad mechanism through its limit positions (closed form, run by run)."""
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):   # rows at the edges
        return _follow_closed(sweeper, plan, skip_bad)


def _follow_closed(sweeper: Swept, plan: Plan, skip_bad: bool) -> SweepResult:
    zig = Zigzag(plan)
    scale = math.pi / 180 if plan.turns else 1.0
    runs: list[_Run] = []
    flips: dict[int, float] = {}
    k, last = 0, plan.steps
    closed = False
    begin: Optional[float] = None
    chunk = max(64, math.ceil(720.0 / zig.h) + 2) if plan.turns and zig.h > 0 else 4096   # rows looked at once
    while k <= last:
        rows = np.arange(k, min(last, k + chunk) + 1)
        q = zig.coordinate(zig.travel(rows))
        out = sweeper.form(flips).solve(q * scale)
        bad = ~np.asarray(out.assembled, dtype=bool)
        j = int(np.argmax(bad)) if bad.any() else len(rows)
        edge = None
        if j < len(rows):
            good_q = float(q[j - 1]) if j > 0 else zig.start
            edge, group = _edge(sweeper, flips, good_q, float(q[j]), int(out.failed[j]), scale, zig.h)
            if zig.limits and abs(edge - zig.start) <= 1e-9 * zig.h:
                why = Said("follow-turns-back")
                partial = _closed_result(sweeper, plan, zig, runs, False)
                raise with_rows(not_followed(plan, edge, zig.travel0, why, "singular"), partial)
        ahead = edge if edge is not None else float(q[-1])
        home = zig.drawn_between(zig.start, ahead) if zig.limits and not any(
            f < 0 for f in flips.values()) else None
        if home is not None:                       # back at the drawing: the cycle is complete
            keep = (q - home) * zig.d < 0
            runs.append(_Run(rows[keep], q[keep], dict(flips), begin, home))
            closed = True
            break
        runs.append(_Run(rows[:j], q[:j], dict(flips), begin, edge))
        if edge is None:                           # no limit among these rows: on to the next
            k, begin = int(rows[-1]) + 1, None
            continue
        if group is None:                          # not a dyad that closes two ways
            why = Said("follow-cannot-close", bodies=Names(out.groups[int(out.failed[j])].bodies, joined="and"))
            if not skip_bad:
                partial = _closed_result(sweeper, plan, zig, runs, False)
                raise with_rows(not_followed(plan, edge, zig.travel0 + abs(edge - zig.start), why), partial)
            runs.append(_Run(rows[j:], q[j:], dict(flips), None, None))
            break
        zig.turn(edge)
        flips[group] = -flips.get(group, 1.0)
        begin = edge
        k = int(rows[j])
    return _closed_result(sweeper, plan, zig, runs, closed)


def _edge(sweeper: Swept, flips: dict[int, float], good: float, bad: float, failed: int,
          scale: float, step: float) -> tuple[float, Optional[int]]:
    """Where between a coordinate that assembles (`good`) and one that does not (`bad`, where
    group `failed` fails first) the motion turns, to about 1e-15 of the step, and the dyad
    that stops it there (None: not a dyad with two closures, so not a limit position)."""
    form = sweeper.form(flips)
    for _ in range(EDGE_LEVELS):
        between = np.linspace(good, bad, 65)
        out = form.solve(between * scale)
        fine = np.asarray(out.assembled, dtype=bool)
        if fine.all():                             # `bad` assembles too here: it is the edge
            good = bad
            break
        if not fine[0]:
            break                                  # `good` itself is the edge (round-off)
        first = int(np.argmin(fine))
        failed = int(out.failed[first])
        good, bad = float(between[first - 1]), float(between[first])
    foldable = failed > 0 and sweeper.closed.chains[failed - 1][0].kind in ("RRR", "RRP", "RPR")
    if not foldable:
        return good, None
    return _fold(form, failed, good, np.sign(bad - good) or 1.0, abs(step), scale), failed


def _fold(form: Any, group: int, good: float, d: float, step: float, scale: float) -> float:
    """The limit position itself, near the edge `good` found by bisection: the dyad's two
    links fall in line there, and the square of the sine between them falls to 0 as the
    distance to it (sin² ∝ q* − q, a fold); a parabola through three points a little before
    the edge gives q* to round-off. (The edge is where the closed form's discriminant passes
    its round-off tolerance, about 1e-12 past q*, farther when it changes slowly.)"""
    back = np.array([1e-6, 2e-6, 3e-6]) * step
    margin = form.solve((good - d * back) * scale).margins[group]
    y = np.asarray(margin, dtype=float) ** 2
    if not np.isfinite(y).all() or not y[0] < y[1] < y[2]:
        return good
    c2, c1, c0 = np.polyfit(back, y, 2)
    roots = np.roots([c2, c1, c0]) if abs(c2) > 0 else np.array([-c0 / c1])
    real = [float(r.real) for r in np.atleast_1d(roots) if abs(r.imag) <= 1e-12 * step]
    if not real:
        return good
    e = min(real, key=abs)                             # how far before `good` the fold is
    return good - d * e if abs(e) < 1e-5 * step else good


def _closed_result(sweeper: Swept, plan: Plan, zig: Zigzag, runs: list[_Run], closed: bool) -> SweepResult:
    """The rows of the runs, each solved with its dyads' sides; every body's angle continued
    from run to run through the limit position between them."""
    scale = math.pi / 180 if plan.turns else 1.0
    model = sweeper.model
    pieces: list[dict] = []
    offsets: dict[str, float] = {}
    for run in runs:
        ends = ([run.begin] if run.begin is not None else []) + list(run.q) + \
            ([run.end] if run.end is not None else [])
        first = 1 if run.begin is not None else 0
        q = np.asarray(ends, dtype=float)
        out = sweeper.form(run.flips).solve(q * scale)
        n = len(q)
        piece = {"ok": (np.asarray(out.assembled, bool) & ~np.asarray(out.singular, bool)) & np.ones(n, bool),
                 "singular": np.asarray(out.singular, bool) & np.ones(n, bool), "bodies": {}, "points": {}}
        for b, track in out.tracks.items():
            theta = np.array(series(track.theta, n), dtype=float)
            if b in offsets and np.isfinite(theta[0]):   # continued from the run before (through
                theta += 2 * math.pi * round((offsets[b] - theta[0]) / (2 * math.pi))   # its limit)
            if np.isfinite(theta[-1]):
                offsets[b] = float(theta[-1])
            piece["bodies"][b] = (theta, series(track.omega, n), series(track.alpha, n))
        for name, body, _ in sweeper.motions:
            piece["points"][name, body] = tuple(np.broadcast_to(np.asarray(x, dtype=complex), (n,))
                                                for x in out.tracks[body].point(name))
        stop = n - (1 if run.end is not None else 0)
        keep = slice(first, stop)
        if closed and run is runs[-1]:
            keep = slice(first, n)                 # the drawing again: the last row
        pieces.append({key: _cut(value, keep) for key, value in piece.items()})
    coordinate = np.concatenate([r.q for r in runs] + ([np.array([runs[-1].end])] if closed else []))
    travel = _travel(zig, coordinate, closed)
    ok = np.concatenate([p["ok"] for p in pieces])
    singular = np.concatenate([p["singular"] for p in pieces])
    bodies = {b: {"angle": np.degrees(np.concatenate([p["bodies"][b][0] for p in pieces])),
                  "omega": np.concatenate([p["bodies"][b][1] for p in pieces]),
                  "alpha": np.concatenate([p["bodies"][b][2] for p in pieces])}
              for b in model.bodies}
    motions = {key: tuple(np.ascontiguousarray(np.concatenate([p["points"][key][i] for p in pieces]))
                          for i in range(3)) for key in pieces[0]["points"]}
    dead = dead_points(coordinate, ok, singular) if not ok.all() else []
    return sweeper.result(plan, ok, bodies, motions, dead, coordinate=coordinate, travel=travel,
                          limits=zig, closed=closed)


def _cut(value: Any, keep: slice) -> Any:
    if isinstance(value, dict):
        return {k: _cut(v, keep) for k, v in value.items()}
    if isinstance(value, tuple):
        return tuple(_cut(v, keep) for v in value)
    return value[keep]


def _travel(zig: Zigzag, coordinate: np.ndarray, closed: bool) -> np.ndarray:
    """The travel of each row: k steps, and the cycle's length for the closing row."""
    n = len(coordinate)
    travel = zig.travel(np.arange(n)).astype(float)
    if closed and n > 1:
        travel[-1] = zig.travel0 + abs(float(coordinate[-1]) - zig.start)
    return travel
