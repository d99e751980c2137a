"""The motion over a range of a driven joint's coordinate (`Sweeper`; `posing.run_sweep`
reads and poses a model, then sweeps it here).

The drawn instant is solved first by the engine (which checks the model). Then, when the
mechanism is a driven crank or slider followed by dyads, every position is solved at once
in closed form (`closed_form`); otherwise each position is assembled by Newton's method
with continuation from the previous one and solved by the engine (`newton`).
"""
from __future__ import annotations

import warnings
from typing import Any, Callable, Optional

import numpy as np

from ..engine.instant import instantiate
from ..engine.system import InstantSolver
from ..joints.capabilities import Coordinate
from ..memory import arrays_on_heap
from ..model.model import Model, PointRef
from ..model.overrides import at_draw_numbers
from ..model.source import as_model
from .coincident import coincide
from .joint_rates import with_joint_rates
from .plan import Plan, bad_row, make_plan, swept_joint
from .result import QUANTITIES, SweepResult, dead_points

Progress = Callable[[int, int], None]


class Sweeper:
    """A model analysed once for sweeps of one driven joint; `run` sweeps it (again and again).

    The analysis solves the drawn instant with the engine and decomposes the mechanism into
    Assur groups; a sweep then costs only the positions themselves. `source` (a path, model
    tree, `Model` or `Mechanism`) is swept as drawn: a model's own `move:` is made by
    `posing.prepare` (as `run_sweep` does) or `move.as_written`.
    """

    def __init__(self, source: Any, joint: Optional[str] = None,
                 flips: Optional[dict[int, float]] = None) -> None:
        arrays_on_heap()                     # a sweep's speed is its own (`memory`)
        model, self.warnings = at_draw_numbers(as_model(source), "sweep", warn=False)
        inst = instantiate(model, False)
        model = with_joint_rates(model, inst)          # a 3D ω along a revolute: its rate
        self.model = model
        self.inst = inst if inst.model is model else instantiate(model, False)
        self.joint, self.driver = swept_joint(model, joint if joint is not None else
                                              (model.sweep.joint if model.sweep else None))
        self.solver = InstantSolver(self.inst)
        self.drawn = self.solver.solve()
        self.points = {k: tuple(float(c) for c in v) for k, v in self.inst.points.items()}
        self.directions = {jid: tuple(float(c) for c in g.along) for jid, g in self.solver.geos.items()
                           if g.along is not None}
        from ..structure.assur import assur_groups      # start-up: simulate reads this module, sweeps nothing

        self.groups = assur_groups(model)
        self._flips = dict(flips or {})
        self.closed = self._closed_form(flips)
        self._forms: dict[tuple, Any] = {(): self.closed}
        self.motions = motion_classes(model)
        self.names = [str(r) for r in model.material_points()]
        self._plans: dict[tuple, Plan] = {}

    def plan(self, by: Optional[float], steps: Optional[int]) -> Plan:
        """The plan of a sweep (kept: its rows are read-only arrays shared by the results)."""
        key = (by, steps)
        if key not in self._plans:
            plan = make_plan(self.inst, self.joint.id, by, steps)
            for arr in (plan.coordinate, plan.increments):
                arr.flags.writeable = False
            self._plans = {key: plan}
        return self._plans[key]

    def _closed_form(self, flips: Optional[dict[int, float]] = None) -> Any:
        """The closed form of this mechanism (dyads closed as drawn, or as `flips` say)."""
        from .closed_form import ClosedForm, applicable     # start-up, as `assur_groups`

        groups = self.groups
        if groups is None or not applicable(self.model, groups, self.joint, self.driver):
            return None
        return ClosedForm.at_drawn(self.model, self.points, self.directions, groups, self.joint,
                                   self.drawn, flips)

    def form(self, flips: dict[int, float]) -> Any:
        """The closed form with the dyads in `flips` (group index → −1) closed the other way
        than at the start (kept: a motion through limit positions comes back to each)."""
        key = tuple(sorted((i, f) for i, f in flips.items() if f < 0))
        if key not in self._forms:
            from .closed_form import ClosedForm

            groups = self.groups
            assert groups is not None, "a mechanism with a closed form decomposes into groups"
            sides = {i: self._flips.get(i, 1.0) * flips.get(i, 1.0) for i in range(1, len(groups))}
            self._forms[key] = ClosedForm.at_drawn(self.model, self.points, self.directions, groups,
                                                   self.joint, self.drawn, sides)
        return self._forms[key]

    def linkage(self) -> Any:
        """The four-bar or slider-crank this mechanism is (`structure.linkages`), or None."""
        from ..structure.linkages import identify

        return identify(self.model, self.groups, self.points, self.directions)

    @property
    def method(self) -> str:
        """How the sweep is solved: "closed form" (dyads closed position by position) or
        "newton" (continuation from the drawn pose)."""
        return "closed form" if self.closed is not None else "newton"

    def run(self, by: Optional[float] = None, steps: Optional[int] = None, skip_bad: bool = False,
            progress: bool | Progress = False, through: bool = True) -> SweepResult:
        """Sweep the joint's coordinate `by` in `steps` (None: the model's `sweep:` section, else
        a revolute's 360° in 360 steps) and return every row's angles, rates and point motions
        with the dead points found. At a limit position the input runs back and the motion goes
        on (`limit_positions`), unless not `through` (as `move` reaches a coordinate): then the
        positions beyond cannot be assembled. A position that cannot be assembled or is
        singular is an error unless `skip_bad`, which leaves its row marked."""
        plan = self.plan(by, steps)
        if self.closed is None:
            from .newton import newton_sweep

            return newton_sweep(self, plan, skip_bad, progress, through)
        out = self.closed.solve(plan.increments)
        ok = out.assembled & ~out.singular
        if not ok.all() and through and not out.assembled.all():
            k = int(np.argmin(out.assembled))
            if skip_bad or ok[:k].all():
                from .limit_positions import follow_closed

                result = follow_closed(self, plan, skip_bad)
                if not skip_bad and not result.ok.all():
                    k = int(np.argmin(result.ok))
                    raise bad_row(plan, k, "singular", at=float(result.coordinate[k]))
                return result
        if not skip_bad and not ok.all():
            k = int(np.flatnonzero(~ok)[0])
            raise bad_row(plan, k, "singular" if out.singular[k] else "assembly", out.worst(k))
        from .closed_form import series

        n = len(ok)
        bodies = {b: {"angle": series(np.degrees(t.theta), n), "omega": series(t.omega, n),
                      "alpha": series(t.alpha, n)} for b, t in out.tracks.items()}
        points = {(name, body): out.tracks[body].point(name) for name, body, _ in self.motions}
        dead = dead_points(plan.coordinate, ok, out.singular, self._edge if not ok.all() else None)
        return self.result(plan, ok, bodies, points, dead)

    def _edge(self, good: float, bad: float) -> float:
        """Where between a row that can be assembled and one that cannot the motion stops:
        the closed form evaluated on finer and finer rows (to 1/4096 of the step)."""
        scale = np.pi / 180 if self.joint.kind.coordinate is Coordinate.ANGLE else 1.0
        for _ in range(2):
            between = np.linspace(good, bad, 65)
            out = self.closed.solve(between * scale)
            fine = out.assembled & ~out.singular
            last = int(np.argmin(fine)) - 1 if not fine.all() else 64
            good, bad = between[max(last, 0)], between[min(last + 1, 64)]
        return float(good)

    def result(self, plan: Plan, ok: np.ndarray, bodies: dict, motions: dict,
               dead: list[float], coordinate: Optional[np.ndarray] = None,
               travel: Optional[np.ndarray] = None, limits: Any = None,
               closed: bool = False) -> SweepResult:
        """A `SweepResult` from per-body arrays and per-motion-class point arrays (NaN if bad);
        a motion through limit positions gives its rows' `coordinate` and `travel`, and
        `limits` (a `limit_positions.Zigzag`)."""
        bad = None if ok.all() else ~ok
        ordered = {b: _filled(bodies[b], bad) for b in self.model.bodies}
        pts: dict[str, dict[str, np.ndarray]] = {}
        for name, body, refs in self.motions:
            arrays = {q: _rows(xy, bad, len(ok)) for q, xy in zip(QUANTITIES, motions[name, body])}
            for ref in refs:
                pts[ref] = arrays
        pts = {name: pts[name] for name in self.names}
        coincide(self.model, ordered, pts)
        for note in self.warnings:          # said with the rows it is true of
            warnings.warn(note, stacklevel=3)
        out = SweepResult(plan.coordinate if coordinate is None else coordinate, plan.joint.id, ok,
                          ordered, pts, dead, plan.unit, self.model.name, self.model.dimension,
                          self.method, self.model.frame, warnings=list(self.warnings))
        if limits is not None and limits.limits:
            out.limits, out.limit_travel = list(limits.limits), list(limits.at)
            out.travel, out.closed = travel, closed
        return out


def _rows(values: Any, bad: Optional[np.ndarray], n: int) -> np.ndarray:
    """(N, 2) rows: kept as they are, or read from complex x + iy (a view: no copy); NaN if bad.

    A constant (a plain complex number) becomes rows with stride 0.
    """
    if not isinstance(values, np.ndarray):
        row = np.array([values.real, values.imag], dtype=float)
        values = np.ndarray((n, 2), float, row, strides=(0, 8))
        values.flags.writeable = False
    elif values.dtype.kind == "c":
        values = values.view(np.float64).reshape(n, 2)
    return values if bad is None else np.where(bad[:, None], np.nan, values)


def _filled(values: dict[str, Any], bad: Optional[np.ndarray]) -> dict[str, np.ndarray]:
    if bad is None:
        return {q: values[q] for q in ("angle", "omega", "alpha")}
    return {q: np.where(bad if np.ndim(values[q]) == 1 else bad[:, None], np.nan, values[q])
            for q in ("angle", "omega", "alpha")}


def motion_classes(model: Model) -> list[tuple[str, str, list[str]]]:
    """Material points that move alike by construction, as (point, body, ["P@body", ...]).

    Bodies joined at P by a revolute or spherical joint (or welded) share P's motion: it is
    computed once.
    """
    return [(point, members[0], [str(PointRef(point, b)) for b in members])
            for point in model.points
            for members in model.motion_classes(point, model.carriers(point))]
