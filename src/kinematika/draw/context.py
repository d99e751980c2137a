"""What drawing a scene into marks needs (`Context`): the scene, the view and the reach, and
the marks drawn so far; what a joint's symbol asks of its figure (`joints.symbols`). The
drawing functions of the bodies (`bodies`), the marks (`marks`) and the vectors (`vectors`)
receive it from `picture`."""
from __future__ import annotations

import itertools
from typing import Any, Optional

import numpy as np
from matplotlib.path import Path

from ..joints.symbols import Mark, ring
from .geometry import Box, clip_line, points_to_data
from .scene import Scene
from .style import LABEL_SIZE


class Context:
    """What drawing a scene needs: the scene, the view and the reach, whether it is a still
    figure (not an animation's frame or the page's moving figure), whether labels and
    English words are shown and the language of numbers; it collects the marks drawn."""

    def __init__(self, scene: Scene, view: Box, still: bool = True, labels: bool = True,
                 words: bool = True, lang: Optional[str] = None,
                 reach: Optional[Box] = None, per_point: Optional[float] = None) -> None:
        self.scene, self.view, self.still = scene, view, still
        self.per_point = per_point            # drawing units a point on the page, when the figure's scale is known
        self.reach = reach or view
        self.labels, self.words, self.lang = labels, words, lang
        self.size = scene.size
        self.frame = scene.frame.name
        self.dim = scene.dim
        self.marks: list[Mark] = []
        self.owner: Optional[str] = None      # the body being drawn: the outlines `avoid` keeps are its
        self.arrows: list[tuple[np.ndarray, np.ndarray]] = []   # the vectors' arrows to draw (start, end): what a wheel's cross-hair leaves room for

    def pt(self, points: float) -> float:
        """`points` on the page in the drawing's units (`geometry.points_to_data`)."""
        return points_to_data(points, self.view, self.per_point)

    # what a joint's symbol asks of its figure (`joints.symbols`) ------------------------
    def centroid(self) -> np.ndarray:
        """The centroid of the moving bodies' points (where "away from the mechanism" starts)."""
        return moving_centroid(self.scene, self.view)

    def points(self, body: str) -> list:
        """The page positions of `body`'s points."""
        return list(self.scene.bodies[body].points.values())

    def joined(self, body: str, but: str = "") -> list:
        """The page places where the scene's joints other than `but` hold `body`: their pins
        (`at`) and contacts."""
        return [np.asarray(p, dtype=float) for j in self.scene.joints if j.id != but and body in (j.a, j.b)
                for p in (j.at, j.contact) if p is not None]

    def keep_out(self) -> list[np.ndarray]:
        """Closed outlines ((n, 2) polygons) a fixed guide stops short of: each moving body's
        circles and closed curves (a cam's profile; not its pitch curve, which a roller's
        centre is on)."""
        out = []
        for body in self.scene.bodies.values():
            if body.name == self.frame:
                continue
            for sh in body.shapes:
                if sh.kind == "circle" and sh.arc is not None:
                    out.append(sh.outline())
                elif sh.kind == "circle" and not sh.ring:
                    out.append(ring(np.asarray(sh.center, dtype=float), float(sh.radius)))
                elif sh.kind == "curve" and sh.closed and sh.role != "pitch" and sh.vertices is not None:
                    out.append(np.asarray(sh.vertices, dtype=float))
        return out

    def hub(self, p: np.ndarray) -> float:
        """The radius of the largest moving body's disc that turns about `p` (centred there;
        not a ring, not a part of a disc), 0 when none does: a fixed pivot there is the
        wheel's axle, whose support `joints.symbols.support` sets outside it."""
        tol = 1e-6 * self.size
        radii = [float(sh.radius) for body in self.scene.bodies.values() if not body.frame and not body.fixed
                 for sh in body.shapes if sh.kind == "circle" and not sh.ring and sh.arc is None
                 and np.linalg.norm(np.asarray(sh.center, dtype=float) - p) <= tol]
        return max(radii, default=0.0)

    def crowded(self, pts: Any, hub: np.ndarray) -> int:
        """How many of `pts` lie on a moving body: inside a disc or a closed outline of it
        (`keep_out`) not centred at `hub`, or on a bar between its points."""
        tol = 1e-6 * self.size
        outlines = [np.asarray(poly, dtype=float) for poly in self.keep_out()
                    if np.linalg.norm(np.mean(np.asarray(poly, dtype=float)[:-1], axis=0) - hub) > tol]
        lines: list[list[Any]] = []
        for body in self.scene.bodies.values():
            if not body.frame and not body.fixed:
                lines += [list(line) for line in body.skeleton] if body.skeleton else [list(body.points.values())]
        bars = [(a, b) for line in lines for a, b in itertools.pairwise(line)]
        near = 0.03 * self.size
        count = 0
        for q in np.asarray(pts, dtype=float):
            inside = any(Path(poly).contains_point(q) for poly in outlines if len(poly) >= 3)
            on_bar = any(_off_segment(q, np.asarray(a, dtype=float), np.asarray(b, dtype=float)) < near for a, b in bars)
            count += int(inside or on_bar)
        return count

    def clip(self, p: np.ndarray, d: np.ndarray, inset: float) -> Optional[tuple]:
        """The part of the line through `p` along `d` inside the reach shrunk by `inset`, or
        None."""
        return clip_line(p, d, self.reach.grow(-inset))

    # drawing ----------------------------------------------------------------------------
    def add(self, kind: str, points: Any, **kw: Any) -> Mark:
        """Draw a mark (labels do not keep off it unless `avoid` says so)."""
        kw.setdefault("avoid", 0.0)
        mark = Mark(kind, np.asarray(points, dtype=float).reshape(-1, 2), **kw)
        self.marks.append(mark)
        return mark

    def avoid(self, *polyline: Any, weight: float = 1.0, radius: float = 0.0, bar: bool = False,
              width: float = 0.0, centre: bool = False) -> None:
        """Keep labels off the polyline through these points (a single point too); `weight`
        says how bad covering it is (arrows and marks more than bars), `radius` (points) how
        far around each point the drawing reaches; drawn while a body is (`owner`), it is
        that body's outline (`bar`: its bar), which that body's name may reach across and
        no other label's leader crosses (`draw.labels`); `width` (points) how wide it is
        drawn, when wider than a line (a bar); `centre`: a wheel's centre line, an outline
        that a point's letter keeps off too (`draw.labels.Layout._lines_under`)."""
        owner = self.owner
        role = "bar" if bar else "centre" if centre else "outline"
        self.add("clear", [np.asarray(p, dtype=float) for p in polyline], avoid=weight,
                 radius=radius, width=width, zorder=0, **({"group": f"{role}:{owner}"} if owner else {}))

    def area(self, *polygon: Any, ground: bool = False) -> None:
        """The region the body being drawn (`owner`) covers, a closed polygon through these
        points (a wheel's disc, a plate; a ring's band as its outer circle then its inner one
        backwards): another body's name or vector value may not sit on it (`draw.labels`,
        `LabelBoard.area`); `ground`: the material beyond a fixed edge, under the ground's
        line (`LabelBoard.area`'s `ground`). Nothing is painted."""
        if self.owner:
            self.add("clear", [np.asarray(p, dtype=float) for p in polygon], avoid=0.0, zorder=0,
                     group=f"{'ground-area' if ground else 'area'}:{'+'.join(self.welded(self.owner))}")

    def welded(self, body: str) -> list[str]:
        """`body` and the moving bodies welded to it, directly or through others (one rigid
        piece: C5-E.6's sprocket on the rear wheel), in the scene's order. Their areas are
        one: the sprocket's name by its hub, on the wheel it is part of, is on no other body
        (`LabelBoard.area`); off the wheel, the only room was under the ground."""
        group, grew = {body}, True
        while grew:
            grew = False
            for j in self.scene.joints:
                if j.kind.rigid and len({j.a, j.b} & group) == 1 and self.frame not in (j.a, j.b) \
                        and not any(self.scene.bodies[b].fixed for b in (j.a, j.b)):
                    group |= {j.a, j.b}
                    grew = True
        return [name for name in self.scene.bodies if name in group]

    def label(self, anchor: Any, text: str, colour: str, priority: int, gid: str,
              prefer: Any = None, body: Optional[str] = None, group: str = "", layer: str = "",
              **kw: Any) -> None:
        """A label at `anchor`, placed by the painter clear of the others (lower `priority`
        first), towards `prefer` when given, `radius` points clear of the anchor (a marker's
        size); none when labels are off."""
        if not self.labels:
            return
        kw.setdefault("size", LABEL_SIZE)
        self.add("text", [anchor], text=text, colour=colour, priority=priority, gid=gid,
                 prefer=None if prefer is None else np.asarray(prefer, dtype=float),
                 moves_with=body, group=group, layer=layer, zorder=20, **kw)


def _off_segment(q: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """The distance from `q` to the segment ab."""
    ab = b - a
    t = float(np.clip((q - a) @ ab / max(float(ab @ ab), 1e-300), 0.0, 1.0))
    return float(np.linalg.norm(a + t * ab - q))


def moving_centroid(scene: Scene, view: Box) -> Any:
    """The centroid of the moving bodies' points (where "away from the mechanism" starts), or
    the view's centre when nothing moves."""
    pts = [p for b in scene.bodies.values() if not b.frame for p in b.points.values()]
    return np.mean(pts, axis=0) if pts else view.centre
