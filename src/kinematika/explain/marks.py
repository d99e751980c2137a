"""The marks that annotate a vector equation's terms, the notes' way (seed 001): M magnitude
known, D direction known, ? unknown.

The notes' letters M and D are single capitals, as a point's name is: on a page that also
names a point, a contact or a body M or D (C5-1.1's and C5-E.5's lowest point D, 001's guide
M), "D" under a term and "D direction known" in the legend read as that point (issue 30,
sixteenth round (f)). The notes keep M and D always, so the page does too: there the legend
says once "M: magnitude known, D: direction known", and that under a term these letters
are always the marks, never the points (words such as mòd/dir, the sixteenth round's, read
as a second notation; issue 30, twentieth round (c)).

The legend names only the letters that are a POINT of the page (a model point, a contact, a
centre placed as a point): "never the point D" on C5-1.1 and C5-E.5, "never the point M" on
C5-2.1. A body called M (001's guide) is not a point; "never the points M and D" named a
point the page does not have (issue 30, twenty-first round (a)).

The seeds no longer name a point M or D: the notes name none of those points so (C5-1.1's
lowest point of the pulley and C5-2.1's middle of the rear axle are P, the notes' letter for
the point asked about and C5-2.2's for an axle's middle; C5-E.5's centre of wheel 1 is the
notes' C), and "v_D" under a mark "D" read badly, the sentence as a patch (issue 30,
twenty-eighth round (b)). The sentence stays for a user's model that names a point so
(jansen_leg's D, car_wheel_steering's M).

The legend itself is plain on every page ("M: magnitude known; D: direction known; ?:
unknown"); the clash is one short sentence of its own after it, naming its letter ("Here D
marks a known direction; it is not the point D."): an aside inside the legend read oddly, and
the Basque one hung M's note on D (issue 30, twenty-fourth round (e)).
"""
from __future__ import annotations

from .context import Ctx

# the notes' letters (001: "D (dirección) erabiliko da, N hizkia normala adierazi behar denean")
NOTES_MARKS = ("M", "D")


def worded_marks(ctx: Ctx) -> tuple[str, ...]:
    """The notes' marks (M, D, in that order) that are also a point of the page — a model
    point, a contact or a centre placed as a point, never a body — which the legend says its
    marks are never; empty when no point clashes."""
    points = set(ctx.model.points) | ctx.labels()
    return tuple(m for m in NOTES_MARKS if m in points)
