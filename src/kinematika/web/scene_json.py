"""A drawing's `Scene` as JSON data, for the page to paint as SVG.

Everything is in page coordinates of the model (floats; y up). What the page paints is the
`picture`: the figure's marks as `draw.picture` makes them for `draw` (outlines, hatches,
symbols, dots, arrows, texts, with their colours, widths, layers and the bodies they move
with) and the box it frames first. Beside it, what the figure shows as data (the bodies
with their points, shapes and reference lines, the joints, the arrows, the instant centres
with their Aronhold–Kennedy lines, the curvature circles, the notes), which the page's
legend, table and plot read. Labels, written for matplotlib's mathtext
(`$v_{\\mathrm{B}}$`), become runs of plain text and subscripts.
"""
from __future__ import annotations

import dataclasses
import math
import re
from typing import Any, Optional

import numpy as np

from ..draw import style
from ..draw.paint import hatching, marker_outline
from ..draw.scene import BodyView, Scene, numbering, numbering_note
from ..joints.symbols import HATCH_BAND, Mark
from ..sweep.angles import reference_line


def scene_data(scene: Scene, twin: Optional[Scene] = None, options: Any = None,
               frame: Optional[list] = None) -> dict[str, Any]:
    """The scene as plain data (lists of floats, texts, runs for labels) with its `picture`
    drawn with `options` for the box `frame` (x0, y0, x1, y1; by default the one it lays out);
    for a 3D model with its depth `twin` (`depth_twin`), also the model coordinates of what
    is drawn."""
    data = {
        "name": scene.name, "dimension": scene.dim, "size": scene.size, "box": list(scene.box),
        "view": scene.projection.view,
        "bodies": {name: {"number": b.number, "colour": b.colour, "frame": b.frame,
                          "points": {p: _floats(xy) for p, xy in b.points.items()},
                          "shapes": [_plain(s) for s in b.shapes],
                          "skeleton": [_floats(line) for line in getattr(b, "skeleton", [])],
                          "passing": list(getattr(b, "passing", [])),
                          "reference": _reference(scene, b)}
                   for name, b in scene.bodies.items()},
        "joints": [_plain(j) for j in scene.joints],
        "picture": picture_data(scene, options, twin, frame),
        "vectors": [{**_plain(v), "key": v.key, "label": runs(v.label)} for v in scene.vectors],
        "marks": [{**_plain(m), "label": runs(m.label)} for m in scene.marks],
        "kennedy": [_plain(k) for k in scene.kennedy],
        "normals": [_plain(k) for k in getattr(scene, "normals", [])],
        "sphere": _value(getattr(scene, "sphere", None)),
        "numbered": bool(getattr(scene, "numbered", False)),
        "curvatures": [{**_plain(c), "label": runs(c.label)} for c in scene.curvatures],
        "axes": [_plain(a) for a in scene.axes],
        "notes": [_unmath(n) for n in scene.notes if n != numbering_note(scene, getattr(options, "lang", None))],
        "numbering": [list(pair) for pair in numbering(scene)] if getattr(scene, "numbered", False) else [],
        "style": STYLE,
    }
    if twin is not None:
        _add_model_coordinates(data, scene, twin)
    return data


def _reference(scene: Scene, body: BodyView) -> Optional[dict[str, Any]]:
    """A planar moving body's reference line (`sweep.angles.reference_line`: the one its angle
    θ is measured along in the table, the plot and the command line's sweep) and its angle at
    the drawn position; None for the frame, a body with one place, or a 3D model."""
    if body.frame or scene.dim != 2:
        return None
    line = reference_line(body.points, scene.frame.points)
    if line is None:
        return None
    return {"from": line.start, "to": line.end, "grounded": line.grounded,
            "angle": line.angle(body.points)}


DASH_DOT = [6.4, 1.6, 1.0, 1.6]      # matplotlib's dash-dot, in line widths


def picture_data(scene: Scene, options: Any = None, twin: Optional[Scene] = None,
                 shown: Optional[list] = None) -> dict[str, Any]:
    """The figure's marks as the page paints them (`draw.figure.zoomable`: laid out as a
    still figure, its infinite lines reaching past the frame) for the box `shown`, else the
    box it frames first, and that box; in a 3D scene, each moving mark's points also in space
    (`xyz`), which the page turns with the sweep's rotations."""
    from ..draw.figure import zoomable
    from ..draw.geometry import Box

    marks, frame = zoomable(scene, options, None if shown is None else Box(*shown))
    lift = _lifter(scene, twin) if twin is not None else None
    return {"marks": [mark_data(m, lift) for m in marks if m.kind != "clear"],
            "frame": [frame.xmin, frame.ymin, frame.xmax, frame.ymax]}


def mark_data(m: Mark, lift: Any = None) -> dict[str, Any]:
    """One mark as the page receives it: what every mark has, and the fields of its kind
    (a text's words as runs, a dash-dot as its dash lengths, a dot's marker as matplotlib's
    outline of it)."""
    out: dict[str, Any] = {"kind": m.kind, "points": _floats(m.points), "colour": m.colour,
                           "fill": m.fill, "width": m.width, "zorder": m.zorder, "body": m.moves_with}
    extra: dict[str, Any] = {"size": m.size, "alpha": m.alpha if m.alpha != 1.0 else None, "hatch": m.hatch or None,
             "dash": DASH_DOT if m.dash is True else (list(m.dash) if m.dash else None),
             "r": m.r or None, "band": m.band or None, "cap": m.cap or None, "join": m.join or None,
             "shape": m.shape if m.kind == "dot" else None,
             "outline": marker_outline(m.shape) if m.kind == "dot" else None, "head": m.head or None,
             "shift": m.shift or None, "halo": m.halo or None, "id": m.gid or None, "group": m.group or None,
             "layer": m.layer or None, "still": m.still or None}
    if m.kind == "text":
        extra.update(text=runs(m.text), priority=m.priority, weight=m.weight, style=m.style,
                     prefer=None if m.prefer is None else _floats(m.prefer),
                     side=None if m.side is None else _floats(m.side), radius=m.radius)
    if m.about:
        extra["about"] = {k: runs(v) if k in ("symbol", "name") else _value(v) for k, v in m.about.items()}
    if lift is not None and m.moves_with is not None:
        extra["xyz"] = lift(m)
    out.update({k: v for k, v in extra.items() if v is not None})
    return out


def _lifter(scene: Scene, twin: Scene) -> Any:
    """For a 3D scene and its depth twin: a mark's points in space, when each is a point, a
    skeleton's vertex, a shape's vertex or centre, or a joint's place of the body it moves
    with (else None); a label's anchor at the depth of those nearest to it."""
    P = scene.projection.matrix
    towards = np.cross(P[0], P[1])
    tol = 1e-7 * scene.size
    known: dict[tuple, list] = {}
    depths: dict[Optional[str], list] = {}

    def note(body: Optional[str], page: Any, deep: Any) -> None:
        for q, d in zip(np.asarray(page, dtype=float).reshape(-1, 2), np.asarray(deep, dtype=float).reshape(-1, 2)):
            if np.all(np.isfinite(q)) and np.all(np.isfinite(d)):
                known[(body, *np.round(q / tol).astype(int))] = space(q, d[0])
                depths.setdefault(body, []).append((q, d[0]))

    def space(q: np.ndarray, depth: float) -> list:
        return _floats(q[0] * P[0] + q[1] * P[1] + depth * towards)

    for name, b in scene.bodies.items():
        t = twin.bodies[name]
        for p, xy in b.points.items():
            note(name, xy, t.points[p])
        for line, deep in zip(b.skeleton, t.skeleton):
            note(name, line, deep)
        for shape, deep_shape in zip(b.shapes, t.shapes):
            if shape.vertices is not None and deep_shape.vertices is not None:
                note(name, shape.vertices, deep_shape.vertices)
            if shape.center is not None and deep_shape.center is not None:
                note(name, shape.center, deep_shape.center)
    for joint, deep_joint in zip(scene.joints, twin.joints):
        if joint.at is not None and deep_joint.at is not None:
            for body in (joint.a, joint.b):
                note(body, joint.at, deep_joint.at)

    def between(body: Optional[str], q: np.ndarray) -> Optional[list]:
        """`q` at the depth of the body's known places, weighted by nearness (a bar's middle
        at the mean of its ends')."""
        known_here = depths.get(body, [])
        if not known_here:
            return None
        w = np.array([1 / max(float(np.linalg.norm(p - q)), tol) ** 2 for p, _ in known_here])
        return space(q, float(w @ np.array([d for _, d in known_here]) / w.sum()))

    def lift(m: Mark) -> Optional[list]:
        pts = np.asarray(m.points, dtype=float)
        out = [known.get((m.moves_with, *np.round(q / tol).astype(int))) if np.all(np.isfinite(q)) else None
               for q in pts]
        if m.kind == "text" and out[0] is None:
            out = [between(m.moves_with, pts[0])]
        return out if all(x is not None for x in out) else None
    return lift


def depth_twin(scene: Scene, sol: Any, options: Any) -> Scene:
    """The scene of a 3D model built again with a map whose first page coordinate is the
    depth along the view (the same bodies, arcs, shapes and joints, in the same order):
    with it, every drawn coordinate has its point in space, which the page turns with the
    sweep's rotations so that the figure follows the slider."""
    from ..draw.projection import Projection
    from ..draw.build import build_scene

    P = scene.projection.matrix
    towards = np.cross(P[0], P[1])
    return build_scene(sol.inst, None, options, solver=getattr(sol, "solver", None),
                       proj=Projection(np.vstack([towards, P[0]]), "depth"))


def _add_model_coordinates(data: dict, scene: Scene, twin: Scene) -> None:
    """`…_xyz` twins of the drawn coordinates (points, skeletons, shapes' vertices and
    centres, joints' places) and the `projection` (2 × 3) that maps them to the page."""
    P = scene.projection.matrix
    towards = np.cross(P[0], P[1])

    def lift(page: Any, depth: Any) -> Any:
        q, d = np.asarray(page, dtype=float), np.asarray(depth, dtype=float)
        return _floats(q[..., :1] * P[0] + q[..., 1:2] * P[1] + d[..., :1] * towards)

    data["projection"] = _floats(P)
    for name, b in scene.bodies.items():
        t, out = twin.bodies[name], data["bodies"][name]
        out["points_xyz"] = {p: lift(xy, t.points[p]) for p, xy in b.points.items()}
        out["skeleton_xyz"] = [lift(line, deep) for line, deep in zip(b.skeleton, t.skeleton)]
        for shape, deep, plain in zip(b.shapes, t.shapes, out["shapes"]):
            if shape.vertices is not None:
                plain["vertices_xyz"] = lift(shape.vertices, deep.vertices)
            if shape.center is not None:
                plain["center_xyz"] = lift(shape.center, deep.center)
    for joint, deep_joint, plain in zip(scene.joints, twin.joints, data["joints"]):
        if joint.at is not None and deep_joint.at is not None:
            plain["at_xyz"] = lift(joint.at, deep_joint.at)


STYLE = {"velocity": style.VELOCITY, "acceleration": style.ACCELERATION, "centre": style.CENTRE,
         "curvature": style.CURVATURE, "ground": style.GROUND, "ink": style.INK,
         "point_label": style.POINT_LABEL, "path": style.PATH, "longest": style.LONGEST, "shortest": style.SHORTEST,
         "hatch_band": HATCH_BAND, "hatch": hatching()}


def runs(label: str) -> list[dict[str, str]]:
    """A mathtext label as runs of text and subscripts:
    `$v_{\\mathrm{B}{\\in}3/2}$ = 9.25` -> `[{"t": "v"}, {"sub": "B∈3/2"}, {"t": " = 9.25"}]`."""
    out: list[dict[str, str]] = []
    label = label.replace("\\$", "\0")               # an escaped dollar is a dollar
    for k, part in enumerate(label.split("$")):
        if not part:
            continue
        if k % 2 == 0:
            out.append({"t": part.replace("\0", "$")})
            continue
        m = _SUBSCRIPTED.match(part)
        if m:
            out += [{"t": _latex_text(m.group(1))}, {"sub": _latex_text(m.group(2))}]
        else:
            out.append({"t": _latex_text(part)})
    return out


_SUBSCRIPTED = re.compile(r"^([^_{}\\]+|\\[A-Za-z]+)_\{(.*)\}$")
_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "theta": "θ",
          "lambda": "λ", "mu": "μ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "φ",
          "varphi": "φ", "psi": "ψ", "omega": "ω", "Omega": "Ω", "Gamma": "Γ", "Delta": "Δ",
          "Theta": "Θ", "Phi": "Φ", "cdot": "·", "in": "∈", "times": "×"}
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _latex_text(text: str) -> str:
    """Plain Unicode for the small LaTeX the figures write (names, short formulas)."""
    text = text.replace("\\ ", " ").replace("\\_", "\1").replace("\\left", "").replace("\\right", "")
    for _ in range(4):       # innermost first: \frac{a}{b}, \sqrt{x}, \mathrm{x}, x^{2}
        text = re.sub(r"\\frac\{([^{}]*)\}\{([^{}]*)\}", r"(\1)/(\2)", text)
        text = re.sub(r"\\sqrt\{([^{}]*)\}", r"√(\1)", text)
        text = re.sub(r"\\(?:mathrm|mathit|operatorname|text)\{([^{}]*)\}", r"\1", text)
        text = re.sub(r"\^\{?(-?[0-9]+)\}?", lambda m: m.group(1).translate(_SUPERSCRIPT), text)
    text = re.sub(r"\\([A-Za-z]+)", lambda m: _GREEK.get(m.group(1), m.group(1)), text)
    text = re.sub(r"\((\w)\)", r"\1", text)         # (a)/(b) of single letters: a/b
    return text.replace("{", "").replace("}", "").replace("\1", "_").replace("\0", "$")


def _unmath(text: str) -> str:
    """Plain text from a note or label written for matplotlib."""
    return "".join(r.get("t", r.get("sub", "")) for r in runs(text))


def _plain(obj: Any) -> dict[str, Any]:
    """A scene dataclass as a dict of JSON values (arrays as lists; NaN and inf as null)."""
    return {f.name: _value(getattr(obj, f.name)) for f in dataclasses.fields(obj)}


def _value(v: Any) -> Any:
    if isinstance(v, np.ndarray):
        return _floats(v)
    if isinstance(v, (list, tuple)):
        return [_value(x) for x in v]
    if isinstance(v, (float, np.floating)):
        return float(v) if math.isfinite(v) else None
    if isinstance(v, (np.integer, np.bool_)):
        return v.item()
    return v


def _floats(arr: Any) -> Any:
    """An array as nested lists of floats, non-finite values as null."""
    values = np.asarray(arr, dtype=float)
    if values.ndim == 0:
        x = float(values)
        return x if math.isfinite(x) else None
    return [_floats(x) for x in values] if values.ndim > 1 else \
        [float(x) if math.isfinite(x) else None for x in values]
