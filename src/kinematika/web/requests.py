"""The JSON body of an API request, read and checked.

Every endpoint takes `{"model": TEXT, "format": "yaml", "set": {...}, "move": {...},
"assembly": N, "lang": "eu"}` (the contract), and each accepts a few more keys that mean
what the command's options mean (`symbolic`, the sweep's `joint`, `by`, `steps`,
`skip_bad`, the figure's `velocities`, `centres`, ...). A key the endpoint does not know,
or a value of the wrong type, is a `usage` error naming the key, like a wrong option on the
command line.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import Any, Optional

from ..commands import How
from ..errors import KinematikaError
from ..limits import PAGE_SWEEP_STEPS

FORMATS = ("yaml", "toml", "json")
COMMON = ("model", "format", "set", "move", "assembly", "lang")
EXTRA = {
    "solve": ("symbolic",),
    "centres": ("symbolic",),
    "sweep": ("joint", "by", "steps", "skip_bad", "as"),
    "simulate": ("time", "steps", "method", "as"),
    "explain": ("symbolic", "length_unit"),
    "draw": ("as", "velocities", "accelerations", "centres", "curvature", "labels", "points",
             "view", "width"),
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
        raise KinematikaError("syntax", f"the request is not JSON: {err}", "request") from None
    if not isinstance(body, dict):
        raise KinematikaError("usage", "the request is a JSON object with at least the key "
                              "'model'", "request")
    allowed = COMMON + EXTRA[endpoint]
    for key in body:
        if key not in allowed:
            raise KinematikaError("usage", f"unknown key {key!r} for /api/{endpoint} (accepted: "
                                  f"{', '.join(allowed)})", key)
    model = body.get("model")
    if not isinstance(model, str):
        raise KinematikaError("usage", "'model' is required: the model file's text", "model")
    fmt = _choice(body, "format", FORMATS, "yaml")
    how = How(fmt=fmt, set=_assignments(body, "set"), move=_assignments(body, "move"),
              assembly=_integer(body, "assembly", None, low=0))
    options = {k: v for k, v in body.items() if k not in ("model", "format", "set", "move",
                                                          "assembly")}
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
            raise KinematikaError("usage", "'points' is a list of point names", "points")
        out["points"] = points or None
        out["view"] = _choice(body, "view", ("iso", "top", "front", "side"), "iso")
        width = _number(body, "width")
        if width is not None and not 1 <= width <= 100:
            raise KinematikaError("usage", "'width' is a figure width in inches, 1 to 100", "width")
        out["width"] = width or 8.0
    elif endpoint == "exercise":
        from .exercise_api import exercise_options

        out.update(exercise_options(body))
    elif endpoint == "build":
        if not isinstance(body.get("op"), dict):
            raise KinematikaError("usage", "'op' is the action: an object with its key 'op'", "op")
        out["op"] = body["op"]
    elif endpoint == "convert":
        out["to"] = _choice(body, "to", FORMATS, "yaml")
    elif endpoint == "edit":
        out["point"] = _text(body, "point")
        to = body.get("to")
        if not (isinstance(to, list) and len(to) == 2 and all(_finite(x) for x in to)):
            raise KinematikaError("usage", "'to' is the point's new place [x, y]", "to")
        out["to"] = (float(to[0]), float(to[1]))
        if not out["point"]:
            raise KinematikaError("usage", "'point' names the point to move", "point")
    return out


def _finite(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _choice(body: dict, key: str, choices: tuple, default: str) -> str:
    value = body.get(key, default)
    if value not in choices:
        raise KinematikaError("usage", f"{value!r}: {key} is one of {', '.join(choices)}", key)
    return value


def _flag(body: dict, key: str) -> Optional[bool]:
    value = body.get(key)
    if value is not None and not isinstance(value, bool):
        raise KinematikaError("usage", f"{key!r} is true, false or null", key)
    return value


def _text(body: dict, key: str) -> Optional[str]:
    value = body.get(key)
    if value is not None and not isinstance(value, str):
        raise KinematikaError("usage", f"{key!r} is a text", key)
    return value


def _number(body: dict, key: str) -> Optional[float]:
    value = body.get(key)
    if value is not None and not _finite(value):
        raise KinematikaError("usage", f"{key!r} is a number", key)
    return None if value is None else float(value)


def _integer(body: dict, key: str, default: Optional[int], low: int = 0,
             high: Optional[int] = None) -> Optional[int]:
    value = body.get(key, default)
    if value is None:
        return None
    if not isinstance(value, int) or isinstance(value, bool) or value < low or \
            (high is not None and value > high):
        bound = f"{low} to {high}" if high is not None else f"at least {low}"
        raise KinematikaError("usage", f"{key!r} is a whole number, {bound}", key)
    return value


def _assignments(body: dict, key: str) -> dict[str, str]:
    """`set` / `move`: names to numbers or expressions (texts), as `--set NAME=VALUE`."""
    value = body.get(key)
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise KinematikaError("usage", f"{key!r} maps names to numbers or expressions", key)
    out = {}
    for name, v in value.items():
        if _finite(v):
            out[name] = repr(v)
        elif isinstance(v, str) and v.strip():
            out[name] = v
        else:
            raise KinematikaError("usage", f"{key}.{name}: a number or an expression", key)
    return out
