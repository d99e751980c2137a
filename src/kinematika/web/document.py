"""A model's text as an editable tree that writes back with its comments and layout.

The page's text is the one source of the model: building by hand, typing a dimension and
converting between formats all read the text into a round-trip tree, change the tree, and
write it back. YAML goes through ruamel.yaml's round-trip mode (comments, key order, flow
style and quotes kept), TOML through tomlkit (the same for TOML), JSON through the
standard library (JSON has no comments). The text is first read by the model reader
(`model.files.parse_text`), so every bound on untrusted input (size, nesting, aliases,
repeated keys) holds before the round-trip reader sees it.
"""
from __future__ import annotations

import io
import json
from typing import Any

from ..errors import KinematikaError, Said
from ..model.files import parse_text

FORMATS = ("yaml", "toml", "json")


def load(text: str, fmt: str) -> Any:
    """The text as a round-trip tree (a mapping); an empty text is an empty mapping."""
    if fmt not in FORMATS:
        raise KinematikaError("usage", "format-one-of", "format", format=repr(fmt), formats=list(FORMATS))
    if not text.strip() or (fmt == "yaml" and all(
            not line.strip() or line.lstrip().startswith("#") for line in text.splitlines())):
        return _empty(fmt, text)
    plain = parse_text(text, fmt, "model")              # the bounds on untrusted input
    if not isinstance(plain, dict):
        raise KinematikaError("schema", "model-mapping", "model")
    if fmt == "json":
        return plain
    if fmt == "toml":
        import tomlkit

        return tomlkit.parse(text)
    return _yaml().load(text)


def dump(tree: Any, fmt: str) -> str:
    """The tree as text in `fmt` (a round-trip tree keeps its comments)."""
    if fmt == "json":
        return _json(plain(tree)) + "\n"
    if fmt == "toml":
        import tomlkit

        return tomlkit.dumps(tree if isinstance(tree, tomlkit.TOMLDocument) else _toml_tree(tree))
    out = io.StringIO()
    _yaml().dump(tree, out)
    return out.getvalue()


def _json(value: Any, depth: int = 0) -> str:
    """JSON in the model files' style: the top two levels one entry a line, every point,
    body, joint, driver and question on one line."""
    pad = "  " * (depth + 1)
    if depth < 2 and isinstance(value, dict) and value and \
            not (depth == 1 and all(not isinstance(v, (dict, list)) for v in value.values())):
        items = [f"{pad}{json.dumps(k, ensure_ascii=False)}: {_json(v, depth + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + "  " * depth + "}"
    if depth < 1 and isinstance(value, list) and value:
        return "[\n" + ",\n".join(f"{pad}{_json(v, depth + 1)}" for v in value) + "\n" + "  " * depth + "]"
    if depth == 1 and isinstance(value, list) and value and any(isinstance(v, dict) for v in value):
        return "[\n" + ",\n".join(f"{pad}{_json(v, 2)}" for v in value) + "\n" + "  " * depth + "]"
    return json.dumps(value, ensure_ascii=False, separators=(", ", ": "))


def convert(text: str, fmt: str, to: str) -> str:
    """The model written in another format: the same tree (YAML comments cannot be kept in
    JSON; TOML and YAML keep the model's own, not its comments, across the change)."""
    if to not in FORMATS:
        raise KinematikaError("usage", "format-one-of", "to", format=repr(to), formats=list(FORMATS))
    if to == fmt:
        return text
    tree = plain(load(text, fmt))
    if to == "yaml":
        return dump(flow_yaml(tree), "yaml")
    if to == "toml":
        tree = _toml_symbols(tree)
        _check_toml(tree)
    return dump(tree, to)


def plain(tree: Any) -> Any:
    """Plain dicts, lists, strings and numbers (no round-trip types)."""
    if isinstance(tree, dict):
        return {str(k): plain(v) for k, v in tree.items()}
    if isinstance(tree, (list, tuple)):
        return [plain(v) for v in tree]
    if isinstance(tree, bool) or tree is None:
        return tree
    if isinstance(tree, int):
        return int(tree)
    if isinstance(tree, float):
        return float(tree)
    return str(tree)


def flow_yaml(tree: Any, depth: int = 0) -> Any:
    """A plain tree as ruamel nodes in the model files' style: sections as blocks, every
    point, body, joint, driver and question on one line (flow style)."""
    from ruamel.yaml.comments import CommentedMap, CommentedSeq

    if isinstance(tree, dict):
        node = CommentedMap((k, flow_yaml(v, depth + 1)) for k, v in tree.items())
        if depth >= 2:
            node.fa.set_flow_style()
        return node
    if isinstance(tree, list):
        seq = CommentedSeq(flow_yaml(v, depth + 1) for v in tree)
        if depth >= 2 or all(not isinstance(v, (dict, list)) for v in tree):
            seq.fa.set_flow_style()
        return seq
    return tree


def new_map(fmt: str, items: dict[str, Any]) -> Any:
    """A mapping written on one line in `fmt` (a flow mapping, an inline table)."""
    if fmt == "yaml":
        return flow_yaml(items, 2)
    if fmt == "toml":
        return _inline(items)
    return dict(items)


def new_list(fmt: str, items: list[Any]) -> Any:
    """A list written on one line in `fmt`."""
    if fmt == "yaml":
        return flow_yaml(list(items), 2)
    if fmt == "toml":
        import tomlkit

        arr = tomlkit.array()
        arr.extend(_inline(v) if isinstance(v, dict) else v for v in items)
        return arr
    return list(items)


ORDER = ("name", "dimension", "frame", "parameters", "draw_at", "points", "bodies", "joints",
         "drivers", "ask", "move", "sweep")


def section(tree: Any, key: str, kind: type, fmt: str) -> Any:
    """The top-level section `key` (a mapping or a list), made when missing and placed where
    the format's examples put it (parameters, points, bodies, joints, drivers, ask)."""
    value = tree.get(key)
    if value is None:
        put(tree, key, _block_map(fmt) if kind is dict else _block_list(fmt))
        value = tree[key]
    return value


def put(tree: Any, key: str, value: Any) -> None:
    """Set the top-level `key` (a section or a value such as `frame`): a new key goes where
    the format's examples put it (`ORDER`), an existing one keeps its place."""
    if key in tree:
        tree[key] = value
        return
    rank = ORDER.index(key) if key in ORDER else len(ORDER)
    keys = list(tree.keys())
    at = next((i for i, k in enumerate(keys) if k in ORDER and ORDER.index(k) > rank), len(keys))
    if hasattr(tree, "insert") and at < len(keys):
        tree.insert(at, key, value)
    elif type(tree) is dict and at < len(keys):
        items = list(tree.items())
        tree.clear()
        tree.update(items[:at] + [(key, value)] + items[at:])
    else:
        tree[key] = value


def _block_map(fmt: str) -> Any:
    if fmt == "yaml":
        from ruamel.yaml.comments import CommentedMap

        return CommentedMap()
    if fmt == "toml":
        import tomlkit

        return tomlkit.table()
    return {}


def _block_list(fmt: str) -> Any:
    if fmt == "yaml":
        from ruamel.yaml.comments import CommentedSeq

        return CommentedSeq()
    if fmt == "toml":
        import tomlkit

        return tomlkit.array().multiline(True)
    return []


def _inline(items: dict[str, Any]) -> Any:
    import tomlkit

    table = tomlkit.inline_table()
    for k, v in items.items():
        table[k] = _inline(v) if isinstance(v, dict) else v
    return table


def _empty(fmt: str, text: str) -> Any:
    if fmt == "yaml":
        return _yaml().load(text + "\n{}\n") if text.strip() else _block_map("yaml")
    return _block_map(fmt)


def _yaml() -> Any:
    from ruamel.yaml import YAML

    yaml = YAML(typ="rt")
    yaml.preserve_quotes = True
    yaml.width = 4096                 # never fold a long flow line
    yaml.indent(mapping=2, sequence=4, offset=2)
    return yaml


def _toml_tree(tree: Any) -> Any:
    """A plain tree as a TOML document: top-level mappings as tables, lists of mappings as
    arrays of inline tables (one joint, driver or question a line)."""
    import tomlkit

    doc = tomlkit.document()
    scalars = {k: v for k, v in tree.items() if not isinstance(v, dict)}
    for k, v in scalars.items():
        doc[k] = _toml_value(v)
    for k, v in tree.items():
        if isinstance(v, dict):
            table = tomlkit.table()
            for kk, vv in v.items():
                table[kk] = _toml_value(vv)
            doc[k] = table
    return doc


def _toml_value(v: Any) -> Any:
    import tomlkit

    if isinstance(v, dict):
        return _inline(v)
    if isinstance(v, list):
        arr = tomlkit.array()
        arr.extend(_toml_value(x) for x in v)
        if any(isinstance(x, dict) for x in v):
            arr.multiline(True)
        return arr
    return v


def _toml_symbols(tree: dict) -> dict:
    """TOML has no null: a symbolic parameter (`r: null`, `{value: null}`) is written
    `{symbolic = true}`, as the format allows."""
    params = tree.get("parameters")
    if not isinstance(params, dict):
        return tree
    out = {}
    for name, value in params.items():
        if value is None:
            value = {"symbolic": True}
        elif isinstance(value, dict) and "value" in value and value["value"] is None:
            value = {**{k: v for k, v in value.items() if k != "value"}, "symbolic": True}
        out[name] = value
    return {**tree, "parameters": out}


def _check_toml(tree: Any, where: str = "") -> None:
    """TOML has no null: a symbolic parameter (`r: null`) cannot be written in it."""
    if tree is None:
        raise KinematikaError("usage", "toml-null", where, place=where or Said("the-model"))
    if isinstance(tree, dict):
        for k, v in tree.items():
            _check_toml(v, f"{where}.{k}" if where else str(k))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            _check_toml(v, f"{where}[{i}]")
