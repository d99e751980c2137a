"""Degrees of freedom by rank, and what to tell the user when the drivers do not fix the motion.

The matrix is made dimensionless first (translation unknowns in units of the model's
length, rows equilibrated), so that ranks and the condition number compare like with like.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Generic, Optional, Sequence, TypeVar

import numpy as np

from ..errors import KinematikaError, Names, Num, Said

SINGULAR_CONDITION = 1e10

Matrix = TypeVar("Matrix")       # a dense array, or the engine's sparse rows (`blocks.SparseRows`)


@dataclass
class Scaled(Generic[Matrix]):
    """A dimensionless copy of the system matrix: A_s = R A C."""

    matrix: Matrix
    row_scale: np.ndarray
    col_scale: np.ndarray


def scale_system(a: np.ndarray, translation_columns: np.ndarray, length: float) -> Scaled[np.ndarray]:
    """A dimensionless copy of A: translation columns times the model's `length` (C), then each
    row divided by its largest entry (R), so A_s = R A C compares rotations with translations
    and rows with rows."""
    col = np.where(translation_columns, length, 1.0)
    scaled = a * col
    norms = np.maximum.reduce(np.abs(scaled), axis=1) if a.size else np.zeros(0)   # (what .max does)
    row = 1.0 / np.where(norms > 0, norms, 1.0)        # a zero (or unknown) row's scale: 1 / 1
    return Scaled(scaled * row[:, None], row, col)


def numeric_rank(a: np.ndarray, reference: float | None = None) -> int:
    """The rank of `a` by its singular values: those above the largest (or `reference`) /
    `SINGULAR_CONDITION` count."""
    if a.size == 0:
        return 0
    s = np.linalg.svd(a, compute_uv=False)
    top = reference if reference is not None else (s[0] if s.size else 0.0)
    return int(np.sum(s > top / SINGULAR_CONDITION)) if top > 0 else 0


class Diagnosis:
    """What the rank of the dimensionless matrix says: `n` unknowns, the degrees of freedom the
    joints leave (`dof` = n − rank of the joint rows), the independent conditions the drivers
    add, and the condition number (the largest singular value over the n-th).

    `dof` and `conditions` may be given, or counted on first use by `ranks()` (the joint
    rows' rank takes an SVD of its own, which a motion solved instant after instant never
    reads: it asks only for the condition number)."""

    __slots__ = ("_conditions", "_dof", "_ranks", "condition_number", "n")

    def __init__(self, n: int, dof: Optional[int] = None, conditions: Optional[int] = None,
                 condition_number: float = math.inf, ranks: Optional[Callable[[], tuple[int, int]]] = None) -> None:
        self.n, self.condition_number = n, condition_number
        self._dof, self._conditions, self._ranks = dof, conditions, ranks

    def _count(self) -> tuple[int, int]:
        """`dof` and `conditions`: as given, or counted once by `ranks()`."""
        if self._dof is None or self._conditions is None:
            assert self._ranks is not None, "a Diagnosis is given dof and conditions, or ranks() to count them"
            joints, total = self._ranks()
            self._dof, self._conditions = self.n - joints, total - joints
            return self._dof, self._conditions
        return self._dof, self._conditions

    @property
    def dof(self) -> int:
        """Degrees of freedom the joints alone leave: n − rank of the joint rows."""
        return self._count()[0]

    @property
    def conditions(self) -> int:
        """Independent conditions the drivers add: rank of all rows − rank of the joint rows."""
        return self._count()[1]

    def __repr__(self) -> str:
        return f"Diagnosis(n={self.n}, dof={self.dof}, conditions={self.conditions}, " \
               f"condition_number={self.condition_number!r})"


def diagnose(scaled: np.ndarray, is_driver: np.ndarray, s: np.ndarray | None = None) -> Diagnosis:
    """The `Diagnosis` of a scaled system whose driver rows are marked by `is_driver`: ranks
    by singular values (`s`, the whole matrix's when the caller has them), dof = n −
    rank(joints), driver conditions = rank(all) − rank(joints); the joint rows' rank is
    counted when first asked for."""
    n = scaled.shape[1]
    if s is None:
        s = np.linalg.svd(scaled, compute_uv=False) if scaled.size else np.zeros(0)
    top = s[0] if s.size else 0.0
    smallest = s[n - 1] if s.size >= n and n > 0 else 0.0
    cond = float(top / smallest) if smallest > 0 else float("inf")

    def ranks() -> tuple[int, int]:
        joints = numeric_rank(scaled[~is_driver], top)
        total = int(np.sum(s > top / SINGULAR_CONDITION)) if top > 0 else 0
        return joints, total

    return Diagnosis(n, condition_number=cond, ranks=ranks)


def underdetermined_error(scaled: np.ndarray, is_driver: np.ndarray, labels: Sequence[Any],
                          wheres: Sequence[str], body_of: list[str], diag: Diagnosis,
                          restating: np.ndarray | None = None) -> KinematikaError:
    """`singular` at a dead point (drivers enough in number), `mobility` otherwise. Driver
    rows that only restate a joint (`restating`) do not count as drivers here."""
    counted = is_driver if restating is None else is_driver & ~restating
    driver_rows = scaled[counted]
    given = numeric_rank(driver_rows)
    free = _free_bodies(scaled, body_of)
    if given >= diag.dof > 0 and diag.conditions < given:
        dependent = _dependent_drivers(scaled, is_driver, labels, wheres)
        return KinematikaError(
            "singular", "dead-point", "drivers", count=len(dependent), drivers=Names(dependent, 3),
            condition=_fmt(diag.condition_number), limit=Num(SINGULAR_CONDITION, ".0e"))
    return KinematikaError(
        "mobility", "mobility-free", "drivers", dof=diag.dof, conditions=diag.conditions, count=len(free),
        free=Names(free, 6))


def conflict_error(residual: np.ndarray, labels: Sequence[Any], wheres: Sequence[str],
                   is_driver: np.ndarray, diag: Diagnosis) -> KinematikaError:
    """Some conditions cannot hold together: name the drivers involved (else the joints)."""
    order = np.argsort(-np.abs(residual))
    worst = [int(i) for i in order if abs(residual[i]) > 1e-6 * max(abs(residual).max(), 1e-300)]
    drivers = _unique(Said("row-driver", where=wheres[i], label=labels[i]) for i in worst if is_driver[i])
    joints = _unique(labels[i] for i in worst if not is_driver[i])
    named = drivers or joints
    given = int(is_driver.sum())
    return KinematikaError(
        "mobility", "drivers-conflict", "drivers", named=Names(named[:3], None, joined=";"), dof=diag.dof,
        given=given, conditions=diag.conditions)


def _unique(items: Any) -> list:
    out: list = []
    for item in items:
        if item not in out:
            out.append(item)
    return out



def _free_bodies(scaled: np.ndarray, body_of: list[str]) -> list[str]:
    if scaled.shape[1] == 0:
        return []
    _, s, vt = np.linalg.svd(scaled)
    top = s[0] if s.size else 1.0
    k = int(np.sum(s > top / SINGULAR_CONDITION))
    null = vt[k:]
    out: list[str] = []
    for col in range(scaled.shape[1]):
        if null.size and np.abs(null[:, col]).max() > 1e-6 and body_of[col] not in out:
            out.append(body_of[col])
    return out


def _dependent_drivers(scaled: np.ndarray, is_driver: np.ndarray, labels: Sequence[Any],
                       wheres: Sequence[str]) -> list[Said]:
    """Drivers whose rows lie (numerically) in the span of the joints' rows."""
    joints = scaled[~is_driver]
    out: list[Said] = []
    for i in np.flatnonzero(is_driver):
        row = scaled[i]
        if joints.size:
            coef, *_ = np.linalg.lstsq(joints.T, row, rcond=None)
            gap = np.linalg.norm(joints.T @ coef - row)
        else:
            gap = np.linalg.norm(row)
        text = Said("row-driver", where=wheres[int(i)], label=labels[int(i)])
        if gap < 1e-8 * max(float(np.linalg.norm(row)), 1e-300) and text not in out:
            out.append(text)
    return out


def _fmt(x: float) -> "Said | Num":
    return Said("infinite") if not np.isfinite(x) else Num(x, ".3g")
