"""The kinds of joint, each in one module that says everything the kind means (its fields,
capabilities, conditions at an instant, structure, centres, drawing and explanation), and
the registry the rest of kinematika asks (`KINDS`, `kind`). Adding a kind is adding its
module and its line below.

A kind's module is imported when a model first uses it (`kind`), or when every kind is asked
for (iterating `KINDS`): a command starts without importing kinds it does not need.
"""
from __future__ import annotations

from collections.abc import Iterator, Mapping
from importlib import import_module

from .base import AXES, Holonomic, JointGeometry, JointKind, Rows, rounding_hint

MODULES = {                        # the kind's name in model files -> its module
    "revolute": "revolute",
    "prismatic": "prismatic",
    "slot": "slot",
    "wheel": "wheel",
    "rolling": "rolling",
    "gear": "gear",
    "spherical": "spherical",
    "weld": "weld",
    "cylindrical": "cylindrical",
    "contact": "contact",
    "curved_slot": "curved_slot",
    "cam": "cam",
}


class Registry(Mapping):
    """The kinds by name, each imported on first use (then remembered: the engine asks a
    joint's kind for every row)."""

    def __init__(self) -> None:
        self._loaded: dict[str, JointKind] = {}

    def __getitem__(self, name: str) -> JointKind:
        found = self._loaded.get(name)
        if found is None:
            module = MODULES[name]           # KeyError for an unknown kind, as a dict's
            found = self._loaded[name] = import_module(f".{module}", __name__).KIND
        return found

    def __iter__(self) -> Iterator[str]:
        return iter(MODULES)

    def __len__(self) -> int:
        return len(MODULES)


KINDS: Mapping[str, JointKind] = Registry()

__all__ = ["AXES", "KINDS", "MODULES", "Holonomic", "JointGeometry", "JointKind", "Rows", "kind", "rounding_hint"]


def kind(name: str) -> JointKind:
    """The kind of joint called `name` in model files."""
    return KINDS[name]
