"""Plain type tests: the words the model file's fast check (`shape`) is written in.

`shape` is generated from `schema` (`generate_shape`): each pydantic class becomes a
`record`, each annotation a combination of the checks below. A check returns the value it
accepts (a `Record` for a section) or raises `Refused` when the value is not certainly what
pydantic would accept unchanged — exact types only, known keys only — and pydantic then
decides, with its error messages. Nothing here imports pydantic: the fast path's start-up.
"""
from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, Callable, ClassVar, Optional

Check = Callable[[Any], Any]       # returns the checked value, or raises Refused


class Refused(Exception):
    """Not certainly valid: pydantic decides."""


REQUIRED: Any = object()            # the default of a field that must be given


class Record:
    """A checked section of a model file: its fields as attributes, as the `schema` class
    of the same name gives them."""

    FIELDS: ClassVar[tuple[str, ...]] = ()
    DEFAULTS: ClassVar[dict[str, Any]] = {}

    def __init__(self, **fields: Any) -> None:
        self.__dict__.update(fields)

    if TYPE_CHECKING:
        def __getattr__(self, name: str) -> Any:
            """A field: the record's class declares its fields at run time (`record`), so to
            the type checker each is what the `schema` class of the same name says."""

    @classmethod
    def make(cls, **given: Any) -> Record:
        """A record of `given` fields and the defaults of the others (a value or a factory)."""
        fields = {}
        for name in cls.FIELDS:
            default = cls.DEFAULTS[name]
            if name in given:
                fields[name] = given[name]
            elif default is REQUIRED:
                raise TypeError(f"{cls.__name__} needs {name!r}")
            else:
                fields[name] = default() if callable(default) else default
        return cls(**fields)

    def model_dump(self, exclude_none: bool = False) -> dict[str, Any]:
        """The fields in `schema`'s order (as pydantic's `model_dump`)."""
        return {k: getattr(self, k) for k in self.FIELDS
                if not (exclude_none and getattr(self, k) is None)}

    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(f'{k}={getattr(self, k)!r}' for k in self.FIELDS)})"


# the exact checks made here and the types each accepts: a list or mapping of such values
# is checked by its values' types at once (`listed`, `mapping`), not value by value
_EXACT: dict[Check, frozenset[type]] = {}


def exact(*types: type) -> Check:
    """A value of exactly one of `types` (never a subclass: a bool is not an int here)."""
    if len(types) == 1:
        only = types[0]

        def check_one(x: Any) -> Any:
            if type(x) is only:
                return x
            raise Refused
        _EXACT[check_one] = frozenset(types)
        return check_one

    def check(x: Any) -> Any:
        if type(x) in types:
            return x
        raise Refused
    _EXACT[check] = frozenset(types)
    return check


def one_of(*choices: Any) -> Check:
    """One of `choices`, of its exact type (pydantic's `Literal`)."""
    types = {type(c) for c in choices}

    def check(x: Any) -> Any:
        if type(x) in types and x in choices:
            return x
        raise Refused
    return check


def either(*checks: Check) -> Check:
    """What the first of `checks` that accepts the value gives (the members of a union take
    values of different types, so at most one accepts)."""
    def check(x: Any) -> Any:
        for c in checks:
            try:
                return c(x)
            except Refused:
                continue
        raise Refused
    return check


def optional(check: Check) -> Check:
    """None, or what `check` accepts."""
    if check in _EXACT:              # None is one more exact type
        return exact(*_EXACT[check], type(None))
    return lambda x: None if x is None else check(x)


def listed(check: Check, shortest: int = 0, longest: Optional[int] = None) -> Check:
    """A list of `shortest` to `longest` items, each checked."""
    types = _EXACT.get(check)
    most = sys.maxsize if longest is None else longest
    if types is not None:            # each value returned as it is: a copy of the list
        def check_exact(x: Any) -> list:
            if type(x) is not list or not shortest <= len(x) <= most:
                raise Refused
            if len(x) > _SHORT:          # the types at once (a set of them)
                if not types.issuperset(map(type, x)):
                    raise Refused
            else:                        # a few values: one by one costs less than the set
                for v in x:
                    if type(v) not in types:
                        raise Refused
            return x.copy()
        return check_exact

    def check_all(x: Any) -> list:
        if type(x) is not list or not shortest <= len(x) <= most:
            raise Refused
        return [check(v) for v in x]
    return check_all


def mapping(check: Check) -> Check:
    """A mapping of text keys to values, each checked."""
    types = _EXACT.get(check)
    if types is not None:            # each value returned as it is: a copy of the mapping
        def check_exact(x: Any) -> dict:
            if type(x) is not dict or not _STR.issuperset(map(type, x)) \
                    or not types.issuperset(map(type, x.values())):
                raise Refused
            return x.copy()
        return check_exact

    def check_all(x: Any) -> dict:
        if type(x) is not dict:
            raise Refused
        out = {}
        for k, v in x.items():
            if type(k) is not str:
                raise Refused
            out[k] = check(v)
        return out
    return check_all


_STR = frozenset((str,))
_SHORT = 4          # a list of up to this many exactly typed values is checked value by value


def first_key(*choices: tuple[str, Check]) -> Check:
    """A mapping checked by the check of the first of the `choices`' keys it has (a union
    told apart by its keys, as `schema.FirstKey`)."""
    def check(x: Any) -> Any:
        if type(x) is dict:
            for key, check_choice in choices:
                if key in x:
                    return check_choice(x)
        raise Refused
    return check


def by_type(choices: dict[type, Check]) -> Check:
    """A value checked by the check of its type (a union told apart by the value's type,
    as `schema.ByType`)."""
    def check(x: Any) -> Any:
        chosen = choices.get(type(x))
        if chosen is None:
            raise Refused
        return chosen(x)
    return check


def pydantic_decides(x: Any) -> Any:
    """A value only pydantic checks (what `generate_shape` cannot write as plain tests)."""
    raise Refused


def record(name: str, fields: dict[str, tuple[Check, Any]],
           keys: Optional[dict[str, str]] = None) -> tuple[type[Record], Check]:
    """A record class and its check; a field's default is `REQUIRED`, a value or a factory.
    `keys` gives the file's key of a field whose name differs (`from` for `from_`)."""
    cls = type(name, (Record,), {"FIELDS": tuple(fields),
                                 "DEFAULTS": {k: d for k, (_, d) in fields.items()}})
    in_file = {(keys or {}).get(f, f): f for f in fields}
    # once per record: each file key's field and check; the fields a file must give; the
    # defaults made by a factory; every field in order with its default (a value, or a
    # place kept for the given or made ones), copied for each section checked
    # a key the record does not know is "checked" by refusing it, in the same look-up
    checks = {key: (field, fields[field][0]) for key, field in in_file.items()}
    unknown = ("", pydantic_decides)
    required = tuple(key for key, field in in_file.items() if fields[field][1] is REQUIRED)
    made = [(key, field, fields[field][1]) for key, field in in_file.items()
            if fields[field][1] is not REQUIRED and callable(fields[field][1])]
    template = {field: default for field, (_, default) in fields.items()}
    new = object.__new__

    def check(x: Any) -> Record:
        if type(x) is not dict:
            raise Refused
        for key in required:
            if key not in x:
                raise Refused
        out = template.copy()
        for key, value in x.items():
            field, check_field = checks.get(key, unknown)
            out[field] = check_field(value)
        if made:
            for key, field, factory in made:
                if key not in x:
                    out[field] = factory()
        section: Record = new(cls)      # (what `Record(**out)` makes, without copying `out`)
        section.__dict__ = out
        return section
    return cls, check


def checked(check: Check, tree: Any) -> Any:
    """What `check` makes of `tree`, or None when pydantic must look at it (it may be wrong)."""
    try:
        return check(tree)
    except (Refused, RecursionError):
        return None
