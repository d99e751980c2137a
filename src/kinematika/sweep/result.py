"""The motion over a range of a driven joint's coordinate, as numpy arrays.

Row k is increment k: the drawn configuration is row 0. A row that could not be solved
(`--skip-bad`) holds NaN in every array and False in `ok`; the JSON and CSV views write it
as null / an empty cell.

A motion followed through limit positions (`limit_positions`) runs its coordinate back at
each: `limits` lists the coordinates where it turned, `travel` the distance travelled by
the input up to each row (equal steps), and the JSON gains `"limits"`, the CSV and the
columnar files a `travel_*` and a `limit_*` column.
"""
from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterator, Optional

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
    limits: list[float] = field(default_factory=list)    # limit positions met, in order
    limit_travel: list[float] = field(default_factory=list)   # the input's travel at each
    travel: Optional[np.ndarray] = None   # (N,) the input's travel up to each row (with limits)
    closed: bool = False                  # back at the drawn configuration after its limits
    warnings: list = field(default_factory=list)   # KinematikaWarning: swept at draw_at numbers, ...

    def __len__(self) -> int:
        return len(self.coordinate)

    def to_json(self) -> dict[str, Any]:
        """The contract's JSON: coordinate, bodies and points, one entry per row (null if bad).

        Numbers are given to 12 significant digits, with round-off (below 1e-12 of the
        largest value of the same quantity) written as 0, as `solve` does.
        """
        scales = self.scales()
        out = {"coordinate": _column(clean(self.coordinate, np.abs(self.coordinate).max(initial=0.0))),
               "bodies": {name: {q: _column(clean(v, scales[q])) for q, v in values.items()}
                          for name, values in self.bodies.items()},
               "points": {name: {q: _column(clean(v, scales[q])) for q, v in values.items()}
                          for name, values in self.points.items()}}
        if self.limits:
            out["limits"] = self._limits_column().tolist()
        if self.warnings:                       # an extension, as `solve`'s: what to know of the rows
            out["warnings"] = [w.as_json() for w in self.warnings]
        return out

    def _limits_column(self) -> np.ndarray:
        """The limit positions, written as the coordinate is (12 digits)."""
        values = np.asarray(self.limits, dtype=float)
        return clean(values, max(np.abs(self.coordinate).max(initial=0.0), np.abs(values).max(initial=0.0)))

    def json_chunks(self) -> Iterator[bytes]:
        """The JSON of `to_json` as UTF-8 pieces, each column written by orjson straight from
        its numpy array (no Python float per number); a column shared by several material
        points (bodies joined by a revolute) is cleaned and written once."""
        import orjson

        scales = self.scales()
        bad = None if self.ok.all() else ~self.ok
        uses: dict[int, int] = {}
        for values in self.points.values():
            for v in values.values():
                uses[id(v)] = uses.get(id(v), 0) + 1
        written: dict[int, bytes] = {}

        def column(v: np.ndarray, scale: float) -> bytes:
            key = id(v)
            text = written.pop(key, None)
            if text is None:
                text = _json_column(clean(v, scale), bad)
            uses[key] = uses.get(key, 1) - 1
            if uses[key] > 0:
                written[key] = text
            return text

        coordinate = self.coordinate
        yield b'{"coordinate":' + _json_column(clean(coordinate, np.abs(coordinate).max(initial=0.0)), bad)
        for part, group in ((b',"bodies":{', self.bodies), (b'},"points":{', self.points)):
            yield part
            for i, (name, values) in enumerate(group.items()):
                yield (b"," if i else b"") + orjson.dumps(name) + b":{"
                for k, (q, v) in enumerate(values.items()):
                    yield (b"," if k else b"") + orjson.dumps(q) + b":" + column(v, scales[q])
                yield b"}"
        yield b"}"
        if self.limits:
            yield b',"limits":' + orjson.dumps(self._limits_column().tolist())
        if self.warnings:
            yield b',"warnings":' + orjson.dumps([w.as_json() for w in self.warnings])
        yield b"}"

    def scales(self) -> dict[str, float]:
        """Each quantity's scale: its largest magnitude, or what the motion makes it at least
        (ω² for α; ω·size for speeds; (α + ω²)·size for accelerations), so that round-off in
        a quantity that is zero throughout is still seen as round-off."""
        top: dict[str, float] = {}
        seen: set[int] = set()            # material points joined by a revolute share arrays
        for group in (self.bodies, self.points):
            for values in group.values():
                for q, v in values.items():
                    if id(v) in seen:
                        continue
                    seen.add(id(v))
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
        if self.limits and self.travel is not None:
            cols += [(f"travel_{self.unit}", self.travel), (f"limit_{self.unit}", self.passed())]
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

    def passed(self) -> np.ndarray:
        """Per row, the limit position passed since the row before (NaN where none was; the
        last one if several were)."""
        out = np.full(len(self.coordinate), np.nan)
        if not self.limits or self.travel is None:
            return out
        at = np.asarray(self.limit_travel, dtype=float)
        rows = np.searchsorted(self.travel, at, side="left")
        keep = rows < len(out)
        out[rows[keep]] = np.asarray(self.limits, dtype=float)[keep]
        return out

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
        for start in range(0, len(table), CSV_ROWS):      # a chunk of Python floats at a time
            writer.writerows([["" if x != x else repr(x) for x in row]      # x != x: NaN
                              for row in table[start:start + CSV_ROWS].tolist()])

    def to_npz(self, path: str | Path) -> None:
        """The CSV's columns as numpy arrays in one .npz file (raw values; bad rows NaN), with
        `ok`: `np.load(path)["B@coupler.velocity_x"]`."""
        columns: dict[str, Any] = {h: np.ascontiguousarray(v) for h, v in self.columns()}
        np.savez(path, ok=self.ok, **columns)

    def to_parquet(self, path: str | Path) -> None:
        """The CSV's columns in a Parquet file (raw values; bad rows null), with `ok`; needs
        pyarrow (`pip install 'kinematika[columnar]'`)."""
        from ..errors import Said
        from ..extras import need

        pa = need("pyarrow", Said("writing-parquet"), "-o", "columnar")
        pq = need("pyarrow.parquet", Said("writing-parquet"), "-o", "columnar")
        names, arrays = ["ok"], [pa.array(self.ok)]
        for header, values in self.columns():
            names.append(header)
            arrays.append(pa.array(np.ascontiguousarray(values), from_pandas=True))   # NaN -> null
        pq.write_table(pa.Table.from_arrays(arrays, names=names), path)


CSV_ROWS = 2048     # rows turned into text at once: memory stays that of the arrays

with np.errstate(over="ignore"):
    _POW10 = np.power(10.0, np.arange(-400, 401, dtype=float))    # 10**k as numpy computes it (inf past 308)


def clean(values: np.ndarray, scale: float) -> np.ndarray:
    """12 significant digits; magnitudes below 1e-12·scale set to 0 (NaN stays NaN).

    x rounded at 10**(11 − ⌊log₁₀|x|⌋), the power read from a table, in a few passes over
    the column without temporaries of Python objects (a sweep may have millions of rows).
    """
    values = np.asarray(values, dtype=float)
    magnitude = np.abs(values)
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = np.log10(magnitude)
    np.floor(exponent, out=exponent)
    np.copyto(exponent, 0.0, where=~np.isfinite(exponent))       # 0, NaN, inf: any power will do
    index = exponent.astype(np.int64)
    np.subtract(411, index, out=index)                            # 11 − ⌊log₁₀|x|⌋, from 10**-400
    factor = _POW10.take(index, mode="clip")
    out = np.multiply(values, factor)
    np.rint(out, out=out)
    with np.errstate(invalid="ignore"):
        np.divide(out, factor, out=out)
    np.copyto(out, values, where=np.isnan(out) & np.isfinite(values))   # below 1e-297: as it is
    np.copyto(out, 0.0, where=magnitude <= 1e-12 * scale)
    np.copyto(out, np.nan, where=np.isinf(values))               # as before: no infinite numbers
    np.add(out, 0.0, out=out)                                     # no -0.0
    return out


def _json_column(values: np.ndarray, bad: np.ndarray | None) -> bytes:
    """One column as JSON: orjson reads the array itself; bad rows (NaN) are null."""
    import orjson

    if bad is None:
        return orjson.dumps(np.ascontiguousarray(values), option=orjson.OPT_SERIALIZE_NUMPY)
    return orjson.dumps(_column(values))


def _column(values: np.ndarray) -> list:
    """A JSON list with NaN rows as null (a bad row is NaN in every component)."""
    out = values.tolist()
    if values.ndim == 1:
        return [None if x != x else x for x in out]
    return [None if row[0] != row[0] else row for row in out]


def dead_points(coordinate: np.ndarray, ok: np.ndarray, singular: np.ndarray,
                refine: Optional[Callable[[float, float], float]] = None) -> list[float]:
    """Where the motion stops being possible: singular rows, and at each edge of a gap the
    last row that could be assembled (or, with `refine(good, bad)`, the edge found between)."""
    if ok.all():
        return []
    out = [float(x) for x in coordinate[singular]]
    edges = np.flatnonzero(ok[:-1] != ok[1:])
    for k in edges:
        good, bad = (k, k + 1) if ok[k] else (k + 1, k)
        if not singular[bad]:            # a singular row is itself the dead point
            edge = float(coordinate[good])
            out.append(refine(edge, float(coordinate[bad])) if refine else edge)
    return sorted(set(out))
