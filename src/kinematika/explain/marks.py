"""The marks that annotate a vector equation's terms, the notes' way (seed 001): M magnitude
known, D direction known, ? unknown.

The notes' letters M and D are single capitals, as a point's name is: on a page that also
names a point, a contact or a body M or D (C5-1.1's and C5-E.5's lowest point D, 001's guide
M), "D" under a term and "D direction known" in the legend read as that point (issue 30,
sixteenth round (f)). The notes keep M and D always, so the page does too: there the legend
says once "M: magnitude known, D: direction known", and that under a term these letters
are always the marks, never the points (words such as mòd/dir, the sixteenth round's, read
as a second notation; issue 30, twentieth round (c)).
"""
from __future__ import annotations

from .context import Ctx

# the notes' letters (001: "D (dirección) erabiliko da, N hizkia normala adierazi behar denean")
NOTES_MARKS = ("M", "D")


def worded_marks(ctx: Ctx) -> bool:
    """Whether the page's legend says its M/D marks are never its points: some point,
    contact, centre placed as a point, or body of the page is named M or D."""
    return bool(ctx.page_names() & set(NOTES_MARKS))
