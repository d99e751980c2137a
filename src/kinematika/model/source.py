"""A model from whatever holds one: a `Model`, a model file's path, a model tree (a dict as a
file holds), a `Mechanism` being built, or a model's text."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Union

from .build import build_model
from .files import load_model, parse_text
from .model import Model

ModelLike = Union[Model, str, Path, dict, Any]


def as_model(source: ModelLike, fmt: Optional[str] = None) -> Model:
    """A `Model` from a model, a file path, a model tree (dict), a `Mechanism` or the text of
    a model (a string of several lines, or any string when `fmt` names its format: 'yaml',
    'toml' or 'json')."""
    if isinstance(source, Model):
        return source
    if isinstance(source, dict):
        return build_model(source)
    if hasattr(source, "to_model"):
        return source.to_model()
    if isinstance(source, str) and (fmt is not None or "\n" in source):   # a model's text
        return build_model(parse_text(source, fmt or "yaml", "<text>"))
    return load_model(source)
