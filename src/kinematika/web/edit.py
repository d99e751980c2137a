"""A point dragged on the page, as an edit of the model's text.

Only the values that place the dragged point change; comments, order and layout stay as
the user wrote them. A point given by coordinates gets the new coordinates. A constructed
point keeps its construction and gets the lengths and angle that put it where it was
dropped: a polar point its `distance` and `angle` (or the parameters they name), a point
in a frame its `at`, an intersection of two circles their radii (and the `side` it fell
on), a point on a circle and a line the radius (the point slides along its line). A point
where two lines meet is placed by its lines: it cannot be dragged itself.

Values are located in the text by the YAML composer's marks (a JSON text is YAML too); a
TOML text can have its coordinates moved (the line `NAME = [x, y]` of `[points]`).
"""
from __future__ import annotations

import math
import re
from typing import Any, Optional

import numpy as np

from ..errors import KinematikaError, parser_problem

Edit = tuple[int, int, str]                 # replace text[start:end] with the text


def move_point(text: str, fmt: str, point: str, to: tuple[float, float]) -> str:
    """`text` with the point `point` placed at `to` (model coordinates)."""
    if fmt == "toml":
        start, end, kind = _toml_span(text, point)
        if kind != "list2":
            raise KinematikaError("usage", "drag-constructed", f"points.{point}", point=point)
        return text[:start] + _pair(to) + text[end:]
    root = _compose(text)
    node = _child(_child(root, "points"), point)
    if node is None:
        raise KinematikaError("schema", "no-point-in-model", "points", point=point)
    if _is_pair(node):
        edits = _coordinate_edits(text, root, node, point, to)
    elif _is_mapping(node):
        edits = _construction_edits(text, fmt, root, node, point, np.array(to, dtype=float))
    else:
        raise KinematikaError("usage", "drag-not-planar", f"points.{point}", point=point)
    for start, end, new in sorted(edits, reverse=True):
        text = text[:start] + new + text[end:]
    return text


def _coordinate_edits(text: str, root: Any, node: Any, point: str,
                      to: tuple[float, float]) -> list[Edit]:
    """A point given by coordinates: a number gets the new coordinate; a coordinate that
    names a parameter (`O4: [d, 0]`) changes the parameter, so that what else uses it follows
    and the parameter keeps its meaning. A formula is not replaced by a number: that point
    is moved by its parameters (a `usage` error says so)."""
    import yaml

    params = _child(root, "parameters")
    edits = Edits(text, root, node, 1.0, False)
    for item, value in zip(node.value, to):
        if not isinstance(item, yaml.ScalarNode):
            raise KinematikaError("usage", "drag-not-planar", f"points.{point}", point=point)
        raw = item.value.strip()
        if params is not None and _child(params, raw) is not None:
            edits.value_node(item, _short(value))
        elif _is_number(raw):
            edits.out.append((item.start_mark.index, _end(text, item), _short(value)))
        else:
            raise KinematikaError("usage", "drag-formula", f"points.{point}", point=point, formula=repr(raw))
    return edits.out


def _is_number(raw: str) -> bool:
    try:
        float(raw)
    except ValueError:
        return False
    return True


# constructions -------------------------------------------------------------------------------
def _construction_edits(text: str, fmt: str, root: Any, node: Any, point: str,
                        to: np.ndarray) -> list[Edit]:
    from ..api import as_model
    from ..engine.instant import instantiate
    from ..model.constructions import CircleLine, InFrame, Polar, TwoCircles

    model = as_model(text, "yaml")
    inst = instantiate(model, False)
    size = float(inst.scale) or 1.0
    where = f"points.{point}"

    def at(loc: Any) -> np.ndarray:
        """A point (by name) or coordinates, as numbers."""
        vec = inst.points[loc] if isinstance(loc, str) else inst.vector(loc, where)
        return np.array([inst.num(c) for c in vec], dtype=float)

    spec = model.points[point]
    edits = Edits(text, root, node, size, fmt == "json")
    if isinstance(spec, Polar):
        origin = at(spec.origin)
        d = to - origin
        angle = math.degrees(math.atan2(d[1], d[0]))
        if spec.reference is not None:
            p, q = (at(x) for x in spec.reference)
            angle -= math.degrees(math.atan2(*(q - p)[::-1]))
        edits.value("distance", edits.length(float(np.hypot(*d))))
        edits.value("angle", f"deg({_short((angle + 180) % 360 - 180, 0.1)})", text=True)
    elif isinstance(spec, InFrame):
        p, q = at(spec.origin), at(spec.toward)
        u = (q - p) / np.linalg.norm(q - p)
        n = np.array([-u[1], u[0]])
        edits.replace(_child(node, "at"), f"[{edits.length(float((to - p) @ u))}, "
                                           f"{edits.length(float((to - p) @ n))}]")
    elif isinstance(spec, TwoCircles):
        c1, c2 = (at(c) for c in spec.centers)
        circles = _key(node, "circles")
        for i, c in enumerate((c1, c2)):
            edits.value_node(circles.value[i].value[1], edits.length(float(np.linalg.norm(to - c))))
        (ux, uy), (vx, vy) = c2 - c1, to - c1
        cross = float(ux * vy - uy * vx)
        edits.side(_child(node, "side"), "left" if cross > 0 else "right", to)
    elif isinstance(spec, CircleLine):
        centre = at(spec.center)
        line = spec.line
        through = at(line.through)
        d = (at(line.toward) - through) if line.toward is not None else at(line.direction)
        d = d / np.linalg.norm(d)
        onto = through + ((to - through) @ d) * d           # the point stays on its line
        foot = through + ((centre - through) @ d) * d
        edits.value_node(_key(node, "circle").value[1],
                         edits.length(float(np.linalg.norm(onto - centre))))
        edits.side(_child(node, "side"), "ahead" if (onto - foot) @ d >= 0 else "behind", onto)
    else:
        raise KinematikaError("usage", "drag-lines-meet", where, point=point)
    return edits.out


class Edits:
    """The edits that write a construction's new values (a value that names a parameter
    changes the parameter's value instead, so that what else uses it follows)."""

    def __init__(self, text: str, root: Any, node: Any, size: float, json: bool) -> None:
        self.text, self.root, self.node, self.size, self.json = text, root, node, size, json
        self.params = _child(root, "parameters")
        self.out: list[Edit] = []

    def length(self, x: float) -> str:
        """A length to a thousandth of a percent of the mechanism's size."""
        return _short(x, 10 ** math.floor(math.log10(self.size / 1e4)))

    def value(self, key: str, new: str, text: bool = False) -> None:
        """Write `new` as the value under key `key` of the construction (`value_node`)."""
        self.value_node(_child(self.node, key), new, text)

    def value_node(self, node: Any, new: str, text: bool = False) -> None:
        """Write `new` as `node`'s value; a value that names a parameter changes that
        parameter's value instead (its `value` key when written in full), so that what else uses
        it follows."""
        import yaml

        if isinstance(node, yaml.ScalarNode) and self.params is not None:
            target = _child(self.params, node.value)
            if target is not None:                   # a parameter's name: change its value
                if _is_mapping(target):
                    target = _child(target, "value")
                self.replace(target, new, text)
                return
        self.replace(node, new, text)

    def side(self, node: Any, side: str, place: np.ndarray) -> None:
        """The side the point fell on (or the sketch point `near`, if that is what is used)."""
        near = _child(self.node, "near")
        if near is not None:
            self.replace(near, _pair(tuple(float(self.length(c)) for c in place)))
        elif node is not None:
            self.replace(node, side, text=True)

    def replace(self, node: Any, new: str, text: bool = False) -> None:
        """Replace a node's text; a text value keeps the node's quotes (JSON: double quotes)."""
        start, end = node.start_mark.index, _end(self.text, node)
        if text:
            quote = self.text[start] if self.text[start] in "'\"" else ('"' if self.json else "")
            new = f"{quote}{new}{quote}"
        self.out.append((start, end, new))


# YAML nodes ----------------------------------------------------------------------------------
def _compose(text: str) -> Any:
    import yaml

    try:
        return yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as err:
        raise KinematikaError("syntax", "model-unreadable", "", problem=parser_problem(str(err))) from None


def _child(node: Any, key: str) -> Optional[Any]:
    if not _is_mapping(node):
        return None
    for k, v in node.value:
        if getattr(k, "value", None) == key:
            return v
    return None


def _key(node: Any, key: str) -> Any:
    """The value under a key the schema requires of a construction (`circles`, `circle`): the
    model was read from this same text, so it is there."""
    found = _child(node, key)
    assert found is not None, f"a checked construction has its {key!r}"
    return found


def _is_mapping(node: Any) -> bool:
    import yaml

    return isinstance(node, yaml.MappingNode)


def _is_pair(node: Any) -> bool:
    import yaml

    return isinstance(node, yaml.SequenceNode) and len(node.value) == 2


def _end(text: str, node: Any) -> int:
    """Where a node's text ends (a block node's mark runs on to the next key: trim it)."""
    end = node.end_mark.index
    while end > node.start_mark.index and text[end - 1] in " \t\r\n":
        end -= 1
    return end


def _pair(xy: Any) -> str:
    return f"[{_short(xy[0])}, {_short(xy[1])}]"


def _short(x: float, step: Optional[float] = None) -> str:
    """`x` (rounded to `step`) in few characters."""
    if step:
        x = round(x / step) * step
        decimals = max(0, -math.floor(math.log10(step) + 1e-9))
        text = f"{x:.{decimals}f}"
        text = text.rstrip("0").rstrip(".") if "." in text else text
    else:
        text = f"{x:.10g}"
    return "0" if text in ("-0", "0", "") else text


# TOML ----------------------------------------------------------------------------------------
def _toml_span(text: str, point: str) -> tuple[int, int, str]:
    """The span of `NAME = [x, y]` (one line) in the `[points]` table, and its kind."""
    table = None
    offset = 0
    for line in text.splitlines(keepends=True):
        head = re.match(r"\s*\[([^\[\]]+)\]\s*(#.*)?$", line)
        if head:
            table = head.group(1).strip()
        elif table == "points":
            m = re.match(rf"\s*\"?{re.escape(point)}\"?\s*=\s*(\[[^\[\]]*\])", line)
            if m:
                parts = [p for p in m.group(1)[1:-1].split(",") if p.strip()]
                return offset + m.start(1), offset + m.end(1), "list2" if len(parts) == 2 else "other"
            if re.match(rf"\s*\"?{re.escape(point)}\"?\s*=\s*\{{", line):
                return 0, 0, "mapping"
        offset += len(line)
    raise KinematikaError("usage", "drag-toml-form", f"points.{point}", point=point)
