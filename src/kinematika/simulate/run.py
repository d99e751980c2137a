"""`run_simulation`: a mechanism's motion followed in time.

The drawn instant is solved by the engine first (which checks the model). The state is every
moving body's pose (`state`); its rate at (t, poses) is the twists the engine solves there
(the drivers' rates at time t, `timed`), integrated by scipy's `solve_ivp`. Two events end
an integration early: the velocity system nearing a dead point (its condition number
reaching `DEAD_POINT`: the motion cannot go on), and the poses drifting from the joints'
position conditions (then they are projected back, `holonomic`, and the integration goes
on from there). Each row is read from the integrator's dense output at its time, projected
back onto the conditions, and solved by the engine for its velocities and accelerations.

What the solver may ask for is counted (`limits.SIMULATE_EVALUATIONS`), never timed. A
motion that cannot be followed (a dead point, a driver's rate that cannot be evaluated, a
contact lost, too many evaluations) stops with one error naming why and when, and the rows
computed before it are kept (`SimulationStopped.result`).
"""
from __future__ import annotations

import bisect
import math
from typing import Any, Callable, Optional

import numpy as np

from .. import limits
from ..engine.instant import instantiate
from ..engine.system import InstantSolver
from ..errors import KinematikaError, Names, Num, Said
from ..model.model import Model
from ..sweep.coincident import coincide
from ..sweep.joint_rates import with_joint_rates
from ..sweep.poses import moved_geometry, moved_instant
from ..sweep.progress import reporter
from ..sweep.result import QUANTITIES
from ..sweep.run import motion_classes
from .clock import Clock, make_clock
from .holonomic import Projection
from .result import SimulationResult
from .state import PoseState
from .timed import timing

Progress = Callable[[int, int], None]

METHODS = ("DOP853", "RK45", "LSODA", "Radau", "BDF")    # scipy's solve_ivp methods offered
DEFAULT_METHOD = "DOP853"       # explicit Runge–Kutta of order 8: few steps, and a stop where it cannot go on
RTOL = 1e-10                 # the integrator's relative tolerance (absolute: this in radians, and
                             # this times the model's size in lengths)
DEAD_POINT = 1e8             # the velocity system's condition number where the motion is stopped
                             # (the engine calls 1e10 singular: the event comes before it)
DRIFT_EVENT = 1e-7           # drift (over the model's size) that stops the integration to project
MIN_STEP = 1e-12             # LSODA's smallest step, as a fraction of the time followed
UNSOLVED = 1e20              # the rate given where the velocities cannot be solved (no step takes it)
PROJECT_ABOVE = 1e-9         # a row whose drift is above this is projected back onto the conditions


class SimulationStopped(KinematikaError):
    """The motion could not be followed to the end: the error, the rows computed before it
    (`result`, a `SimulationResult` whose `stopped` is this error) and the model simulated."""

    def __init__(self, err: KinematikaError, result: SimulationResult, model: Model) -> None:
        super().__init__(err.kind, err.said, err.where)
        self.result, self.model = result, model
        result.stopped = self


def run_simulation(source: Any, time: Optional[float] = None, steps: Optional[int] = None,
                   method: Optional[str] = None, progress: bool | Progress = False) -> SimulationResult:
    """Follow `source` (a path, model tree, `Model` or `Mechanism`) in time.

    `time` (seconds) and `steps` override the model's `simulate:` section; `method` is one of
    `METHODS` (scipy's names). A motion that cannot be followed to the end raises
    `SimulationStopped`, whose `result` holds the rows before. `progress`: True for a progress
    bar on a terminal, or a callable `(done, total)` over the rows.
    """
    return Simulator(source).run(time, steps, method, progress)


def needs_time(model: Model) -> bool:
    """Whether the model's motion can only be followed in time: a joint of it constrains
    velocities only (a knife edge; a disc rolling on a plane)."""
    return any(model.dimension in j.kind.velocity_only for j in model.joints)


class Simulator:
    """A model prepared once for simulations: its drawn instant solved, its drivers in time, the
    layout of its state and its position conditions; `run` follows it (again and again)."""

    def __init__(self, source: Any, default_time: Optional[float] = None) -> None:
        from ..sweep.posing import prepare

        model, self.notes = at_numbers(prepare(source))
        model = with_joint_rates(model)                # a 3D ω along a revolute: its rate
        self.timing = timing(model)
        self.notes += self.timing.notes
        self.model = self.timing.model
        self.default_time = default_time
        inst = instantiate(self.model, False)
        self.base_env = inst.env
        inst.env = self.timing.env(inst.env, self.timing.start)
        self.inst = inst
        self.solver = InstantSolver(inst)
        self.drawn = self.solver.solve()
        self.owners = owners(self.model)
        self.state = PoseState(self.solver.unknowns, inst.ref, self.model.dimension)
        self.projection = Projection(inst, self.solver.geos, self.solver.wheres, self.solver.is_driver)
        self.projection.check(self.state.poses(self.state.drawn()))
        self.points = {k: tuple(float(c) for c in v) for k, v in inst.points.items()}
        self.motions = motion_classes(self.model)
        self.names = [str(r) for r in self.model.material_points()]
        self._last: tuple[Any, Any] = (None, None)          # (key, solver) of the last instant solved
        self.aux: dict = {}
        self.aux_log = AuxLog()                              # the continuous angles at each step
        self.evaluations = 0                                 # velocity solutions asked for, this run
        self.failure: Optional[tuple[KinematikaError, float]] = None   # the last instant not solved
        self.reached = 0.0                                   # the last time a step reached

    # one instant ----------------------------------------------------------------------------
    def engine_at(self, t: float, poses: Any, accelerations: bool = False) -> InstantSolver:
        """The engine at time `t` and `poses`, its velocity matrix analysed (raises `singular`
        at a dead point, `mobility` when the drivers conflict there); with `accelerations`, the
        drivers' accelerations there too (for `solve`)."""
        inst = moved_instant(self.inst, poses, self.owners)
        inst.env = self.timing.env(self.base_env, t, accelerations)
        geos = {jid: moved_geometry(g, poses, inst) for jid, g in self.solver.geos.items()}
        solver = InstantSolver(inst, geos)
        try:
            solver.prepare()
        except np.linalg.LinAlgError:
            raise KinematikaError("singular", "simulate-at", "simulate", at=Num(t, ".6g"),
                                  what=Said("simulate-velocity-matrix")) from None
        return solver

    def rates(self, t: float, y: np.ndarray) -> np.ndarray:
        """ẏ at (t, y): the twists the engine solves there. Where it cannot (or past the count of
        evaluations), a rate far too large for any step to be accepted (`UNSOLVED`): every
        solver then takes smaller steps towards the last instant it could solve, and stops
        there; the first such error is kept to be reported."""
        self.evaluations += 1
        try:
            if self.evaluations > limits.SIMULATE_EVALUATIONS:
                raise KinematikaError("assembly", "simulate-too-many-evaluations", "simulate",
                                      limit=limits.SIMULATE_EVALUATIONS)
            if not np.isfinite(y).all():
                raise KinematikaError("assembly", "simulate-positions-not-finite", "simulate")
            solver = self.engine_at(t, self.state.poses(y, self.aux))
            twists = solver.solve_linear(solver.b_v, check=True)
        except KinematikaError as err:
            if self.failure is None or err.where != "simulate":
                self.failure = (err, t)
            return np.full(len(y), UNSOLVED)
        self._last = ((t, y.tobytes()), solver)
        return self.state.rates(y, twists)

    def condition(self, t: float, y: np.ndarray) -> float:
        """The velocity system's condition number at (t, y) (infinite where it cannot be solved)."""
        key, solver = self._last
        if key != (t, y.tobytes()):
            if not np.isfinite(y).all():
                return math.inf
            try:
                solver = self.engine_at(t, self.state.poses(y, self.aux))
            except KinematikaError:
                return math.inf
        return float(solver.analysis.diagnosis.condition_number)

    # the motion -------------------------------------------------------------------------------
    def run(self, time: Optional[float] = None, steps: Optional[int] = None, method: Optional[str] = None,
            progress: bool | Progress = False) -> SimulationResult:
        """Follow the motion over `time` seconds in `steps` rows (see `run_simulation`)."""
        method = method or DEFAULT_METHOD
        if method not in METHODS:
            raise KinematikaError("usage", "simulate-unknown-method", "--method", method=method,
                                  methods=Names(METHODS))
        clock = make_clock(self.model, self.timing.start, time, steps, self.default_time)
        rows = Rows(self, clock)
        report = reporter(progress, len(clock.times), "simulating")
        self.evaluations, self.failure, self.reached, self.aux = 0, None, clock.start, {}
        self.aux_log = AuxLog()
        rows.store(0, clock.start, self.state.poses(self.state.drawn()), self.solver, self.drawn, 0.0)
        report(1)
        stopped = None
        try:
            stopped = self._integrate(clock, rows, method, report)
        except KinematikaError as err:
            stopped = err
        report(None)
        result = rows.result(method, self.evaluations, self.notes)
        if stopped is not None:
            raise SimulationStopped(stopped, result.rows(rows.done), self.model)
        return result

    def _integrate(self, clock: Clock, rows: "Rows", method: str, report: Any) -> Optional[KinematikaError]:
        """Integrate from the drawn configuration to the clock's end, the rows stored as they are
        passed; the error that stopped the motion early, or None."""
        from scipy.integrate import solve_ivp

        times = clock.times
        t, y = clock.start, self.state.drawn()
        atol = self.state.tolerances(self.inst.scale, RTOL)

        def dead(t: float, y: np.ndarray) -> float:
            return math.log10(min(max(self.condition(t, y), 1.0), 1e300)) - math.log10(DEAD_POINT)

        def drift(t: float, y: np.ndarray) -> float:
            if not np.isfinite(y).all():
                return 1.0
            q = self.state.poses(y, self.aux)        # after each step taken: what it reached
            size = self.projection.size(q)
            self.projection.keep(q)
            self.aux, self.reached = q.aux, max(self.reached, t)
            self.aux_log.add(t, q.aux)
            self.failure = None                       # a step was taken past the failures so far
            return min(size, 1.0) - DRIFT_EVENT

        # LSODA's steps may otherwise shrink without end towards an instant it cannot pass
        options = {"min_step": MIN_STEP * clock.duration} if method == "LSODA" else {}
        for event in (dead, drift):
            event.terminal, event.direction = True, 1      # type: ignore[attr-defined]  # scipy solve_ivp reads these attributes of an event function
        while rows.done < len(times):
            self.failure = None
            try:
                sol = solve_ivp(self.rates, (t, clock.end), y, method=method, t_eval=times[rows.done:],
                                rtol=RTOL, atol=atol, events=[dead, drift], **options)
            except (ValueError, ArithmeticError, np.linalg.LinAlgError) as err:
                return self._failed(str(err))
            for tk, yk in zip(sol.t, np.asarray(sol.y).reshape(len(y), -1).T):
                rows.next(tk, yk)
                report(rows.done)
            if sol.status == 0:
                return None
            if sol.status == 1 and len(sol.t_events[1]):
                t, y = float(sol.t_events[1][0]), sol.y_events[1][0]
                y = self.state.vector(rows.projected(t, self.state.poses(y, self.aux))[0], y)
                continue
            if sol.status == 1:
                at = float(sol.t_events[0][0])
                return KinematikaError("singular", "simulate-dead-point", "simulate", at=Num(at, ".6g"),
                                       condition=Num(DEAD_POINT, ".0e"))
            return self._failed(sol.message)
        return None

    def _failed(self, message: str) -> KinematikaError:
        """Why the integrator stopped: the error of the instant that could not be solved (with
        its time), or the integrator's own message."""
        if self.failure is not None:
            err, _ = self.failure
            return KinematikaError(err.kind, "simulate-not-followed", err.where or "simulate",
                                   at=Num(self.reached, ".6g"), why=err.said)
        return KinematikaError("assembly", "simulate-not-followed", "simulate", at=Num(self.reached, ".6g"),
                               why=Said("simulate-integrator-stopped", message=message))


class AuxLog:
    """The continuous angles (a rolling pair's line of centres, `Projection.keep`) the
    integration reached at each step, by time. A row is read after its stretch has been
    integrated, when the angles kept are those of the stretch's end: it must be read with
    those of the step nearest its time, else an angle that turned by more than half a turn
    since would be read on another sheet (a wheel rolling round a cylinder, ψ past π)."""

    def __init__(self) -> None:
        self.times: list[float] = []
        self.values: list[dict] = []

    def add(self, t: float, aux: dict) -> None:
        """Keep the angles reached at time t."""
        k = bisect.bisect_left(self.times, t)
        if k < len(self.times) and self.times[k] == t:
            self.values[k] = dict(aux)
            return
        self.times.insert(k, t)
        self.values.insert(k, dict(aux))

    def near(self, t: float, default: dict) -> dict:
        """The angles kept at the step nearest time t (`default` when none was kept)."""
        if not self.times:
            return default
        k = bisect.bisect_left(self.times, t)
        nearest = min((i for i in (k - 1, k) if 0 <= i < len(self.times)), key=lambda i: abs(self.times[i] - t))
        return self.values[nearest]


class Rows:
    """The rows of a simulation as they are computed: each projected onto the joints' position
    conditions and solved by the engine (velocities and accelerations)."""

    def __init__(self, sim: Simulator, clock: Clock) -> None:
        self.sim, self.clock = sim, clock
        n, dim = len(clock.times), sim.model.dimension
        shape = (n,) if dim == 2 else (n, 3)
        self.bodies = {b: {q: np.full(shape, np.nan) for q in ("angle", "omega", "alpha")}
                       for b in sim.model.bodies}
        self.motions = {(name, body): tuple(np.full((n, dim), np.nan) for _ in QUANTITIES)
                        for name, body, _ in sim.motions}
        self.drift = np.full(n, np.nan)
        self.done = 0
        self.before: Any = None

    def projected(self, t: float, poses: Any) -> tuple[Any, float]:
        """`poses` brought back onto the joints' position conditions at time t, and the drift."""
        sim = self.sim
        drift = sim.projection.size(poses)
        if drift <= PROJECT_ABOVE:
            return poses, drift

        def matrix(q: Any) -> np.ndarray:
            a = sim.engine_at(t, q).a_num
            return a.toarray() if hasattr(a, "toarray") else np.asarray(a)

        return sim.projection.project(poses, matrix, sim.solver.unknowns)

    def next(self, t: float, y: np.ndarray) -> None:
        """Row `done` at time t from the integrated state y."""
        sim = self.sim
        poses, drift = self.projected(t, sim.state.poses(y, sim.aux_log.near(t, sim.aux), self.before))
        try:
            solver = sim.engine_at(t, poses, accelerations=True)
            motion = solver.solve()
        except KinematikaError as err:
            said = err.said if err.said.key == "simulate-at" else Said("simulate-at", at=Num(t, ".6g"), what=err.said)
            raise KinematikaError(err.kind, said, err.where) from None
        self.store(self.done, t, poses, solver, motion, drift)

    def store(self, k: int, t: float, poses: Any, solver: Any, motion: Any, drift: float) -> None:
        """Row k: every body's angle (from its drawn pose, degrees), ω and α; every material
        point's place, velocity and acceleration (`Motion`'s formulas)."""
        for b, values in self.bodies.items():
            s = motion.states[b]
            values["angle"][k] = np.degrees(poses.angle(b))
            values["omega"][k] = s.omega
            values["alpha"][k] = s.alpha
        for (name, body), (pos, vel, acc) in self.motions.items():
            p = poses.point(body, self.sim.points[name])
            state = motion.states[body]
            pos[k] = p
            vel[k] = motion.velocity(state, p)
            acc[k] = motion.acceleration(state, p)
        self.drift[k] = drift
        self.before = poses
        self.done = k + 1

    def result(self, method: str, evaluations: int, notes: list[str]) -> SimulationResult:
        """The rows as a `SimulationResult` (every material point keyed as `solve` keys it)."""
        sim = self.sim
        pts: dict[str, dict[str, np.ndarray]] = {}
        for name, body, refs in sim.motions:
            arrays = dict(zip(QUANTITIES, self.motions[name, body]))
            for ref in refs:
                pts[ref] = arrays
        pts = {name: pts[name] for name in sim.names}
        bodies = {b: self.bodies[b] for b in sim.model.bodies}
        coincide(sim.model, bodies, pts)
        ok = np.arange(len(self.clock.times)) < self.done
        return SimulationResult(coordinate=np.array(self.clock.times), joint="time", ok=ok, bodies=bodies,
                                points=pts, unit="s", name=sim.model.name, dimension=sim.model.dimension,
                                method=method, frame=sim.model.frame, drift=self.drift,
                                duration=self.clock.duration, evaluations=evaluations, notes=notes)


def owners(model: Model) -> dict[str, str]:
    """Which body's material point stands for each point name in a moved instant: the one that
    gives its place (`Model.place_owner`: a knife edge's wheel, a pin), or a velocity driver's."""
    out = {p: model.place_owner(p) if model.carriers(p) else model.frame for p in model.points}
    for d in model.drivers:
        if d.kind == "velocity" and d.point is not None:
            out[d.point.point] = d.point.body
    return out


def at_numbers(model: Model) -> tuple[Model, list[str]]:
    """`model` with its symbols at their `draw_at` numbers (and a note saying so); a symbol
    without one is a `schema` error asking for a value."""
    symbols = [n for n, p in model.parameters.items() if p.value is None]
    if not symbols:
        return model, []
    missing = [n for n in symbols if n not in model.draw_at]
    if missing:
        raise KinematikaError("schema", "needs-draw-at", "parameters", what="simulate", names=Names(missing))
    from ..model.overrides import with_parameters

    values = {n: repr(float(model.draw_at[n])) for n in symbols}
    note = "symbols at their draw_at numbers: " + ", ".join(f"{n} = {v}" for n, v in values.items())
    return with_parameters(model, values), [note]
