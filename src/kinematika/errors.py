"""The one error type users see: a kind from the contract, a message and a place."""
from __future__ import annotations

from .limits import MESSAGE_CHARS, WHERE_CHARS
from .text import clip_middle, shown

KINDS = ("syntax", "schema", "geometry", "mobility", "singular", "assembly",
         "output",     # an extension: a result file that cannot be written
         "usage",      # an extension: a command-line option the command does not accept
         "limit")      # an extension: valid work beyond a documented limit (symbolic time)


class KinematikaError(Exception):
    """A problem with the user's model, reported as one line, never a traceback.

    `kind` is one of the contract's error kinds; `where` names the place in the model
    (``joints[2] (j3)``, ``points.A``) or is empty when the whole model is concerned. Both
    are one printable line (control characters escaped) of bounded length.
    """

    def __init__(self, kind: str, message: str, where: str = "") -> None:
        if kind not in KINDS:
            raise ValueError(f"unknown error kind {kind!r}")
        message = shown(message, MESSAGE_CHARS)
        where = clip_middle(shown(where), WHERE_CHARS)
        super().__init__(message)
        self.kind = kind
        self.message = message
        self.where = where

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message

    def as_json(self) -> dict:
        """The contract's JSON form of the error."""
        return {"error": {"kind": self.kind, "message": self.message, "where": self.where}}


class KinematikaWarning(UserWarning):
    """Input answered as written that is most likely a mistake (an angle of 30 rad where 30°
    was meant): a message and a place, one line each. The command line prints it on
    standard error, the JSON answer lists it under `warnings`, the page shows it, and from
    Python it is a standard warning (`warnings.catch_warnings` catches it)."""

    def __init__(self, message: str, where: str = "") -> None:
        self.message = shown(message, MESSAGE_CHARS)
        self.where = clip_middle(shown(where), WHERE_CHARS)
        super().__init__(self.message)

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message

    def as_json(self) -> dict:
        """The answer's JSON form: `{"message": ..., "where": ...}`."""
        return {"message": self.message, "where": self.where}
