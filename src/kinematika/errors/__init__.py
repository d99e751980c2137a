"""The one error type users see: a kind from the contract, a message and a place.

The message is a key of the errors' catalogue and its arguments (`said.Said`), written in
the language in use when it is read (`said.language`: English unless the command line's
`--lang`, its locale, or a web request's `lang` says otherwise); see docs/model-format.md,
"Errors"."""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..limits import MESSAGE_CHARS, WHERE_CHARS
from ..text import clip_middle, shown
from .said import Names, Num, Said, SaidLater, language, speak, speaking

__all__ = ["KINDS", "KinematikaError", "KinematikaWarning", "Names", "Num", "Said", "SaidLater", "language", "parser_problem",
           "pydantic_choices", "pydantic_problem", "reason", "said_of", "speak", "speaking"]

KINDS = ("syntax", "schema", "geometry", "mobility", "singular", "assembly",
         "output",     # an extension: a result file that cannot be written
         "usage",      # an extension: a command-line option the command does not accept
         "limit")      # an extension: valid work beyond a documented limit (symbolic time)


class _OneLine:
    """What an error and a warning share: a `said` message and a `where`, written as one line
    (`where: message`) in the language in use."""

    said: Said
    where: str

    @property
    def message(self) -> str:
        """The message in the language in use."""
        return shown(self.said.said(), MESSAGE_CHARS)

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message


class KinematikaError(_OneLine, Exception):
    """A problem with the user's model, reported as one line, never a traceback.

    `kind` is one of the contract's error kinds (the same English word in every language);
    `message` a key of the errors' catalogue, its arguments given by name
    (``KinematikaError("schema", "unknown-point", where, point="B", points=["A", "C"])``),
    or a `Said`; `where` names the place in the model (``joints[2] (j3)``, ``points.A``) or
    is empty when the whole model is concerned. The message and the place are one printable
    line (control characters escaped) of bounded length.
    """

    def __init__(self, kind: str, message: "str | Said", /, where: str = "", **args: Any) -> None:
        if kind not in KINDS:
            raise ValueError(f"unknown error kind {kind!r}")
        self.said = Said.of(message, args)
        where = clip_middle(shown(where), WHERE_CHARS)
        super().__init__(kind, self.said, where)
        self.kind = kind
        self.where = where

    def __reduce__(self) -> tuple:
        return type(self), (self.kind, self.said, self.where)

    def as_json(self) -> dict:
        """The contract's JSON form of the error (its message in the language in use)."""
        return {"error": {"kind": self.kind, "message": self.message, "where": self.where}}


class KinematikaWarning(_OneLine, UserWarning):
    """Input answered as written that is most likely a mistake (an angle of 30 rad where 30°
    was meant): a message (a catalogue's key and its arguments, as an error's) and a place,
    one line each. The command line prints it on standard error, the JSON answer lists it
    under `warnings`, the page shows it, and from Python it is a standard warning
    (`warnings.catch_warnings` catches it)."""

    def __init__(self, message: "str | Said", /, where: str = "", **args: Any) -> None:
        self.said = Said.of(message, args)
        self.where = clip_middle(shown(where), WHERE_CHARS)
        super().__init__(self.said, self.where)

    def __reduce__(self) -> tuple:
        return type(self), (self.said, self.where)

    def as_json(self) -> dict:
        """The answer's JSON form: `{"message": ..., "where": ...}`."""
        return {"message": self.message, "where": self.where}


def reason(err: OSError) -> Said:
    """Why the operating system refused (a file that cannot be read or written): said by
    its error number's name (`ENOENT`, `EACCES`…) in every language the catalogue knows it,
    else in the system's own words."""
    import errno

    return Said("reason", errno=errno.errorcode.get(err.errno or 0, "other"), text=str(err.strerror or err))


# what the YAML, JSON and TOML readers and Python's parser and math say most often, by words
# of their own message
PROBLEMS = (("mapping values are not allowed", "mapping-values"), ("could not find expected ':'", "colon"),
            ("cannot start any token", "token"), ("did not find expected key", "key"),
            ("did not find expected ',' or ']'", "bracket"), ("did not find expected ',' or '}'", "brace"),
            ("found unexpected end of stream", "end"), ("found undefined alias", "alias"),
            ("did not find expected node content", "node"), ("found unknown escape character", "escape"),
            ("Expecting value", "value"), ("Expecting property name", "property"),
            ("Expecting ',' delimiter", "comma"), ("Expecting ':' delimiter", "colon"),
            ("Extra data", "extra"), ("Unterminated string", "string"), ("Invalid control character", "control"),
            ("Invalid \\escape", "escape"), ("Invalid value", "value"), ("Unclosed array", "bracket"),
            ("Unclosed inline table", "brace"), ("Expected '=' after a key", "equals"),
            ("Cannot overwrite a value", "duplicate"), ("Cannot declare", "duplicate"),
            ("invalid syntax", "syntax"), ("was never closed", "unclosed"), ("unmatched", "unmatched"),
            ("unexpected EOF", "end"), ("invalid decimal literal", "literal"), ("math domain error", "domain"),
            ("math range error", "range"), ("too small for floating-point", "small"),
            ("division by zero", "zero"), ("division or modulo by zero", "zero"))


def parser_problem(text: str) -> Said:
    """A reader's complaint (PyYAML's, json's, tomllib's, Python's), said in the language in use
    when it is one of the usual ones (`PROBLEMS`), else in the reader's own words."""
    code = next((code for phrase, code in PROBLEMS if phrase in text), "other")
    return Said("problem", code=code, text=text)


def pydantic_problem(error: Mapping[str, Any], lower: bool = False) -> Said:
    """What pydantic found wrong with a value (one of its `errors()`), said by the error's
    type and context (`too_short` and its `min_length`…) in every language the catalogue
    knows it, else in pydantic's own words (`lower`: its first letter small, as English
    writes it after a colon)."""
    text = str(error.get("msg", ""))
    ctx = {k: v for k, v in (error.get("ctx") or {}).items() if isinstance(v, (int, float, str))}
    return Said("pydantic", type=str(error.get("type", "")), text=text.lower() if lower else text,
                **{f"ctx_{k}": v for k, v in ctx.items() if not isinstance(v, bool)})


def pydantic_choices(expected: str) -> "Names | str":
    """pydantic's list of the values a literal allows (`'a', 'b' or 'c'`), as names joined
    by the language's "or" when it has that shape, else as it is."""
    import re

    values = re.findall(r"'[^']*'|\d+(?:\.\d+)?", expected)
    rebuilt = ", ".join(values[:-1]) + " or " + values[-1] if len(values) > 1 else "".join(values)
    return Names(values, joined="last-or") if rebuilt == expected else expected


def said_of(err: BaseException) -> Said:
    """What an exception says: its `said` (an `ExpressionError`'s), the `Said` it was raised
    with (``ValueError(Said("spline-points-differ"))``), else its text as it is."""
    said = getattr(err, "said", None)
    if isinstance(said, Said):
        return said
    if err.args and isinstance(err.args[0], Said):
        return err.args[0]
    return Said.text_of(str(err))
