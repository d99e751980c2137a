"""The instant problem: assemble the rows, solve velocities, then accelerations.

    A x_v = b_v          x_v = (ω, v₀) of every moving body
    A x_a = b_a(x_v)     x_a = (α, a₀); the same A, a right side from the velocities

One code path for numbers and symbols: only the last step differs (SVD solve on floats,
block-by-block exact solve on sympy expressions, the blocks found numerically).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ..model.model import Model
from .drivers import driver_rows
from .instant import Instant, instantiate
from .joints import JointGeometry, Row, joint_geometry, joint_rows
from .levels import AccelerationLevel, Level, Unknowns, VelocityLevel
from .motion import BodyState, Motion
from .linsolve import Analysis, analyse, solve_numeric, solve_symbolic


class InstantSolver:
    """Builds and solves the velocity and acceleration systems of one instant."""

    def __init__(self, inst: Instant) -> None:
        self.inst = inst
        model = inst.model
        self.space = inst.space
        self.unknowns = Unknowns(model.moving_bodies, self.space)
        self.geos: dict[str, JointGeometry] = {j.id: joint_geometry(inst, j) for j in model.joints}
        self.analysis: Analysis | None = None
        self.rows_v: list[Row] = []

    def rows(self, lv: Level) -> list[Row]:
        out: list[Row] = []
        for j in self.inst.model.joints:
            out += joint_rows(self.geos[j.id], lv)
        for d in self.inst.model.drivers:
            out += driver_rows(self.inst, d, self.geos, lv)
        return out

    def matrix(self, rows: list[Row]) -> tuple[list[list[Any]], list[Any]]:
        n = self.unknowns.n
        a = [[0] * n for _ in rows]
        b = []
        for i, row in enumerate(rows):
            for col, coef in row.lin.terms.items():
                a[i][col] = coef
            b.append(-row.lin.const)
        return a, b

    def solve(self) -> Motion:
        inst, u = self.inst, self.unknowns
        rows_v = self.rows(VelocityLevel(u, inst.ref))
        self.rows_v = rows_v
        a, b_v = self.matrix(rows_v)
        a_num = np.array([[inst.num(c) for c in row] for row in a], dtype=float).reshape(len(a), u.n)
        labels = [r.label for r in rows_v]
        wheres = [r.where for r in rows_v]
        is_driver = np.array([r.driver for r in rows_v], dtype=bool)
        translation = np.array([(c % u.width) >= self.space.rot for c in range(u.n)], dtype=bool)
        body_of = [u.body_of(c) for c in range(u.n)]
        an = analyse(a_num, is_driver, translation, inst.scale, labels, wheres, body_of,
                     want_blocks=inst.symbolic)
        self.analysis = an

        def solve(b: list[Any], check: bool) -> list[Any]:
            b_num = np.array([inst.num(v) for v in b], dtype=float)
            x_num = solve_numeric(an, b_num, labels, wheres, is_driver, check)
            if not inst.symbolic:
                return [float(v) for v in x_num]
            exact = solve_symbolic(an, a, b, a_num)
            inst.backend.check_against(exact, x_num, inst.probe)
            return exact

        x_v = solve(b_v, check=True)
        velocities = self._motion(x_v, None)
        rows_a = self.rows(AccelerationLevel(u, inst.ref, velocities))
        _, b_a = self.matrix(rows_a)
        x_a = solve(b_a, check=False)
        return self._motion(x_v, x_a)

    def _motion(self, x_v: list[Any], x_a: list[Any] | None) -> Motion:
        sp, u = self.space, self.unknowns
        states = {}
        for body in self.inst.model.bodies:
            if body not in u.offset:
                zero = sp.zero()
                states[body] = BodyState(sp.rot_zero(), zero, sp.rot_zero(), zero)
                continue
            o = u.offset[body]
            w, v0 = _split(x_v, o, sp.rot, sp.dim)
            if x_a is None:
                alpha, a0 = sp.rot_zero(), sp.zero()
            else:
                alpha, a0 = _split(x_a, o, sp.rot, sp.dim)
            states[body] = BodyState(w, v0, alpha, a0)
        return Motion(sp, self.inst.ref, states)


def _split(x: list[Any], o: int, rot: int, dim: int) -> tuple[Any, tuple]:
    w = tuple(x[o:o + rot])
    v0 = tuple(x[o + rot:o + rot + dim])
    return (w[0] if rot == 1 else w), v0


def solve_instant(model: Model, symbolic: bool | None = None) -> tuple[Instant, Motion, InstantSolver]:
    """Evaluate `model` and solve its instant; errors are `KinematikaError`s."""
    inst = instantiate(model, symbolic)
    solver = InstantSolver(inst)
    return inst, solver.solve(), solver
