"""The whole explanation of a solved instant, in the notes' order.

Planar: structure and order of solution, velocities and accelerations step by step,
instant centres, composition of motions asked for, curvature, answers. Spatial (the fan):
structure, absolute angular velocity and acceleration body by body, the fields of
velocities and accelerations, composition of motions, answers.
"""
from __future__ import annotations

from ..draw.names import body_numbers
from ..solution import Solution
from .answers import answers_section, curvature_section
from .centres import centres_section
from .context import Ctx
from .document import Document, Equation, Section, msg
from .group import refine
from .order import solution_order
from .planar import PlanarSteps
from .polygon import level_polygon, polygon
from .positions import position_section
from .spatial import composition_pairs, composition_section, fields_section, rates_section
from .structure import structure_section, values_table


def build(sol: Solution, length_unit: str = "m") -> Document:
    """The `Document` of `sol`: every value in it is read from the solution."""
    ctx = Ctx(sol)
    levels: list[Section] = []
    doc = Document(sol.model.name, sol.symbolic, sol.space.dim, length_unit,
                   numbers=body_numbers(sol.model))
    intro = Section(msg("sec.data"))
    intro.add(msg("data.symbolic" if sol.symbolic else "data.numeric", unit=length_unit))
    intro.add(msg("data.planar" if sol.space.dim == 2 else "data.spatial"))
    doc.sections.append(intro)
    if ctx.planar:
        steps = refine(ctx, solution_order(sol))
        doc.sections.append(structure_section(ctx, steps))
        placed = position_section(ctx)
        if placed is not None:
            doc.sections.append(placed)
        for level in ("v", "a"):
            sec = PlanarSteps(ctx, steps, level).section()
            levels.append(sec)
            drawn = level_polygon(ctx, _equations(sec), level)
            if drawn is not None:
                sec.add(drawn)
            doc.sections.append(sec)
        summary = Section(msg("sec.rates_summary"))
        summary.add(values_table(ctx))
        doc.sections.append(summary)
        doc.sections.append(centres_section(ctx))
    else:
        doc.sections.append(structure_section(ctx, []))
        doc.sections.append(rates_section(ctx))
        doc.sections += [fields_section(ctx, "v"), fields_section(ctx, "a")]
    extra = [composition_section(ctx, composition_pairs(ctx)), curvature_section(ctx)]
    doc.sections += [s for s in extra if s is not None]
    doc.sections.append(answers_section(ctx))
    in_levels = {id(e) for sec in levels for e in _equations(sec)}
    for eq in doc.equations():
        if id(eq) not in in_levels:
            eq.polygon = polygon(ctx, eq)
    return doc


def _equations(sec: Section) -> list[Equation]:
    out: list = []
    for b in sec.blocks:
        out += _equations(b) if isinstance(b, Section) else [b] if isinstance(b, Equation) else []
    return out
