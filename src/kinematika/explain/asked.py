"""Which sections of an explanation work out each of the model's questions: the kinds say
(`QuestionKind.explain`, choosing among a `questions.Steps`' ways), `Worked` gathers them."""
from __future__ import annotations

from typing import Any

from ..questions import QUESTIONS
from .context import Ctx


class Worked:
    """The model's questions by the section that works each out (`QuestionKind.explain`):
    instant centres, path curvatures, contact points, compositions; in the order asked."""

    def __init__(self, questions: list) -> None:
        self.centres: list = []
        self.curvatures: list = []
        self.contacts: list = []
        self.compositions: list = []
        for q in questions:
            QUESTIONS[q.kind].explain(self, q)

    def instant_centre(self, q: Any) -> None:
        """Found (and checked) in the instant centres' section (`centres`)."""
        self.centres.append(q)

    def path_curvature(self, q: Any) -> None:
        """Worked out in the curvature section (`answers.curvature_section`)."""
        self.curvatures.append(q)

    def contact_points(self, q: Any) -> None:
        """Worked out in the contact section (`contacts.contact_section`)."""
        self.contacts.append(q)

    def composition(self, q: Any) -> None:
        """Worked out as a composition of motions (`spatial.composition_section`)."""
        self.compositions.append(q)


def worked(ctx: Ctx) -> Worked:
    """The model's questions by the section that works each out (`Worked`)."""
    return Worked(ctx.model.questions)
