"""Reading model files: YAML, TOML or JSON into one tree, with unreadable files reported.

A model file is untrusted input: a repeated key (which YAML and JSON readers would let the
last one win silently), nesting deep enough to exhaust the parser's recursion, integers too
long to convert and oversized files are `syntax` errors, never a wrong model or a crash.
"""
from __future__ import annotations

import json
import tomllib
from pathlib import Path
from typing import Any

from ..errors import KinematikaError
from .build import build_model
from .model import Model

FORMATS = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}
MAX_BYTES = 5_000_000      # a model is a few kilobytes; anything this large is not one


def read_tree(path: str | Path) -> Any:
    """The file's content as plain data; a `syntax` error names the line when it can."""
    if not isinstance(path, (str, Path)):
        raise KinematikaError("schema", f"a model is a file path, a dict or a Mechanism, "
                              f"not {type(path).__name__}")
    path = Path(path)
    where = str(path)
    kind = FORMATS.get(path.suffix.lower())
    if kind is None:
        known = ", ".join(FORMATS)
        raise KinematikaError("syntax", f"unknown file type {path.suffix or '(none)'!r}: "
                              f"a model file ends in {known}", where)
    try:
        if path.stat().st_size > MAX_BYTES:
            raise KinematikaError("syntax", f"the file is too large for a model "
                                  f"({path.stat().st_size} bytes; at most {MAX_BYTES})", where)
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise KinematikaError("syntax", f"no such file: {path}", where) from None
    except (OSError, UnicodeDecodeError) as err:
        raise KinematikaError("syntax", f"cannot read {path}: {err}", where) from None
    if not text.strip() or (kind == "yaml" and _only_comments(text)):
        raise KinematikaError("syntax", "the file is empty", where)
    tree = parse_text(text, kind, where)
    if not isinstance(tree, dict):
        raise KinematikaError("schema", f"a model is a mapping with keys points, bodies, joints, "
                              f"drivers; this file holds {_kind_of(tree)}", where)
    return tree


def _kind_of(tree: Any) -> str:
    return {list: "a list", str: "a text", type(None): "nothing"}.get(type(tree), "a single value")


def _only_comments(text: str) -> bool:
    return all(not line.strip() or line.lstrip().startswith("#") for line in text.splitlines())


def parse_text(text: str, kind: str, where: str = "") -> Any:
    """Plain data from a model's text in `kind` ('yaml', 'toml' or 'json')."""
    readers = {"json": _json, "toml": _toml, "yaml": _yaml}
    try:
        return readers[kind](text, where)
    except RecursionError:
        raise KinematikaError("syntax", "the file is nested too deeply to be a model", where) from None
    except ValueError as err:       # e.g. an integer literal of thousands of digits
        raise KinematikaError("syntax", f"unreadable {kind.upper()}: {err}", where) from None


def _duplicate(key: Any, where: str, line: int | None = None) -> KinematikaError:
    at = f" at line {line}" if line else ""
    return KinematikaError("syntax", f"duplicate key {key!r}{at}: each key may appear only once",
                           where)


def _json(text: str, where: str) -> Any:
    def pairs(items: list[tuple[str, Any]]) -> dict:
        out: dict = {}
        for key, value in items:
            if key in out:
                raise _duplicate(key, where)
            out[key] = value
        return out

    try:
        return json.loads(text, object_pairs_hook=pairs)
    except json.JSONDecodeError as err:
        raise KinematikaError("syntax", f"invalid JSON at line {err.lineno}, column {err.colno}: "
                              f"{err.msg}", where) from None


def _toml(text: str, where: str) -> Any:
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise KinematikaError("syntax", f"invalid TOML: {err}", where) from None


def _yaml(text: str, where: str) -> Any:
    import yaml

    try:
        return yaml.load(text, Loader=_unique_key_loader(yaml, where))
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        problem = getattr(err, "problem", None) or "unreadable"
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        raise KinematikaError("syntax", f"invalid YAML{at}: {problem}", where) from None


def _unique_key_loader(yaml: Any, where: str) -> type:
    """yaml.SafeLoader that refuses a key repeated in one mapping."""

    class Loader(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> dict:
            seen: set = set()
            for key_node, _ in node.value:
                key = self.construct_object(key_node, deep=deep)
                try:
                    repeated = key in seen
                    seen.add(key)
                except TypeError:             # an unhashable key: SafeLoader reports it
                    break
                if repeated:
                    raise _duplicate(key, where, key_node.start_mark.line + 1)
            return super().construct_mapping(node, deep=deep)

    return Loader


def load_model(path: str | Path) -> Model:
    """Read and check a model file."""
    return build_model(read_tree(path))
