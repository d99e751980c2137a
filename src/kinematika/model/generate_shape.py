"""Write `shape.py`, the model file's fast check, from `schema`'s pydantic classes.

Building pydantic's validators costs more than reading, checking and solving a small
model, so the CLI checks a file with plain type tests first and calls pydantic only for a
file those tests refuse (it may be wrong, and then pydantic's message is the one shown).

    python -m kinematika.model.generate_shape          # rewrite src/kinematika/model/shape.py
    python -m kinematika.model.generate_shape --check  # exit 1 if it is not what it would write

Each class reachable from `schema.ModelSpec` becomes a `plain.record` with the same fields,
file keys (aliases) and defaults; each annotation becomes the `plain` checks that accept
exactly the values pydantic takes unchanged (exact types, lengths, literals, discriminated
unions by `schema.FirstKey` / `schema.ByType`). What cannot be written so — another
module's classes (the cam design of `cams.spec`), a validator, a constraint other than a
length, a union whose members could take the same value — becomes `plain.pydantic_decides`:
the fast check refuses it and pydantic checks the file, so that every error message comes
from `schema`. A test (tests/core/test_fast_paths.py) regenerates the module and compares.
"""
from __future__ import annotations

import re
import sys
import types
import typing
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal, Optional, Union, get_args, get_origin

import annotated_types
import pydantic
from pydantic import BaseModel, Discriminator, Tag
from pydantic.fields import FieldInfo
from pydantic.types import Strict

from ..generated import write_or_check
from ..joints import KINDS
from . import schema

TARGET = Path(__file__).with_name("shape.py")
COMMAND = "python -m kinematika.model.generate_shape"
SCALARS = (int, float, str, bool)
# values of a literal that are a registry's names: written as the registry, not copied
REGISTRIES = {tuple(KINDS): ("..joints", "KINDS")}
# the words of `plain` the generated checks may use
PLAIN_WORDS = ("REQUIRED", "by_type", "either", "exact", "first_key", "listed", "mapping", "one_of", "optional",
               "pydantic_decides", "record")
# model settings that change no accepted value (others, such as stripping text, may)
PLAIN_CONFIG = {"extra", "populate_by_name", "validate_by_name", "title"}
# `schema`'s constants that the fast path needs too, copied
CONSTANTS = ("JOINT_KEYS",)
# names of the generated module a named type of `schema` must not take
RESERVED = {name.lower() for name in (*PLAIN_WORDS, "record", "checked", "spec_of", "RECORDS", "KINDS", *CONSTANTS)}


@dataclass(frozen=True)
class Written:
    """A check as source text, and the Python types of the values it may accept (members of
    a union must take disjoint types, or the first that accepts might not be pydantic's)."""

    code: str
    takes: frozenset


DECIDES = Written("pydantic_decides", frozenset())


class _Writer:
    """Writes the checks of `schema`'s classes and named types as source text (`blocks`),
    each once and before its first use."""

    def __init__(self) -> None:
        self.records: dict[type, Optional[str]] = {}     # class → its check's name (None: pydantic's)
        self.named: dict[str, Written] = {}              # schema's type aliases written so far
        self.blocks: list[str] = []
        self.imports: set[tuple[str, str]] = set()
        # schema's named types (`Value`, `Location`, `PointSpec`…): each written once, by name
        self.aliases = [(name, tp) for name, tp in vars(schema).items()
                        if name[:1].isupper() and get_origin(tp) is not None and name not in vars(pydantic)]

    # classes ------------------------------------------------------------------------------
    def model(self, cls: type[BaseModel]) -> Written:
        if cls not in self.records:
            self.records[cls] = None          # a cycle is left to pydantic
            self.records[cls] = self._record(cls)
        name = self.records[cls]
        return DECIDES if name is None else Written(name, frozenset({dict}))

    def _record(self, cls: type[BaseModel]) -> Optional[str]:
        if cls.__module__ != schema.__name__ or _has_validators(cls) or not set(cls.model_config) <= PLAIN_CONFIG:
            return None
        fields, keys = [], {}
        for name, field in cls.model_fields.items():
            check = self.field(field)
            if field.is_required():
                if check is DECIDES:
                    return None
                default = "REQUIRED"
            elif field.default_factory is not None:
                default = _factory(field.default_factory)
            elif type(field.default) in (str, int, float, bool, type(None)):
                default = repr(field.default)
            else:
                return None                   # a default written as code only pydantic copies right
            fields.append(f"    {name!r}: ({check.code}, {default}),")
            key = field.alias or name
            if key != name:
                keys[name] = key
        check_name = _snake(cls.__name__)
        keys_text = f", keys={keys!r}" if keys else ""
        self.blocks.append(f"{cls.__name__}, {check_name} = record({cls.__name__!r}, {{\n"
                           + "\n".join(fields) + f"\n}}{keys_text})")
        return check_name

    def field(self, field: FieldInfo) -> Written:
        return self.annotation(field.annotation, list(field.metadata))

    # annotations --------------------------------------------------------------------------
    def annotation(self, tp: Any, metadata: list) -> Written:
        """The check of the type `tp` with pydantic `metadata` (constraints, tags, strictness)."""
        if get_origin(tp) is typing.Annotated:          # (a union member's tag says nothing here)
            base, *more = get_args(tp)
            kept = [m for m in more if not isinstance(m, Tag)]
            tp = typing.Annotated[(base, *kept)] if kept else base
        alias = None if metadata else next((name for name, named in self.aliases if named == tp), None)
        if alias is not None:
            return self.alias(alias, tp)
        return self.written(tp, metadata)

    def alias(self, name: str, tp: Any) -> Written:
        """One of schema's named types, written once under its name (`location`)."""
        if _snake(name) in RESERVED:
            return self.written(tp, [])
        if name not in self.named:
            self.named[name] = DECIDES                       # (a cycle is left to pydantic)
            written = self.written(tp, [])
            if written is DECIDES:
                return DECIDES
            self.blocks.append(_wrapped(f"{_snake(name)} = ", written.code))
            self.named[name] = Written(_snake(name), written.takes)
        return self.named[name]

    def written(self, tp: Any, metadata: list) -> Written:
        """The check of `tp` itself (`annotation` without looking for a named type)."""
        if get_origin(tp) is typing.Annotated:
            base, *more = get_args(tp)
            return self.written(base, [*metadata, *more])
        metadata = _flat(metadata)
        shortest, longest, discriminator = 0, None, None
        for item in metadata:
            if isinstance(item, annotated_types.MinLen):
                shortest = item.min_length
            elif isinstance(item, annotated_types.MaxLen):
                longest = item.max_length
            elif isinstance(item, Discriminator):
                discriminator = item.discriminator
            elif not isinstance(item, (Strict, Tag)):
                return DECIDES                     # a constraint plain tests do not check
        origin = get_origin(tp)
        if discriminator is not None:
            return self.discriminated(tp, discriminator)
        if (shortest or longest is not None) and origin is not list:
            return DECIDES
        if tp in SCALARS:
            return Written(f"exact({tp.__name__})", frozenset({tp}))
        if origin in (Union, types.UnionType):
            return self.union(get_args(tp))
        if origin is list:
            (item,) = get_args(tp)
            return self.listed(self.annotation(item, []), shortest, longest)
        if origin is dict:
            key, value = get_args(tp)
            if key is not str:
                return DECIDES
            inner = self.annotation(value, [])
            return Written(f"mapping({inner.code})", frozenset({dict}))
        if origin is Literal:
            return self.literal(get_args(tp))
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            return self.model(tp)
        return DECIDES

    def listed(self, item: Written, shortest: int, longest: Optional[int]) -> Written:
        lengths = f", {shortest}, {longest}" if longest is not None else (f", {shortest}" if shortest else "")
        return Written(f"listed({item.code}{lengths})", frozenset({list}))

    def union(self, members: tuple) -> Written:
        nullable = type(None) in members
        checks = [self.annotation(m, []) for m in members if m is not type(None)]
        if any(c is DECIDES for c in checks) or _overlap(checks):
            inner = DECIDES
        else:
            inner = _either(checks)
        if not nullable:
            return inner
        return Written(f"optional({inner.code})", inner.takes | {type(None)})

    def literal(self, values: tuple) -> Written:
        if not all(type(v) in (str, int) for v in values):
            return DECIDES
        registry = REGISTRIES.get(values)
        if registry is not None:
            self.imports.add(registry)
            return Written(f"one_of(*{registry[1]})", frozenset({str}))
        return Written(f"one_of({', '.join(map(repr, values))})", frozenset(type(v) for v in values))

    def discriminated(self, tp: Any, discriminator: Any) -> Written:
        members = {}
        for member in get_args(tp):
            tag = next((m.tag for m in get_args(member)[1:] if isinstance(m, Tag)), None) \
                if get_origin(member) is typing.Annotated else None
            if tag is None:
                return DECIDES
            members[tag] = self.annotation(member, [])
        if isinstance(discriminator, schema.FirstKey):
            pairs = ", ".join(f"({key!r}, {members[tag].code})" for key, tag in discriminator.tags.items())
            return Written(f"first_key({pairs})", frozenset({dict}))
        if isinstance(discriminator, schema.ByType) and set(discriminator.tags) <= {dict, list, *SCALARS}:
            table = ", ".join(f"{kind.__name__}: {members[tag].code}" for kind, tag in discriminator.tags.items())
            return Written(f"by_type({{{table}}})", frozenset(discriminator.tags))
        return DECIDES


def _wrapped(start: str, call: str, width: int = 100) -> str:
    """`start` + `call` (`f(a, b, …)`), its arguments wrapped on indented lines when long."""
    if len(start) + len(call) <= width:
        return start + call
    opening = call.index("(")
    args, depth, begin = [], 0, opening + 1
    for i, char in enumerate(call[opening + 1:-1], opening + 1):
        depth += char in "([{"
        depth -= char in ")]}"
        if char == "," and depth == 0:
            args.append(call[begin:i].strip())
            begin = i + 1
    args.append(call[begin:-1].strip())
    return start + call[:opening + 1] + "\n" + _packed(args, width) + ")"


def _packed(items: list[str], width: int) -> str:
    """`items` joined by commas on lines of at most `width` (an item is never cut), indented."""
    lines = [""]
    for item in items:
        if lines[-1] and len(lines[-1]) + len(item) + 6 > width:
            lines.append("")
        lines[-1] += (", " if lines[-1] else "") + item
    return ",\n".join("    " + line for line in lines)


def _either(checks: list[Written]) -> Written:
    """The first of `checks` that accepts a value (they take disjoint types); the exact type
    tests among them made one."""
    exacts = [c for c in checks if c.code.startswith("exact(")]
    if len(exacts) > 1:
        merged = Written(f"exact({', '.join(c.code[6:-1] for c in exacts)})", frozenset().union(*(c.takes for c in exacts)))
        first = checks.index(exacts[0])
        checks = [c for c in checks if c not in exacts]
        checks.insert(first, merged)
    if len(checks) == 1:
        return checks[0]
    return Written(f"either({', '.join(c.code for c in checks)})", frozenset().union(*(c.takes for c in checks)))


def _flat(metadata: list) -> list:
    """Constraints given through `Field(...)` inside an annotation, as their own items."""
    out = []
    for item in metadata:
        if isinstance(item, FieldInfo):
            out.extend(_flat(list(item.metadata)))
            if item.discriminator is not None:
                out.append(item.discriminator)
        else:
            out.append(item)
    return out


def _overlap(checks: list[Written]) -> bool:
    seen: set = set()
    for c in checks:
        if seen & c.takes:
            return True
        seen |= c.takes
    return False


def _has_validators(cls: type[BaseModel]) -> bool:
    decorators = cls.__pydantic_decorators__
    return any(getattr(decorators, kind) for kind in (
        "validators", "field_validators", "root_validators", "model_validators", "computed_fields"))


def _factory(factory: Any) -> str:
    if factory in (list, dict):
        return factory.__name__
    raise TypeError(f"a default factory {factory!r} the generator cannot write")


def _snake(name: str) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


HEADER = '''"""The model file's shape checked in plain Python: `spec_of` returns `schema`'s records
for a file that is right, or None so that pydantic checks it and says what is wrong.

GENERATED from `schema` by `{command}`:
do not edit (why and how: that module's docstring).
"""
from __future__ import annotations

from typing import Any, Optional
{imports}
{plain}

'''

FOOTER = '''

RECORDS = (
{records}
)


def spec_of(tree: Any) -> Optional[Record]:
    """The checked model file, or None when pydantic must look at it (it may be wrong)."""
    return checked({check}, tree)
'''


def source() -> str:
    """The text of `shape.py` for the current `schema`."""
    writer = _Writer()
    top = writer.model(schema.ModelSpec)
    if top is DECIDES:
        raise TypeError("schema.ModelSpec cannot be written as plain checks")
    imports = "".join(f"\nfrom {module} import {name}" for module, name in sorted(writer.imports))
    body = "\n".join(writer.blocks)
    words = sorted({"Record", "checked", *(w for w in PLAIN_WORDS if re.search(rf"\b{w}\b", body))},
                   key=lambda w: (w.upper() != w, w[0].islower(), w))
    start = "from .plain import ("
    plain = start + _packed(words, 100 - len(start)).replace("    ", "", 1).replace("\n    ", "\n" + " " * len(start)) + ")"
    names = [cls.__name__ for cls, name in writer.records.items() if name is not None]
    records = _packed(names, 100) + ","
    constants = "".join(f"{name} = {getattr(schema, name)!r}\n" for name in CONSTANTS)
    return (HEADER.format(command=COMMAND, imports=imports, plain=plain) + constants + "\n" + body
            + FOOTER.format(records=records, check=top.code))


def main(argv: Optional[list[str]] = None) -> int:
    """Write `shape.py` (or, with --check, say whether it is current: status 1 if not)."""
    return write_or_check(TARGET, source(), COMMAND, argv)


if __name__ == "__main__":
    sys.exit(main())
