"""Bodies that are neither a bar nor a plate, drawn as the course notes draw them.

A plate (the hull of a body's points) is right for a linkage's ternary link, wrong for a
body that carries wheels at its points (a planet carrier is arms, a vehicle's chassis a
frame of bars) and for any body in space (a shaft with its fork is two bars, not a
triangle). Those are drawn as their skeleton: the shortest tree of bars joining their
points. In a spherical linkage (every moving body turns about one point O, its points on a
sphere about O, as the spherical four-bar) each link is drawn instead as great-circle arcs
on that sphere, between the points where its joints' axes pierce it. A Hooke joint is
drawn as the textbook draws it: two shafts ending in forks (yokes) and the cross between.
"""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

ARC_SAMPLES = 25


def add_skeletons(scene: Any, inst: Any, num: Any, geos: dict) -> None:
    """Set `skeleton` on the bodies drawn as trees of bars or as arcs (and `scene.sphere`)."""
    model = inst.model
    xyz = {name: num.vector(p) for name, p in inst.points.items()}
    hooke = _hooke(model, xyz, geos, num) if scene.dim == 3 else None
    if hooke is not None:
        for name, lines in hooke.items():
            scene.bodies[name].skeleton = [np.array([num.proj(p) for p in line]) for line in lines]
        return
    sphere = _sphere(model, xyz) if scene.dim == 3 else None
    if sphere is not None:
        centre, radius = sphere
        c = xyz[centre]
        scene.sphere = (num.proj(c), radius)
        for name, body in scene.bodies.items():
            vertices = _sphere_vertices(model, name, centre, c, radius, xyz, geos, num)
            body.skeleton = [np.array([num.proj(p) for p in _arc(c, radius, a, b)])
                             for a, b in _tree(vertices)]
        return
    for name, body in scene.bodies.items():
        if body.frame:
            continue
        pts = [xyz[p] for p in model.bodies[name].points if p not in body.passing]
        pts = _distinct(pts, 1e-9 * max(scene.size, 1e-300))
        if len(pts) >= 3 and (scene.dim == 3 or _carrier(scene, model, name)):
            body.skeleton = [np.array([num.proj(a), num.proj(b)]) for a, b in _tree(pts)]


def _carrier(scene: Any, model: Any, name: str) -> bool:
    """Whether a planar body carries wheels at two or more of its points: other bodies'
    circles centred there (a planet carrier, a bicycle frame), or knife-edge wheels."""
    body = scene.bodies[name]
    centres = [s.center for other in scene.bodies.values() if other.name != name
               for s in other.shapes if s.kind == "circle" and not s.ring]
    at_centres = sum(any(np.linalg.norm(p - c) <= 1e-9 * scene.size for c in centres)
                     for p in body.points.values())
    wheels = sum(j.kind.knife_edge and name in (j.a, j.b) for j in model.joints)   # knife edges
    return at_centres + wheels >= 2


def _tree(pts: list[np.ndarray]) -> list[tuple[np.ndarray, np.ndarray]]:
    """The edges of the shortest tree joining `pts` (Prim)."""
    if len(pts) < 2:
        return []
    inside, edges = [0], []
    rest = list(range(1, len(pts)))
    while rest:
        i, j = min(((i, j) for i in inside for j in rest),
                   key=lambda e: float(np.linalg.norm(pts[e[0]] - pts[e[1]])))
        edges.append((pts[i], pts[j]))
        inside.append(j)
        rest.remove(j)
    return edges


def _distinct(pts: list[np.ndarray], tol: float) -> list[np.ndarray]:
    out: list[np.ndarray] = []
    for p in pts:
        if all(np.linalg.norm(p - q) > tol for q in out):
            out.append(p)
    return out


# spherical linkages -------------------------------------------------------------------------
def _sphere(model: Any, xyz: dict) -> Optional[tuple[str, float]]:
    """(centre point, radius) when every moving body carries one point and every other point
    lies at one distance from it; else None."""
    moving = [b for name, b in model.bodies.items() if name != model.frame]
    if len(moving) < 3:
        return None
    common = set(moving[0].points).intersection(*(b.points for b in moving[1:]))
    for centre in common:
        c = xyz[centre]
        dists = [float(np.linalg.norm(p - c)) for name, p in xyz.items() if name != centre]
        if dists and min(dists) > 0 and max(dists) - min(dists) <= 1e-6 * max(dists):
            return centre, float(np.mean(dists))
    return None


def _sphere_vertices(model: Any, body: str, centre: str, c: np.ndarray, radius: float,
                     xyz: dict, geos: dict, num: Any) -> list[np.ndarray]:
    """Where the body meets the sphere: its points off the centre, and the points where the
    axes of its joints through the centre pierce the sphere (on the side of the joined
    bodies' points)."""
    out = [xyz[p] for p in model.bodies[body].points if p != centre]
    for j in model.joints:
        geo = geos.get(j.id)
        if body not in (j.a, j.b) or geo is None or geo.axis is None:
            continue
        axis = num.vector(geo.axis)
        if np.linalg.norm(axis) == 0:
            continue
        axis = axis / np.linalg.norm(axis)
        near = [xyz[p] for b in (j.a, j.b) for p in model.bodies[b].points if p != centre]
        mean = np.mean(near, axis=0) - c if near else axis
        out.append(c + radius * (axis if float(axis @ mean) >= 0 else -axis))
    return _distinct(out, 1e-9 * radius)


def _arc(c: np.ndarray, radius: float, a: np.ndarray, b: np.ndarray) -> list[np.ndarray]:
    """The shorter great-circle arc from a to b on the sphere (c, radius)."""
    u, v = (a - c) / radius, (b - c) / radius
    angle = float(np.arccos(np.clip(u @ v, -1.0, 1.0)))
    if angle < 1e-9:
        return [a, b]
    return [c + radius * (np.sin((1 - t) * angle) * u + np.sin(t * angle) * v) / np.sin(angle)
            for t in np.linspace(0, 1, ARC_SAMPLES)]


# Hooke (Cardan) joints ----------------------------------------------------------------------
YOKE_DEPTH = 0.4        # the fork's prongs, as a fraction of the cross's arm
SHAFT_LENGTH = 1.8      # each shaft from the centre, in arms


def _hooke(model: Any, xyz: dict, geos: dict, num: Any) -> Optional[dict]:
    """The bodies of a Hooke joint as a textbook draws them, or None: a cross held at one
    point O by two revolute joints with perpendicular axes to two shafts, each shaft turning
    in a bearing at O. Each shaft is a bar along its bearing ending in a fork (yoke) whose
    prongs hold the cross's arm; the cross is its two arms."""
    revolute = [j for j in model.joints if j.kind.pins and not j.kind.ball and j.at and geos.get(j.id) is not None
                and geos[j.id].axis is not None]
    for cross in model.bodies:
        own = [j for j in revolute if cross in (j.a, j.b)]
        if cross == model.frame or len(own) != 2 or len({j.at for j in own}) != 1:
            continue
        centre = own[0].at
        units = [_unit(num.vector(geos[j.id].axis)) for j in own]
        arms = [a for a in units if a is not None]
        if len(arms) < 2 or abs(float(arms[0] @ arms[1])) > 1e-6:
            continue
        shafts = [j.b if j.a == cross else j.a for j in own]
        found = [next((b for b in revolute if b.at == centre and {b.a, b.b} == {s, model.frame}), None)
                 for s in shafts]
        bearings = [b for b in found if b is not None]
        if model.frame in shafts or len(bearings) < len(shafts):
            continue
        c = xyz[centre]
        arm = max(float(np.linalg.norm(xyz[p] - c)) for s in shafts for p in model.bodies[s].points)
        out = {cross: [np.array([c - arm * a, c + arm * a]) for a in arms]}
        for shaft, bearing, a in zip(shafts, bearings, arms):
            s = _unit(num.vector(geos[bearing.id].axis))
            if s is None:
                return None
            away = [xyz[p] - c for p in model.bodies[shaft].points if float(np.linalg.norm(xyz[p] - c)) > 0]
            side = float(np.sign(sum(float(v @ s) for v in away)) or 1.0)
            s = side * s
            base = c + YOKE_DEPTH * arm * s
            out[shaft] = [np.array([base, c + SHAFT_LENGTH * arm * s]),
                          np.array([c + arm * a, base + arm * a, base - arm * a, c - arm * a])]
        return out
    return None


def _unit(v: np.ndarray) -> Optional[np.ndarray]:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else None
