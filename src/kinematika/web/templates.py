"""Starter models for the page's New menu, in the student's language: a blank model and
two mechanisms stated by their dimensions (a four-bar, an offset slider-crank), their
comments and body names in en, es, ca, eu (`templates/NAME.yaml`, `templates/NAME.LANG.yaml`),
read once from the package."""
from __future__ import annotations

from importlib import resources

_FOLDER = resources.files("kinematika.web") / "templates"
_FILES = {f.name.removesuffix(".yaml"): f.read_text(encoding="utf-8")
          for f in sorted(_FOLDER.iterdir(), key=str) if f.name.endswith(".yaml")}
NAMES = tuple(n for n in _FILES if "." not in n)


def template(name: str, lang: str = "en") -> str:
    """The starter model `name` in `lang` (English where no translation is shipped)."""
    return _FILES.get(f"{name}.{lang}", _FILES[name])
