"""The model's questions answered, and the curvature of paths worked out (seed 002):
a = aᵗ + aⁿ with aᵗ ∥ v and aⁿ ⊥ v, then ρ = v² / |aⁿ|."""
from __future__ import annotations

from typing import Any

from ..model.model import PointRef
from ..questions import answer
from ..questions.curvature import intrinsic
from .context import Ctx
from .document import Ann, Derived, Equation, Inline, Name, Section, Sym, Table, Term, Value, msg
from .terms import KNOWN

UNITS = {"velocity": "speed", "acceleration": "accel", "omega": "rate", "alpha": "rate2",
         "drag": None, "relative": None, "coriolis": None, "total": None, "point": "len",
         "center": "len", "radius": "len", "direction": "", "speed": "speed", "tangent": "",
         "tangential": "accel", "normal": "accel", "tangential_vector": "accel",
         "normal_vector": "accel", "omega_axis": "rate", "slide": "speed"}


def answers_section(ctx: Ctx) -> Section:
    sec = Section(msg("sec.answers"))
    rows = []
    for q in ctx.model.questions:
        asked = ", ".join(f"{k}: {v}" for k, v in q.echo.items())
        rows.append([asked, flatten(ctx, q.kind, answer(ctx.sol, q))])
    if rows:
        sec.add(Table([msg("col.question"), msg("col.answer")], rows))
    else:
        sec.add(msg("answers.none"))
    return sec


def flatten(ctx: Ctx, kind: str, value: Any, unit: str | None = None) -> list:
    """An answer as a list of (label, Value) items, units from the kind of each entry."""
    unit = unit if unit is not None else UNITS.get(kind, "")
    if kind == "axis":
        unit = ""
    if isinstance(value, dict):
        out = []
        for key, v in value.items():
            if key == "omega" and kind == "axis":
                sub_unit = "rate"
            elif key in ("velocity", "acceleration"):
                sub_unit = UNITS[key]
            else:
                sub_unit = UNITS.get(key) or unit
            for label, item in flatten(ctx, kind, v, sub_unit):
                out.append((f"{key}" + (f".{label}" if label else ""), item))
        return out
    if value is None or isinstance(value, (bool, str)):
        return [("", Value(value, ""))]
    clean = ctx.clean(tuple(value) if isinstance(value, (tuple, list)) else value, unit or "len")
    return [("", Value(clean, unit or ""))]


def curvature_section(ctx: Ctx) -> Section | None:
    """Each `curvature` question: the acceleration split along and across the velocity."""
    asked = [q for q in ctx.model.questions if q.kind == "curvature" and ctx.planar]
    if not asked:
        return None
    sec = Section(msg("sec.curvature"))
    sec.add(msg("curvature.intro", rho=Inline([Sym("ρ", vector=False), " = |", Sym("v"), "|² / |",
                                               Sym("a", sup="n"), "|"])))
    for q in asked:
        sec.blocks += curvature_steps(ctx, q)
    return sec


def curvature_steps(ctx: Ctx, q) -> list:
    ref: PointRef = q.target
    rel = q.relative_to
    v, a = ctx.sol.velocity(ref, rel), ctx.sol.acceleration(ref, rel)
    result = answer(ctx.sol, q)
    label = str(ref) if not ctx.shared(ref.point) else ref.point
    if result.get("rest"):
        return [msg("curvature.rest", point=Name(label))]
    split = intrinsic(ctx.sol, q)             # the solver's aᵗ and aⁿ of the same point
    at, an = split["tangential_vector"], split["normal_vector"]
    target = Term(Sym("a", label), ctx.clean(a, "accel"), *KNOWN, kind="point")
    tangential = Term(Sym("a", label, "t"), ctx.clean(at, "accel"), Ann("M"),
                      Ann("para", Sym("v", label)), kind="tangential")
    normal = Term(Sym("a", label, "n"), ctx.clean(an, "accel"), Ann("M"),
                  Ann("perp", Sym("v", label)), kind="normal")
    out: list = [msg("curvature.point", point=Name(label), v=Value(ctx.clean(v, "speed"), "speed")),
                 Equation(target, [[tangential, normal]], "a", ref, rel, figure=False)]
    if result.get("radius") is None:
        out.append(msg("curvature.straight", point=Name(label)))
        return out
    radius = Value(ctx.clean(result["radius"], "len"), "len")
    out.append(Derived(Sym("ρ", label, vector=False), ["|", Sym("v", label), "|² / |", Sym("a", label, "n"), "|"],
                       radius, kind="radius", source=normal, arm=ctx.clean(v, "speed")))
    out.append(msg("curvature.centre", point=Name(label), centre=Value(ctx.clean(result["center"], "len"), "len")))
    return out
