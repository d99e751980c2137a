"""The JSON body of an API request, read and checked.

Every endpoint takes `{"model": TEXT, "format": "yaml", "set": {...}, "move": {...},
"assembly": N, "lang": "eu"}` (the contract), and each accepts a few more keys that mean
what the command's options mean (`symbolic`, the sweep's `joint`, `by`, `steps`,
`skip_bad`, the figure's `velocities`, `centres`, ...), and `row` (the model posed at
that row of its own sweep, through limit positions: what the page's slider shows). A key the endpoint does not know,
or a value of the wrong type, is a `usage` error naming the key, like a wrong option on the
command line.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import Any, Optional

from ..commands import How
from ..errors import KinematikaError, parser_problem
from ..limits import PAGE_SWEEP_STEPS

FORMATS = ("yaml", "toml", "json")
COMMON = ("model", "format", "set", "move", "assembly", "lang")
EXTRA = {
    "solve": ("symbolic", "row"),
    "centres": ("symbolic", "row"),
    "sweep": ("joint", "by", "steps", "skip_bad", "as"),
    "simulate": ("time", "steps", "method", "as"),
    "explain": ("symbolic", "length_unit", "row"),
    "draw": ("row", "as", "velocities", "accelerations", "centres", "curvature", "labels", "points",
             "view", "width", "frame"),
    "edit": ("point", "to"),
    "assemblies": (),
    "exercise": ("vary", "seed", "variant", "answers", "reveal"),     # web.exercise_api
    "build": ("op",),
    "sketch": (),
    "convert": ("to",),
}
AS = {"sweep": ("json", "csv"), "simulate": ("json", "csv"), "draw": ("data", "svg", "png")}


@dataclass
class Request:
    """A checked request: the model's text and how to read it, and the endpoint's options."""

    endpoint: str
    model: str
    how: How
    options: dict[str, Any] = field(default_factory=dict)

    def get(self, key: str, default: Any = None) -> Any:
        """The endpoint's option `key`, or `default` when the request does not give it."""
        return self.options.get(key, default)


def parse_body(endpoint: str, raw: bytes) -> Request:
    """The request in `raw` (UTF-8 JSON), checked for `endpoint`."""
    try:
        body = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as err:
        raise KinematikaError("syntax", "request-not-json", "request", problem=parser_problem(str(err))) from None
    if not isinstance(body, dict):
        raise KinematikaError("usage", "request-object", "request")
    allowed = COMMON + EXTRA[endpoint]
    for key in body:
        if key not in allowed:
            raise KinematikaError("usage", "request-unknown-key", key, key=key, endpoint=endpoint,
                                  accepted=list(allowed))
    model = body.get("model")
    if not isinstance(model, str):
        raise KinematikaError("usage", "request-model", "model")
    fmt = _choice(body, "format", FORMATS, "yaml")
    how = How(fmt=fmt, set=_assignments(body, "set"), move=_assignments(body, "move"),
              assembly=_integer(body, "assembly", None, low=0),
              row=_integer(body, "row", None, low=0, high=PAGE_SWEEP_STEPS))
    options = {k: v for k, v in body.items() if k not in ("model", "format", "set", "move",
                                                          "assembly", "row")}
    return Request(endpoint, model, how, _options(endpoint, options))


def _options(endpoint: str, body: dict) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if "lang" in body:
        from ..languages import LANGS

        out["lang"] = _choice(body, "lang", tuple(LANGS), "en")
    if "symbolic" in body:
        out["symbolic"] = _flag(body, "symbolic")
    if endpoint in AS:
        out["as"] = _choice(body, "as", AS[endpoint], AS[endpoint][0])
    if endpoint == "sweep":
        out["joint"] = _text(body, "joint")
        out["by"] = _number(body, "by")
        out["steps"] = _integer(body, "steps", None, low=1, high=PAGE_SWEEP_STEPS)
        out["skip_bad"] = bool(_flag(body, "skip_bad"))
    elif endpoint == "simulate":
        from ..simulate.run import METHODS

        out["time"] = _number(body, "time")
        out["steps"] = _integer(body, "steps", None, low=1, high=PAGE_SWEEP_STEPS)
        out["method"] = _choice(body, "method", METHODS, METHODS[0])
    elif endpoint == "explain":
        out["length_unit"] = _text(body, "length_unit") or "m"
    elif endpoint == "draw":
        for key in ("velocities", "accelerations", "centres", "curvature"):
            out[key] = _flag(body, key)
        out["labels"] = _flag(body, "labels") is not False
        points = body.get("points")
        if points is not None and not (isinstance(points, list) and
                                       all(isinstance(p, str) for p in points)):
            raise KinematikaError("usage", "request-points", "points")
        out["points"] = points or None
        out["view"] = _choice(body, "view", ("iso", "top", "front", "side"), "iso")
        width = _number(body, "width")
        if width is not None and not 1 <= width <= 100:
            raise KinematikaError("usage", "request-width", "width")
        out["width"] = width or 8.0
        frame = body.get("frame")
        if frame is not None and not (isinstance(frame, list) and len(frame) == 4 and all(_finite(x) for x in frame)
                                      and frame[0] < frame[2] and frame[1] < frame[3]):
            raise KinematikaError("usage", "request-frame", "frame")
        out["frame"] = None if frame is None else [float(x) for x in frame]
    elif endpoint == "exercise":
        from .exercise_api import exercise_options

        out.update(exercise_options(body))
    elif endpoint == "build":
        if not isinstance(body.get("op"), dict):
            raise KinematikaError("usage", "request-op", "op")
        out["op"] = body["op"]
    elif endpoint == "convert":
        out["to"] = _choice(body, "to", FORMATS, "yaml")
    elif endpoint == "edit":
        out["point"] = _text(body, "point")
        to = body.get("to")
        if not (isinstance(to, list) and len(to) == 2 and all(_finite(x) for x in to)):
            raise KinematikaError("usage", "request-to", "to")
        out["to"] = (float(to[0]), float(to[1]))
        if not out["point"]:
            raise KinematikaError("usage", "request-point", "point")
    return out


def _finite(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _choice(body: dict, key: str, choices: tuple, default: str) -> str:
    value = body.get(key, default)
    if value not in choices:
        raise KinematikaError("usage", "request-choice", key, value=repr(value), key=key, choices=list(choices))
    return value


def _flag(body: dict, key: str) -> Optional[bool]:
    value = body.get(key)
    if value is not None and not isinstance(value, bool):
        raise KinematikaError("usage", "request-flag", key, key=key)
    return value


def _text(body: dict, key: str) -> Optional[str]:
    value = body.get(key)
    if value is not None and not isinstance(value, str):
        raise KinematikaError("usage", "request-text", key, key=key)
    return value


def _number(body: dict, key: str) -> Optional[float]:
    value = body.get(key)
    if value is not None and not _finite(value):
        raise KinematikaError("usage", "request-number", key, key=key)
    return None if value is None else float(value)


def _integer(body: dict, key: str, default: Optional[int], low: int = 0,
             high: Optional[int] = None) -> Optional[int]:
    value = body.get(key, default)
    if value is None:
        return None
    if not isinstance(value, int) or isinstance(value, bool) or value < low or \
            (high is not None and value > high):
        if high is not None:
            raise KinematikaError("usage", "request-whole-range", key, key=key, low=low, high=high)
        raise KinematikaError("usage", "request-whole-least", key, key=key, low=low)
    return value


def _assignments(body: dict, key: str) -> dict[str, str]:
    """`set` / `move`: names to numbers or expressions (texts), as `--set NAME=VALUE`."""
    value = body.get(key)
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise KinematikaError("usage", "request-assignments", key, key=key)
    out = {}
    for name, v in value.items():
        if _finite(v):
            out[name] = repr(v)
        elif isinstance(v, str) and v.strip():
            out[name] = v
        else:
            raise KinematikaError("usage", "request-assignment", key, key=f"{key}.{name}")
    return out
