"""The whole explanation of a solved instant, in the notes' order.

Planar: structure and order of solution, velocities and accelerations step by step,
instant centres, composition of motions asked for, curvature, answers. Spatial (the fan):
structure, absolute angular velocity and acceleration body by body, the fields of
velocities and accelerations, composition of motions, answers.
"""
from __future__ import annotations

from ..solution import Solution
from .answers import answers_section, curvature_section
from .centres import centres_section
from .context import Ctx
from .document import Document, Section, msg
from .group import refine
from .order import solution_order
from .planar import PlanarSteps
from .polygon import polygon
from .spatial import composition_pairs, composition_section, fields_section, rates_section
from .structure import structure_section, values_table


def build(sol: Solution, length_unit: str = "m") -> Document:
    """The `Document` of `sol`: every value in it is read from the solution."""
    ctx = Ctx(sol)
    doc = Document(sol.model.name, sol.symbolic, sol.space.dim, length_unit)
    intro = Section(msg("sec.data"))
    intro.add(msg("data.symbolic" if sol.symbolic else "data.numeric", unit=length_unit))
    intro.add(msg("data.planar" if sol.space.dim == 2 else "data.spatial"))
    doc.sections.append(intro)
    if ctx.planar:
        steps = refine(ctx, solution_order(sol))
        doc.sections.append(structure_section(ctx, steps))
        for level in ("v", "a"):
            doc.sections.append(PlanarSteps(ctx, steps, level).section())
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
    for eq in doc.equations():
        eq.polygon = polygon(ctx, eq)
    return doc
