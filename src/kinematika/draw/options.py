"""What a drawing shows: one set of options shared by `draw`, `animate` and Jupyter."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

Auto = Optional[bool]     # None: decided by the model's questions


@dataclass
class DrawOptions:
    """Choices of what to draw.

    `lang`: None (the default) writes numbers as Python does (2.5, -0.3, 1e-05), as the
    figure always has; a language (en, es, ca, eu) writes them as an explanation in it
    does (2,5, −0,3, 1×10⁻⁵ in es), so that a figure beside its text reads the same, and
    the figure's own words (title, legend, notes, "at ∞") in that language (`draw.words`).

    `velocities` / `accelerations`: None draws the vectors the model asks for (its
    `velocity` / `acceleration` questions); True draws them at every shown point; False
    none. Shown points are `points` when given, else the points the questions name, else
    every point of a moving body. `centres`: None marks the centres the model asks for
    (`icr`), True every instant centre with its Aronhold–Kennedy lines — or, with
    `centre_pairs`, only the centres of those pairs of bodies and the lines that found them
    from centres drawn (an explanation's figure shows the centres its text uses). `curvature`: None
    or True draws the curvature questions' circles. `labels`: names and magnitudes.
    """

    velocities: Auto = None
    accelerations: Auto = None
    centres: Auto = None
    curvature: Auto = None
    centre_pairs: Optional[list] = None  # with centres=True: only these pairs (body, body)
    labels: bool = True
    points: Optional[list[str]] = None
    view: str = "iso"                 # 3D projection: iso, top, front, side
    width: float = 8.0                # figure width, inches
    title: Optional[str] = None       # default: the model's name
    bare: bool = False                # the drawing alone: no title, legend or notes (a page
                                      # that embeds it says them, in its own language)
    lang: Optional[str] = None        # how numbers and words are written: None as Python
                                      # does and in English, else as that language (see above)
    dimensions: Optional[list] = None  # `draw.dimensions.Dimension` marks (a statement's data)
    contacts: Optional[dict] = None   # joint id -> the letter a text names its contact point
                                      # by (J, K, T2): the figure labels that contact's dot
                                      # with it, and no other contact (issue 30, 13th round)
    construction: Optional[list] = None  # [(pair of bodies, point), …] with centres=True: the
                                      # line from each point (model coordinates) to the pair's
                                      # centre, a line the text finds that centre on ("lies on
                                      # the perpendicular to v_J through J …; these lines
                                      # meet"): drawn as the lines to pins are (issue 30, 19d)
    coincident: Optional[str] = None  # "velocity" or "acceleration": at each asked contact the
                                      # three points that coincide there (each body's point and
                                      # the geometric contact point) with their arrows of that
                                      # kind, named as the text names them (issue 30, 28a)

    def __post_init__(self) -> None:
        if self.lang is not None:
            from ..languages import known

            known(self.lang)            # one of the explanation's languages, else a usage error
        if self.coincident not in (None, "velocity", "acceleration"):
            raise ValueError(f"coincident: velocity or acceleration, not {self.coincident!r}")

    def shows(self, flag: Auto, asked: bool) -> bool:
        """Whether a tri-state option draws: explicitly, or by default when asked."""
        return asked if flag is None else flag
