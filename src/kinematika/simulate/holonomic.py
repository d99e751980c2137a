"""Keeping the integrated poses on the joints' position conditions.

The velocities the engine solves keep every joint's condition's rate at zero, so the exact
motion stays on them; an integrator's does only to its tolerance, and the distance grows
with time (drift). Each joint says which part of its condition is on positions
(`JointKind.holonomic`: a pin's points coincide; a knife edge, nothing; a disc on a plane,
its gap). Their residual Φ(q) is projected back to zero by Gauss–Newton steps of least
change, δ = −J⁺ Φ in the dimensionless pose coordinates (rotations in radians, translations
over the model's size), with J = W A: the engine's velocity matrix A (the Jacobian of the
conditions in the pose coordinates, `sweep.poses`) taken along each part's weights W.

The drift reported is the largest residual before the projection over the model's size (an
angle counted as an arc of the model's size): how far the integrated poses had left the
conditions. Poses within `TOLERANCE` of them are left as they are.
"""
from __future__ import annotations

import math
from typing import Any, Callable, Sequence

import numpy as np

from ..engine.instant import Instant
from ..errors import KinematikaError
from ..joints import JointGeometry
from ..joints.holonomic import Holonomic

ITERATIONS = 8
TOLERANCE = 1e-12          # a correction this small (dimensionless) is the conditions met


class Projection:
    """The position conditions of a model's joints, and the projection onto them."""

    def __init__(self, inst: Instant, geos: dict[str, JointGeometry], wheres: Sequence[str],
                 drivers: Any) -> None:
        self.scale = inst.scale
        self.parts: list[tuple[Holonomic, list[int]]] = []
        for j in inst.model.joints:
            try:
                part = j.kind.holonomic(inst, geos[j.id], inst.ref)
            except KinematikaError as err:
                if err.said.key != "sweep-velocity-only":
                    raise
                raise KinematikaError(err.kind, "simulate-velocity-only", err.where, kind=err.said.args["kind"],
                                      dim=err.said.args["dim"]) from None
            rows = [i for i, w in enumerate(wheres) if w == j.where and not drivers[i]]
            self.parts.append((part, rows))

    def check(self, q: Any) -> None:
        """Each part whose values are its rows has as many values as the engine has rows (the
        sweep's check of its constraints, `sweep.newton`)."""
        for part, rows in self.parts:
            if part.weights is None and len(part.values(q, 0.0)) != len(rows):
                raise RuntimeError(f"a joint's position conditions do not match its engine rows ({rows})")

    def residual(self, q: Any) -> np.ndarray:
        """Φ(q): every part's values, in joint order."""
        return np.array([x for part, _ in self.parts for x in part.values(q, 0.0)], dtype=float)

    def size(self, q: Any) -> float:
        """The residual's largest value over the model's size (a quick measure of drift, for
        the integrator's event: rotations count as lengths of the model's size)."""
        r = self.residual(q)
        return float(np.abs(r).max(initial=0.0)) / self.scale

    def jacobian(self, q: Any, a: np.ndarray) -> np.ndarray:
        """J = W A at `q`, A the engine's velocity matrix there."""
        out = []
        for part, rows in self.parts:
            block = a[rows]
            if part.weights is None:
                out.append(block)
            else:
                weights = np.asarray(part.weights(q), dtype=float).reshape(-1, len(rows))
                out.append(weights @ block)
        return np.vstack(out) if out else np.zeros((0, a.shape[1]))

    def project(self, q: Any, matrix_at: Callable[[Any], np.ndarray], unknowns: Any) -> tuple[Any, float]:
        """`q` moved onto the conditions, and the drift (`size` before);
        `matrix_at(q)` is the engine's velocity matrix at q, in the columns of `unknowns`
        (`engine.levels.Unknowns`). A projection that does not
        converge is an `assembly` error (the motion has left what the joints allow)."""
        translation = np.array([(c % unknowns.width) >= unknowns.space.rot for c in range(unknowns.n)])
        column = np.where(translation, self.scale, 1.0)
        drift = self.size(q)
        if not math.isfinite(drift):
            raise KinematikaError("assembly", "simulate-positions-not-finite", "joints")
        for _ in range(ITERATIONS):
            phi = self.residual(q)
            if float(np.abs(phi).max(initial=0.0)) <= TOLERANCE * self.scale:
                self.keep(q)
                return q, drift
            j = self.jacobian(q, matrix_at(q)) * column
            step, *_ = np.linalg.lstsq(j, -phi, rcond=None)
            if not np.isfinite(step).all():
                break
            q = q.stepped(step * column, unknowns)
        raise KinematikaError("assembly", "simulate-projection-fails", "joints")

    def keep(self, q: Any) -> None:
        """Record the continuous angles (a rolling pair's line of centres) of the poses `q`."""
        for part, _ in self.parts:
            function = part.values
            if hasattr(function, "aux"):
                q.aux[function.key] = function.aux(q)  # type: ignore[attr-defined]  # `key` and `aux` ride on the residual function (`joints.rolling`), checked by hasattr
