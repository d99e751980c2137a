"""The motion of D designs over their sweep, as the metrics read it: (D, N) arrays.

Two sources give the same view: a batch of designs solved together (`sweep.batch`), and
one design swept on its own (`run_sweep`'s `SweepResult`, D = 1). Angles are in degrees
from the drawn configuration, positions, velocities and accelerations complex (x + iy).
"""
from __future__ import annotations

import numpy as np

from ..model.model import PointRef
from ..sweep.batch import Batch
from ..sweep.result import SweepResult


class Cycle:
    """What every source provides; `coordinate` is the input's increments (sweep units)."""

    coordinate: np.ndarray       # (N,)
    ok: np.ndarray               # (D, N) assembled and not singular
    dead: np.ndarray             # (D,) number of dead points met

    def angle(self, body: str) -> np.ndarray:
        """`body`'s rotation from its drawn configuration over the sweep, degrees: (D, N)."""
        raise NotImplementedError

    def omega(self, body: str) -> np.ndarray:
        """`body`'s angular velocity ω over the sweep, rad/s: (D, N)."""
        raise NotImplementedError

    def alpha(self, body: str) -> np.ndarray:
        """`body`'s angular acceleration α over the sweep, rad/s²: (D, N)."""
        raise NotImplementedError

    def motion(self, ref: PointRef) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, acceleration of a material point: complex (D, N)."""
        raise NotImplementedError

    def drawn(self, point: str) -> np.ndarray:
        """A point's drawn location per design: complex (D,)."""
        raise NotImplementedError

    def direction(self, joint: str) -> np.ndarray:
        """A prismatic or slot joint's unit `along` (drawn) per design: complex (D,)."""
        raise NotImplementedError

    @property
    def complete(self) -> np.ndarray:
        """(D,): the whole sweep was assembled."""
        return np.asarray(self.ok.all(axis=1))


class BatchCycle(Cycle):
    """The cycle of a batch of designs solved together (`sweep.batch`): each design's rows; a
    value shared by every design is broadcast to (D, N)."""

    def __init__(self, batch: Batch) -> None:
        self.batch = batch
        self.coordinate = batch.plan.coordinate
        self.ok = batch.ok
        self.shape = self.ok.shape
        self.dead = _dead_points(self.ok, batch.outcome.singular)

    def _rows(self, x) -> np.ndarray:
        return np.broadcast_to(x, self.shape)

    def angle(self, body: str) -> np.ndarray:
        """`body`'s rotation from its drawn configuration over the sweep, degrees: (D, N)."""
        return np.degrees(self._rows(self.batch.outcome.tracks[body].theta))

    def omega(self, body: str) -> np.ndarray:
        """`body`'s angular velocity ω over the sweep, rad/s: (D, N)."""
        return self._rows(self.batch.outcome.tracks[body].omega)

    def alpha(self, body: str) -> np.ndarray:
        """`body`'s angular acceleration α over the sweep, rad/s²: (D, N)."""
        return self._rows(self.batch.outcome.tracks[body].alpha)

    def motion(self, ref: PointRef) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, acceleration of a material point: complex (D, N)."""
        p, v, a = (self._rows(x) for x in self.batch.outcome.tracks[ref.body].point(ref.point))
        return p, v, a

    def drawn(self, point: str) -> np.ndarray:
        """A point's drawn location per design: complex (D,)."""
        return self.batch.points[point]

    def direction(self, joint: str) -> np.ndarray:
        """A prismatic or slot joint's unit `along` (drawn) per design: complex (D,)."""
        return self.batch.directions[joint]


class ResultCycle(Cycle):
    """The cycle of one design swept on its own (`SweepResult`, D = 1), for models the batch
    kernel does not take; `directions` are the joints' drawn `along`."""

    def __init__(self, result: SweepResult, directions: dict[str, tuple]) -> None:
        self.result = result
        self.directions = directions
        self.coordinate = result.coordinate
        self.ok = result.ok[None, :]
        self.dead = np.array([len(result.dead_points)])

    def angle(self, body: str) -> np.ndarray:
        """`body`'s rotation from its drawn configuration over the sweep, degrees: (1, N)."""
        return self.result.bodies[body]["angle"][None, :]

    def omega(self, body: str) -> np.ndarray:
        """`body`'s angular velocity ω over the sweep, rad/s: (1, N)."""
        return self.result.bodies[body]["omega"][None, :]

    def alpha(self, body: str) -> np.ndarray:
        """`body`'s angular acceleration α over the sweep, rad/s²: (1, N)."""
        return self.result.bodies[body]["alpha"][None, :]

    def motion(self, ref: PointRef) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, acceleration of a material point: complex (1, N)."""
        values = self.result.points[str(ref)]
        p, v, a = (_complex(values[q])[None, :] for q in ("position", "velocity", "acceleration"))
        return p, v, a

    def drawn(self, point: str) -> np.ndarray:
        """A point's drawn location (the sweep's first row, from any body that carries it):
        complex (1,)."""
        name = next(k for k in self.result.points if k.partition("@")[0] == point)
        return _complex(self.result.points[name]["position"][:1])

    def direction(self, joint: str) -> np.ndarray:
        """A prismatic or slot joint's unit `along` (drawn): complex (1,)."""
        return np.array([complex(*self.directions[joint])])


def _complex(xy: np.ndarray) -> np.ndarray:
    return xy[:, 0] + 1j * xy[:, 1]


def _dead_points(ok: np.ndarray, singular: np.ndarray) -> np.ndarray:
    """Per design, as `sweep.run.dead_points` counts them: singular rows, and each edge of a
    range that cannot be assembled (an edge whose bad side is singular is that row)."""
    edges = ok[:, :-1] != ok[:, 1:]
    bad_side = np.where(ok[:, :-1], singular[:, 1:], singular[:, :-1])
    return singular.sum(axis=1) + (edges & ~bad_side).sum(axis=1)
