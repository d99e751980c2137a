"""The kinds of joint, each in one module that says everything the kind means (its fields,
capabilities, conditions at an instant, structure, centres, drawing and explanation), and
the registry the rest of kinematika asks (`KINDS`, `kind`). Adding a kind is adding its
module and its line below.

A kind's module is imported when a model first uses it (`kind`), or when every kind is asked
for (iterating `KINDS`): a command starts without importing kinds it does not need.
"""
from __future__ import annotations

from collections.abc import Mapping

from ..registry import Registry
from .base import AXES, JointGeometry, JointKind, NumericRows, Rows, rounding_hint

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


KINDS: Mapping[str, JointKind] = Registry(__name__, MODULES)   # each kind imported on first use

__all__ = ["AXES", "KINDS", "MODULES", "JointGeometry", "JointKind", "NumericRows", "Rows", "kind", "rounding_hint"]


def kind(name: str) -> JointKind:
    """The kind of joint called `name` in model files."""
    return KINDS[name]
