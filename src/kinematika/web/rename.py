"""Naming things on the page: a body or a point renamed everywhere the model names it, and
its names per language (the model's `names:`), as edits of the model's round-trip tree.

A body is named by `bodies`' keys, `frame:`, the joints' `bodies`, the drivers' `omega`
and `relative_to`, the questions about bodies (`omega: crank`) and after `@` in a material
point (`B@crank`), `relative_to` and `moving`, `names.LANG.bodies` and the `notation` keys
`omega(crank)`, `alpha(rod/crank)`. A point is named by `points`' keys and the places of
the constructions that use it (`from`, `reference`, `frame`, a circle's centre, a line's
points), the bodies' point lists and shapes (a circle's `center`, a curve's `through` …),
the joints' `at` and `along`, a velocity driver, the questions about points (before `@`),
`names.LANG.points` and the exercise's `dimensions`. Only those places change: a
parameter that happens to be spelt like the name is left alone.
"""
from __future__ import annotations

import re
from typing import Any

from ..errors import KinematikaError, Names
from ..languages import LANGS
from ..questions import QUESTIONS
from . import document
from .tree import Tree

NAME = re.compile(r"[^\W\d]\w*['’]*")          # a letter, then letters, digits, _; primes (A')
RATE_KEY = re.compile(r"^(omega|alpha)\((.+)\)$")


def rename(tree: Tree, element: str, to: Any) -> str:
    """Rename `element` (`body:NAME` or `point:NAME`) to `to` wherever the model names it;
    the element to select afterwards."""
    kind, _, old = str(element).partition(":")
    new = str(to).strip() if isinstance(to, str) else ""
    if not NAME.fullmatch(new):
        raise KinematikaError("usage", "rename-not-a-name", "to", name=new)
    if kind == "body":
        _rename_body(tree, old, new)
    elif kind == "point":
        _rename_point(tree, old, new)
    else:
        raise KinematikaError("usage", "rename-element", "element", element=element)
    return f"{kind}:{new}"


def name_in(tree: Tree, element: str, lang: Any, text: Any) -> None:
    """How a body is called in `lang` (`names.LANG.bodies`), or what a point is
    (`names.LANG.points`); an empty text takes the name away."""
    kind, _, name = str(element).partition(":")
    if lang not in LANGS:
        raise KinematikaError("usage", "rename-language", "lang", lang=lang, langs=Names(LANGS))
    section = {"body": "bodies", "point": "points"}.get(kind)
    if section is None or name not in (tree.bodies() if kind == "body" else tree.points()):
        raise KinematikaError("usage", "rename-nothing", "element", element=element)
    words = " ".join(str(text or "").split())
    names = tree.root.get("names")
    if not words:
        entry = (names or {}).get(lang) or {}
        if name in (entry.get(section) or {}):
            del entry[section][name]
        return
    entry = document.section(document.section(tree.root, "names", dict, tree.fmt), lang, dict, tree.fmt)
    if entry.get(section) is None:
        entry[section] = tree.map({})
    entry[section][name] = words


# bodies ------------------------------------------------------------------------------------
def _rename_body(tree: Tree, old: str, new: str) -> None:
    bodies = tree.bodies()
    if old not in bodies:
        raise KinematikaError("usage", "rename-no-body", "element", name=old)
    if new == old:
        return
    if new in bodies:
        raise KinematikaError("usage", "rename-body-exists", "to", name=new)
    if old == tree.frame:
        document.put(tree.root, "frame", new)
    _rekey(bodies, old, new)
    for j in tree.existing("joints"):
        _replace_in_list(j.get("bodies"), old, new)
    for d in tree.existing("drivers"):
        for key in ("omega", "relative_to"):
            if str(d.get(key)) == old:
                d[key] = new
        if isinstance(d.get("velocity"), str):
            d["velocity"] = _at_body(d["velocity"], old, new)
    for a in tree.existing("ask"):
        for key in list(a):
            value = str(a[key])
            if _about(key) == "point":
                a[key] = _at_body(value, old, new)
            elif _about(key) != "joint" and value == old:   # a body's question, relative_to, moving
                a[key] = new
    for entry in (tree.root.get("names") or {}).values():
        if isinstance(entry, dict) and isinstance(entry.get("bodies"), dict) and old in entry["bodies"]:
            _rekey(entry["bodies"], old, new)
    notation = tree.root.get("notation")
    if isinstance(notation, dict):
        for key, rate_key in [(k, m) for k in notation if (m := RATE_KEY.match(str(k)))]:
            rate, inside = rate_key.groups()
            parts = [new if p == old else p for p in inside.split("/")]
            if "/".join(parts) != inside:
                _rekey(notation, key, f"{rate}({'/'.join(parts)})")


def _about(key: Any) -> str | None:
    """What a question's key names (`QuestionKind.about`: a point, a body, a joint); None for
    `relative_to`, `moving` or an unknown key."""
    key = str(key)
    return QUESTIONS[key].about if key in QUESTIONS else None


def _at_body(ref: str, old: str, new: str) -> str:
    """A material point `P@BODY` with the body renamed (a bare point stays)."""
    point, at, body = ref.partition("@")
    return f"{point}@{new}" if at and body == old else ref


# points ------------------------------------------------------------------------------------
def _rename_point(tree: Tree, old: str, new: str) -> None:
    points = tree.points()
    if old not in points:
        raise KinematikaError("usage", "rename-no-point", "element", name=old)
    if new == old:
        return
    if new in points:
        raise KinematikaError("usage", "rename-point-exists", "to", name=new)
    _rekey(points, old, new)
    for name in list(points):
        _construction(points[name], old, new)
    for name in list(tree.bodies()):
        body = tree.bodies()[name]
        if isinstance(body, list):
            _replace_in_list(body, old, new)
            continue
        if not isinstance(body, dict):
            continue
        _replace_in_list(body.get("points"), old, new)
        for shape, key in (("circle", "center"), ("line", "through"), ("disc", "center"),
                           ("plane", "through"), ("cam", "center")):
            part = body.get(shape)
            if isinstance(part, dict) and str(part.get(key)) == old:
                part[key] = new
        curve = body.get("curve")
        if isinstance(curve, dict):
            _replace_in_list(curve.get("through"), old, new)
    for j in tree.existing("joints"):
        if str(j.get("at")) == old:
            j["at"] = new
        for key in ("along", "axis"):
            _replace_in_list(j.get(key), old, new)
    for d in tree.existing("drivers"):
        if isinstance(d.get("velocity"), str):
            d["velocity"] = _point_at(d["velocity"], old, new)
    for a in tree.existing("ask"):
        for key in [k for k in a if _about(k) == "point"]:
            a[key] = _point_at(str(a[key]), old, new)
    for entry in (tree.root.get("names") or {}).values():
        if isinstance(entry, dict) and isinstance(entry.get("points"), dict) and old in entry["points"]:
            _rekey(entry["points"], old, new)
    exercise = tree.root.get("exercise")
    if isinstance(exercise, dict):
        for dim in exercise.get("dimensions") or []:
            if isinstance(dim, dict):
                _replace_in_list(dim.get("between"), old, new)


def _point_at(ref: str, old: str, new: str) -> str:
    """A point `P` or a material point `P@BODY` with the point renamed."""
    point, at, body = ref.partition("@")
    return f"{new}{at}{body}" if point == old else ref


def _construction(spec: Any, old: str, new: str) -> None:
    """The places a construction names (`from`, `reference`, `frame`, circles' centres,
    lines' points), renamed; its values (distances, angles, expressions) left alone."""
    if not isinstance(spec, dict):
        return
    if str(spec.get("from")) == old:
        spec["from"] = new
    for key in ("reference", "frame"):
        _replace_in_list(spec.get(key), old, new)
    circles = spec.get("circles")
    for circle in [*(circles if isinstance(circles, list) else []), spec.get("circle")]:
        if isinstance(circle, list) and circle and str(circle[0]) == old:
            circle[0] = new
    lines = spec.get("lines")
    for line in [*(lines if isinstance(lines, list) else []), spec.get("line")]:
        if isinstance(line, dict):
            if str(line.get("through")) == old:
                line["through"] = new
        else:
            _replace_in_list(line, old, new)


# the tree ----------------------------------------------------------------------------------
def _replace_in_list(items: Any, old: str, new: str) -> None:
    """Every item of a list that is the name `old`, renamed (in place, keeping its style)."""
    if not isinstance(items, list):
        return
    for i, item in enumerate(items):
        if isinstance(item, str) and item == old:
            items[i] = new


def _rekey(mapping: Any, old: Any, new: str) -> None:
    """Rename a mapping's key in place, keeping its place among the keys and its comment."""
    keys = list(mapping.keys())
    at = keys.index(old)
    value = mapping[old]
    if hasattr(mapping, "insert") and hasattr(mapping, "ca"):            # ruamel: keep order and comment
        comment = mapping.ca.items.pop(old, None)
        del mapping[old]
        mapping.insert(at, new, value)
        if comment is not None:
            mapping.ca.items[new] = comment
        return
    items = [(new if k == old else k, mapping[k]) for k in keys]
    if hasattr(mapping, "remove"):                                       # tomlkit: rebuild in order
        for k in keys:
            mapping.remove(k)
        for k, v in items:
            mapping[k] = v
        return
    mapping.clear()
    mapping.update(items)
