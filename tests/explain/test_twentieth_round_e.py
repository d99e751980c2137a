"""Issue 30, twentieth round (e): the order of what is said.

1. A joint's condition is said before the first line of its step that uses it (C5-1.3: the
   sentence "prismatic pair: the bar slides along the support without turning relative to
   it" came after ω_support = ω_bar (prismatic pair …), which uses it)."""
from __future__ import annotations

from kinematika.explain.document import Section
from kinematika.explain.said_first import said_joint, used_joints

from .helpers import LANGS, SEEDS, explained, over, rendered


def _steps(blocks: list) -> list[Section]:
    """Every step subsection (level 3) of the velocity and acceleration sections."""
    out = []
    for b in blocks:
        if isinstance(b, Section):
            out += [b] if b.level == 3 else _steps(b.blocks)
    return out


@over(name=SEEDS)
def test_a_joints_condition_before_the_line_that_uses_it(name: str) -> None:
    _, doc = explained(name)
    bad = []
    for step in _steps([s for s in doc.sections if s.title.key in ("sec.velocities", "sec.accelerations")]):
        used: dict = {}
        for i, b in enumerate(step.blocks):
            for j in used_joints(b):
                used.setdefault(j, i)
            j = said_joint(b)
            if j is not None and j in used:
                bad.append((str(step.title.args), j, "said at", i, "used at", used[j]))
    assert not bad, bad


@over(lang=LANGS)
def test_bar_in_sleeve_prismatic_pair_said_before_omega_support(lang: str) -> None:
    """C5-1.3, by the page a reader reads: the pair's sentence, then ω_support = ω_bar."""
    page = rendered("seed_c5_1_3_bar_in_sleeve", lang)
    said = {"en": "Prismatic pair:", "es": "Par prismático:", "ca": "Enllaç prismàtic:",
            "eu": "Lotura prismatikoa:"}[lang]
    carried = {"en": "ω_support = ω_bar", "es": "ω_soporte = ω_barra", "ca": "ω_suport = ω_barra",
               "eu": "ω_euskarria = ω_barra"}[lang]
    assert said in page and carried in page
    assert page.index(said) < page.index(carried)
