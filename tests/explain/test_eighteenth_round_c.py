"""Issue 30, eighteenth round (c): names and descriptions two strict teachers read on main
(aedc7c2). Each test is a rule over the 19 seeds in the languages where it applies, and fails
on that output: C5-1.2's K0 "a point of the *ground*, the *left plane*, and the *right plane*"
and C5-1.5's G "a point of the *ceiling* and *strand 1*" (a list of bodies); C5-1.6's T1 named
on the *belt*, T2 on the *moving pulley*; C5-E.5's "wheel R" beside "*wheel of radius R*";
C5-2.1's "centre of the wheel C1 (rear left)" beside "centre of the rear right wheel"."""
from __future__ import annotations

import re


from .helpers import SEEDS, explained, rendered, over

LANGS = ("en", "es", "ca", "eu")


@over(name=SEEDS, lang=LANGS)
def test_a_point_shared_by_parts_with_no_joint_there_is_described_by_the_model(name: str, lang: str) -> None:
    """A point several bodies hold with no joint at it and no circle centred there (only
    parts welded together share it: C5-1.2's K0, C5-1.5's G) is said in the model's own words
    ("the corner where the two planes meet", "where *strand 1* is tied to the *ceiling*"),
    never as the list of the bodies that hold it."""
    sol, _ = explained(name)
    model = sol.model
    touching = set(re.findall(r"^\| (\w+) \| the point of .* where (?:it touches|they touch)",
                              rendered(name, "en", "md", drawings=False), re.M))
    for p in set(model.points) - touching:
        holders = [b for b, body in model.bodies.items() if p in body.points]
        at_joint = any(getattr(j, "at", None) == p for j in model.joints)
        centre = any(getattr(s, "center_point", None) == p for b in model.bodies.values() for s in b.shapes)
        if len(holders) >= 2 and not at_joint and not centre:
            assert model.wording.point(p, lang), (name, lang, p, holders)


ROW = re.compile(r"^\| \w+ \| the point of (?:the )?\*([^*]+)\* where (?:it touches|they touch) (?:the )?\*([^*]+)\*")


@over(name=SEEDS)
def test_contact_points_are_named_on_the_same_body(name: str) -> None:
    """The Data's contact points are points of one body consistently: no body is the point's
    body in one row and the body touched in another (C5-1.6: T1 and T2 both "the point of the
    *belt* where it touches …"). One code path words all four languages; English is read."""
    rows = [ROW.match(ln) for ln in rendered(name, "en", "md", drawings=False).splitlines()]
    own = {m.group(1) for m in rows if m}
    touched = {m.group(2) for m in rows if m}
    assert not own & touched, (name, own & touched)


def test_the_belts_contacts_by_hand() -> None:
    page = rendered("seed_c5_1_6_belt", "en", "md", drawings=False)
    assert "| T1 | the point of the *belt* where it touches the *fixed pulley* |" in page
    assert "| T2 | the point of the *belt* where it touches the *moving pulley* |" in page


# a body named after a dimension: the noun and the dimension's symbol, per language
_OF_RADIUS = {"en": r"(\w+) of radius (\w+)", "es": r"(\w+) de radio (\w+)", "ca": r"(\w+) de radi (\w+)"}


@over(name=SEEDS, lang=LANGS)
def test_a_body_named_by_its_radius_keeps_its_name(name: str, lang: str) -> None:
    """A body the model names "wheel of radius R" is never "wheel R" on the page (C5-E.5: the
    model's data and parameter words said "wheel R" three times)."""
    sol, _ = explained(name)
    page = rendered(name, lang, "md", drawings=False)
    for spelt in sol.model.wording.bodies.get(lang, {}).values():
        if lang == "eu":
            m = re.search(r"(\w+) erradioko (\w+?)a\b", spelt)
            short = m and rf"(?<!erradioko )\b{m.group(1)} {m.group(2)}a"
        else:
            m = re.search(_OF_RADIUS[lang], spelt)
            short = m and rf"\b{m.group(1)} {m.group(2)}\b"
        if short:
            assert not re.search(short, page), (name, lang, spelt, re.search(short, page).group(0))


@over(name=SEEDS, lang=LANGS)
def test_sibling_points_described_alike(name: str, lang: str) -> None:
    """Where the model describes a point through a body's code ("centre of the wheel C1 (rear
    left)"), the points numbered alike (C2) are described through theirs too (C5-2.1: "centre
    of the rear right wheel" read as another body)."""
    sol, _ = explained(name)
    said = sol.model.wording.points.get(lang, {})
    for p, text in said.items():
        if not re.fullmatch(r"[A-Z]\d", p) or not re.search(rf"\b{p}\b[^()]*\(", text):
            continue
        for q, other in said.items():
            if q != p and re.fullmatch(rf"{p[0]}\d", q):
                assert re.search(rf"\b{q}\b[^()]*\(", other), (name, lang, p, q, other)
