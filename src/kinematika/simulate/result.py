"""A motion in time, as numpy arrays: a sweep's result with `time` (seconds) in place of
`coordinate`, and the drift of each row.

Row k is at time `time[k]`; row 0 is the drawn configuration. The JSON is the sweep's,
`{"time": [...], "bodies": {...}, "points": {...}}`, with `"drift": [...]` after it (per row,
how far the integrated poses had left the joints' position conditions before they were
projected back, `simulate.holonomic`); the CSV and Parquet columns are the sweep's with
`time_s` first and `drift` after it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Iterator, Optional

import numpy as np

from ..sweep.result import SweepResult, clean


@dataclass
class SimulationResult(SweepResult):
    """The rows of a simulation: `time` (N,) in seconds, per body angle/omega/alpha, per
    material point position/velocity/acceleration (N, dim), and `drift` (N,)."""

    drift: np.ndarray = field(default_factory=lambda: np.zeros(0))
    duration: float = 0.0                # the time asked for (seconds): the last row's, unless stopped
    evaluations: int = 0                 # velocity solutions the ODE solver asked for
    notes: list[str] = field(default_factory=list)    # what the summary must say (drivers, numbers)
    stopped: Optional[Any] = None        # the KinematikaError that ended the motion early, if any

    @property
    def time(self) -> np.ndarray:
        """The rows' times in seconds (the sweep's `coordinate`)."""
        return self.coordinate

    def to_json(self) -> dict[str, Any]:
        """The JSON of `simulate --json`: the sweep's with `time` for `coordinate`, and `drift`."""
        out = super().to_json()
        data = {"time": out.pop("coordinate"), **out}
        data["drift"] = [float(x) for x in _drift(self.drift)]
        return data

    def json_chunks(self) -> Iterator[bytes]:
        """`to_json` as UTF-8 pieces (the sweep's, with its first key renamed and the drift
        added before the closing brace)."""
        import orjson

        chunks = super().json_chunks()
        first = next(chunks)
        head = b'{"coordinate":'
        assert first.startswith(head)
        last = b'{"time":' + first[len(head):]
        for chunk in chunks:
            yield last
            last = chunk
        assert last.endswith(b"}")                    # the object's closing brace, last
        yield last[:-1] + b',"drift":' + orjson.dumps(np.ascontiguousarray(_drift(self.drift)),
                                                      option=orjson.OPT_SERIALIZE_NUMPY) + b"}"

    def columns(self) -> list[tuple[str, np.ndarray]]:
        """One (header, values) per scalar: `time_s`, `drift`, then the sweep's columns."""
        cols = super().columns()
        return [("time_s", self.coordinate), ("drift", self.drift)] + cols[1:]

    def rows(self, count: int) -> "SimulationResult":
        """The first `count` rows (those computed before the motion stopped)."""
        cut = slice(0, count)
        return SimulationResult(
            coordinate=self.coordinate[cut], joint=self.joint, ok=self.ok[cut],
            bodies={b: {q: v[cut] for q, v in values.items()} for b, values in self.bodies.items()},
            points={p: {q: v[cut] for q, v in values.items()} for p, values in self.points.items()},
            unit=self.unit, name=self.name, dimension=self.dimension, method=self.method, frame=self.frame,
            drift=self.drift[cut], duration=self.duration, evaluations=self.evaluations,
            notes=list(self.notes), stopped=self.stopped)


def _drift(values: np.ndarray) -> np.ndarray:
    """The drift to 3 significant digits (a measure, not a result)."""
    out = clean(np.asarray(values, dtype=float), 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        digits = np.where(out > 0, 2 - np.floor(np.log10(np.where(out > 0, out, 1.0))), 0)
    return np.array([round(float(x), int(d)) for x, d in zip(out, digits)])
