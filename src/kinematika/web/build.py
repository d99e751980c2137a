"""Building a model by hand on the page: each action is an edit of the model's text.

`apply(text, fmt, op)` reads the text into a round-trip tree (`document`), changes it, and
writes it back with its comments: placing an element of the palette (`palette.TOOLS`),
typing a dimension (`set`), choosing the input (`drive`), asking a question (`ask`),
deleting. `sketch(text, fmt)` says what the page needs to draw and select while a model is
being built, solvable or not yet: where every point is (the constructions worked out, no
motion solved), what each body carries, and the dimensions of each element that can be
typed (`properties`: where in the text, what kind of quantity, its value now).
"""
from __future__ import annotations

import json
import math
from typing import Any, Optional

import numpy as np

from ..errors import KinematikaError
from ..questions import QUESTIONS
from . import document
from .palette import Context, tool
from .rename import name_in, rename
from .tree import Tree, degrees, name_of, number

ACTIONS = ("add", "set", "delete", "drive", "ask", "rename", "name")
# the words new bodies are named with, per language (a name is an identifier in the text)
NAMES = {
    "en": {"link": "link", "slider": "slider", "wheel": "wheel", "gear": "gear", "ground": "ground"},
    "es": {"link": "barra", "slider": "corredera", "wheel": "rueda", "gear": "engranaje", "ground": "bancada"},
    "ca": {"link": "barra", "slider": "corredora", "wheel": "roda", "gear": "engranatge", "ground": "terra"},
    "eu": {"link": "barra", "slider": "irristaria", "wheel": "gurpila", "gear": "engranajea", "ground": "lurra"},
}


def apply(text: str, fmt: str, op: dict[str, Any], lang: str = "en") -> tuple[str, Optional[str]]:
    """The model's text after one action of the page (see the module's docstring), and the
    element to select then (`body:link1`, or None)."""
    if not isinstance(op, dict) or op.get("op") not in ACTIONS:
        raise KinematikaError("usage", "build-op", "op", actions=list(ACTIONS))
    tree = Tree(document.load(text, fmt), fmt)
    action, selected = op["op"], None
    if action == "add":
        picks = op.get("picks")
        t = tool(str(op.get("kind")))
        if not isinstance(picks, list) or len(picks) != len(t.picks) or \
                not all(_is_pick(p) for p in picks):
            raise KinematikaError("usage", "tool-picks", "picks", tool=t.kind, count=len(t.picks), picks=list(t.picks))
        words = NAMES.get(lang, NAMES["en"])
        _name_the_frame(tree, words["ground"])
        ctx = Context(tree, positions(text, fmt), words, op.get("values") or {})
        selected = t.write(ctx, picks)
    elif action == "set":
        for path in [op.get("path"), *(op.get("also") or [])]:
            _set(tree, path, op.get("value"), op.get("unit"))
    elif action == "delete":
        _delete(tree, str(op.get("element", "")))
    elif action == "drive":
        _drive(tree, op)
    elif action == "rename":
        selected = rename(tree, str(op.get("element", "")), op.get("to"))
    elif action == "name":
        name_in(tree, str(op.get("element", "")), op.get("lang"), op.get("text"))
    else:
        _ask(tree, str(op.get("question", "")), str(op.get("target", "")))
    return document.dump(tree.root, fmt), selected


def _name_the_frame(tree: Tree, word: str) -> None:
    """A model whose first body is being placed: its fixed body is named in the student's
    language (`frame: lurra`), unless the model names it already."""
    if word != "ground" and tree.root.get("frame") is None and not (tree.root.get("bodies") or {}):
        document.put(tree.root, "frame", word)


def _is_pick(p: Any) -> bool:
    if isinstance(p, str):
        return bool(p)
    if isinstance(p, dict):
        return isinstance(p.get("body"), str)
    return isinstance(p, list) and len(p) == 2 and all(
        isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in p)


# where things are ------------------------------------------------------------------------------
def numeric_instant(text: str, fmt: str) -> Any:
    """The model's instant with numbers (constructions worked out, nothing solved); None when
    the model cannot be read yet, or has symbols (exact formulas are the solver's work, not
    the builder's: a symbolic model is built in its text)."""
    from ..api import as_model
    from ..engine.instant import instantiate

    try:
        model = as_model(text, fmt)
        if any(p.value is None for p in model.parameters.values()):
            return None
        return instantiate(model, False)
    except KinematikaError:
        return None


def positions(text: str, fmt: str) -> dict[str, np.ndarray]:
    """Every planar point's place; {} when there is no numeric instant (see above)."""
    inst = numeric_instant(text, fmt)
    if inst is None:
        return {}
    return {name: np.array([inst.num(c) for c in xy[:2]], dtype=float)
            for name, xy in inst.points.items() if len(xy) == 2}


def sketch(text: str, fmt: str) -> dict[str, Any]:
    """What the page draws and selects while building: points (places), bodies (the points
    they carry, a circle's centre and radius), joints, drivers, questions, and the typed
    dimensions of each element. `problem` is why the places could not be worked out."""
    tree = Tree(document.load(text, fmt), fmt)
    at, problem = {}, None
    values = _Values(tree, text, fmt)
    if tree.root.get("points") and values.inst is not None:
        at = {name: np.array([values.inst.num(c) for c in xy[:2]], dtype=float)
              for name, xy in values.inst.points.items() if len(xy) == 2}
    elif tree.root.get("points"):
        problem = _problem(text, fmt)
    bodies = {}
    for name in tree.root.get("bodies") or {}:
        body = tree.root["bodies"][name]
        circle = body.get("circle") if isinstance(body, dict) else None
        circle = (circle[0] if circle else None) if isinstance(circle, list) else circle    # the first of several
        bodies[str(name)] = {"points": tree.body_points(str(name)), "frame": str(name) == tree.frame,
                             "circle": {"center": str(circle["center"]),
                                        "radius": values.number(circle["radius"])} if circle else None}
    joints = []
    for jid, j in zip(tree.joint_ids(), tree.root.get("joints") or []):
        joints.append({"id": jid, "type": str(j.get("type")), "bodies": [str(b) for b in j.get("bodies", [])],
                       "at": str(j["at"]) if isinstance(j.get("at"), str) else None,
                       "rate_unit": rate_unit(str(j.get("type")))})
    return {"points": {k: [float(v[0]), float(v[1])] for k, v in at.items()},
            "bodies": bodies, "joints": joints,
            "drivers": [document.plain(d) for d in tree.root.get("drivers") or []],
            "ask": [document.plain(a) for a in tree.root.get("ask") or []],
            "properties": properties(tree, values), "problem": problem,
            "name": str(tree.root.get("name") or ""),
            "names": document.plain(tree.root.get("names") or {})}


def offered_questions(about: Optional[str] = None) -> list[str]:
    """The kinds of question the page's builder offers (`QuestionKind.page`), of a point's or
    a body's (`about`) or all, in the registry's order."""
    return [k.name for k in QUESTIONS.values() if k.page and about in (None, k.about)]


def rate_unit(joint_type: str) -> Optional[str]:
    """The unit of a joint's rate as a driver gives it, from the kind's own coordinate (the
    joints' registry): rad/s for an angle, m/s for a length; None for a kind whose rate no
    driver can give (a gear, a weld) or an unknown type."""
    from ..joints import KINDS

    found = KINDS.get(joint_type)
    coordinate = found.coordinate if found is not None else None
    return {"angle": "rad/s", "length": "m/s"}.get(coordinate or "")


def _problem(text: str, fmt: str) -> Optional[dict[str, str]]:
    """Why there is no numeric instant: the model's error, or None (it has symbols)."""
    from ..api import as_model
    from ..engine.instant import instantiate

    try:
        model = as_model(text, fmt)
        if any(p.value is None for p in model.parameters.values()):
            return None
        instantiate(model, False)
    except KinematikaError as err:
        return err.as_json()["error"]
    return None


class _Values:
    """The numbers the text's values stand for (expressions over the parameters)."""

    def __init__(self, tree: Tree, text: str, fmt: str) -> None:
        self.tree = tree
        self.inst = numeric_instant(text, fmt)

    def number(self, raw: Any) -> Optional[float]:
        if isinstance(raw, bool):
            return None
        if isinstance(raw, (int, float)):
            return float(raw)
        if self.inst is None or not isinstance(raw, str):
            return None
        from ..expressions import ExpressionError, parse

        try:
            return self.inst.num(self.inst.value(parse(raw), "value"))
        except (KinematikaError, ExpressionError, ValueError, TypeError):
            return None


# the dimensions that can be typed ----------------------------------------------------------
def properties(tree: Tree, values: _Values) -> dict[str, list[dict[str, Any]]]:
    """Per element (`point:A`, `body:crank`, `driver:0`), its typed dimensions: a label key,
    the path of the value in the tree, the kind of quantity (`length`, `angle`, `rate`,
    `accel`, `direction`), the value now (degrees for angles) and the text written.

    One quantity has one word wherever it shows: the distance between two points of one
    body is that body's `length` (`of`: the two points) on the body and on each point; a
    slider's guide is typed on the slider only (its pin says where: a `note` row)."""
    out: dict[str, list[dict[str, Any]]] = {}
    points = tree.root.get("points") or {}
    for name in points:
        out[f"point:{name}"] = _point_properties(tree, values, str(name), points[name])
    guides: dict[str, str] = {}                     # a guide's paths -> the body it is typed on
    for name in tree.root.get("bodies") or {}:
        rows = _body_properties(tree, values, str(name))
        out[f"body:{name}"] = rows
        for row in rows:
            if row.get("guide"):
                for path in [row["path"], *row.get("also", [])]:
                    guides[json.dumps(path)] = str(name)
    for name in points:
        rows = out[f"point:{name}"]
        typed_on = {guides[json.dumps(r["path"])] for r in rows if json.dumps(r["path"]) in guides}
        if typed_on:
            out[f"point:{name}"] = [r for r in rows if json.dumps(r["path"]) not in guides] + \
                [{"label": "prop-guide-on", "kind": "note", "about": b, "path": None, "value": None,
                  "text": None, "parameter": None} for b in sorted(typed_on)]
    for i, d in enumerate(tree.root.get("drivers") or []):
        rows = []
        for key, kind in (("value", "rate"), ("rate", "rate"), ("alpha", "accel"), ("accel", "accel")):
            if key in d or (key in ("alpha",) and "omega" in d) or (key == "accel" and "joint" in d):
                rows.append(_row(values, f"driver-{key}", ["drivers", i, key], kind, d.get(key, 0)))
        out[f"driver:{i}"] = rows
    return out


def _row(values: _Values, label: str, path: list, kind: str, raw: Any) -> dict[str, Any]:
    """One typed dimension; a value that names a parameter is typed into the parameter."""
    name = name_of(raw)
    params = values.tree.parameters() or {}
    if name is not None and name in params:
        target = params[name]
        path = ["parameters", name] + (["value"] if isinstance(target, dict) else [])
        raw = target.get("value") if isinstance(target, dict) else target
    number_now = _degrees(raw) if kind == "angle" else None
    if number_now is None:
        number_now = values.number(raw)
        if kind == "angle" and number_now is not None:
            number_now = math.degrees(number_now)
    return {"label": label, "path": path, "kind": kind, "value": number_now,
            "text": None if raw is None else str(raw),
            "parameter": name if name is not None and name in params else None}


def _degrees(raw: Any) -> Optional[float]:
    """`deg(30)` as 30."""
    if isinstance(raw, str) and raw.strip().startswith("deg(") and raw.strip().endswith(")"):
        try:
            return float(raw.strip()[4:-1])
        except ValueError:
            return None
    return None


def _distance_row(tree: Tree, values: _Values, name: str, centre: Any, path: list,
                  raw: Any) -> dict[str, Any]:
    """A point's distance from `centre`: the `length` of the body that carries both (its
    `of`: the two points), else its `distance` from the centre (`about`)."""
    centre = str(centre)
    shared = any(centre in pts and name in pts for pts in map(tree.body_points, map(str, tree.bodies())))
    if shared:
        return _row(values, "prop-length", path, "length", raw) | {"of": [centre, name]}
    return _row(values, "prop-distance", path, "length", raw) | {"about": centre}


def _point_properties(tree: Tree, values: _Values, name: str, spec: Any) -> list[dict[str, Any]]:
    base = ["points", name]
    if isinstance(spec, list) and len(spec) == 2:
        return [_row(values, "prop-x", base + [0], "length", spec[0]),
                _row(values, "prop-y", base + [1], "length", spec[1])]
    if not isinstance(spec, dict):
        return []
    if "from" in spec:
        return [_distance_row(tree, values, name, spec["from"], base + ["distance"], spec["distance"]),
                _row(values, "prop-angle", base + ["angle"], "angle", spec["angle"])
                | {"of": [str(spec["from"]), name]}]
    if "circles" in spec:
        return [_distance_row(tree, values, name, c[0], base + ["circles", i, 1], c[1])
                for i, c in enumerate(spec["circles"])]
    if "circle" in spec:
        rows = [_distance_row(tree, values, name, spec["circle"][0], base + ["circle", 1], spec["circle"][1])]
        line = spec.get("line")
        if isinstance(line, dict) and isinstance(line.get("through"), list):
            rows += [_row(values, "prop-line-x", base + ["line", "through", 0], "length", line["through"][0]),
                     _row(values, "prop-line-y", base + ["line", "through", 1], "length", line["through"][1])]
        if isinstance(line, dict) and isinstance(line.get("direction"), list):
            rows.append(_direction_row(values, base + ["line", "direction"], line["direction"]))
        return rows
    if "frame" in spec:
        return [_row(values, "prop-along", base + ["at", 0], "length", spec["at"][0]),
                _row(values, "prop-across", base + ["at", 1], "length", spec["at"][1])]
    return []


def _direction_row(values: _Values, path: list, raw: Any) -> dict[str, Any]:
    dx, dy = (values.number(c) for c in raw)
    angle = math.degrees(math.atan2(dy, dx)) if dx is not None and dy is not None else None
    return {"label": "prop-direction", "path": path, "kind": "direction", "value": angle,
            "text": None, "parameter": None}


def _body_properties(tree: Tree, values: _Values, body: str) -> list[dict[str, Any]]:
    """A wheel's or gear's radius, a link's lengths and angles (where one of its points is
    placed from another), a slider's guide (`guide`: typed here only). A value two rows
    would type (a wheel's radius, which also places its centre) is typed once."""
    rows: list[dict[str, Any]] = []
    listed = tree.body_points(body)
    points = tree.root.get("points") or {}
    shape = tree.bodies().get(body)
    if isinstance(shape, dict) and isinstance(shape.get("circle"), dict):
        rows.append(_row(values, "prop-radius", ["bodies", body, "circle", "radius"], "length",
                         shape["circle"]["radius"]))
    for p in listed:
        spec = points.get(p)
        for row in _point_properties(tree, values, p, spec) if isinstance(spec, dict) else []:
            if row["label"] in ("prop-length", "prop-angle") and all(q in listed for q in row["of"]):
                rows.append(row)
    for i, j in enumerate(tree.root.get("joints") or []):
        if body != tree.frame and body in [str(b) for b in j.get("bodies", [])] and \
                isinstance(j.get("along"), list) and \
                not any(isinstance(c, str) and name_of(c) in points for c in j["along"]):
            guide = _direction_row(values, ["joints", i, "along"], j["along"]) | {"label": "prop-guide",
                                                                                   "guide": True}
            for p in listed:           # the pin's guide line, written on the point
                spec = points.get(p)
                if isinstance(spec, dict) and isinstance(spec.get("line"), dict):
                    rows += [r | {"guide": True} for r in _point_properties(tree, values, p, spec)
                             if r["label"] in ("prop-line-x", "prop-line-y")]
                    if isinstance(spec["line"].get("direction"), list):
                        guide["also"] = [["points", p, "line", "direction"]]
            rows.append(guide)
    seen: set[str] = set()
    unique = []
    for row in rows:
        key = json.dumps(row["path"])
        if key not in seen:
            seen.add(key)
            unique.append(row)
    return unique


# typing a dimension ------------------------------------------------------------------------------
def _set(tree: Tree, path: Any, value: Any, unit: Any) -> None:
    """Write `value` at `path` (a list of keys and indices). An angle (unit `deg`) is written
    `deg(...)`; a direction (unit `direction`, degrees) as its unit vector; a value that
    names a parameter changes the parameter."""
    if not isinstance(path, list) or not path or not all(isinstance(k, (str, int)) for k in path):
        raise KinematikaError("usage", "build-path", "path")
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise KinematikaError("usage", "build-value", "value")
    if isinstance(value, str) and not value.strip():
        raise KinematikaError("usage", "build-value-empty", "value")
    if isinstance(value, (int, float)) and not math.isfinite(value):
        raise KinematikaError("usage", "build-value-finite", "value")
    parent, key = _locate(tree.root, path)
    if unit == "direction":
        a = math.radians(float(value))
        parent[key] = tree.list([number(math.cos(a), 12), number(math.sin(a), 12)])
        return
    current = parent[key]
    name = name_of(current)
    params = tree.parameters() or {}
    if name is not None and name in params and path[0] != "parameters":
        target = params[name]
        if isinstance(target, dict):
            parent, key, current = target, "value", target.get("value")
        else:
            parent, key = params, name
    if unit == "deg" and isinstance(value, (int, float)):
        parent[key] = degrees(value)
    elif isinstance(value, (int, float)):
        parent[key] = number(value, 10)
    else:
        parent[key] = value.strip()


def _locate(root: Any, path: list) -> tuple[Any, Any]:
    node = root
    for k in path[:-1]:
        node = _step(node, k, path)
    _step(node, path[-1], path)
    return node, path[-1]


def _step(node: Any, key: Any, path: list) -> Any:
    try:
        if isinstance(key, int) and isinstance(node, list):
            return node[key]
        if isinstance(key, str) and isinstance(node, dict):
            return node[key]
    except (IndexError, KeyError):
        pass
    raise KinematikaError("usage", "build-nothing-at", "path", path=".".join(map(str, path)))


# deleting ---------------------------------------------------------------------------------------
def _delete(tree: Tree, element: str) -> None:
    """Delete a point, a body, a joint, a driver or a question, and what cannot stay without
    it (a body's joints and drivers; a point's joints, questions and the points built on it)."""
    kind, _, name = element.partition(":")
    if kind == "point":
        _delete_point(tree, name)
    elif kind == "body":
        _delete_body(tree, name)
    elif kind in ("joint", "driver", "ask"):
        items = tree.existing({"joint": "joints", "driver": "drivers", "ask": "ask"}[kind])
        index = tree.joint_ids().index(name) if kind == "joint" and name in tree.joint_ids() else \
            (int(name) if name.isdigit() else -1)
        if not 0 <= index < len(items):
            raise KinematikaError("usage", "delete-missing", "element", element=element)
        del items[index]
    else:
        raise KinematikaError("usage", "delete-what", "element", element=repr(element))


def _delete_point(tree: Tree, name: str) -> None:
    points = tree.points()
    if name not in points:
        raise KinematikaError("usage", "delete-no-point", "element", point=name)
    doomed, changed = {name}, True
    while changed:                                   # and every point built on a doomed one
        changed = False
        for p, spec in points.items():
            if str(p) not in doomed and _uses(spec) & doomed:
                doomed.add(str(p))
                changed = True
    for p in doomed:
        del points[p]
    shrunk = set()
    for b in list(tree.bodies()):
        body = tree.bodies()[b]
        listed = (body.get("points") if isinstance(body, dict) else body) or []
        for p in [x for x in listed if str(x) in doomed]:
            listed.remove(p)
            shrunk.add(str(b))
    _remove(tree.existing("joints"), lambda j: str(j.get("at")) in doomed or bool(_uses(j.get("along")) & doomed))
    _remove(tree.existing("ask"), lambda a: any(str(v).split("@")[0] in doomed for v in a.values()))
    _remove(tree.existing("drivers"), lambda d: str(d.get("velocity", "")).split("@")[0] in doomed)
    for b in [str(b) for b in tree.bodies()]:         # a link that lost an end goes too
        shaped = isinstance(tree.bodies()[b], dict) and any(k != "points" for k in tree.bodies()[b])
        if b != tree.frame and (not tree.body_points(b) or
                                (b in shrunk and len(tree.body_points(b)) < 2 and not shaped)):
            if b in tree.bodies():
                _delete_body(tree, b)


def _delete_body(tree: Tree, name: str) -> None:
    bodies = tree.bodies()
    if name not in bodies or name == tree.frame:
        raise KinematikaError("usage", "delete-no-body", "element", body=name)
    listed = tree.body_points(name)
    del bodies[name]
    ids = tree.joint_ids()
    joints = tree.existing("joints")
    gone = {ids[i] for i, j in enumerate(joints) if name in [str(b) for b in j.get("bodies", [])]}
    _remove(joints, lambda j: name in [str(b) for b in j.get("bodies", [])])
    _remove(tree.existing("drivers"), lambda d: name in (str(d.get("omega")), str(d.get("relative_to")))
            or str(d.get("joint")) in gone)
    _remove(tree.existing("ask"), lambda a: any(str(v).split("@")[-1] == name for v in a.values()))
    for p in listed:                               # points no other body carries
        if p in tree.points() and not tree.carriers(p):
            _delete_point(tree, p)


def _remove(items: Any, doomed: Any) -> None:
    for i in reversed(range(len(items))):
        if isinstance(items[i], dict) and doomed(items[i]):
            del items[i]


def _uses(spec: Any) -> set[str]:
    """The names a value mentions (points a construction is built on)."""
    if isinstance(spec, str):
        return {spec.strip()}
    if isinstance(spec, dict):
        return set().union(*(_uses(v) for v in spec.values())) if spec else set()
    if isinstance(spec, list):
        return set().union(*(_uses(v) for v in spec)) if spec else set()
    return set()


# the input and the questions ----------------------------------------------------------------------
def _drive(tree: Tree, op: dict[str, Any]) -> None:
    """The input: a body's angular velocity (`body`) or a joint's rate (`joint`), with its
    acceleration; it replaces a driver of the same body or joint."""
    body, joint = op.get("body"), op.get("joint")
    rate, accel = op.get("value", 1), op.get("alpha", 0)
    for x in (rate, accel):
        if isinstance(x, bool) or not isinstance(x, (int, float, str)):
            raise KinematikaError("usage", "driver-value", "value")
    if isinstance(body, str) and body in tree.bodies() and body != tree.frame:
        item = {"omega": body, "value": _value(rate), "alpha": _value(accel)}
        same = lambda d: str(d.get("omega")) == body and "relative_to" not in d
    elif isinstance(joint, str) and joint in tree.joint_ids():
        item = {"joint": joint, "rate": _value(rate), "accel": _value(accel)}
        same = lambda d: str(d.get("joint")) == joint
    else:
        raise KinematikaError("usage", "input-body-or-joint", "body")
    drivers = tree.drivers()
    for i, d in enumerate(drivers):
        if isinstance(d, dict) and same(d):
            drivers[i] = tree.map(item)
            return
    drivers.append(tree.map(item))


def _value(x: Any) -> Any:
    return number(float(x), 10) if isinstance(x, (int, float)) else str(x)


def _ask(tree: Tree, question: str, target: str) -> None:
    """Add a question about a point or a body (once): a kind the page offers (`page`)."""
    offered = offered_questions()
    if question not in offered:
        raise KinematikaError("usage", "question-kind", "question", question=repr(question), kinds=offered)
    if not target:
        raise KinematikaError("usage", "question-target", "target")
    item = {question: target}
    if QUESTIONS[question].moving:
        base = target.split("@")[0]
        moving = next((b for b in tree.carriers(base) if b != tree.frame), None)
        if moving is None:
            raise KinematikaError("usage", "target-not-moving", "target", target=target)
        item = {question: target, "moving": moving}
    asks = tree.asks()
    if any(document.plain(a) == item for a in asks):
        return
    asks.append(tree.map(item))
