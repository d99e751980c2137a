"""Assembling a mechanism at an increment of its swept coordinate (`Assembler`): Newton's
method on the joints' position residuals, with the engine's velocity matrix as Jacobian
(see `newton`, which follows the motion row by row with it, and `continuation`, which
follows it through limit positions).
"""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from ..engine.system import InstantSolver
from ..errors import KinematikaError
from .constraints import remembers, residual_functions
from .plan import Plan
from .poses import AnyPoses, Poses, SpatialPoses, moved_geometry, moved_instant
from .swept import Swept

MAX_HALVINGS = 10
CHORD_ITERATIONS = 25
NEWTON_ITERATIONS = 40
TOLERANCE = 1e-12       # step size, dimensionless (rotations; translations / length scale)


class Assembler:
    """Assembles the mechanism at any increment of the swept coordinate, by continuation."""

    def __init__(self, sweeper: Swept, plan: Plan) -> None:
        inst = sweeper.inst
        self.base = inst
        self.base_geos = sweeper.solver.geos
        self.unknowns = sweeper.solver.unknowns
        self.owners = _owners(inst.model)
        self.functions = residual_functions(inst, self.base_geos, plan)
        self.scale = inst.scale
        u = self.unknowns
        self.translation = np.array([(c % u.width) >= u.space.rot for c in range(u.n)], dtype=bool)
        self.poses_class = Poses if inst.space.dim == 2 else SpatialPoses
        _check_rows(sweeper.solver, self.functions)

    def residual(self, poses: AnyPoses, dq: float) -> np.ndarray:
        """Every joint's position residual at `poses`, with the swept coordinate advanced by
        `dq`, as one vector (zero when the mechanism is assembled there)."""
        return np.array([x for _, f in self.functions for x in f(poses, dq)], dtype=float)

    def solver_at(self, poses: AnyPoses) -> InstantSolver:
        """The engine at `poses`, its matrix analysed (raises `singular` at a dead point)."""
        inst = moved_instant(self.base, poses, self.owners)
        geos = {jid: moved_geometry(g, poses, inst) for jid, g in self.base_geos.items()}
        solver = InstantSolver(inst, geos)
        solver.prepare()
        return solver

    def size(self, dx: np.ndarray) -> float:
        """The size of a Newton step, dimensionless: the largest rotation (radians) or
        translation over the model's length scale, compared with `TOLERANCE`."""
        return float(np.abs(np.where(self.translation, dx / self.scale, dx)).max(initial=0.0))

    def step(self, poses: AnyPoses, solver: InstantSolver, dq_from: float, dq_to: float,
             depth: int = 0) -> tuple[AnyPoses, InstantSolver]:
        """The poses at increment `dq_to`, from the assembled `poses` at `dq_from`."""
        found = self._corrected(poses, solver, dq_to)
        if found is not None:
            return found, self.solver_at(found)
        if depth >= MAX_HALVINGS:
            raise NotAssembled()
        middle = 0.5 * (dq_from + dq_to)
        half, half_solver = self.step(poses, solver, dq_from, middle, depth + 1)
        return self.step(half, half_solver, middle, dq_to, depth + 1)

    def _corrected(self, poses: AnyPoses, solver: InstantSolver, dq: float) -> Optional[AnyPoses]:
        """Chord iterations from `poses` with the matrix of `solver`; None when they fail."""
        current = poses
        first, last = None, math.inf
        for _ in range(CHORD_ITERATIONS):
            r = self.residual(current, dq)
            dx = -np.asarray(solver.solve_linear(list(r), check=False))
            size = self.size(dx)
            if not math.isfinite(size) or size > 2 * last + 1e-9:
                return None
            current = current.stepped(dx, self.unknowns)
            if first is None:
                first = size                    # the predictor
            elif size > 0.3 * first + 1e-9:
                return None                     # the correction rivals the step: a jump
            if size < TOLERANCE or (size < 1e3 * TOLERANCE and size > 0.5 * last):
                self.keep_aux(current)         # converged (or stalled at round-off)
                return current
            last = size
        return None

    def assemble(self, poses: AnyPoses, dq: float) -> tuple[AnyPoses, InstantSolver]:
        """Newton's method from any nearby poses (after a gap of skipped rows): the Jacobian
        rebuilt at each iterate and steps limited to 0.3 rad (0.3 of the model's length)."""
        current = poses
        for _ in range(NEWTON_ITERATIONS):
            try:
                solver = self.solver_at(current)
            except KinematikaError:
                break
            dx = -np.asarray(solver.solve_linear(list(self.residual(current, dq)), check=False))
            size = self.size(dx)
            if not math.isfinite(size):
                break
            if size < TOLERANCE:
                self.keep_aux(current)
                return current, solver
            current = current.stepped(dx * min(1.0, 0.3 / size), self.unknowns)
        raise NotAssembled()

    def keep_aux(self, poses: AnyPoses) -> None:
        """Record the continuous angles (rolling joints) of the newly assembled poses."""
        for _, f in self.functions:
            if remembers(f):
                poses.aux[f.key] = f.aux(poses)


class NotAssembled(Exception):
    """The position could not be assembled from the poses given."""


def _owners(model: Any) -> dict[str, str]:
    """Which body's material point stands for each point name in a moved instant."""
    owners = {p: (model.carriers(p) or [model.frame])[0] for p in model.points}
    for d in model.drivers:
        if d.kind == "velocity":
            owners[d.point.point] = d.point.body
    return owners


def _check_rows(solver: InstantSolver, functions: list) -> None:
    """The constraints must match the engine's rows one for one (by place)."""
    if solver.analysis is None:
        solver.prepare()
    engine = [r.where for r in solver.rows_v]
    kind = Poses if solver.space.dim == 2 else SpatialPoses
    poses = kind.drawn(solver.inst.ref, list(solver.unknowns.offset))
    ours = [where for where, f in functions for _ in f(poses, 0.0)]
    if engine != ours:
        raise RuntimeError(f"position constraints do not match the engine rows: {ours} != {engine}")
