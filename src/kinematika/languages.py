"""The languages kinematika speaks (explanations, figures' numbers, the page): their codes,
and the check of a code given by a user."""
from __future__ import annotations

from .errors import KinematikaError

LANGS = ("en", "es", "ca", "eu")


def known(lang: str) -> str:
    """`lang` when it is one of LANGS, else the one-line error naming `--lang`."""
    if lang not in LANGS:
        raise KinematikaError("schema", f"unknown language {lang!r} (languages: {', '.join(LANGS)})",
                              "--lang")
    return lang
