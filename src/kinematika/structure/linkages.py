"""The classical linkages recognised in a decomposed mechanism: four-bar and slider-crank.

A four-bar is a driven crank followed by one RRR dyad closing on the frame; a slider-crank
is a driven crank followed by one RRP dyad whose slider runs on the frame. For these the
textbook gives more than a sweep: Grashof's classification (which links can turn fully),
the transmission angle, and the limit positions (crank and coupler in line), found here
in closed form from the drawn lengths.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional, Union

from ..model.model import Joint, Model
from .assur import Group


@dataclass
class LimitPosition:
    """A limit of the output's travel: crank and coupler in line (`extended` or `folded`)."""

    name: str
    crank: float          # crank rotation from the drawn position, degrees in [0, 360)
    output: float         # rocker rotation (degrees) or slider travel (length) from the drawn position


@dataclass
class FourBar:
    """A four-bar found in the mechanism: its four lengths (ground O2O4, crank O2A, coupler AB,
    rocker O4B, from the drawing), the bodies in each role, the drawn pin positions and their
    names, and its limit positions; it answers Grashof's classification and whether the crank
    turns fully."""

    ground: float
    crank: float
    coupler: float
    rocker: float
    bodies: dict[str, str]                          # role -> body name
    points: dict[str, tuple]                        # O2, A, B, O4 (drawn)
    names: dict[str, str] = field(default_factory=dict)   # O2, A, B, O4 -> point names
    limits: list[LimitPosition] = field(default_factory=list)

    kind = "four-bar"

    @property
    def grashof(self) -> str:
        """Grashof's classification, naming which link is the shortest."""
        lengths = {"ground": self.ground, "crank": self.crank, "coupler": self.coupler,
                   "rocker": self.rocker}
        s, l = min(lengths.values()), max(lengths.values())
        rest = sum(lengths.values()) - s - l
        gap = (s + l) - rest
        if abs(gap) <= 1e-9 * l:
            return "change point (s + l = p + q): the linkage can fold into a line"
        if gap > 0:
            return "non-Grashof (s + l > p + q): triple rocker, no link turns fully"
        shortest = min(lengths, key=lengths.__getitem__)
        return {"ground": "Grashof double crank (drag link): crank and rocker both turn fully",
                "crank": "Grashof crank-rocker: the crank turns fully, the rocker oscillates",
                "coupler": "Grashof double rocker: only the coupler turns fully",
                "rocker": "Grashof rocker-crank: the output turns fully, the input oscillates",
                }[shortest]

    @property
    def crank_turns(self) -> bool:
        """The input can make full turns (crank-rocker or drag link)."""
        lengths = [self.ground, self.crank, self.coupler, self.rocker]
        s, l = min(lengths), max(lengths)
        return s + l <= sum(lengths) - s - l + 1e-9 * l and min(self.ground, self.crank) == s

    def summary(self, drawn: Optional[dict[str, float]] = None) -> list[str]:
        """Lines for the summary of `kinematika sweep`: the lengths, Grashof's classification,
        the limit positions and, when the crank turns fully and both limits exist, the time
        ratio of the rocker's strokes, the larger crank angle between the limits over the
        smaller. With the `drawn` angles θ of the crank and the rocker (from the x axis), a
        limit position gives their angles θ there; else the turns from the drawing."""
        out = [f"four-bar: ground {self.ground:.6g}, crank {self.crank:.6g}, coupler "
               f"{self.coupler:.6g}, rocker {self.rocker:.6g}", f"  {self.grashof}"]
        for lim in self.limits:
            if drawn and "rocker" in drawn:
                out.append(f"  limit position ({lim.name}): crank at θ = {drawn['crank'] + lim.crank:.4g} "
                           f"deg, rocker at θ = {drawn['rocker'] + lim.output:.4g} deg")
            else:
                out.append(f"  limit position ({lim.name}): crank at {lim.crank:.4g} deg from the drawn "
                           f"position, rocker at {lim.output:+.4g} deg")
        if len(self.limits) == 2 and self.crank_turns:
            a = (self.limits[1].crank - self.limits[0].crank) % 360.0
            ratio = max(a, 360 - a) / min(a, 360 - a) if 0 < a < 360 else float("nan")
            out.append(f"  time ratio of the rocker's strokes: {ratio:.4g}")
        return out


@dataclass
class SliderCrank:
    """A slider-crank found in the mechanism: crank length r, connecting rod l and offset e of
    the slider's line from the crank pivot, the bodies in each role, the drawn points and the
    slider's direction, and its limit positions."""

    crank: float
    rod: float
    offset: float                                   # of the slider's line from the crank pivot
    bodies: dict[str, str]
    points: dict[str, tuple]                        # O, A, B (drawn)
    direction: tuple                                # the slider's path (unit)
    names: dict[str, str] = field(default_factory=dict)   # O, A, B -> point names
    limits: list[LimitPosition] = field(default_factory=list)

    kind = "slider-crank"

    @property
    def crank_turns(self) -> bool:
        """Whether the crank can make full turns: r + |e| ≤ l."""
        return self.crank + abs(self.offset) <= self.rod * (1 + 1e-12)

    @property
    def stroke(self) -> Optional[float]:
        """The slider's stroke between its dead points, √((l + r)² − e²) − √((l − r)² − e²);
        None when the crank cannot turn fully."""
        if not self.crank_turns:
            return None
        e2 = self.offset ** 2
        return math.sqrt((self.rod + self.crank) ** 2 - e2) - math.sqrt((self.rod - self.crank) ** 2 - e2)

    def summary(self, drawn: Optional[dict[str, float]] = None) -> list[str]:
        """Lines for the summary of `kinematika sweep`: the lengths and offset, whether the
        crank turns fully, the stroke, and the limit positions (the crank's angle θ when its
        `drawn` one is given, else its turn from the drawing; the slider's travel)."""
        turns = ("the crank turns fully (r + |e| <= l)" if self.crank_turns else
                 "the crank cannot turn fully (r + |e| > l): it rocks between dead points")
        out = [f"slider-crank: crank {self.crank:.6g}, connecting rod {self.rod:.6g}, offset "
               f"{self.offset:.6g}", f"  {turns}"]
        if self.stroke is not None:
            out.append(f"  stroke {self.stroke:.6g}")
        for lim in self.limits:
            crank = (f"crank at θ = {drawn['crank'] + lim.crank:.4g} deg" if drawn else
                     f"crank at {lim.crank:.4g} deg from the drawn position")
            out.append(f"  limit position ({lim.name}): {crank}, slider at {lim.output:+.6g} from its "
                       "drawn position")
        return out


Linkage = Union[FourBar, SliderCrank]


def identify(model: Model, groups: Optional[list[Group]], points: dict[str, tuple],
             directions: dict[str, tuple]) -> Optional[Linkage]:
    """The four-bar or slider-crank `model` is, with its limit positions; else None.

    `points` are the drawn coordinates, `directions` the unit `along` of prismatic joints.
    """
    if not groups or len(groups) != 2 or groups[0].kind != "input" or model.dimension != 2:
        return None
    first, dyad = groups
    crank_joint = model.joint(first.joints[0])
    if (first.letters != "R" or dyad.kind not in ("RRR", "RRP") or len(dyad.bodies) != 2
            or dyad.known != [first.bodies[0], model.frame]):
        return None          # e.g. an inverted slider-crank (RPR): its middle pair has no point
    j1, j2, j3 = (model.joint(j) for j in dyad.joints)
    o, a, b = points[_pin(crank_joint)], points[_pin(j1)], points[_pin(j2)]
    bodies = {"crank": first.bodies[0], "coupler": dyad.bodies[0], "output": dyad.bodies[1]}
    if dyad.kind == "RRR":
        o4 = points[_pin(j3)]
        fb = FourBar(math.dist(o, o4), math.dist(o, a), math.dist(a, b), math.dist(b, o4), bodies,
                     {"O2": o, "A": a, "B": b, "O4": o4},
                     {"O2": _pin(crank_joint), "A": _pin(j1), "B": _pin(j2), "O4": _pin(j3)})
        fb.limits = _four_bar_limits(fb)
        return fb
    u = directions[j3.id]                     # RRP: the slider's guide on the frame
    n = (-u[1], u[0])
    offset = (b[0] - o[0]) * n[0] + (b[1] - o[1]) * n[1]
    sc = SliderCrank(math.dist(o, a), math.dist(a, b), offset, bodies, {"O": o, "A": a, "B": b}, u,
                     {"O": _pin(crank_joint), "A": _pin(j1), "B": _pin(j2)})
    sc.limits = _slider_limits(sc)
    return sc


def _pin(joint: Joint) -> str:
    """The point a revolute joint (an R of the groups' letters) turns about: its `at`."""
    assert joint.at is not None, f"{joint.where}: a revolute joint has its point"
    return joint.at


def transmission_angle(linkage: Linkage, result: Any) -> Any:
    """The transmission angle over a sweep's rows, in degrees.

    Four-bar: the angle at B between the coupler (B→A) and the rocker (B→O4), 0–180°
    (90° is best; near 0° or 180° the rocker is hard to drive). Slider-crank: the angle
    between the connecting rod and the normal to the slider's path, 0–90° (90° best).
    """
    import numpy as np

    coupler = linkage.bodies["coupler"]
    a = result.points[f"{linkage.names['A']}@{coupler}"]["position"]
    b = result.points[f"{linkage.names['B']}@{coupler}"]["position"]
    ba = a - b
    if isinstance(linkage, FourBar):
        o4 = result.points[f"{linkage.names['O4']}@{linkage.bodies['output']}"]["position"]
        bo = o4 - b
        cos = (ba * bo).sum(axis=1) / (np.linalg.norm(ba, axis=1) * np.linalg.norm(bo, axis=1))
        return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    u = linkage.direction
    n = np.array([-u[1], u[0]])
    cos = np.abs(ba @ n) / np.linalg.norm(ba, axis=1)
    return np.degrees(np.arccos(np.clip(cos, 0.0, 1.0)))


def _angle(v: tuple) -> float:
    return math.degrees(math.atan2(v[1], v[0]))


def _four_bar_limits(fb: FourBar) -> list[LimitPosition]:
    """Crank and coupler in line: |O2B| = coupler ± crank, B on the drawn side of O2O4."""
    o2, a, b, o4 = fb.points["O2"], fb.points["A"], fb.points["B"], fb.points["O4"]
    g = (o4[0] - o2[0], o4[1] - o2[1])
    # the drawn branch: the side of AB that O4 is on; in line, that is the side of O2O4 B is on
    side = 1.0 if ((o4[0] - a[0]) * (b[1] - a[1]) - (o4[1] - a[1]) * (b[0] - a[0])) >= 0 else -1.0
    crank0, rocker0 = _angle((a[0] - o2[0], a[1] - o2[1])), _angle((b[0] - o4[0], b[1] - o4[1]))
    out = []
    for name, reach, along in (("extended", fb.coupler + fb.crank, 1.0),
                               ("folded", fb.coupler - fb.crank, -1.0)):
        if reach <= 0:
            continue
        # B at `reach` from O2 and `rocker` from O4
        d = fb.ground
        x = (reach ** 2 - fb.rocker ** 2 + d ** 2) / (2 * d)
        h2 = reach ** 2 - x ** 2
        if h2 < 0:
            continue
        ux, uy = g[0] / d, g[1] / d
        h = side * math.sqrt(h2)
        bx, by = o2[0] + x * ux - h * uy, o2[1] + x * uy + h * ux
        crank = _angle((along * (bx - o2[0]), along * (by - o2[1])))
        rocker = _angle((bx - o4[0], by - o4[1]))
        out.append(LimitPosition(name, (crank - crank0) % 360.0, _wrap180(rocker - rocker0)))
    return out


def _slider_limits(sc: SliderCrank) -> list[LimitPosition]:
    o, a, b = sc.points["O"], sc.points["A"], sc.points["B"]
    u, e = sc.direction, sc.offset
    n = (-u[1], u[0])
    s0 = (b[0] - o[0]) * u[0] + (b[1] - o[1]) * u[1]
    side = 1.0 if (b[0] - a[0]) * u[0] + (b[1] - a[1]) * u[1] >= 0 else -1.0   # the drawn branch
    crank0 = _angle((a[0] - o[0], a[1] - o[1]))
    out = []
    for name, reach, along in (("extended", sc.rod + sc.crank, 1.0), ("folded", sc.rod - sc.crank, -1.0)):
        if reach <= abs(e):
            continue
        s = side * math.sqrt(reach ** 2 - e ** 2)
        bx, by = o[0] + s * u[0] + e * n[0], o[1] + s * u[1] + e * n[1]
        crank = _angle((along * (bx - o[0]), along * (by - o[1])))
        out.append(LimitPosition(name, (crank - crank0) % 360.0, s - s0))
    return out


def _wrap180(x: float) -> float:
    return (x + 180.0) % 360.0 - 180.0
