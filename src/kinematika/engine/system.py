"""The instant problem: assemble the rows, solve velocities, then accelerations.

    A x_v = b_v          x_v = (ω, v₀) of every moving body
    A x_a = b_a(x_v)     x_a = (α, a₀); the same A, a right side from the velocities

One code path for numbers and symbols: only the last step differs (SVD solve on floats,
block-by-block exact solve on sympy expressions, the blocks found numerically).
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import KinematikaError, Said, SaidLater
from .drivers import driver_rows
from .idle import idle_rows
from .instant import Instant
from ..joints import JointGeometry, NumericRows
from .joints import Row, joint_geometry, joint_known_terms, joint_rows
from .levels import AccelerationLevel, KnownTerms, Level, Unknowns, VelocityLevel
from .motion import BodyState, Motion
from .terms import MECHANICS, Terms
from .blocks import SparseRows
from .linsolve import LARGE, SparseAnalysis, analyse_sparse, solve_numeric, solve_symbolic, sparse_matrix
from .positions import fresh_name

if TYPE_CHECKING:
    from .dense import Analysis


class InstantSolver:
    """Builds and solves the velocity and acceleration systems of one instant.

    `geos` may give the joints' geometry already evaluated (a sweep moves it with the bodies).
    """

    def __init__(self, inst: Instant, geos: dict[str, JointGeometry] | None = None,
                 terms: Terms = MECHANICS) -> None:
        self.inst = inst
        self.terms = terms          # mechanics, or a student's mistake (`engine.terms`)
        model = inst.model
        self.space = inst.space
        self.unknowns = Unknowns(model.moving_bodies, self.space)
        self.geos: dict[str, JointGeometry] = (geos if geos is not None else
                                               {j.id: joint_geometry(inst, j) for j in model.joints})
        self.analysis: Analysis | SparseAnalysis | None = None
        # set by `prepare`: each velocity row's label, place, and whether a driver gives it
        self.labels: Sequence[Any]
        self.wheres: Sequence[str]
        self.pairs: Sequence[frozenset | None]      # the two bodies each row relates (`rows`)
        self.is_driver: np.ndarray
        self.said_rows: dict[Any, Sequence[Said]] = {}    # per joint kind, its rows' labels (`JointArrays`)
        self.rows_v: list[Row] = []
        # set by `prepare`: the velocity system A x = b_v (A exact for a symbolic instant, and as
        # numbers: dense, or sparse for a large numeric one)
        self.a_sym: list[list[Any]] | None
        self.a_num: np.ndarray | SparseRows
        self.b_v: list[Any]
        self.exact: Any = None      # a symbolic instant's solution in stand-ins (`engine.exact`)

    @property
    def batched(self) -> bool:
        """Whether the joints' rows are filled as arrays (`JointArrays`): a large numeric
        system, kept sparse."""
        return not self.inst.symbolic and self.unknowns.n > LARGE

    def rows(self, lv: Level, joints: bool = True) -> list[Row]:
        """The rows of one level: each joint's conditions, each driver's, and the idle spins'
        (`engine.idle`), in that order; the pair of bodies each joint or driver row relates is
        kept in `pairs`. Without `joints`: the drivers' and the idle spins' only."""
        out: list[Row] = []
        pairs: list[frozenset | None] = []          # the two bodies each joint row or driver row relates
        model = self.inst.model
        paired = not lv.accel     # the same at both levels: taken at the velocity level
        for j in model.joints if joints else ():
            rows = joint_rows(self.geos[j.id], lv)
            out += rows
            if paired:
                pairs += [frozenset((j.a, j.b))] * len(rows)
        for d in model.drivers:
            rows = driver_rows(self.inst, d, self.geos, lv)
            out += rows
            body = (d.driven_body() if d.kind == "omega" else d.driven_point().body if d.kind == "velocity"
                    else None)
            pairs += [frozenset((body, d.relative_to or model.frame)) if body else None] * len(rows)
        idle = idle_rows(self.inst, lv)
        if paired:
            self.pairs = pairs + [None] * len(idle)
        return out + idle

    def matrix(self, rows: list[Row]) -> tuple[list[list[Any]], list[Any]]:
        """The rows as A x = b: A[i][col] the coefficients of row i's linear form, b[i] minus
        its constant."""
        n = self.unknowns.n
        a = [[0] * n for _ in rows]
        b = []
        for i, row in enumerate(rows):
            for col, coef in row.lin.terms.items():
                a[i][col] = coef
            b.append(-row.lin.const)
        return a, b

    def prepare(self) -> None:
        """The velocity rows, their matrix and its analysis: what both levels share.

        Large numeric systems are kept sparse and factorised by sparse LU; small ones (and
        symbolic ones) are analysed densely with the SVD.
        """
        inst, u = self.inst, self.unknowns
        translation, body_of = u.layout()
        if self.batched:
            self.a_sym = None
            self.a_num = sparse = self._prepare_sparse(VelocityLevel(u, inst.ref))
            self.analysis = analyse_sparse(sparse, self.is_driver, translation, inst.scale,
                                           self.labels, self.wheres, body_of, self._restating)
            return
        rows_v = self.rows(VelocityLevel(u, inst.ref))
        self.rows_v = rows_v
        self.labels = [r.label for r in rows_v]
        self.wheres = [r.where for r in rows_v]
        self.is_driver = np.array([r.driver for r in rows_v], dtype=bool)
        if inst.symbolic:
            a, self.b_v = self.matrix(rows_v)
            self.a_sym = a
            dense = np.array([[inst.num(c) for c in row] for row in a], dtype=float).reshape(len(a), u.n)
        else:                       # numbers: the matrix filled from the rows' terms at once
            self.a_sym, self.b_v, dense = None, [-r.lin.const for r in rows_v], self._numeric(rows_v)
        self.a_num = dense
        from .dense import analyse       # (defined only where a dense analysis is made: see its module)

        self.analysis = analyse(dense, self.is_driver, translation, inst.scale, self.labels,
                                self.wheres, body_of, want_blocks=inst.symbolic,
                                restating=self._restating)

    def _prepare_sparse(self, lv: Level) -> SparseRows:
        """`prepare`'s rows of a large numeric system, as arrays: the joints' (`JointArrays`:
        each kind's `numeric_rows` where it fills them at once, else `rows` joint by joint),
        then the drivers' and the idle spins' as `rows` gives them; the same matrix, right
        sides, labels and pairs, row for row."""
        joints = JointArrays(self, lv)
        others = self.rows(lv, joints=False)
        extra = sparse_matrix(others, self.unknowns.n)
        self.rows_v = []
        self.b_v = joints.b + [-r.lin.const for r in others]
        self.labels = joints.labels + [r.label for r in others]
        self.wheres = joints.wheres + [r.where for r in others]
        self.is_driver = np.array([False] * len(joints.b) + [r.driver for r in others], dtype=bool)
        self.pairs = joints.pairs + self.pairs
        indptr = np.concatenate([joints.indptr, joints.indptr[-1] + extra.indptr[1:]])
        return SparseRows(indptr, np.concatenate([joints.cols, extra.cols]),
                          np.concatenate([joints.vals, extra.vals]), (len(self.b_v), self.unknowns.n))

    def _numeric(self, rows: list[Row]) -> np.ndarray:
        """A of a numeric instance as floats, the entries the rows' terms give (others 0)."""
        a = np.zeros((len(rows), self.unknowns.n))
        num = self.inst.num
        for i, row in enumerate(rows):
            for col, coef in row.lin.terms.items():
                a[i, col] = coef if type(coef) is float else num(coef)     # (a float is its own number)
        return a

    def _restating(self) -> np.ndarray:
        """The driver rows that restate what a joint between the same two bodies fixes in
        every configuration (ω_x = 0 of a body turning about y): accepted, but not counted
        as conditions when the drivers are too few (`mobility`, not a dead point)."""
        a = self.a_num.toarray() if isinstance(self.a_num, SparseRows) else self.a_num
        out = np.zeros(len(self.pairs), dtype=bool)
        for i, pair in enumerate(self.pairs):
            if not self.is_driver[i] or pair is None:
                continue
            local = [k for k, p in enumerate(self.pairs) if p == pair and not self.is_driver[k]]
            if not local:
                continue
            joints, row = a[local], a[i]
            coef, *_ = np.linalg.lstsq(joints.T, row, rcond=None)
            out[i] = np.linalg.norm(joints.T @ coef - row) <= 1e-9 * np.linalg.norm(row)
        return out

    def _analysed(self) -> Analysis | SparseAnalysis:
        """The analysis `prepare` made (every solve comes after it)."""
        assert self.analysis is not None, "prepare() first"
        return self.analysis

    def _dense(self) -> tuple[Analysis, np.ndarray]:
        """The dense analysis and numeric matrix of a symbolic instant, which is never kept
        sparse (`prepare`): what the exact solve orders its blocks by."""
        from .dense import Analysis      # (made by `prepare` for every symbolic instant)

        assert isinstance(self.analysis, Analysis) and isinstance(self.a_num, np.ndarray), "a dense system"
        return self.analysis, self.a_num

    def solve_linear(self, b: list[Any], check: bool = True,
                     labels: Sequence[Any] | None = None, level: int = 0) -> list[Any]:
        """The solution of A x = b with the analysed matrix (exact for a symbolic instant).
        `level` 1 (velocities) or 2 (accelerations): the right side's natural size is the
        model's rate to that power (`linsolve.solve_numeric`'s check of redundant rows)."""
        inst = self.inst
        num = inst.num
        b_num = np.array([v if type(v) is float else num(v) for v in b], dtype=float)
        with np.errstate(all="ignore"):
            x_num = solve_numeric(self._analysed(), b_num, labels or self.labels, self.wheres,
                                  self.is_driver, check, inst.rate ** level if level else 0.0)
        if not (np.isfinite(b_num).all() and np.isfinite(x_num).all()):
            raise KinematikaError("schema", "values-overflow", "drivers")
        if not inst.symbolic:
            return x_num.tolist()
        from ..budget import check as within_budget

        within_budget("stage-solving")
        analysis, a_num = self._dense()
        assert self.a_sym is not None, "a symbolic instant keeps its exact matrix"
        exact = solve_symbolic(analysis, self.a_sym, b, a_num)
        rate = max(inst.rate, inst.rate ** 2)        # the size of rates and their squares
        inst.backend.check_against(exact, x_num, inst.probe, rate * max(1.0, inst.scale))
        return exact

    def solve(self) -> Motion:
        """The instant's `Motion`: A x_v = b_v for (ω, v₀), then A x_a = b_a(x_v) for (α, a₀)
        with the same matrix (only the known terms rebuilt); a symbolic instant is solved
        exactly in stand-ins (`engine.exact`). Redundant conditions must agree at both levels."""
        inst, u = self.inst, self.unknowns
        if self.analysis is None:
            self.prepare()
        # in stand-ins (`engine.exact`): planar models, and spatial ones in exact numbers (whose
        # written-out solve spent its time in gcds of long integers); spatial formulas in
        # symbols are solved as written (as fast, and their points' motions read shorter)
        if inst.symbolic and (self.space.dim == 2 or not inst.probe):
            return self._solve_exact()
        x_v = self.solve_linear(self.b_v, check=True, level=1)
        velocities = self._motion(x_v, None)
        # the acceleration system has the same matrix: only its known terms are built
        b_a, labels_a = self.known_terms(AccelerationLevel(KnownTerms(u), inst.ref, velocities))
        # redundant conditions must agree at this level too: an α the joints forbid is a conflict
        x_a = self.solve_linear(b_a, labels=labels_a, level=2)
        return self._motion(x_v, x_a)

    def known_terms(self, lv: Level) -> tuple[list[Any], Sequence[Any]]:
        """The right side b of the rows at level `lv` and their labels, in `rows`'s order: the
        same numbers and labels as `rows(lv)` gives, the joints' without building their `Row`s
        (the acceleration level, whose matrix is the velocity level's)."""
        b: list[Any] = []
        labels: list[Any] = []
        joints: Sequence[Any] = []
        if self.batched:
            arrays = JointArrays(self, lv)
            b, joints = arrays.b, arrays.labels
        else:
            for j in self.inst.model.joints:
                for value, label in joint_known_terms(self.geos[j.id], lv):
                    b.append(value)
                    labels.append(label)
        for r in [*(r for d in self.inst.model.drivers for r in driver_rows(self.inst, d, self.geos, lv)),
                  *idle_rows(self.inst, lv)]:
            b.append(-r.lin.const)
            labels.append(r.label)
        return b, (joints + labels if isinstance(joints, SaidLater) else labels)

    def _solve_exact(self) -> Motion:
        """Both levels solved with the coordinates as stand-ins (`engine.exact`), then the
        coordinates written in: the same analysis (blocks, pivots) as the numeric twin."""
        from .exact import ExactWorld, Reveal, stand_in_instant, stand_in_values

        inst, u = self.inst, self.unknowns
        standin, values = stand_in_instant(inst)
        twin = InstantSolver(standin, terms=self.terms)
        a, b_v = twin.matrix(twin.rows(VelocityLevel(u, inst.ref)))
        x_v = self._solve_exact_level(standin, a, b_v, self.labels, values, "v")
        # the accelerations are solved with the velocities as stand-ins too
        x_w, known = stand_in_values(x_v, standin, "x")
        values.update(known)
        public = self._velocity_names(x_w, known)
        velocities = twin._motion(x_w, None)
        rows_a = twin.rows(AccelerationLevel(KnownTerms(u), inst.ref, velocities))
        x_a = self._solve_exact_level(standin, a, [-r.lin.const for r in rows_a],
                                      [r.label for r in rows_a], values, "a")
        self.exact = ExactWorld(standin, twin._motion(x_v, x_a), twin._motion(x_w, x_a),
                                Reveal(values, set(known), public, inst, standin.probe))
        states = {body: self.exact.state(body) for body in self.exact.motion.states}
        return Motion(self.space, inst.ref, states, self.terms)

    def _velocity_names(self, x_w: list[Any], known: dict) -> dict:
        """The name each solved velocity's stand-in takes when an acceleration would be too
        long with it written in: omega_BODY (omega_BODY_x in 3D), v0x_BODY for the velocity
        of the body's point at the origin."""
        import sympy

        u, rot = self.unknowns, self.space.rot
        out: dict[Any, Any] = {}
        for column, s in enumerate(x_w):
            if s not in known:
                continue
            body = u.body_of(column)
            k = column - u.offset[body]
            if k < rot:
                wanted = f"omega_{body}" + (f"_{'xyz'[k]}" if rot == 3 else "")
            else:
                wanted = f"v0{'xyz'[k - rot]}_{body}"
            out[s] = sympy.Symbol(fresh_name(self.inst, wanted, {str(v) for v in out.values()}),
                                  real=True)
        return out

    def _solve_exact_level(self, standin: Instant, a: list[list[Any]], b: list[Any],
                           labels: Sequence[Any], values: dict, prefix: str) -> list[Any]:
        """A x = b exactly (in stand-ins), after the numeric solve checks its consistency.
        Each compound unknown reaches later blocks as a stand-in too (its value added to
        `values`, from where it is revealed), so that a later loop is solved in its terms."""
        from .exact import stand_in_values

        b_num = np.array([standin.num(v) for v in b], dtype=float)
        with np.errstate(all="ignore"):
            x_num = solve_numeric(self._analysed(), b_num, labels, self.wheres, self.is_driver, True,
                                  self.inst.rate ** (1 if prefix == "v" else 2))
        if not (np.isfinite(b_num).all() and np.isfinite(x_num).all()):
            raise KinematikaError("schema", "values-overflow", "drivers")

        def name(column: int, value: Any) -> Any:
            (out,), known = stand_in_values([value], standin, f"{prefix}{column}_")
            values.update(known)
            return out

        analysis, a_num = self._dense()
        exact = solve_symbolic(analysis, a, b, a_num, name)
        rate = max(self.inst.rate, self.inst.rate ** 2)     # the size of rates and their squares
        standin.backend.check_against(exact, x_num, standin.probe, rate * max(1.0, self.inst.scale))
        return exact

    def _motion(self, x_v: list[Any], x_a: list[Any] | None) -> Motion:
        sp, offset = self.space, self.unknowns.offset
        rot, dim = sp.rot, sp.dim
        states = {}
        for body in self.inst.model.bodies:
            o = offset.get(body)
            if o is None:
                zero = sp.zero()
                states[body] = BodyState(sp.rot_zero(), zero, sp.rot_zero(), zero)
                continue
            # (ω, v₀) of the body: its `rot` unknowns, then `dim` (ω a scalar in the plane)
            w = x_v[o] if rot == 1 else tuple(x_v[o:o + rot])
            v0 = tuple(x_v[o + rot:o + rot + dim])
            if x_a is None:
                alpha, a0 = sp.rot_zero(), sp.zero()
            else:
                alpha = x_a[o] if rot == 1 else tuple(x_a[o:o + rot])
                a0 = tuple(x_a[o + rot:o + rot + dim])
            states[body] = BodyState(w, v0, alpha, a0)
        return Motion(sp, self.inst.ref, states, self.terms)



class JointArrays:
    """The joints' rows of one level of a large numeric system, in the model's order of joints:
    each kind's joints filled at once by its `numeric_rows` (else each joint's `rows`), then
    put in order. `indptr`, `cols`, `vals`: the coefficients by rows (at the velocity level);
    `b` the right sides, `labels`, `wheres` and `pairs` (the two bodies) of each row."""

    def __init__(self, solver: InstantSolver, lv: Level) -> None:
        joints = solver.inst.model.joints
        geos = solver.geos
        groups: dict[Any, list[int]] = {}
        for k, j in enumerate(joints):
            groups.setdefault(j.kind, []).append(k)
        start = np.zeros(len(joints), dtype=np.int64)
        count = np.zeros(len(joints), dtype=np.int64)
        ptrs, cols, vals = [np.zeros(1, dtype=np.int64)], [], []
        b: list[Any] = []
        pieces: list[Sequence[Said]] = []         # the rows' labels, kind after kind
        entries = 0
        for kind, ks in groups.items():
            batch = kind.numeric_rows([geos[joints[k].id] for k in ks], lv)
            if batch is not None and batch.labels is None and kind not in solver.said_rows:
                batch = None        # labels said at a level not filled as arrays: joint by joint
            parts = ([(ks, batch, True)] if batch is not None else
                     [([k], _from_rows(joint_rows(geos[joints[k].id], lv), solver.unknowns.n, lv.accel), False)
                      for k in ks])
            for members, part, said in parts:
                per = part.per_joint
                start[members] = len(b) + per * np.arange(len(members))
                count[members] = per
                if part.labels is None:      # the velocity level's, said once
                    pieces.append(solver.said_rows[kind])
                elif said:        # the kind's labels, said as the joint's (as `joint_rows` does)
                    solver.said_rows[kind] = mine = _said_as_joints(part.labels, joints, members, per)
                    pieces.append(mine)
                else:
                    pieces.append(part.labels)
                b += part.b.tolist() if isinstance(part.b, np.ndarray) else part.b
                if part.indptr is not None:
                    ptrs.append(part.indptr[1:] + entries)
                    cols.append(part.cols)
                    vals.append(part.vals)
                    entries += int(part.indptr[-1])
        first = np.zeros(len(joints), dtype=np.int64)
        np.cumsum(count[:-1], out=first[1:])
        order = np.repeat(start - first, count) + np.arange(len(b))
        shuffled = not np.array_equal(order, np.arange(len(b)))
        labels = SaidLater.joined(pieces)      # made when an error names a row
        if shuffled:
            b = [b[i] for i in order.tolist()]
            labels = labels.reordered(order.tolist())
        self.b, self.labels = b, labels
        if lv.accel:            # (the right sides only: the matrix is the velocity level's)
            return
        per_joint = count.tolist()
        rows = len(b)       # each row's place and pair of bodies: read only on errors, made then
        self.wheres: SaidLater[str] = SaidLater(
            rows, lambda: [j.where for j, c in zip(joints, per_joint) for _ in range(c)])
        self.pairs: SaidLater[frozenset | None] = SaidLater(
            rows, lambda: [pair for j, c in zip(joints, per_joint) for pair in [frozenset((j.a, j.b))] * c])
        indptr = np.concatenate(ptrs)
        col = np.concatenate(cols) if cols else np.zeros(0, dtype=np.int64)
        val = np.concatenate(vals) if vals else np.zeros(0)
        if shuffled:
            lengths = np.diff(indptr)[order]
            new = np.zeros(len(order) + 1, dtype=np.int64)
            np.cumsum(lengths, out=new[1:])
            at = np.repeat(indptr[order] - new[:-1], lengths) + np.arange(int(new[-1]))
            indptr, col, val = new, col[at], val[at]
        self.indptr, self.cols, self.vals = indptr, col.astype(np.int64), val.astype(float)


def _said_as_joints(labels: Sequence[Said], joints: Sequence[Any], members: list[int], per: int) -> SaidLater:
    """A kind's `labels` of its joints `members` (`per` rows each) said as each joint's, as
    `joint_rows` says them: made when read."""
    return SaidLater(len(labels), lambda: [Said("row-joint", id=joints[k].id, label=label)
                                           for k, label in zip(np.repeat(members, per).tolist(), labels)])


def _from_rows(rows: list[Row], n: int, accel: bool) -> NumericRows:
    """One joint's `Row`s as `NumericRows` (its labels already said as the joint's)."""
    matrix = None if accel else sparse_matrix(rows, n)
    return NumericRows(len(rows), None if matrix is None else matrix.indptr,
                       None if matrix is None else matrix.cols, None if matrix is None else matrix.vals,
                       [-r.lin.const for r in rows], [r.label for r in rows])
