"""What an error or a warning says, in the language of whoever reads it.

An error carries a message *key* of the errors' catalogue and the message's arguments
(`Said`), never a finished sentence; the sentence is written when it is read, in the
language in use. The catalogues are Project Fluent files, one per language
(`errors/locales/LANG.ftl`, read with `fluent.runtime` as the explanations' and the page's
catalogues are), so plurals (`{ $n -> [one] … *[other] … }`), a word chosen by an argument
(`{ $side -> [internal] … }`) and the order of words belong to each language's file, not
to the code.

The language in use is `language()`: the one a web request asked for (`speaking(lang)`,
for the request's thread), else the process's (`speak(lang)`: the command line's `--lang`
or its locale), else English. English stays the default, so a program that says nothing
reads the messages it always read.

Arguments are written as the language writes them: a float with 6 significant digits and
the language's decimal sign (`0,5` in es, ca, eu), an int as its digits (`fluent_number`
without grouping, so `{ $n -> [one] … }` chooses the plural), a `Num` with its own format
(`Num(gap, ".6g")`), a nested `Said` in the same language (a hint, a list of words), a list
of names joined by commas. Fluent is imported only when a message is read: a command that
succeeds never loads it.
"""
from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from functools import lru_cache
from pathlib import Path
from typing import Any, TypeVar, overload

LOCALES = Path(__file__).resolve().parent / "locales"
KEY = re.compile(r"[a-z][a-z0-9]*(?:-[a-z0-9]+)*\Z")     # a catalogue's key: words joined by dashes
ENGLISH = "en"

_process = [ENGLISH]                                           # the command line's language
_request: ContextVar[str | None] = ContextVar("kinematika_language", default=None)


def language() -> str:
    """The language messages are said in now: the request's (`speaking`), else the
    process's (`speak`), else English."""
    return _request.get() or _process[0]


def speak(lang: str) -> None:
    """Say every message of this process in `lang` (the command line, once, at its start)."""
    _process[0] = lang


@contextmanager
def speaking(lang: str | None) -> Iterator[None]:
    """Say the messages read inside the block in `lang` (a web request's language; None
    leaves the language as it is). A context variable: other threads' requests keep theirs."""
    token = _request.set(lang or None)
    try:
        yield
    finally:
        _request.reset(token)


class Num:
    """A number with its own format spec (`Num(gap, ".6g")`, `Num(size, ",")`): written with
    the spec, then with the language's decimal sign and digit grouping."""

    __slots__ = ("spec", "value")

    def __init__(self, value: float, spec: str) -> None:
        self.value, self.spec = value, spec

    def written(self, lang: str) -> str:
        """The number in `lang` (its format spec, the language's signs)."""
        return localized(format(self.value, self.spec), lang)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Num) and (self.value, self.spec) == (other.value, other.spec)

    def __hash__(self) -> int:
        return hash((self.value, self.spec))

    def __reduce__(self) -> tuple:
        return Num, (self.value, self.spec)


class Names:
    """Names for a message, joined by commas: at most `limit` of them, then how many more
    (`…, (3 more)` in the language in use); `none` in that language when there are none.
    With `joined="or"` (or `"and"`) they are joined by the language's word for it (`a or b or c`), with
    `joined="last-or"` the last two only (`a, b or c`)."""

    __slots__ = ("items", "joined", "limit")

    def __init__(self, items: Any, limit: int | None = 12, joined: str = ",") -> None:
        self.items, self.limit, self.joined = list(items), limit, joined

    def written(self, lang: str) -> str:
        """The names as `lang` joins them (its words for none, or, and, more)."""
        from ..text import shown

        cat = catalogue(lang)
        items = [str(_argument(i, lang)) for i in self.items]
        if not items:
            return cat.format("none", {})
        if self.joined in ("or", "and"):
            return f" {cat.format(self.joined + '-word', {})} ".join(items)
        if self.joined == "last-or":
            return ", ".join(items[:-1]) + f" {cat.format('or-word', {})} " + items[-1] if len(items) > 1 else items[0]
        if self.joined == ";":
            return "; ".join(items)
        if self.limit is None:
            return ", ".join(items)
        head = ", ".join(shown(n, 40) for n in items[:self.limit])
        more = len(items) - self.limit
        return head + (cat.format("more", {"n": _argument(more, lang)}) if more > 0 else "")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Names) and (self.items, self.limit, self.joined) == (
            other.items, other.limit, other.joined)

    def __hash__(self) -> int:
        return hash((len(self.items), self.limit, self.joined))

    def __reduce__(self) -> tuple:
        return Names, (self.items, self.limit, self.joined)


def localized(number: str, lang: str) -> str:
    """A number Python wrote (`1,234.5`) with the language's signs (`1.234,5` in es)."""
    if lang == ENGLISH:
        return number
    from ..numerals import decimal_sign

    return number if decimal_sign(lang) == "." else number.translate(_SWAPPED)


_SWAPPED = str.maketrans({".": ",", ",": "."})


class Said:
    """A message of the errors' catalogue: its `key` and its arguments, said in any language.

    A `Said` made from text that is not a key (`Said.text_of`) says that text as it is, in
    every language: the words of another program (an operating system's reason) or of the
    user."""

    __slots__ = ("_cache", "args", "key")

    def __init__(self, key: str, /, **args: Any) -> None:
        self.key = key
        self.args = args
        self._cache: dict[str, str] = {}

    @classmethod
    def text_of(cls, text: str) -> "Said":
        """Text said as it is, in every language (not a catalogue's message)."""
        return cls("", text=str(text))

    @classmethod
    def of(cls, message: "str | Said", args: dict[str, Any]) -> "Said":
        """`message` as a `Said`: itself, a key with `args`, or text that is not a key."""
        if isinstance(message, Said):
            return message
        message = str(message)
        return cls(message, **args) if KEY.match(message) else cls.text_of(message)

    def said(self, lang: str | None = None) -> str:
        """The message in `lang` (default: the language in use)."""
        lang = lang or language()
        if lang not in self._cache:
            self._cache[lang] = self._written(lang)
        return self._cache[lang]

    def _written(self, lang: str) -> str:
        if not self.key:
            return str(self.args.get("text", ""))
        return catalogue(lang).format(self.key, {k: _argument(v, lang) for k, v in self.args.items()})

    def __str__(self) -> str:
        return self.said()

    def __repr__(self) -> str:
        return f"Said({self.key!r}, {self.args!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Said) and (self.key, self.args) == (other.key, other.args)

    def __hash__(self) -> int:
        return hash(self.key)

    def __reduce__(self) -> tuple:
        return _said, (self.key, self.args)


def _said(key: str, args: dict[str, Any]) -> Said:
    return Said(key, **args)


_T = TypeVar("_T")


class SaidLater(Sequence[_T]):
    """`count` messages made on first reading, by `make` (which gives them all, in order).

    The rows of a large system carry a label each (thousands for a 1000-body chain: a
    tenth of its solve's work), read only when an error names a row; made here when one is
    read (`len` needs none). A `SaidLater` and a sequence added (`+`) are another, and
    `reordered` gives the messages in another order, both made when read. The messages are
    the same objects every reading gives, as the list `make` returns. Other texts read only
    with them (each row's place in the file) are made later the same way."""

    __slots__ = ("_count", "_made", "_make")

    def __init__(self, count: int, make: Callable[[], Sequence[_T]]) -> None:
        self._count, self._make = count, make
        self._made: Sequence[_T] | None = None

    def made(self) -> Sequence[_T]:
        """Every message, made on the first call."""
        if self._made is None:
            self._made = self._make()
            if len(self._made) != self._count:
                raise ValueError(f"{len(self._made)} messages made where {self._count} were counted")
        return self._made

    def __len__(self) -> int:
        return self._count

    @overload
    def __getitem__(self, index: int) -> _T: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[_T]: ...

    def __getitem__(self, index: int | slice) -> _T | Sequence[_T]:
        return self.made()[index]

    def __iter__(self) -> Iterator[_T]:
        return iter(self.made())

    def __add__(self, other: Sequence[_T]) -> "SaidLater[_T]":
        return SaidLater.joined([self, other])

    @staticmethod
    def joined(pieces: Sequence[Sequence[_T]]) -> "SaidLater[_T]":
        """The messages of `pieces`, one after the other."""
        return SaidLater(sum(len(p) for p in pieces), lambda: [said for p in pieces for said in p])

    def reordered(self, order: Sequence[int]) -> "SaidLater[_T]":
        """The messages at `order`'s positions, in that order."""
        return SaidLater(len(order), lambda: [self.made()[i] for i in order])

    def __repr__(self) -> str:
        return f"SaidLater({self._count}, made={self._made is not None})"


def _argument(value: Any, lang: str) -> Any:
    """An argument as Fluent takes it in `lang` (see the module's docstring)."""
    if isinstance(value, Said):
        return value.said(lang)
    if isinstance(value, (Num, Names)):
        return value.written(lang)
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int):
        from fluent.runtime.types import fluent_number

        return fluent_number(value, useGrouping=False)
    if isinstance(value, float):
        return localized(format(value, "g"), lang)
    if isinstance(value, (list, tuple)):
        return Names(value, None).written(lang)
    return "" if value is None else str(value)


class Catalogue:
    """The errors' messages in one language (a Fluent bundle)."""

    def __init__(self, lang: str, source: str) -> None:
        from fluent.runtime import FluentBundle, FluentResource

        self.lang = lang
        self.source = source
        self.bundle = FluentBundle([lang], use_isolating=False)
        self.bundle.add_resource(FluentResource(source))

    def keys(self) -> list[str]:
        """The catalogue's keys, in file order."""
        return re.findall(r"^([a-z][\w-]*)\s*=", self.source, re.M)

    def format(self, key: str, args: dict[str, Any]) -> str:
        """Message `key` with its arguments; a key the catalogue lacks is said in English
        (and a key no catalogue has, as the key itself: a test keeps every key known)."""
        if not self.bundle.has_message(key):
            return catalogue(ENGLISH).format(key, args) if self.lang != ENGLISH else key
        message = self.bundle.get_message(key)
        if message.value is None:
            return key
        text, _ = self.bundle.format_pattern(message.value, args)
        return str(text)


def read_catalogue(folder: Path, lang: str) -> Catalogue:
    """The Fluent catalogue `folder/LANG.ftl` (English for a language kinematika does not
    speak): the errors' here, the figures' words in `draw.words`."""
    path = folder / f"{lang}.ftl"
    if not path.is_file():
        lang, path = ENGLISH, folder / f"{ENGLISH}.ftl"
    return Catalogue(lang, path.read_text(encoding="utf-8"))


@lru_cache(maxsize=None)
def catalogue(lang: str) -> Catalogue:
    """The errors' catalogue of `lang` (English for a language kinematika does not speak)."""
    return read_catalogue(LOCALES, lang)
