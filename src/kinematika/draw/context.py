"""What drawing a scene into marks needs (`Context`): the scene, the view and the reach, and
the marks drawn so far; what a joint's symbol asks of its figure (`joints.symbols`). The
drawing functions of the bodies (`bodies`), the marks (`marks`) and the vectors (`vectors`)
receive it from `picture`."""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

from ..joints.symbols import Mark, ring
from .geometry import Box, clip_line
from .scene import Scene
from .style import LABEL_SIZE


class Context:
    """What drawing a scene needs: the scene, the view and the reach, whether it is a still
    figure (not an animation's frame or the page's moving figure), whether labels and
    English words are shown and the language of numbers; it collects the marks drawn."""

    def __init__(self, scene: Scene, view: Box, still: bool = True, labels: bool = True,
                 words: bool = True, lang: Optional[str] = None,
                 reach: Optional[Box] = None) -> None:
        self.scene, self.view, self.still = scene, view, still
        self.reach = reach or view
        self.labels, self.words, self.lang = labels, words, lang
        self.size = scene.size
        self.frame = scene.frame.name
        self.dim = scene.dim
        self.marks: list[Mark] = []
        self.owner: Optional[str] = None      # the body being drawn: the outlines `avoid` keeps are its

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

    def avoid(self, *polyline: Any, weight: float = 1.0, radius: float = 0.0, bar: bool = False) -> None:
        """Keep labels off the polyline through these points (a single point too); `weight`
        says how bad covering it is (arrows and marks more than bars), `radius` (points) how
        far around each point the drawing reaches; drawn while a body is (`owner`), it is
        that body's outline (`bar`: its bar), which that body's name may reach across and
        no other label's leader crosses (`draw.labels`)."""
        owner = self.owner
        role = "bar" if bar else "outline"
        self.add("clear", [np.asarray(p, dtype=float) for p in polyline], avoid=weight,
                 radius=radius, zorder=0, **({"group": f"{role}:{owner}"} if owner else {}))

    def area(self, *polygon: Any) -> None:
        """The region the body being drawn (`owner`) covers, a closed polygon through these
        points (a wheel's disc, a plate; a ring's band as its outer circle then its inner one
        backwards): another body's name or vector value may not sit on it (`draw.labels`,
        `LabelBoard.area`). Nothing is painted."""
        if self.owner:
            self.add("clear", [np.asarray(p, dtype=float) for p in polygon], avoid=0.0, zorder=0,
                     group=f"area:{self.owner}")

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


def moving_centroid(scene: Scene, view: Box) -> Any:
    """The centroid of the moving bodies' points (where "away from the mechanism" starts), or
    the view's centre when nothing moves."""
    pts = [p for b in scene.bodies.values() if not b.frame for p in b.points.values()]
    return np.mean(pts, axis=0) if pts else view.centre
