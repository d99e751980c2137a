"""A registry of kinds (joints, questions): one module per kind, each imported on first use.

A kind's module defines `KIND`, its one instance; the registry maps the kind's name in model
files to it, importing `package.module` only when the kind is first asked for (a command
loads only the kinds its model uses) and remembering it after (the engine asks a joint's
kind for every row)."""
from __future__ import annotations

from collections.abc import Iterator, Mapping
from importlib import import_module
from typing import Generic, TypeVar

K = TypeVar("K")


class Registry(Mapping[str, K], Generic[K]):
    """The kinds of `package` by name: `modules` maps each name to its module in the package."""

    def __init__(self, package: str, modules: Mapping[str, str]) -> None:
        self._package = package
        self._modules = modules
        self._loaded: dict[str, K] = {}

    def __getitem__(self, name: str) -> K:
        found = self._loaded.get(name)
        if found is None:
            module = self._modules[name]     # KeyError for an unknown kind, as a dict's
            found = self._loaded[name] = import_module(f".{module}", self._package).KIND
        return found

    def __iter__(self) -> Iterator[str]:
        return iter(self._modules)

    def __len__(self) -> int:
        return len(self._modules)
