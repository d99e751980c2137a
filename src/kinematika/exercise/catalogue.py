"""The words of an exercise (statement, sheets, key, the quiz's feedback, the page's exercise
mode) in en, es, ca and eu: Fluent catalogues in `exercise/locales/`, read as the
explanation's are (`explain.catalogue.Catalogue`), kept apart from the explanation's own."""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from ..explain.catalogue import Catalogue
from ..languages import LANGS, known

LOCALES = Path(__file__).resolve().parent / "locales"

__all__ = ["LANGS", "catalogue"]


@lru_cache(maxsize=None)
def catalogue(lang: str) -> Catalogue:
    """The exercise catalogue of `lang` (one of LANGS, else the `--lang` usage error)."""
    return Catalogue(known(lang), (LOCALES / f"{lang}.ftl").read_text(encoding="utf-8"))
