"""Figures of a study a designer reads at a glance: a metric's map over two parameters, two
metrics against each other with their Pareto front, and the best designs' paths over the
targets. Each reads a study's table (pandas) and writes a file matplotlib can write."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Iterable, Optional

import numpy as np

from ..errors import KinematikaError, said_of

GREY = "#c8c8c8"


def _figure(width: float = 6.4, height: float = 4.8) -> tuple[Any, Any]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt.subplots(figsize=(width, height), dpi=120)


def _save(fig: Any, path: Path) -> None:
    try:
        fig.savefig(path, bbox_inches="tight")
    except ValueError as err:                     # a format matplotlib cannot write
        raise KinematikaError("output", "cannot-write", str(path), path=str(path), reason=said_of(err)) from None
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def _column(table: Any, name: str, where: str) -> Any:
    if name not in table.columns:
        raise KinematikaError("usage", "study-no-column", where, name=name, columns=list(map(str, table.columns)))
    return table[name]


def metric_map(table: Any, x: str, y: str, metric: str, path: Path) -> None:
    """The metric over two parameters: a coloured grid (or the sampled designs as dots); designs
    that do not assemble or do not complete their cycle are grey."""
    xs = _column(table, x, "--map").to_numpy(dtype=float)
    ys = _column(table, y, "--map").to_numpy(dtype=float)
    values = _column(table, metric, "--map")
    fig, ax = _figure()
    classes = values.dtype == object or str(values.dtype).startswith(("string", "str"))
    if classes:
        _class_map(ax, xs, ys, values)
    else:
        v = values.to_numpy(dtype=float, na_value=np.nan)
        ux, uy = np.unique(xs), np.unique(ys)
        if len(ux) * len(uy) == len(v) and len(ux) > 1 and len(uy) > 1:       # a grid
            grid = np.full((len(uy), len(ux)), np.nan)
            grid[np.searchsorted(uy, ys), np.searchsorted(ux, xs)] = v
            ax.pcolormesh(ux, uy, np.isnan(grid).astype(float), cmap=_grey_map(), shading="nearest")
            mesh = ax.pcolormesh(ux, uy, np.ma.masked_invalid(grid), cmap="viridis", shading="nearest")
            if np.isfinite(grid).sum() > 3 and np.nanmax(grid) > np.nanmin(grid):
                lines = ax.contour(ux, uy, np.ma.masked_invalid(grid), colors="white", linewidths=0.6,
                                   levels=6)
                ax.clabel(lines, fontsize=7, fmt="%.3g")
        else:
            bad = ~np.isfinite(v)
            ax.scatter(xs[bad], ys[bad], s=6, color=GREY, label="no full cycle")
            mesh = ax.scatter(xs[~bad], ys[~bad], c=v[~bad], s=8, cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=metric)
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    grey = "not assembled" if classes else "does not complete its cycle"
    ax.set_title(f"{metric} over {x} and {y} (grey: {grey})", fontsize=10)
    _save(fig, path)


def _grey_map() -> Any:
    from matplotlib.colors import ListedColormap

    return ListedColormap([(1, 1, 1, 0), GREY])


def _class_map(ax: Any, xs: np.ndarray, ys: np.ndarray, values: Any) -> None:
    labels = values.astype(object).where(values.notna(), None)
    kinds = [k for k in dict.fromkeys(labels) if k is not None]
    colours = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"]
    missing = labels.isna().to_numpy()
    ax.scatter(xs[missing], ys[missing], s=10, color=GREY, marker="s", label="not assembled")
    for kind, colour in zip(kinds, colours * 3):
        mask = (labels == kind).to_numpy()
        ax.scatter(xs[mask], ys[mask], s=10, color=colour, marker="s", label=str(kind))
    ax.legend(fontsize=8, loc="best", markerscale=1.5)


def pareto_front(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Indices of the designs no other design beats in both (both minimised), by increasing a."""
    order = np.lexsort((b, a))
    front, best = [], np.inf
    for i in order:
        if b[i] < best:
            front.append(i)
            best = b[i]
    return np.array(front, dtype=int)


def pareto(table: Any, first: str, second: str, path: Path, maximize: Iterable[str] = ()) -> Any:
    """Two metrics against each other, the Pareto front (designs no other beats in both) drawn;
    returns the front's rows."""
    maximize = set(maximize)
    a = _column(table, first, "--pareto").to_numpy(dtype=float, na_value=np.nan)
    b = _column(table, second, "--pareto").to_numpy(dtype=float, na_value=np.nan)
    good = np.flatnonzero(np.isfinite(a) & np.isfinite(b))
    sa = -a[good] if first in maximize else a[good]
    sb = -b[good] if second in maximize else b[good]
    front = good[pareto_front(sa, sb)]
    fig, ax = _figure()
    ax.scatter(a[good], b[good], s=6, color="#9ab", label=f"designs ({len(good)})")
    ax.plot(a[front], b[front], "-o", color="#c0392b", ms=4, lw=1.2, label=f"Pareto front ({len(front)})")
    ax.set_xlabel(first + (" (higher is better)" if first in maximize else " (lower is better)"))
    ax.set_ylabel(second + (" (higher is better)" if second in maximize else " (lower is better)"))
    ax.legend(fontsize=8)
    ax.set_title(f"{second} against {first}", fontsize=10)
    _save(fig, path)
    return table.iloc[front]


def paths_over_targets(model: Any, designs: list[dict[str, float]], point: str, targets: Optional[np.ndarray],
                       path: Path, labels: Optional[list[str]] = None) -> None:
    """The point's path of each design (the best first, in colour, its linkage drawn at the
    drawn position), with the target points."""
    from ..model.overrides import with_parameters
    from ..sweep import run_sweep

    fig, ax = _figure(6.4, 5.6)
    colours = ["#c0392b", "#2471a3", "#27ae60", "#8e44ad", "#d68910"]
    for rank, design in enumerate(designs):
        m = with_parameters(model, {k: repr(v) for k, v in design.items()})
        result = run_sweep(m, skip_bad=True)
        ref = m.resolve_point(point)
        xy = result.points[str(ref)]["position"]
        colour = colours[rank % len(colours)]
        label = labels[rank] if labels else f"design {rank + 1}"
        ax.plot(xy[:, 0], xy[:, 1], color=colour, lw=1.6 if rank == 0 else 1.0, label=label,
                alpha=1.0 if rank == 0 else 0.7, zorder=3 if rank == 0 else 2)
        if rank == 0:
            _linkage(ax, m, result)
    if targets is not None:
        ax.plot(targets.real, targets.imag, "x", color="black", ms=8, mew=2, label="targets")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8, loc="best")
    ax.set_title(f"path of {point}: the best designs over the targets", fontsize=10)
    _save(fig, path)


def _linkage(ax: Any, model: Any, result: Any) -> None:
    """The best design at its drawn position: each body as lines between its points, pins."""
    for body in model.bodies.values():
        pts = [result.points[f"{p}@{body.name}"]["position"][0] for p in body.points]
        if len(pts) < 2 or body.name == model.frame:
            for p in pts:
                ax.plot(*p, marker="^" if body.name == model.frame else "s", color="#555", ms=7)
            continue
        loop = np.array(pts + ([pts[0]] if len(pts) > 2 else []))
        ax.fill(loop[:, 0], loop[:, 1], color="#999", alpha=0.25) if len(pts) > 2 else None
        ax.plot(loop[:, 0], loop[:, 1], "-o", color="#444", lw=2, ms=4)


def function_over_targets(model: Any, designs: list[dict[str, float]], body: str, table: np.ndarray,
                          path: Path, labels: Optional[list[str]] = None) -> None:
    """The body's rotation against the input's for each design, with the target rows."""
    from ..model.overrides import with_parameters
    from ..sweep import run_sweep

    fig, ax = _figure()
    colours = ["#c0392b", "#2471a3", "#27ae60", "#8e44ad", "#d68910"]
    for rank, design in enumerate(designs):
        m = with_parameters(model, {k: repr(v) for k, v in design.items()})
        result = run_sweep(m, skip_bad=True)
        label = labels[rank] if labels else f"design {rank + 1}"
        ax.plot(result.coordinate, result.bodies[body]["angle"], color=colours[rank % len(colours)],
                lw=1.6 if rank == 0 else 1.0, label=label)
    ax.plot(table[:, 0], table[:, 1], "x", color="black", ms=8, mew=2, label="targets")
    ax.set_xlabel("input (from the drawn position)")
    ax.set_ylabel(f"rotation of {body} (deg)")
    ax.legend(fontsize=8)
    ax.set_title(f"function generation: {body} against the input", fontsize=10)
    _save(fig, path)
