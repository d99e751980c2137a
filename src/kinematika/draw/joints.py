"""Joint symbols: each kind of joint says how it is drawn (its `symbol`: polygons, lines and
dots; `kinematika.joints.symbols`), in the body it moves with (an animation and the page
move them), keeping labels off them. `draw.picture` puts them in the figure with their
colours; the painters paint them as they are."""
from __future__ import annotations

from ..joints import kind as joint_kind
from ..joints.symbols import Mark
from .geometry import Box
from .context import Context
from .scene import Scene


def scene_symbols(scene: Scene, view: Box, still: bool = True) -> list[Mark]:
    """Every joint's marks on a figure of `scene` showing `view` (colours as roles)."""
    ctx = Context(scene, view, still)
    return [m for j in scene.joints for m in joint_kind(j.type).symbol(j, ctx)]
