"""The kinds of joint, each in one module that says everything the kind means (its fields,
capabilities, conditions at an instant, structure, centres, drawing and explanation), and
the registry the rest of kinematika asks (`KINDS`, `kind`). Adding a kind is adding its
module and its line below."""
from __future__ import annotations

from . import cam, contact, curved_slot, cylindrical, gear, prismatic, revolute, rolling, slot, spherical, weld, wheel
from .base import AXES, JointGeometry, JointKind, Rows, rounding_hint

KINDS: dict[str, JointKind] = {k.name: k for k in (
    revolute.KIND, prismatic.KIND, slot.KIND, wheel.KIND, rolling.KIND, gear.KIND,
    spherical.KIND, weld.KIND, cylindrical.KIND, contact.KIND, curved_slot.KIND, cam.KIND,
)}

__all__ = ["AXES", "KINDS", "JointGeometry", "JointKind", "Rows", "kind", "rounding_hint"]


def kind(name: str) -> JointKind:
    """The kind of joint called `name` in model files."""
    return KINDS[name]
