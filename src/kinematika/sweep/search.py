"""Assemblies of mechanisms that are not made of dyads: the real solutions found numerically.

A triad, or a spatial loop, has no closed form for its closures. With the input held where
it is drawn, the position constraints (`constraints`, the same the sweep's Newton path
solves) are solved by least squares from the drawn poses and from many random ones; the
distinct solutions are the assemblies found. They are ordered by the bodies' directions
(the angle of each moving body's first two points), so the numbers do not depend on which
assembly the model draws. Being a search, it may miss an assembly that is hard to reach;
mechanisms with rolling contacts or knife edges keep the drawn assembly only.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..joints.capabilities import Side
from ..model.model import Model
from .assembler import Assembler
from .assembly import Assembly
from .plan import make_plan
from .posed import posed_model
from .poses import Poses, SpatialPoses, exp_rotation
from .result import SweepResult

STARTS = 48                 # random starting poses
RESIDUAL = 1e-9             # relative to the model's size: a solution
BUDGET = 30                 # evaluations per unknown for a start (the solutions of the examples
                            # and textbook cases take at most 20); past it, a start goes on
CLOSING = 1e-6              # only when its residual is below this (it is closing, slowly)
SEED = 20261124


def searched_assemblies(model: Model, sweeper: Any) -> list:
    """The assemblies found, in a stable order; the drawn one marked."""
    drawn = _places_of(model, sweeper, None)
    if not _searchable(model):
        return [Assembly(1, True, [], model, drawn)]
    search = _Search(model, sweeper)
    found: list[tuple[dict, Any]] = [(drawn, None)]
    for poses in search.solutions():
        places = _places_of(model, sweeper, poses)
        if not any(_same(places, p, sweeper.inst.scale) for p, _ in found):
            found.append((places, poses))
    found.sort(key=lambda item: _order(model, item[0]))
    out = []
    for number, (places, poses) in enumerate(found, start=1):
        posed = model if poses is None else posed_model(model, search.result(poses), 0)
        out.append(Assembly(number, poses is None, _directions(model, places), posed, places))
    return out


def _searchable(model: Model) -> bool:
    return not any(j.kind.touches or j.kind.along_in is Side.B for j in model.joints)


class _Search:
    """Least squares on the position constraints over the moving bodies' poses."""

    def __init__(self, model: Model, sweeper: Any) -> None:
        self.model, self.sweeper = model, sweeper
        self.asm = Assembler(sweeper, make_plan(sweeper.inst, sweeper.joint.id, 0.0, 1))
        self.bodies = list(self.asm.unknowns.offset)
        self.planar = model.dimension == 2
        self.width = 3 if self.planar else 6
        self.scale = sweeper.inst.scale

    def poses(self, x: np.ndarray) -> Any:
        ref = self.sweeper.inst.ref
        w = self.width
        if self.planar:
            xs = x.tolist()                 # floats read once (an array's items one by one are slower)
            return Poses(ref, {b: xs[w * i] for i, b in enumerate(self.bodies)},
                         {b: (xs[w * i + 1], xs[w * i + 2]) for i, b in enumerate(self.bodies)}, {})
        rot = {b: exp_rotation(x[w * i:w * i + 3]) for i, b in enumerate(self.bodies)}
        return SpatialPoses(ref, rot, {b: np.asarray(x[w * i + 3:w * i + 6], float) for i, b in enumerate(self.bodies)},
                            {b: np.asarray(x[w * i:w * i + 3], float) for i, b in enumerate(self.bodies)}, {})

    def residual(self, x: np.ndarray) -> np.ndarray:
        """The position residuals at poses x over the model's size: every row scaled alike
        (the lengths' rows dominate), so that `RESIDUAL` is relative to the model's size."""
        return self.asm.residual(self.poses(x), 0.0) / self.scale

    def solutions(self):
        """Poses that satisfy the constraints, from random starts. A start that stalls in a
        false minimum (a spherical four-bar has several, each crawling for seconds) is given
        up after its budget."""
        from scipy.optimize import least_squares

        rng = np.random.default_rng(SEED)
        n = self.width * len(self.bodies)
        for _ in range(STARTS):
            x0 = np.zeros(n)
            for i in range(len(self.bodies)):
                if self.planar:
                    x0[3 * i] = rng.uniform(-math.pi, math.pi)
                    x0[3 * i + 1:3 * i + 3] = rng.normal(0, self.scale, 2)
                else:
                    x0[6 * i:6 * i + 3] = rng.normal(0, 1.5, 3)
                    x0[6 * i + 3:6 * i + 6] = rng.normal(0, self.scale, 3)
            fit = least_squares(self.residual, x0, method="lm", xtol=1e-14, ftol=1e-14, max_nfev=BUDGET * n)
            if fit.status == 0 and np.abs(fit.fun).max(initial=0.0) < CLOSING:
                fit = least_squares(self.residual, fit.x, method="lm", xtol=1e-14, ftol=1e-14, max_nfev=400 * n)
            if np.abs(fit.fun).max(initial=0.0) < RESIDUAL and self.proper(self.poses(fit.x)):
                yield self.poses(fit.x)

    def proper(self, poses: Any) -> bool:
        """Constraints written for nearby poses also hold for a body turned half a turn about
        an axis across a joint's (the axes then only parallel): keep the solutions whose joint
        axes keep their sense and whose input is where it is drawn."""
        geos = self.asm.base_geos
        for j in self.model.joints:
            axis = geos[j.id].axis
            if axis is None or self.planar:
                continue
            if float(np.dot(poses.turn(j.a, axis), poses.turn(j.b, axis))) < 0.999:
                return False
        j = self.sweeper.joint
        if self.planar:
            turn = (poses.angle(j.b) - poses.angle(j.a) + math.pi) % (2 * math.pi) - math.pi
            return abs(turn) < 1e-6
        return float(np.abs(np.asarray(poses.rotation_error(j.a, j.b))).max()) < 1e-6

    def result(self, poses: Any) -> SweepResult:
        """A one-row `SweepResult` of these poses (what `posed_model` reads)."""
        model = self.model
        bodies = {b: {"angle": np.array([_degrees(poses.angle(b))])} for b in model.bodies}
        points = {str(ref): {"position": np.array([poses.point(ref.body, self.sweeper.inst.points[ref.point])],
                                                  dtype=float)}
                  for ref in model.material_points()}
        return SweepResult(np.zeros(1), self.sweeper.joint.id, np.ones(1, bool), bodies, points,
                           dimension=model.dimension, frame=model.frame)


def _degrees(angle: Any) -> Any:
    return np.degrees(np.asarray(angle, dtype=float))


def _places_of(model: Model, sweeper: Any, poses: Any) -> dict[str, tuple]:
    """Every material point's place: as drawn, or carried by `poses`."""
    out = {}
    for ref in model.material_points():
        p = sweeper.inst.points[ref.point]
        q = p if poses is None else poses.point(ref.body, tuple(float(c) for c in p))
        out[str(ref)] = tuple(float(c) for c in q)
    return out


def _same(a: dict[str, tuple], b: dict[str, tuple], scale: float) -> bool:
    return all(np.allclose(a[k], b[k], atol=1e-6 * scale, rtol=0) for k in a)


def _body_directions(model: Model, places: dict[str, tuple]) -> list[tuple[str, float]]:
    """(body, the angle of its first two points in degrees, 0 to 360) of the moving bodies."""
    out = []
    for name, body in model.bodies.items():
        if name == model.frame or len(body.points) < 2:
            continue
        p, q = (places[f"{n}@{name}"] for n in body.points[:2])
        out.append((name, math.degrees(math.atan2(q[1] - p[1], q[0] - p[0])) % 360.0))
    return out


def _order(model: Model, places: dict[str, tuple]) -> tuple:
    return tuple(round(angle, 6) for _, angle in _body_directions(model, places))


def _directions(model: Model, places: dict[str, tuple]) -> list[str]:
    """How an assembly looks, in words: each moving body's direction (planar), or where the
    joints' points that move are (3D)."""
    if model.dimension == 2:
        return [f"{name} at {angle:.4g}°" for name, angle in _body_directions(model, places)]
    out = []
    for j in model.joints:
        if j.at is None or model.frame in (j.a, j.b):
            continue
        size = max(abs(c) for p in places.values() for c in p) or 1.0
        shown = ", ".join(f"{c if abs(c) > 1e-9 * size else 0.0:.3g}" for c in places[f"{j.at}@{j.b}"])
        text = f"{j.at} at ({shown})"
        if text not in out:
            out.append(text)
    return out
