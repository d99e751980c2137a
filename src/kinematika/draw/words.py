"""The words a figure writes itself, in the figure's language: its legend, the notes under
it and the labels that say where a far-off or infinite centre lies.

Everything else on a figure is the model's (bodies' and points' names, in the language
through the model's `names`) or a symbol. The words are a Project Fluent catalogue per
language (`draw/locales/LANG.ftl`), read with the errors' `Catalogue` (the same reader as
every other catalogue); a figure without a language (`DrawOptions.lang` None) is English.
A test keeps the four catalogues' keys the same (tests/draw/test_words.py).
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any, Optional

from ..errors.said import ENGLISH, Catalogue, read_catalogue

LOCALES = Path(__file__).resolve().parent / "locales"


@lru_cache(maxsize=None)
def catalogue(lang: str) -> Catalogue:
    """The figures' words in `lang` (English for a language kinematika does not speak)."""
    return read_catalogue(LOCALES, lang)


def word(key: str, lang: Optional[str] = None, **args: Any) -> str:
    """Message `key` of the figures' catalogue in `lang` (None: English), its arguments
    already written (numbers in the language's own way by the caller)."""
    return catalogue(lang or ENGLISH).format(key, args)
