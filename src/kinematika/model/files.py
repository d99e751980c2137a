"""Reading model files: YAML, TOML or JSON into one tree, with unreadable files reported.

A model file is untrusted input. Whatever the path is (a link to /dev/zero, a FIFO, a
folder) at most `limits.FILE_BYTES` are read, without blocking; a repeated key (which
YAML and JSON readers would let the last one win silently), nesting deeper than
`limits.NESTING`, YAML aliases that expand beyond `limits.ALIAS_NODES` values, integers too
long to convert and text that is not Unicode are `syntax` errors, never a wrong model, a
hang or a crash. YAML is read by libyaml's C parser when PyYAML has it.
"""
from __future__ import annotations

import os
import re
import select
import stat
import time
from pathlib import Path
from typing import Any

from .. import limits
from ..errors import KinematikaError, Said, parser_problem, reason
from ..text import brief
from .build import build_model
from .model import Model
import contextlib

FORMATS = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}


def read_tree(path: str | Path) -> Any:
    """The file's content as plain data; a `syntax` error names the line when it can."""
    if not isinstance(path, (str, Path)):
        raise KinematikaError("schema", "model-not-a-path", type=type(path).__name__)
    path = Path(path)
    where = str(path)
    text, kind = read_text(path, "model-file")
    if kind == "yaml" and _only_comments(text):
        raise KinematikaError("syntax", "file-empty", where)
    tree = parse_text(text, kind, where)
    if not isinstance(tree, dict):
        raise KinematikaError("schema", "model-not-a-mapping", where, holds=_kind_of(tree))
    return tree


def read_text(path: Path, noun: str) -> tuple[str, str]:
    """The text of a model or cam file and its kind (yaml, toml, json, by the suffix): at
    most `limits.FILE_BYTES`, UTF-8 (a byte-order mark allowed), not blank; each refusal a
    `syntax` error naming the file (`noun` says what such a file is: `model-file` or `cam-file`)."""
    where = str(path)
    kind = FORMATS.get(path.suffix.lower())
    if kind is None:
        raise KinematikaError("syntax", "file-type-unknown", where, suffix=brief(path.suffix or '(none)', 20),
                              noun=noun, suffixes=list(FORMATS))
    data = read_bytes(path, where)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        raise KinematikaError("syntax", "file-not-utf8", where, byte=err.start + 1) from None
    if not text.strip():
        raise KinematikaError("syntax", "file-empty", where)
    return text, kind


def read_bytes(path: Path, where: str) -> bytes:
    """At most `limits.FILE_BYTES` of the file, never blocking on a FIFO or a device and
    never trusting the size it reports (/dev/zero says 0 and never ends)."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        fd = os.open(path, flags)
    except FileNotFoundError:
        raise KinematikaError("syntax", "file-missing", where) from None
    except OSError as err:
        raise KinematikaError("syntax", "file-unreadable", where, reason=reason(err)) from None
    try:
        mode = os.fstat(fd).st_mode
        if stat.S_ISDIR(mode):
            raise KinematikaError("syntax", "file-is-a-folder", where)
        chunks = _read_regular(fd) if stat.S_ISREG(mode) else _read_stream(fd, where)
    except OSError as err:
        raise KinematikaError("syntax", "file-unreadable", where, reason=reason(err)) from None
    finally:
        os.close(fd)
    data = b"".join(chunks)
    if len(data) > limits.FILE_BYTES:
        raise KinematikaError("syntax", "file-too-large", where, limit=limits.FILE_BYTES)
    return data


def _read_regular(fd: int) -> list[bytes]:
    chunks, size = [], 0
    while size <= limits.FILE_BYTES:
        chunk = os.read(fd, min(1 << 20, limits.FILE_BYTES + 1 - size))
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    return chunks


def _read_stream(fd: int, where: str) -> list[bytes]:
    """A pipe, socket or device, read as it comes until its end, the size limit or the
    time limit (a FIFO nobody writes to, a terminal)."""
    chunks, size = [], 0
    deadline = time.monotonic() + limits.READ_SECONDS
    while size <= limits.FILE_BYTES:
        left = deadline - time.monotonic()
        if left <= 0 or not select.select([fd], [], [], left)[0]:
            raise KinematikaError("syntax", "file-no-end", where, seconds=float(limits.READ_SECONDS))
        try:
            chunk = os.read(fd, min(1 << 20, limits.FILE_BYTES + 1 - size))
        except BlockingIOError:       # woken without data: wait again, within the time limit
            continue
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    return chunks


def _kind_of(tree: Any) -> Said:
    return Said("holds", what={list: "list", str: "text", type(None): "nothing"}.get(type(tree), "value"))


def _only_comments(text: str) -> bool:
    return all(not line.strip() or line.lstrip().startswith("#") for line in text.splitlines())


def parse_text(text: str, kind: str, where: str = "") -> Any:
    """Plain data from a model's text in `kind` ('yaml', 'toml' or 'json'), within the
    limits on nesting and aliases, its strings valid Unicode."""
    readers = {"json": _json, "toml": _toml, "yaml": _yaml}
    if len(text) > limits.FILE_BYTES:
        raise KinematikaError("syntax", "text-too-large", where, limit=limits.FILE_BYTES)
    if kind == "yaml":
        tree = _plain_yaml(text)
        if tree is not _UNUSUAL:
            return tree
    try:
        tree = readers[kind](text, where)
    except RecursionError:
        raise _too_deep(where) from None
    except ValueError as err:       # e.g. an integer literal of thousands of digits
        raise KinematikaError("syntax", "text-unreadable", where, format=kind.upper(), detail=str(err)) from None
    check_tree(tree, where)
    return tree


def _too_deep(where: str, line: int | None = None) -> KinematikaError:
    return KinematikaError("syntax", "file-too-deep", where, levels=limits.NESTING, line=line or 0)


def check_tree(tree: Any, where: str = "") -> None:
    """A parsed tree within the nesting limit, its keys (names) within `limits.NAME_CHARS`,
    its texts encodable (no lone surrogates from a JSON or YAML escape such as \\ud800):
    walked without recursion."""
    stack = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        if isinstance(node, str):
            if not node.isascii():
                _check_unicode(node, where)
            continue
        if isinstance(node, dict):
            long = next((k for k in node if isinstance(k, str) and len(k) > limits.NAME_CHARS), None)
            if long is not None:
                raise KinematikaError("syntax", "name-too-long", where, name=brief(long, 30), length=len(long),
                                      limit=limits.NAME_CHARS)
            children = [*node.keys(), *node.values()]
        elif isinstance(node, list):
            children = node
        else:
            continue
        if depth >= limits.NESTING:
            raise _too_deep(where)
        stack.extend((child, depth + 1) for child in children)


def _check_unicode(text: str, where: str) -> None:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise KinematikaError("syntax", "text-lone-surrogate", where, text=brief(text, 30)) from None


def _duplicate(key: Any, where: str, line: int | None = None) -> KinematikaError:
    return KinematikaError("syntax", "key-duplicate", where, key=brief(key), line=line or 0)


def _json(text: str, where: str) -> Any:
    import json         # only for a JSON file (a YAML model never needs it: 14 M instructions at start-up)

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
        raise KinematikaError("syntax", "json-invalid", where, line=err.lineno, column=err.colno,
                              problem=parser_problem(err.msg)) from None


def _toml(text: str, where: str) -> Any:
    import tomllib          # only for a TOML file (a YAML or JSON one never needs it)

    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise KinematikaError("syntax", "toml-invalid", where, problem=parser_problem(str(err))) from None


def _yaml(text: str, where: str) -> Any:
    import yaml

    loader = _unique_key_loader(yaml, where)
    try:
        _check_events(yaml, text, loader, where)
        return yaml.load(text, Loader=loader)
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        problem = getattr(err, "problem", None) or "unreadable"
        if "nesting depth" in problem:      # PyYAML ≥ 6.0.4 stops at its own depth first
            raise _too_deep(where, mark.line + 1 if mark else None) from None
        raise KinematikaError("syntax", "yaml-invalid", where, line=mark.line + 1 if mark else 0,
                              column=mark.column + 1 if mark else 0, problem=parser_problem(problem)) from None


_UNUSUAL = object()     # what `_plain_yaml` leaves to the full reader
_PLAIN_TAGS = {f"tag:yaml.org,2002:{t}" for t in ("str", "int", "float", "bool", "null", "timestamp")}


def _plain_yaml(text: str) -> Any:
    """The tree of a plain YAML document, built in one pass over the parser's events: what
    `yaml.load` gives, with the limits of `_check_events` and `check_tree` and the
    duplicate-key check, in a fraction of the time (a model of 10 000 bodies is read in
    about a quarter of it). Anything else (anchors and aliases, explicit tags, merge keys,
    several documents, a limit or a check that fails) returns `_UNUSUAL`: the full reader
    then reads the text again and reports what it finds, so errors stay the same. The tree
    returned has passed `check_tree`'s checks.

    Scalars are resolved as the loader resolves them (`_Scalars`), so `yes`, `1_000`,
    `0x1f`, `.inf`, `2001-12-14` read as with `yaml.load`."""
    import yaml

    events = yaml.events
    scalar_event, alias_event, document_start = events.ScalarEvent, events.AliasEvent, events.DocumentStartEvent
    opening = {events.MappingStartEvent: True, events.SequenceStartEvent: False}
    closing = (events.MappingEndEvent, events.SequenceEndEvent)
    parser = (getattr(yaml, "CSafeLoader", None) or yaml.SafeLoader)(text)
    next_event = parser.get_event               # None once the stream has ended
    plain = _Scalars(yaml, parser)
    resolved = plain.resolved                   # a plain scalar's text: its value (met before)
    stack: list[tuple] = []           # the open collections around the innermost: (it, is_mapping, its key)
    container: Any = None             # the innermost open collection (None: at the top)
    is_mapping = False
    key: Any = _UNUSUAL               # the innermost mapping's key awaiting its value
    key_types = (str, int, float, bool, type(None))
    name_chars = limits.NAME_CHARS
    root: Any = _UNUSUAL
    documents = 0
    nesting = limits.NESTING
    try:
        while (event := next_event()) is not None:
            kind = type(event)
            if kind is scalar_event:
                if event.anchor is not None or event.tag not in (None, "!"):
                    return _UNUSUAL
                value = event.value
                if event.implicit[0]:             # plain: resolved by its text
                    value = resolved.get(value, _UNUSUAL)
                    if value is _UNUSUAL:
                        value = plain.value(event)
                        if value is _UNUSUAL:
                            return _UNUSUAL
                elif not value.isascii() and not _encodable(value):   # quoted or `!`: a string
                    return _UNUSUAL
            elif kind in opening:
                if event.anchor is not None or event.tag not in (None, "!") or len(stack) >= nesting:
                    return _UNUSUAL
                stack.append((container, is_mapping, key))
                is_mapping = opening[kind]
                container = {} if is_mapping else []
                key = _UNUSUAL
                continue
            elif kind in closing:
                value = container
                container, is_mapping, key = stack.pop()
            elif kind is document_start:
                documents += 1
                if documents > 1:
                    return _UNUSUAL
                continue
            elif kind is alias_event:
                return _UNUSUAL
            else:                                     # stream start and end, document end
                continue
            if container is None:
                root = value
            elif not is_mapping:
                container.append(value)
            elif key is _UNUSUAL:                     # a key: every earlier key has its value by now
                if (not isinstance(value, key_types) or value in container
                        or (isinstance(value, str) and len(value) > name_chars)):
                    return _UNUSUAL
                key = value
            else:
                container[key] = value
                key = _UNUSUAL
    except (ValueError, TypeError, yaml.YAMLError):
        return _UNUSUAL
    return root


def _encodable(text: str) -> bool:
    """Whether `text` is valid Unicode (no lone surrogate, as a double-quoted `\\ud800` gives)."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


class _Scalars:
    """The values of plain scalars (`implicit[0]` true, no tag) as `parser`'s resolver and
    constructors give them, each text resolved once (`resolved`).

    The resolver (PyYAML's `BaseResolver.resolve`) tries the implicit resolvers listed under
    the text's first character (and under None, for every text) and otherwise gives the
    string tag, whose constructor returns the text itself: a text whose first character
    has no resolver is that string, without the search. Decimal integers and numbers with
    a point are converted directly (`_plain_number`). Any other text goes through the
    resolver and the constructors themselves; a tag other than `_PLAIN_TAGS`' gives
    `_UNUSUAL`."""

    __slots__ = ("_constructors", "_node", "_parser", "_starts", "resolved")

    def __init__(self, yaml: Any, parser: Any) -> None:
        self._parser = parser
        self._node = yaml.ScalarNode
        self._constructors = parser.yaml_constructors
        tables = parser.yaml_implicit_resolvers
        general = None in tables or getattr(parser, "yaml_path_resolvers", None)
        self._starts = None if general else frozenset(tables)   # first characters with a resolver
        self.resolved: dict[str, Any] = {}

    def value(self, event: Any) -> Any:
        """The value of a plain scalar met for the first time (remembered unless a NaN, which is
        never shared, nor a dict key)."""
        text = event.value
        value = _plain_number(text)
        if value is None:
            if self._starts is not None and text and text[0] not in self._starts:
                value = text
            else:
                tag = self._parser.resolve(self._node, text, event.implicit)
                if tag not in _PLAIN_TAGS:
                    return _UNUSUAL
                value = self._constructors[tag](self._parser, self._node(tag, text, event.start_mark,
                                                                          event.end_mark, event.style))
            if isinstance(value, str) and not value.isascii() and not _encodable(value):
                return _UNUSUAL
        if value == value:
            self.resolved[text] = value
        return value


_DECIMAL = re.compile(r"[-+]?(?:0|[1-9][0-9]*)\Z")       # what YAML 1.1 reads as a decimal integer ...
_POINTED = re.compile(r"[-+]?[0-9]+\.[0-9]*\Z")          # ... and as a number with a point (no _, no exponent)


def _plain_number(text: str) -> Any:
    """A plain scalar's `text` written as a decimal integer or a number with a point, as the
    YAML loader reads it (`int(text)`, `float(text)`: the resolver's int and float patterns
    match these texts, and its constructors give the same values), without the resolver's
    search; None for any other text."""
    if _POINTED.match(text):
        return float(text)
    if _DECIMAL.match(text):
        return int(text)
    return None


def _check_events(yaml: Any, text: str, loader: type, where: str) -> None:
    """Nesting and alias expansion measured on the parser's events, before any tree is
    built: libyaml's composer recurses in C (deep nesting would crash the process), and
    a billion-laughs file expands a few hundred bytes into billions of values."""
    events = yaml.events
    sizes: dict[str, tuple[int, int]] = {}    # anchor: (values, depth) of what it names
    stack: list[list] = []                    # open collections: [anchor, values, depth below]
    added = 0                                 # values the aliases add

    def close(anchor: str | None, count: int, below: int, line: int | None) -> None:
        if anchor is not None:
            sizes[anchor] = (count, below)
        if stack:
            parent = stack[-1]
            parent[1] += count
            parent[2] = max(parent[2], below + 1)
            if len(stack) + below > limits.NESTING:
                raise _too_deep(where, line)

    for event in yaml.parse(text, Loader=loader):
        line = event.start_mark.line + 1 if event.start_mark else None
        if isinstance(event, (events.SequenceStartEvent, events.MappingStartEvent)):
            if len(stack) >= limits.NESTING:
                raise _too_deep(where, line)
            stack.append([event.anchor, 1, 0])
        elif isinstance(event, events.CollectionEndEvent):
            anchor, count, below = stack.pop()
            close(anchor, count, below, line)
        elif isinstance(event, events.ScalarEvent):
            close(event.anchor, 1, 0, line)
        elif isinstance(event, events.AliasEvent):
            if event.anchor not in sizes:
                inside = any(frame[0] == event.anchor for frame in stack)
                raise KinematikaError("syntax", "yaml-alias-inside" if inside else "yaml-alias-unknown", where,
                                      alias=brief(event.anchor, 30)[1:-1], line=line or 0)
            count, below = sizes[event.anchor]
            added += count - 1
            if added > limits.ALIAS_NODES:
                raise KinematikaError("syntax", "yaml-aliases-too-many", where, limit=limits.ALIAS_NODES,
                                      line=line or 0)
            close(None, count, below, line)


def _unique_key_loader(yaml: Any, where: str) -> type:
    """PyYAML's safe loader (libyaml's C parser when available) that refuses a key
    repeated in one mapping."""
    base: Any = getattr(yaml, "CSafeLoader", None) or yaml.SafeLoader

    def construct_mapping(self: Any, node: Any, deep: bool = False) -> dict:
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
        return base.construct_mapping(self, node, deep=deep)      # (what super() gives in a class body)

    # made with type(): a class statement cannot take a base known only at run time
    return type("Loader", (base,), {"construct_mapping": construct_mapping})


def load_model(path: str | Path) -> Model:
    """Read and check a model file."""
    return build_model(read_tree(path))


def load_cam(path: str | Path) -> Any:
    """Read, check and build a cam-design file (YAML, TOML or JSON; `cams.spec`), with the
    same limits on untrusted files as a model's; or a model file whose body carries a `cam:`
    shape (its design, at the speed of the model's `omega` driver of that body)."""
    from ..cams.spec import design, parse

    path = Path(path)
    text, kind = read_text(path, "cam-file")
    tree = parse_text(text, kind, str(path))
    if isinstance(tree, dict) and "bodies" in tree:
        return _model_cam(build_model(tree), str(path))
    return design(parse(tree))


def _model_cam(model: Model, where: str) -> Any:
    """The first cam shape of a model, at the speed its body is driven with (when a number)."""
    import dataclasses

    from ..algebra.backend import Numeric
    from ..expressions import ExpressionError, evaluate
    from .body_shapes import CamShape
    from .overrides import numeric_parameters

    for body in model.bodies.values():
        for shape in body.shapes:
            if isinstance(shape, CamShape):
                speed = shape.design.speed
                for d in model.drivers:
                    if d.kind == "omega" and d.body == body.name and d.relative_to in (None, model.frame):
                        value = d.given()
                        if isinstance(value, tuple):          # a spatial ω: no speed of a planar cam
                            continue
                        with contextlib.suppress(ExpressionError, TypeError, ValueError, ZeroDivisionError,
                                                 OverflowError):
                            speed = abs(float(evaluate(value, numeric_parameters(model), Numeric())))
                return dataclasses.replace(shape.design, speed=speed, title=model.name)
    raise KinematikaError("schema", "model-no-cam", where)

