"""The motion over a range of a driven joint's coordinate, as numpy arrays.

Row k is increment k: the drawn configuration is row 0. A row that could not be solved
(`--skip-bad`) holds NaN in every array and False in `ok`; the JSON and CSV views write it
as null / an empty cell.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

QUANTITIES = ("position", "velocity", "acceleration")
BODY_QUANTITIES = ("angle", "omega", "alpha")


@dataclass
class SweepResult:
    """Arrays of one sweep: `coordinate` (N,), per body angle/omega/alpha, per material point
    position/velocity/acceleration (N, dim). Angles in degrees from the drawn configuration."""

    coordinate: np.ndarray
    joint: str
    ok: np.ndarray
    bodies: dict[str, dict[str, np.ndarray]]
    points: dict[str, dict[str, np.ndarray]]
    dead_points: list[float] = field(default_factory=list)
    unit: str = "deg"                  # of `coordinate`: "deg" (revolute) or "length"
    name: str = "Mechanism"
    dimension: int = 2
    method: str = "closed form"        # "closed form" (Assur groups) or "newton"
    frame: str = "ground"

    def __len__(self) -> int:
        return len(self.coordinate)

    def to_json(self) -> dict[str, Any]:
        """The contract's JSON: coordinate, bodies and points, one entry per row (null if bad)."""
        return {"coordinate": _column(self.coordinate),
                "bodies": {name: {q: _column(v) for q, v in values.items()}
                           for name, values in self.bodies.items()},
                "points": {name: {q: _column(v) for q, v in values.items()}
                           for name, values in self.points.items()}}

    def columns(self) -> list[tuple[str, np.ndarray]]:
        """One (header, values) per scalar: coordinate, body quantities, point components."""
        axes = "xyz"
        cols = [(f"coordinate_{self.unit}", self.coordinate)]
        for name, values in self.bodies.items():
            for q, v in values.items():
                if v.ndim == 1:
                    cols.append((f"{name}.{q}", v))
                else:
                    cols += [(f"{name}.{q}_{axes[i]}", v[:, i]) for i in range(v.shape[1])]
        for name, values in self.points.items():
            for q, v in values.items():
                cols += [(f"{name}.{q}_{axes[i]}", v[:, i]) for i in range(v.shape[1])]
        return cols

    def to_csv(self, path: str | Path) -> None:
        """One row per position, one column per scalar, a header; bad rows have empty cells."""
        cols = self.columns()
        table = np.column_stack([v for _, v in cols]) if cols else np.zeros((0, 0))
        with open(path, "w", newline="", encoding="utf-8") as f:
            writer = csv.writer(f)
            writer.writerow([h for h, _ in cols])
            for row in table.tolist():
                writer.writerow(["" if math.isnan(x) else repr(x) for x in row])


def _column(values: np.ndarray) -> list:
    """A JSON list with NaN rows as null (a bad row is NaN in every component)."""
    out = values.tolist()
    if values.ndim == 1:
        return [None if x != x else x for x in out]
    return [None if row[0] != row[0] else row for row in out]
