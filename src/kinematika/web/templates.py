"""Starter models for the page's New menu: a blank model and two mechanisms stated by their
dimensions (a four-bar, an offset slider-crank), read once from the package."""
from __future__ import annotations

from importlib import resources

_FOLDER = resources.files("kinematika.web") / "templates"
TEMPLATES: dict[str, str] = {f.name.removesuffix(".yaml"): f.read_text(encoding="utf-8")
                             for f in sorted(_FOLDER.iterdir(), key=str) if f.name.endswith(".yaml")}
