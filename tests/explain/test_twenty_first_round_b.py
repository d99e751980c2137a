"""Issue 30, twenty-first round (b): one word for the fixed body on a page. An absolute
centre or velocity is said relative to the ground (the notes' "respecte al terra") in every
sentence that says it, whatever the model calls its fixed body (C5-1.5's "relative to the
*ceiling*" beside "relative to the *ground*", C5-1.4's "respecto del *bastidor*"); the
structure table's fixed row keeps the model's name for it (C5-1.1 en: *ceiling*, as es
*techo*)."""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, over, plain_page, model_tree

# the reference of a motion as each language writes it, the body's name captured
REFERENCE = {"en": r"relative to the \*([^*]+)\*", "es": r"respecto de(?:l| la) \*([^*]+)\*",
             "ca": r"respecte de(?:l| la|l’) ?\*([^*]+)\*", "eu": r"\*([^* ]+?)a?rekiko\*"}
WORD = {"en": "ground", "es": "suelo", "ca": "terra", "eu": "lurr"}


def _ground_name(name: str, lang: str) -> str:
    model = model_tree(name)
    said = ((model.get("names") or {}).get(lang) or {}).get("bodies", {}).get("ground", "")
    return re.sub(r"^(el|la|l’) ", "", said)


@over(name=SEEDS, lang=LANGS)
def test_the_fixed_body_has_one_name_where_it_is_a_reference(name: str, lang: str) -> None:
    """One word for the fixed body on a page: a shapeless one named otherwise than the ground
    is the reference by its own name (twenty-seventh round (e): "respecto del *bastidor*",
    never "respecto del *suelo*" beside "*bastidor* (fijo)"); a ground named after a part of
    it with a shape (C5-1.6's fixed pulley) is the ground, as the notes say."""
    own = _ground_name(name, lang)
    model = model_tree(name)
    ground = (model.get("bodies") or {}).get("ground")
    shaped = isinstance(ground, dict) and any(k in ground for k in ("circle", "line", "circles", "lines"))
    if not own or own.startswith(WORD[lang]) or shaped:
        return
    refs = set(re.findall(REFERENCE[lang], plain_page(name, lang)))
    assert not any(r.startswith(WORD[lang]) for r in refs), (own, sorted(refs))


def test_pulley_on_cable_keeps_the_ceiling_in_its_table() -> None:
    """C5-1.1: the model names its fixed body the ceiling in every language."""
    page = plain_page("seed_c5_1_1_pulley_on_cable", "en")
    assert "| 1 | *ceiling* (fixed) |" in page    # twenty-seventh round (e): one name, no tie
    assert "relative to the *ceiling*" in page and "relative to the *ground*" not in page


def _messages(blocks: list, key: str) -> list:
    from kinematika.explain.document import Msg, Section

    out: list = []
    for b in blocks:
        if isinstance(b, Section):
            out += _messages(b.blocks, key)
        elif isinstance(b, Msg) and b.key == key:
            out.append(b)
    return out


@over(name=SEEDS)
def test_the_composition_sum_names_the_point_as_its_step(name: str) -> None:
    """001 p_pair: "So v_B = v_{drag,B} + … is the equation of Step 2, which found
    v_{B∈rocker}" named one velocity twice; the sum now writes the step's v_{B∈rocker}."""
    from .helpers import explained

    _, doc = explained(name)
    for m in _messages(doc.sections, "composition.sum_seen"):
        sym = m.args["sym"]
        point = sym.sub.partition("∈")[0]
        # a velocity the step found for this very point (not a relative one) is named so
        same = [s.sub for s in m.args["seen"].items if getattr(s, "base", "") == sym.base
                and s.sub.partition("∈")[0] == point and "/" not in s.sub]
        assert all(sub == sym.sub for sub in same), (sym.sub, same)


def test_p_pair_sum_by_hand() -> None:
    # the block N pinned to the rocker at B: one label, B∈N (twenty-first round (e))
    assert "So v_{B∈N} = v_{drag,B} + v_{B∈N rel M}" in plain_page("seed_001_p_pair_coriolis", "en")
    assert "Así, v_{B∈N} = v_{arr,B} + v_{B∈N rel M}" in plain_page("seed_001_p_pair_coriolis", "es")


def _said_twice(blocks: list, bad: list) -> None:
    from kinematika.explain.document import Section
    from kinematika.explain.said_first import USES_CONDITION, said_joint, used_joints

    said: set = set()
    for b in blocks:
        if isinstance(b, Section):
            _said_twice(b.blocks, bad)
            continue
        if said_joint(b) is not None:
            said.add(said_joint(b))
        twice = said & set(used_joints(b))
        if twice:
            bad.append((str(b.sym), sorted(map(str, twice)), USES_CONDITION))


@over(name=SEEDS)
def test_a_joint_condition_is_said_once_before_use(name: str) -> None:
    """C5-1.3: "Prismatic pair: the bar slides along the support without turning relative to
    it." and then "ω_support = ω_bar (prismatic pair: no relative rotation)": the sentence
    said first stays, the parenthesis goes."""
    from .helpers import explained

    _, doc = explained(name)
    bad: list = []
    _said_twice(doc.sections, bad)
    assert not bad, bad


def test_bar_in_sleeve_by_hand() -> None:
    page = plain_page("seed_c5_1_3_bar_in_sleeve", "en")
    assert "without turning relative to it" in page
    assert "no relative rotation" not in page


def _centre_before_equation(blocks: list, bad: list) -> None:
    from kinematika.explain.document import CentreNote, Equation, Section

    for b in blocks:
        if isinstance(b, Section):
            _centre_before_equation(b.blocks, bad)
    notes = [i for i, b in enumerate(blocks) if isinstance(b, CentreNote)]
    eqs = [i for i, b in enumerate(blocks) if isinstance(b, Equation)]
    bad += [(blocks[i].pair) for i in notes if any(e > i and "\\ue010" not in repr(blocks[e]) for e in eqs)]


def test_a_step_writes_its_equations_before_the_centre_that_reads_them() -> None:
    """C5-1.4, Step 2: "I_planet1: A1 moves with the carrier about O…" stood before the
    v_{S∈ring} equation block: the ring's equations first, then the centre's paragraph."""
    from .helpers import explained

    for name in SEEDS:
        _, doc = explained(name)
        bad: list = []
        _centre_before_equation(doc.sections, bad)
        assert not bad, (name, bad)
    page = plain_page("seed_c5_1_4_epicyclic", "en")
    assert page.index("v_SO = ω_ring × OS") < page.index("I_{planet1}: A1 moves with the *carrier*")
