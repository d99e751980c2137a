"""JSON as every view writes it (the CLI's `--json`, the page's API): orjson, compact, UTF-8,
numpy arrays and scalars written directly, NaN as null."""
from __future__ import annotations

from pathlib import Path
from typing import Any


def json_bytes(data: Any) -> bytes:
    """`data` as compact JSON in UTF-8."""
    import orjson

    try:
        return orjson.dumps(data, default=_plain, option=orjson.OPT_SERIALIZE_NUMPY)
    except orjson.JSONEncodeError:       # e.g. an integer beyond 64 bits: the standard library
        import json

        return json.dumps(data, default=_plain, ensure_ascii=False, separators=(",", ":")).encode()


def _plain(value: Any) -> Any:
    """What orjson cannot write itself: numpy arrays that are not contiguous, paths."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"{type(value).__name__} is not JSON serializable")
