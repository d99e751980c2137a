"""The page's own words in en, es, ca and eu: Fluent catalogues (web/locales/LANG.ftl, read
with the explanations' `Catalogue`), served to the page as JSON (`GET /api/strings/LANG`).

A message's variables come to the page as `{$name}` markers, which `i18n.js` fills; page
messages therefore use no selectors (a test keeps it so). The decimal sign is the one the
explanations write (Babel's: a comma in es, ca, eu).
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Any

from ..errors import KinematikaError
from ..explain.catalogue import VARIABLE, Catalogue
from ..languages import known
from ..numerals import decimal_sign

LOCALES = Path(__file__).resolve().parent / "locales"


@lru_cache(maxsize=None)
def page_catalogue(lang: str) -> Catalogue:
    """The page's catalogue of `lang`."""
    known(lang, "lang", "usage")
    return Catalogue(lang, (LOCALES / f"{lang}.ftl").read_text(encoding="utf-8"))


@lru_cache(maxsize=None)
def page_strings(lang: str) -> dict[str, Any]:
    """Every message of the page in `lang`, its variables left as `{$name}` markers."""
    cat = page_catalogue(lang)
    messages = {}
    for key in cat.keys():  # noqa: SIM118 - the catalogue's ids in file order (Catalogue.keys)
        message = cat.bundle.get_message(key)
        if message.value is None:       # a message of attributes only: the page shows none
            raise KinematikaError("schema", "page-message-error", "strings", key=key, lang=lang,
                                  problem="the message has no value")
        names = set(VARIABLE.findall(_source(cat.source, key)))
        text, errors = cat.bundle.format_pattern(message.value, {n: f"{{${n}}}" for n in names})
        if errors:
            raise KinematikaError("schema", "page-message-error", "strings", key=key, lang=lang, problem=str(errors[0]))
        messages[key] = text
    return {"lang": lang, "decimal": decimal_sign(lang), "messages": messages}


def _source(source: str, key: str) -> str:
    """A message's lines in the catalogue (its first line and the indented ones after it)."""
    found = re.search(rf"^{re.escape(key)}\s*=.*(?:\n[ \t]+.*)*", source, re.M)
    return found.group(0) if found else ""
