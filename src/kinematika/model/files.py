"""Reading model files: YAML, TOML or JSON into one tree, with unreadable files reported."""
from __future__ import annotations

import json
import tomllib
from pathlib import Path
from typing import Any

from ..errors import KinematikaError
from .build import build_model
from .model import Model

FORMATS = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}


def read_tree(path: str | Path) -> Any:
    """The file's content as plain data; a `syntax` error names the line when it can."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise KinematikaError("syntax", f"no such file: {path}", str(path)) from None
    except (OSError, UnicodeDecodeError) as err:
        raise KinematikaError("syntax", f"cannot read {path}: {err}", str(path)) from None
    kind = FORMATS.get(path.suffix.lower(), "yaml")
    return parse_text(text, kind, str(path))


def parse_text(text: str, kind: str, where: str = "") -> Any:
    if kind == "json":
        try:
            return json.loads(text)
        except json.JSONDecodeError as err:
            raise KinematikaError("syntax", f"invalid JSON at line {err.lineno}, column {err.colno}: "
                                  f"{err.msg}", where) from None
    if kind == "toml":
        try:
            return tomllib.loads(text)
        except tomllib.TOMLDecodeError as err:
            raise KinematikaError("syntax", f"invalid TOML: {err}", where) from None
    import yaml

    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        problem = getattr(err, "problem", None) or "unreadable"
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        raise KinematikaError("syntax", f"invalid YAML{at}: {problem}", where) from None


def load_model(path: str | Path) -> Model:
    """Read and check a model file."""
    return build_model(read_tree(path))
