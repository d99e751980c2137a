"""Message catalogues: every word of an explanation, per language, in locales/LANG.yaml.

A message is a string with named placeholders (`{body}`); the renderer fills them with
formatted symbols, values and nested messages. The code holds keys only.
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import yaml

from ..errors import KinematikaError

LANGS = ("en", "es", "ca", "eu")
LOCALES = Path(__file__).resolve().parent / "locales"
PLACEHOLDER = re.compile(r"\{(\w+)\}")


class Catalogue:
    """The messages of one language."""

    def __init__(self, lang: str, messages: dict[str, str]) -> None:
        self.lang = lang
        self.messages = messages

    def get(self, key: str) -> str:
        try:
            return self.messages[key]
        except KeyError:
            raise KinematikaError("schema", f"no message {key!r} in the {self.lang!r} catalogue",
                                  "explain") from None

    def pieces(self, key: str) -> list[tuple[str, str]]:
        """The message split into ("text", literal) and ("arg", name) pieces."""
        text, out, last = self.get(key), [], 0
        for m in PLACEHOLDER.finditer(text):
            out.append(("text", text[last:m.start()]))
            out.append(("arg", m.group(1)))
            last = m.end()
        out.append(("text", text[last:]))
        return out


@lru_cache(maxsize=None)
def catalogue(lang: str) -> Catalogue:
    """The catalogue of `lang` (one of LANGS), read once."""
    if lang not in LANGS:
        raise KinematikaError("schema", f"unknown language {lang!r} (languages: {', '.join(LANGS)})",
                              "--lang")
    with open(LOCALES / f"{lang}.yaml", encoding="utf-8") as fh:
        data = yaml.safe_load(fh)
    return Catalogue(lang, {str(k): str(v) for k, v in data.items()})
