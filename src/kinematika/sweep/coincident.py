"""Points of several bodies at one place, row by row: the coincident points of a sweep.

A point name listed by bodies that move differently there (a pin and the slot it slides
in, a drawn contact) is one place at every row (`Model.place_owner`'s material point);
the other bodies' points of that name are their points coinciding with it, whose motion
follows from the body's: v = v_Q + ω × QP, a = a_Q + α × QP + ω × (ω × QP), with Q the
body's own material point of that name. So every row is what `solve` answers for the
mechanism drawn there, and `move` equals the sweep's last row.
"""
from __future__ import annotations

import numpy as np

from ..model.model import Model


def coincide(model: Model, bodies: dict[str, dict[str, np.ndarray]],
             points: dict[str, dict[str, np.ndarray]]) -> None:
    """Replace, in `points`, each non-owning carrier's tracks by its coincident point's."""
    for name in model.points:
        classes = model.motion_classes(name, model.carriers(name))
        if len(classes) < 2:
            continue
        owner = model.place_owner(name)
        place = points[f"{name}@{owner}"]["position"]
        for members in classes:
            if owner in members:
                continue
            body = members[0]
            own = points[f"{name}@{body}"]
            tracks = _coincident(own, place, bodies[body]["omega"], bodies[body]["alpha"], model.dimension)
            for b in members:
                points[f"{name}@{b}"] = tracks


def _coincident(own: dict[str, np.ndarray], place: np.ndarray, omega: np.ndarray, alpha: np.ndarray,
                dim: int) -> dict[str, np.ndarray]:
    r = np.asarray(place, dtype=float) - np.asarray(own["position"], dtype=float)
    w = np.asarray(omega, dtype=float)
    al = np.asarray(alpha, dtype=float)
    if dim == 2:
        w, al = np.broadcast_to(w, r.shape[:1])[:, None], np.broadcast_to(al, r.shape[:1])[:, None]
        kr = np.stack([-r[:, 1], r[:, 0]], axis=1)
        v = own["velocity"] + w * kr
        a = own["acceleration"] + al * kr - (w * w) * r
    else:
        w, al = np.broadcast_to(w, r.shape), np.broadcast_to(al, r.shape)
        v = own["velocity"] + np.cross(w, r)
        a = own["acceleration"] + np.cross(al, r) + np.cross(w, np.cross(w, r))
    return {"position": np.array(place, dtype=float), "velocity": v, "acceleration": a}
