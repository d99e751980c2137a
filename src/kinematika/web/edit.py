"""A point dragged on the page, as an edit of the model's text.

Only the dragged point's value changes; comments, order and layout stay as the user wrote
them. A point given by coordinates gets the new coordinates. The value's place in the text
is found by the YAML composer's marks (a JSON text is YAML too); in TOML, by the line
`NAME = [...]` of the `[points]` table.
"""
from __future__ import annotations

import re
from typing import Any, Optional

from ..errors import KinematikaError


def move_point(text: str, fmt: str, point: str, to: tuple[float, float]) -> str:
    """`text` with the point `point` placed at `to` (model coordinates)."""
    span = _toml_span(text, point) if fmt == "toml" else _yaml_span(text, point)
    start, end, node = span
    if node == "mapping":
        raise KinematikaError("usage", f"{point} is constructed from other points: drag the "
                              "points it is built from, or edit its construction", f"points.{point}")
    if node != "list2":
        raise KinematikaError("usage", f"{point} is not a planar point with two coordinates",
                              f"points.{point}")
    return text[:start] + f"[{_number(to[0])}, {_number(to[1])}]" + text[end:]


def _number(x: float) -> str:
    """A short form of `x` (the page has already rounded it to the drawing's precision)."""
    text = f"{x:.10g}"
    return "0" if text in ("-0", "0") else text


def _yaml_span(text: str, point: str) -> tuple[int, int, str]:
    """Start and end (character offsets) of the point's value, and its kind."""
    import yaml

    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as err:
        raise KinematikaError("syntax", f"the model cannot be read: {err}", "") from None
    points = _child(root, "points")
    node = _child(points, point) if points is not None else None
    if node is None:
        raise KinematikaError("schema", f"no point {point!r} in the model", "points")
    kind = "other"
    if isinstance(node, yaml.MappingNode):
        kind = "mapping"
    elif isinstance(node, yaml.SequenceNode) and len(node.value) == 2:
        kind = "list2"
    return node.start_mark.index, _end(text, node), kind


def _end(text: str, node: Any) -> int:
    """Where a node's text ends (a block sequence's mark runs to the next key: trim it)."""
    end = node.end_mark.index
    while end > node.start_mark.index and text[end - 1] in " \t\r\n":
        end -= 1
    return end


def _child(node: Any, key: str) -> Optional[Any]:
    import yaml

    if not isinstance(node, yaml.MappingNode):
        return None
    for k, v in node.value:
        if isinstance(k, yaml.ScalarNode) and k.value == key:
            return v
    return None


def _toml_span(text: str, point: str) -> tuple[int, int, str]:
    """The span of `NAME = [x, y]` (one line) in the `[points]` table."""
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
            m = re.match(rf"\s*\"?{re.escape(point)}\"?\s*=\s*\{{", line)
            if m:
                return 0, 0, "mapping"
        offset += len(line)
    raise KinematikaError("usage", f"the point {point!r} is not written as `{point} = [x, y]` "
                          "in the [points] table", f"points.{point}")
