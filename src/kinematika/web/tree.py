"""A model's round-trip tree (see `document`), read and changed as the model format says:
its points, bodies (short and long forms), joints, drivers and questions, fresh names,
and numbers written as a person writes them."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterable, Optional

from ..errors import KinematikaError
from . import document

PIVOTS = "O"                                       # ground pivots: O1, O2, ...
LETTERS = "ABCDEFGHJKLMNPQRSTUVWXYZ"               # moving points: A, B, ... (no I, no O)


@dataclass
class Tree:
    """The tree of one model text and its format."""

    root: Any
    fmt: str

    # sections --------------------------------------------------------------------------
    @property
    def frame(self) -> str:
        """The fixed body's name (`frame:`, else ground)."""
        return str(self.root.get("frame") or "ground")

    def points(self) -> Any:
        """The `points` section (made when missing)."""
        return document.section(self.root, "points", dict, self.fmt)

    def bodies(self) -> Any:
        """The `bodies` section, with the fixed body in it (both made when missing)."""
        bodies = document.section(self.root, "bodies", dict, self.fmt)
        if self.frame not in bodies:
            bodies[self.frame] = document.new_list(self.fmt, [])
        return bodies

    def joints(self) -> Any:
        """The `joints` list (made when missing)."""
        return document.section(self.root, "joints", list, self.fmt)

    def drivers(self) -> Any:
        """The `drivers` list (made when missing)."""
        return document.section(self.root, "drivers", list, self.fmt)

    def asks(self) -> Any:
        """The `ask` list (made when missing)."""
        return document.section(self.root, "ask", list, self.fmt)

    def existing(self, key: str) -> list:
        """A top-level list (joints, drivers, ask) as it is, or an empty one (nothing made)."""
        return self.root.get(key) or []

    def parameters(self) -> Optional[Any]:
        """The `parameters` section, or None when the model has none (nothing made)."""
        return self.root.get("parameters")

    # bodies ----------------------------------------------------------------------------
    def body_points(self, name: str) -> list[str]:
        """The points a body lists (short form `[A, B]` or `{points: [...]}`)."""
        body = self.bodies().get(name)
        if body is None:
            return []
        listed = body.get("points", []) if isinstance(body, dict) else body
        return [str(p) for p in listed or []]

    def add_to_body(self, name: str, point: str) -> None:
        """List `point` in body `name` (made, in the short form, when new)."""
        bodies = self.bodies()
        body = bodies.get(name)
        if body is None:
            bodies[name] = document.new_list(self.fmt, [point])
            return
        listed = body.get("points") if isinstance(body, dict) else body
        if listed is None:
            body["points"] = document.new_list(self.fmt, [point])
        elif point not in [str(p) for p in listed]:
            listed.append(point)

    def carriers(self, point: str) -> list[str]:
        """The bodies that list `point`, the fixed body first."""
        names = [b for b in self.bodies() if point in self.body_points(str(b))]
        return sorted((str(b) for b in names), key=lambda b: b != self.frame)

    def owner(self, point: str) -> Optional[str]:
        """The body a new joint at `point` joins: the fixed body if it lists the point, else
        the first body that does."""
        found = self.carriers(point)
        return found[0] if found else None

    # names -----------------------------------------------------------------------------
    def fresh_point(self, pivot: bool = False) -> str:
        """A point name not used yet: O1, O2 ... for a ground pivot, else A, B, C ..."""
        used = {str(p) for p in self.points()}
        if pivot:
            return next(f"{PIVOTS}{i}" for i in range(1, 10_000) if f"{PIVOTS}{i}" not in used)
        for suffix in ("", *map(str, range(1, 1000))):
            for letter in LETTERS:
                if letter + suffix not in used:
                    return letter + suffix
        raise KinematikaError("usage", "no-free-point-name", "points")

    def fresh_body(self, prefix: str) -> str:
        """A body name not used yet: `prefix` numbered from 1 (crank1, crank2 ...)."""
        used = {str(b) for b in self.bodies()}
        return next(f"{prefix}{i}" for i in range(1, 10_000) if f"{prefix}{i}" not in used)

    def fresh_parameter(self, prefix: str) -> str:
        """A parameter name not used yet: `prefix` numbered from 1 (R1, R2 ...)."""
        used = {str(p) for p in (self.parameters() or {})}
        return next(f"{prefix}{i}" for i in range(1, 10_000) if f"{prefix}{i}" not in used)

    def set_parameter(self, name: str, value: Any) -> None:
        """Give a parameter a value (the section made before `points` if new)."""
        document.section(self.root, "parameters", dict, self.fmt)[name] = value

    # joints ----------------------------------------------------------------------------
    def joint_ids(self) -> list[str]:
        """Each joint's id: its own, else j1, j2, ... in file order (the format's rule)."""
        return [str(j.get("id") or f"j{i + 1}") for i, j in enumerate(self.existing("joints"))]

    def add_joint(self, items: dict[str, Any]) -> None:
        """Append a joint (a mapping in the file's format, flow style)."""
        self.joints().append(document.new_map(self.fmt, items))

    def map(self, items: dict[str, Any]) -> Any:
        """A mapping in the file's format (YAML flow style or a TOML inline table)."""
        return document.new_map(self.fmt, items)

    def list(self, items: Iterable[Any]) -> Any:
        """A list in the file's format (YAML flow style or a TOML array)."""
        return document.new_list(self.fmt, list(items))


def number(x: float, digits: int = 6) -> float | int:
    """`x` to `digits` significant digits, as an integer when whole (0.15, 30, -0.02)."""
    if not math.isfinite(x):
        raise KinematikaError("usage", "not-finite-number", "value", value=str(x))
    if x == 0:
        return 0
    rounded = float(f"{x:.{digits}g}")
    return int(rounded) if rounded.is_integer() and abs(rounded) < 1e15 else rounded


def degrees(x: float) -> str:
    """An angle in degrees as the format writes it: `deg(30)`."""
    return f"deg({number(round(x, 6), 6)})"


def name_of(node: Any) -> Optional[str]:
    """The text of a scalar that is a bare name (a parameter, a point), else None."""
    if isinstance(node, str) and node.strip().isidentifier():
        return node.strip()
    return None
