"""The marks that annotate a vector equation's terms, the notes' way (seed 001): M magnitude
known, D direction known, ? unknown.

The notes' letters M and D are single capitals, as a point's name is: on a page that also
names a point, a contact or a body M or D (C5-1.1's and C5-E.5's lowest point D, 001's guide
M), "D" under a term and "D direction known" in the legend read as that point (issue 30,
sixteenth round (f)). There the page marks both with the language's short words instead
(mòd, dir), which no point can be named: the legend's marks never are a name on the page.
"""
from __future__ import annotations

from .context import Ctx

# the notes' letters (001: "D (dirección) erabiliko da, N hizkia normala adierazi behar denean")
NOTES_MARKS = ("M", "D")


def worded_marks(ctx: Ctx) -> bool:
    """Whether the page writes its M/D marks as words: some point, contact, centre placed as a
    point, or body of the page is named M or D."""
    return bool(ctx.page_names() & set(NOTES_MARKS))
