"""The teacher's audit of the seed pages (docs/explain.md, "Fixed after the audit"): a step
is titled by the bodies it finds, not by the program's "group solved together", and the
acceleration section says the Coriolis terms are known only where its equations have one."""
from __future__ import annotations


import pytest

from kinematika.explain.document import Equation, Figure, Section

from .helpers import LANGS, SEEDS, explained, rendered

# the program's word for a group that is no named kind, in each catalogue (before the fix)
GROUP = {"en": "solved together", "es": "resuelto en conjunto", "ca": "resolt conjuntament", "eu": "batera ebatzitako"}
# the acceleration section's sentence that says the Coriolis terms are known
CORIOLIS = {"en": "every Coriolis term is known", "es": "normales y de Coriolis son conocidos",
            "ca": "normals i de Coriolis són coneguts", "eu": "Coriolisen termino guztiak ezagunak"}
# the level polygon's caption naming Coriolis terms among those drawn
CAPTION = {"en": "relative and Coriolis", "es": "relativos y de Coriolis", "ca": "relatius i de Coriolis",
           "eu": "erlatiboak eta Coriolisen terminoak"}


def _text(name: str, lang: str) -> str:
    return rendered(name, lang)


def _accelerations(doc) -> Section | None:
    return next((s for s in doc.sections if s.title.key == "sec.accelerations"), None)


def _walk(sec: Section):
    for b in sec.blocks:
        yield b
        if isinstance(b, Section):
            yield from _walk(b)


def _has_coriolis(sec: Section) -> bool:
    """Whether an acceleration equation of the section writes a Coriolis term 2 ω × v_rel."""
    return any(t.kind == "coriolis" for eq in _walk(sec) if isinstance(eq, Equation)
               for side in eq.sides for t in side)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_steps_are_titled_by_their_bodies_and_coriolis_said_only_where_written(name, lang):
    _, doc = explained(name)
    text = _text(name, lang)
    assert GROUP[lang] not in text
    acc = _accelerations(doc)
    coriolis = acc is not None and _has_coriolis(acc)
    assert (CORIOLIS[lang] in text) == coriolis
    captions = [b for b in (_walk(acc) if acc is not None else []) if isinstance(b, Figure)
                and b.caption.key.startswith("fig.level_a")]
    if not coriolis:
        assert CAPTION[lang] not in text
    assert all((b.caption.key == "fig.level_a") == coriolis for b in captions)


def test_the_order_of_solution_names_bodies_not_joints():
    """The order of solution says which bodies each step finds and from which ("1. *rear
    wheel* and *sprocket*, from *ground*"): the joints are the step's own business."""
    for name in SEEDS:
        order = _text(name, "en").split("### Order of solution", 1)
        if len(order) == 2:
            assert "(joint" not in order[1].split("\n#", 1)[0], name
