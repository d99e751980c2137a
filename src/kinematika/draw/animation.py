"""The motion over a sweep as an animation (GIF, or MP4 when ffmpeg is installed).

The mechanism is painted once, as in a still figure, with every body's artists placed by
a transform of its own; each frame only updates those transforms from the sweep's arrays
(a body turns by its `angle` about one of its points, which moves to its swept position),
the traced paths of chosen points (coupler curves) and the live vectors. Arrows keep one
scale per kind over the whole motion. Rows the sweep could not assemble are skipped.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Optional

import numpy as np
from matplotlib.transforms import Affine2D

from ..errors import KinematikaError
from .canvas import Canvas
from .geometry import Box
from .options import DrawOptions
from .scene import Scene, VectorView
from .names import plain, value_text
from .style import INK, KIND_COLOURS, PATH, POINT_LABEL, TITLE_SIZE
from .geometry import perpendicular, unit
from ..joints.symbols import Mark
from .paint import artist
from .vectors import arrow_for, arrow_mark, side_shifts
from matplotlib.transforms import offset_copy

FORMATS = ("gif", "mp4")
DPI = 100            # an 8-inch frame is 800 pixels wide
WIDTH = 8.0          # inches
LABEL = 11.0         # points: names and vector labels in frames


def animate(source: Any, path: Path | str, joint: Optional[str] = None, by: Optional[float] = None,
            steps: Optional[int] = None, frames: int = 120, fps: int = 20,
            options: Optional[DrawOptions] = None, trace: Optional[list[str]] = None,
            skip_bad: bool = False, progress: bool | Callable[[int, int], None] = False) -> Path:
    """Render the sweep of `source` (path, tree, Model or Mechanism) to `path` (.gif/.mp4).

    `frames`: at most this many frames (rows are subsampled evenly); `options`: which live
    vectors (velocities, accelerations; the model's relative vectors are not swept);
    `trace`: the points whose paths are drawn (default: the asked points, else every
    moving point); `progress`: True for a rich bar, or a callable (done, total).
    """
    path = Path(path)
    writer = _writer(path, fps)
    film = Film.of(source, joint, by, steps, frames, options, trace, skip_bad)
    return _render(film, writer, path, progress)


def animate_rows(model: Any, result: Any, path: Path | str, frames: int = 120, fps: int = 20,
                 options: Optional[DrawOptions] = None, trace: Optional[list[str]] = None,
                 progress: bool | Callable[[int, int], None] = False) -> Path:
    """Render rows of a motion already computed (`result`, a sweep's or a simulation's, of the
    `Model` `model`) to `path` (.gif/.mp4), as `animate` renders a sweep."""
    path = Path(path)
    writer = _writer(path, fps)
    return _render(Film.of_rows(model, result, frames, options, trace), writer, path, progress)


def _render(film: "Film", writer: Any, path: Path, progress: bool | Callable[[int, int], None]) -> Path:
    from ..sweep.progress import reporter

    report = reporter(progress, len(film.rows), "rendering frames")
    with writer.saving(film.fig, str(path), film.fig.dpi):
        for i, k in enumerate(film.rows):
            film.show(k)
            writer.grab_frame()
            report(i + 1)
    report(None)
    return path


@dataclass
class Film:
    """A painted mechanism ready to be shown at any row of its sweep."""

    fig: Any
    motion: "Motion"
    rows: list[int]
    title: Any
    axis: tuple = (None, None)     # the driving crank's absolute angle per row, and its name

    @classmethod
    def of(cls, source: Any, joint: Optional[str] = None, by: Optional[float] = None,
           steps: Optional[int] = None, frames: int = 120, options: Optional[DrawOptions] = None,
           trace: Optional[list[str]] = None, skip_bad: bool = False) -> "Film":
        """The film of `source` (a path, tree, Model or Mechanism; planar only): the model swept
        (`joint`, `by`, `steps`), at most `frames` of its rows kept, its drawn instant painted
        once with `options`' live vectors and the `trace`d points' paths, ready for `show`."""
        from ..model.source import as_model
        from ..sweep import run_sweep

        model = as_model(source)
        _planar(model)
        result = run_sweep(model, joint=joint, by=by, steps=steps, skip_bad=skip_bad)
        return cls.of_rows(model, result, frames, options, trace)

    @classmethod
    def of_rows(cls, model: Any, result: Any, frames: int = 120, options: Optional[DrawOptions] = None,
                trace: Optional[list[str]] = None) -> "Film":
        """The film of rows already computed (`result`: a sweep's or a simulation's) of the
        planar `Model` `model`, its drawn instant painted once (see `of`)."""
        from ..sweep.posing import solved as solve
        from .figure import new_figure
        from .build import build_scene

        _planar(model)
        options = options or DrawOptions()
        rows = _rows(result, frames)
        sol = solve(model)
        still = DrawOptions(**{**options.__dict__, "velocities": False, "accelerations": False,
                               "centres": False, "curvature": False})
        scene = build_scene(sol.inst, sol, still)
        motion = Motion(scene, result, _live_vectors(sol, options, result))
        view = motion.box(rows).grow(0.08 * scene.size)
        fig, ax = new_figure(view.grow(0.06 * scene.size), DrawOptions(width=options.width), 0)
        fig.set_dpi(DPI)
        cv = Canvas(ax, scene, view, labels=False, placement=motion.transform, lang=options.lang)
        _paint(cv)
        motion.attach(cv, trace)
        title = fig.text(0.5, 1 - 0.3 / fig.get_figheight(), "", ha="center", va="center",
                         fontsize=TITLE_SIZE, weight="bold", color=INK)
        return cls(fig, motion, rows, title, _reading(result))

    def show(self, k: int) -> None:
        """The mechanism at row `k` of the sweep."""
        self.motion.show(k)
        name = self.motion.scene.name.replace("$", r"\$")
        self.title.set_text(f"{name}  —  {self.coordinate(k)}")

    def coordinate(self, k: int) -> str:
        """The driving coordinate at row k as a student reads it: `crank θ = 230°`."""
        x, label = self.axis
        if label is not None:
            return f"{label} θ = {float(x[k]) % 360:.0f}°"
        if getattr(self.motion.result, "unit", "deg") == "s":
            return _coordinate(self.motion.result, k)
        return f"{self.motion.result.joint} {_coordinate(self.motion.result, k)}"


def _planar(model: Any) -> None:
    if model.dimension != 2:
        raise KinematikaError("schema", "animate-planar", "dimension")


def _reading(result: Any) -> tuple[Any, Optional[str]]:
    """(values, body) of the driving crank's absolute angle, or (None, None) when the sweep
    does not turn a body from the frame."""
    from ..sweep.angles import body_angle, driving_body
    from .plots import _moving_bodies

    angles = {n: a for n in _moving_bodies(result) if (a := body_angle(result, n)) is not None}
    driver = driving_body(result, angles)
    return (angles[driver], driver) if driver is not None else (None, None)


def _writer(path: Path, fps: int) -> Any:
    from matplotlib import animation

    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ValueError(f"cannot write {path.name!r}: give a .gif or .mp4 file")
    if fmt == "gif":
        return animation.PillowWriter(fps=fps)
    if not animation.writers.is_available("ffmpeg"):
        raise KinematikaError("output", "ffmpeg-missing", str(path))
    return animation.FFMpegWriter(fps=fps, bitrate=1800)


def _rows(result: Any, frames: int) -> list[int]:
    """The rows to show: assembled ones, at most `frames`, evenly spread."""
    ok = np.flatnonzero(np.asarray(result.ok, dtype=bool))
    if not len(ok):
        raise KinematikaError("assembly", "sweep-none-assembled")
    if len(ok) <= frames:
        return [int(k) for k in ok]
    pick = np.unique(np.round(np.linspace(0, len(ok) - 1, frames)).astype(int))
    return [int(ok[i]) for i in pick]


def _coordinate(result: Any, k: int) -> str:
    unit = getattr(result, "unit", "deg")
    x = float(result.coordinate[k])
    if unit == "s":
        return f"t = {x:.4g} s"
    return f"{x:+.0f}°" if unit == "deg" else f"{x:+.4g}"


def _paint(cv: Canvas) -> None:
    """The mechanism as a moving figure draws it (no labels, no results): each body's marks
    placed through its transform."""
    from .paint import paint
    from .picture import picture

    paint(cv, picture(cv.scene, cv.view, still=False, labels=False, results=False))


def _live_vectors(sol: Any, options: DrawOptions, result: Any) -> list[VectorView]:
    """The vectors to animate: those a still figure would show, absolute ones only."""
    from .results import vector_targets
    from .scene import vector_label

    out = []
    for kind in ("velocity", "acceleration"):
        flag = options.velocities if kind == "velocity" else options.accelerations
        for ref, rel in vector_targets(sol, options, kind, flag):
            if rel not in (None, sol.model.frame) or str(ref) not in result.points:
                continue
            label = vector_label(kind, sol.model, ref, None)
            out.append(VectorView(kind, str(ref), label, np.zeros(2), np.zeros(2), 0.0, ""))
    return out


class Motion:
    """Moves a painted scene through the sweep's rows."""

    def __init__(self, scene: Scene, result: Any, live: list[VectorView]) -> None:
        self.scene, self.result, self.live = scene, result, live
        self.places = {name: Affine2D() for name in scene.bodies}
        self.anchors = {name: self._anchor(name) for name in scene.bodies}
        self.largest = {kind: self._largest(kind) for kind in KIND_COLOURS}
        self.traces: list[tuple[Any, np.ndarray]] = []
        self.arrows: list[tuple[VectorView, Any, Any]] = []
        self.lang: Optional[str] = None       # the live labels' numbers (the canvas's language)

    def transform(self, body: str) -> Affine2D:
        """The placement of `body` at the row shown (an affine map from its drawn pose), which
        its artists are drawn through."""
        return self.places[body]

    def _anchor(self, body: str) -> Optional[str]:
        """The material point a body's placement follows (its first swept point)."""
        b = self.scene.bodies[body]
        if b.frame:
            return None
        for name in b.points:
            if f"{name}@{body}" in self.result.points:
                return name
        return None

    def _largest(self, kind: str) -> float:
        values = [np.linalg.norm(self.result.points[v.ref][kind], axis=1) for v in self.live
                  if v.kind == kind]
        return float(np.nanmax(np.concatenate(values))) if values else 0.0

    def positions(self, ref: str) -> np.ndarray:
        """Material point `ref`'s page positions over the sweep's rows: (rows, 2)."""
        return np.asarray(self.result.points[ref]["position"], dtype=float)[:, :2]

    def box(self, rows: list[int]) -> Box:
        """Everything the animation will show, over the rows drawn."""
        pts = [np.array(self.scene.box[:2]), np.array(self.scene.box[2:])]
        for ref in self.result.points:
            pts += list(self.positions(ref)[rows])
        for k in rows:
            pts += [a.end for a in self._arrows(k)]
        return Box.around(p for p in pts if np.all(np.isfinite(p)))

    def _arrows(self, k: int) -> list:
        out = []
        for v in self.live:
            data = self.result.points[v.ref]
            value = np.asarray(data[v.kind][k], dtype=float)
            out.append(arrow_for(v, self.largest[v.kind], self.scene.size,
                                 origin=self.positions(v.ref)[k], value=value,
                                 magnitude=float(np.linalg.norm(value))))
        return out

    def attach(self, cv: Canvas, trace: Optional[list[str]]) -> None:
        """Add the traced paths and the live arrows (with their labels) to the axes."""
        ax = cv.ax
        self.lang = cv.lang
        for ref in self._traced(trace):
            path = self.positions(ref)
            ax.plot(*path.T, lw=1.0, ls=(0, (3, 2)), color=POINT_LABEL, alpha=0.55, zorder=1)
            line, = ax.plot([], [], lw=1.6, color=PATH, alpha=0.9, zorder=2,
                            gid=f"trace:{ref}")
            self.traces.append((line, path))
        for v in self.live:
            patch = artist(Mark("arrow", np.array([[0.0, 0.0], [1.0, 0.0]]),
                                **arrow_mark(arrow_for(v, 1.0, 1.0, np.zeros(2), np.array([1.0, 0.0]), 1.0),
                                             v.key)))
            ax.add_patch(patch)
            text = ax.annotate("", xy=(0, 0), xytext=(4, 4), textcoords="offset points",
                               fontsize=LABEL, color=KIND_COLOURS[v.kind], zorder=20,
                               annotation_clip=False,
                               bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none",
                                         alpha=0.7))
            self.arrows.append((v, patch, text))
        named: set[str] = set()
        for body in self.scene.bodies.values():
            tf = cv.transform(None if body.frame else body.name)
            for name, p in body.points.items():
                if name in named or name in body.passing:
                    continue
                named.add(name)
                ax.annotate(plain(name), xy=p, xycoords=tf, xytext=(6, 6),
                            textcoords="offset points", fontsize=LABEL, color=POINT_LABEL,
                            weight="bold", zorder=19)

    def _traced(self, trace: Optional[list[str]]) -> list[str]:
        """The swept keys (P@body) of the traced points; fixed points are not traced."""
        model_points = {key.partition("@")[0]: key for key in self.result.points}
        if trace:
            keys = []
            for name in trace:
                key = name if name in self.result.points else model_points.get(name)
                if key is None:
                    raise KinematikaError("schema", "trace-unknown-point", "--trace", point=name)
                keys.append(key)
        else:
            keys = [v.ref for v in self.live] or list(self.result.points)
        out: list = []
        seen: list = []
        for key in keys:
            path = self.positions(key)
            spread = np.nanmax(np.linalg.norm(path - path[0], axis=1)) if len(path) else 0.0
            if spread <= 1e-9 * self.scene.size:
                continue
            if any(np.allclose(path, q, equal_nan=True) for q in seen):
                continue
            seen.append(path)
            out.append(key)
        return out

    def show(self, k: int) -> None:
        """Place every body, trace and arrow at row `k`."""
        for body, place in self.places.items():
            anchor = self.anchors[body]
            if anchor is None:
                continue
            p0 = self.scene.bodies[body].points[anchor]
            pk = self.positions(f"{anchor}@{body}")[k]
            theta = math.radians(float(self.result.bodies[body]["angle"][k]))
            place.clear().translate(-p0[0], -p0[1]).rotate(theta).translate(pk[0], pk[1])
        for line, path in self.traces:
            line.set_data(path[: k + 1, 0], path[: k + 1, 1])
        arrows = self._arrows(k)
        for (v, patch, text), arrow, shift in zip(self.arrows, arrows,
                                                  side_shifts(arrows, self.scene.size)):
            patch.set_positions(tuple(arrow.start), tuple(arrow.end))
            patch.set_visible(arrow.drawn)
            d = unit(arrow.end - arrow.start)
            n = perpendicular(d) * shift
            ax = patch.axes
            patch.set_transform(offset_copy(ax.transData, fig=ax.figure, x=n[0], y=n[1],
                                            units="points"))
            magnitude = float(np.linalg.norm(self.result.points[v.ref][v.kind][k]))
            text.xy = tuple(arrow.end)
            _beyond(text, d, 1.0 if v.kind == "velocity" else -1.0)
            text.set_text(f"{v.label} = {value_text(magnitude, self.lang)}")
            text.set_visible(arrow.drawn)


def _beyond(text: Any, d: np.ndarray, side: float) -> None:
    """Put a tip's label just beyond the tip, a little to one side of the arrow (velocities
    left, accelerations right: one point's two labels do not meet when its arrows line up)."""
    if not np.any(d):
        d = np.array([1.0, 0.0])
    off = 6.0 * d + 7.0 * side * perpendicular(d)
    c, s = off / np.linalg.norm(off)
    text.xyann = tuple(off)
    text.set_ha("left" if c > 0.3 else "right" if c < -0.3 else "center")
    text.set_va("bottom" if s > 0.3 else "top" if s < -0.3 else "center")
