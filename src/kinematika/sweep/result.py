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
        """The contract's JSON: coordinate, bodies and points, one entry per row (null if bad).

        Numbers are given to 12 significant digits, with round-off (below 1e-12 of the
        largest value of the same quantity) written as 0, as `solve` does.
        """
        scales = self.scales()
        return {"coordinate": _column(clean(self.coordinate, np.abs(self.coordinate).max(initial=0.0))),
                "bodies": {name: {q: _column(clean(v, scales[q])) for q, v in values.items()}
                           for name, values in self.bodies.items()},
                "points": {name: {q: _column(clean(v, scales[q])) for q, v in values.items()}
                           for name, values in self.points.items()}}

    def scales(self) -> dict[str, float]:
        """Each quantity's scale: its largest magnitude, or what the motion makes it at least
        (ω² for α; ω·size for speeds; (α + ω²)·size for accelerations), so that round-off in
        a quantity that is zero throughout is still seen as round-off."""
        top: dict[str, float] = {}
        for group in (self.bodies, self.points):
            for values in group.values():
                for q, v in values.items():
                    biggest = float(np.nanmax(np.abs(v))) if np.isfinite(v).any() else 0.0
                    top[q] = max(top.get(q, 0.0), biggest)
        w, size = top.get("omega", 0.0), top.get("position", 0.0)
        top["alpha"] = max(top.get("alpha", 0.0), w * w)
        top["velocity"] = max(top.get("velocity", 0.0), w * size)
        top["acceleration"] = max(top.get("acceleration", 0.0), top["alpha"] * size,
                                  top["velocity"] ** 2 / size if size else 0.0)
        return top

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
        with open(path, "w", newline="", encoding="utf-8") as f:
            self.write_csv(f)

    def write_csv(self, f: Any) -> None:
        """The CSV of `to_csv`, written to the text stream `f` (opened with newline="")."""
        scales = self.scales()
        cols = [(h, clean(v, scales.get(h.rpartition(".")[2].rsplit("_", 1)[0], 0.0)))
                for h, v in self.columns()]
        table = np.column_stack([v for _, v in cols]) if cols else np.zeros((0, 0))
        writer = csv.writer(f)
        writer.writerow([h for h, _ in cols])
        for row in table.tolist():
            writer.writerow(["" if math.isnan(x) else repr(x) for x in row])


def clean(values: np.ndarray, scale: float) -> np.ndarray:
    """12 significant digits; magnitudes below 1e-12·scale set to 0 (NaN stays NaN)."""
    values = np.asarray(values, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        magnitude = np.abs(values)
        digits = 11 - np.floor(np.log10(np.where(magnitude > 0, magnitude, 1.0)))
        factor = 10.0 ** digits
        out = np.round(values * factor) / factor
    out = np.where(magnitude <= 1e-12 * scale, 0.0, out)
    return out + 0.0


def _column(values: np.ndarray) -> list:
    """A JSON list with NaN rows as null (a bad row is NaN in every component)."""
    out = values.tolist()
    if values.ndim == 1:
        return [None if x != x else x for x in out]
    return [None if row[0] != row[0] else row for row in out]
