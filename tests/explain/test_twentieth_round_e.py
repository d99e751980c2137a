"""Issue 30, twentieth round (e): the order of what is said.

1. A joint's condition is said before the first line of its step that uses it (C5-1.3: the
   sentence "prismatic pair: the bar slides along the support without turning relative to
   it" came after ω_support = ω_bar (prismatic pair …), which uses it)."""
from __future__ import annotations

from kinematika.explain.context import Ctx
from kinematika.explain.document import CentreNote, Derived, Equation, Section
from kinematika.explain.said_first import said_joint, used_joints

from .helpers import LANGS, SEEDS, explained, over, rendered

VELOCITIES = ("sec.velocities", "sec.accelerations")


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
    for step in _steps([s for s in doc.sections if s.title.key in VELOCITIES]):
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


def _in_order(blocks: list) -> list:
    """Every block of the page in reading order, subsections' blocks in their place."""
    out: list = []
    for b in blocks:
        out += _in_order(b.blocks) if isinstance(b, Section) else [b]
    return out


@over(name=SEEDS)
def test_no_velocity_or_rate_used_before_the_line_that_finds_it(name: str) -> None:
    """Walk the page: an equation finds its target's velocity, a derived line its body's ω,
    the statement the driven bodies' ω; a centre's construction from two points' velocities
    (each point turning with a body) reads those velocities, one from a body's ω that ω —
    each must be found on an earlier line."""
    sol, doc = explained(name)
    ctx = Ctx(sol)
    motions: set[str] = set()
    rates = {d.body for d in sol.model.drivers if d.kind == "omega"}
    bad = []
    for b in _in_order(doc.sections):
        if isinstance(b, Equation) and b.point is not None and b.level == "v":
            motions.add(ctx.motion_key(b.point.point, b.point.body))
        elif isinstance(b, Derived) and b.kind == "omega":
            rates.add(b.body)
        elif isinstance(b, CentreNote) and ctx.frame in b.pair:
            body = next(x for x in b.pair if x != ctx.frame)
            if b.how == "proportional" and len(b.witnesses) == len(b.via):
                for (p, _, _), k in zip(b.witnesses, b.via):
                    if not str(p).startswith("I:") and ctx.motion_key(p, k) not in motions:
                        bad.append((f"I_{body}", f"v_{p} (with the {k})", "not found before"))
            if b.how in ("field", "rate") and body not in rates:
                bad.append((f"I_{body}", f"ω_{body}", "not found before"))
    assert not bad, bad


@over(lang=LANGS)
def test_epicyclic_planet_centre_after_the_velocities_it_reads(lang: str) -> None:
    """C5-1.4 by the page: v_A1 (step 1) and v_Q∈ring (step 3) are written before the
    sentence that places I_planet1 between A1 and Q at 2r/5 from A1, which comes before
    the step starts from it; "Instant centres" says where it is placed."""
    page = rendered("seed_c5_1_4_epicyclic", lang)
    velocities = page.index("v_A1 = (2·r·ω")
    ring = page.index("- v_{Q∈")
    placed = page.index("2·r/5")
    start = page.index("v_{I_")
    assert velocities < ring < placed < start, (velocities, ring, placed, start)
