"""The languages kinematika speaks (explanations, figures' numbers, the page): their codes,
and the check of a code given by a user."""
from __future__ import annotations

from .errors import KinematikaError

LANGS = ("en", "es", "ca", "eu")


def known(lang: str, where: str = "--lang", kind: str = "schema") -> str:
    """`lang` when it is one of LANGS, else the one-line error of `kind` naming its place
    `where` (an option, a model's key such as ``names.fr``, a request's field)."""
    if lang not in LANGS:
        raise KinematikaError(kind, "unknown-language", where, lang=lang, langs=list(LANGS))
    return lang
