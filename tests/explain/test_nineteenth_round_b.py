"""Issue 30, nineteenth round (b): wording left from the readers' last round.

- a centre at infinity is said as the translation it is, the translation first: "the body
  translates: every point has the velocity v; its instant centre is at infinity,
  perpendicular to v" (C5-2.2, C5-E.4), never "meet at infinity in the direction (0, −1)"
  alone, nor "(its instant centre is at infinity: it translates)";
- Catalan says "perpendicular a" (never "perpendicularment a la recta") and "per sobre"
  (never "a dalt de");
- the Basque annotation legend writes each mark with a colon, "?: ezezaguna (norabidea edo
  modulua)", never the bare "? ezezaguna";
- a body is named by the model's name, never by position words the model does not use
  ("the lower wheels", "the upper one");
- Spanish 001 p_pair: the guide imposes the direction of the relative velocity;
- a wheel's rolling relation uses the model's radius symbol, ω = −|v_O| / r, never a bare
  length with its unit (C5-1.2's "−|v_O| / 1 m").
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from .helpers import LANGS, SEEDS, over, rendered

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

INFINITY = {"en": "infinity", "es": "infinito", "ca": "infinit", "eu": "infinituan"}
TRANSLATES = {"en": "translat", "es": "trasla", "ca": "trasllad", "eu": "traslatzen"}
PERPENDICULAR = {"en": "perpendicular", "es": "perpendicular", "ca": "perpendicular", "eu": "perpendikular"}


def _sentences(line: str) -> list[str]:
    """A line cut at its sentence ends."""
    return [s for s in re.split(r"(?<=\.)\s+", line) if s]


@over(name=SEEDS, lang=LANGS)
def test_infinity_is_said_after_the_translation(name: str, lang: str) -> None:
    """Every mention of a centre at infinity comes after the word that the body translates,
    in the same sentence (the notes: the points' one velocity first, the centre after)."""
    for line in rendered(name, lang).splitlines():
        for sentence in _sentences(line):
            at = sentence.find(INFINITY[lang])
            if at < 0:
                continue
            assert 0 <= sentence.find(TRANSLATES[lang]) < at, (name, lang, sentence)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["seed_c5_e4_upper_wheel"])
def test_translating_centre_says_perpendicular_to_the_velocity(name: str, lang: str) -> None:
    """C5-E.4's chassis (the perpendiculars to v_A1 and v_A2 are parallel) translates: its centre
    is at infinity perpendicular to the velocity. (C5-2.2's chassis S1, v_C1 = v_C2, is said to
    translate in a velocity step, with ω_S1 = 0 and no centre: twenty-eighth round (d).)"""
    lines = [x for x in rendered(name, lang).splitlines() if INFINITY[lang] in x and not x.startswith("ω")]
    assert lines, (name, lang)
    for x in lines:
        tail = x[x.find(INFINITY[lang]):]
        assert re.search(PERPENDICULAR[lang] + r".*v_\w+|v_\w+ abiadurarekiko norabide perpendikular", x), x
        assert "v_" in tail, (name, lang, x)


@over(name=SEEDS)
def test_catalan_perpendicular_and_above(name: str) -> None:
    page = rendered(name, "ca")
    # a verb's manner is the adverb, "es mou perpendicularment a la recta que l'uneix amb I"
    # (twenty-first round (a)); elsewhere "perpendicular a"
    assert not re.search(r"perpendicularment a la recta(?! que l’uneix amb)", page), name
    assert not re.search(r"\ba dalt d", page), name


@over(name=SEEDS)
def test_basque_legend_marks_with_colons(name: str) -> None:
    page = rendered(name, "eu")
    assert ", ? ezezaguna" not in page, name
    if "apunteetan bezala idazten da" in page:
        assert "?: ezezaguna (norabidea edo modulua)" in page, name
        assert re.search(r"(M: modulua ezaguna; D: norabidea ezaguna|mod: modulua ezaguna; norab: norabidea ezaguna)",
                         page), name


# position words for bodies, per language; a page uses one only when the model's names do
POSITION = {"en": ("upper one", "lower one", "lower wheels"), "es": ("ruedas inferiores",),
            "ca": ("rodes inferiors",), "eu": ("beheko gurpil",)}


def _names_block(name: str, lang: str) -> str:
    text = (EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8")
    m = re.search(rf"^  {lang}:\n((?:    .*\n)+)", text.split("\nnames:\n", 1)[-1], re.M)
    if not m:
        return ""
    return "\n".join(x for x in m.group(1).splitlines() if x.strip().startswith(("bodies:", "points:")))


@over(name=SEEDS, lang=LANGS)
def test_bodies_named_by_the_model(name: str, lang: str) -> None:
    # a circles' intersection "is the upper one" (twenty-ninth round (d)): a point, no body
    page = re.sub(r"it is the (upper|lower) one:", "", rendered(name, lang).lower())
    own = _names_block(name, lang).lower()
    for words in POSITION[lang]:
        assert words not in page or words in own, (name, lang, words)


def test_spanish_guide_imposes_the_relative_velocity() -> None:
    page = rendered("seed_001_p_pair_coriolis", "es")
    assert "fija la dirección" not in page
    assert "impone la dirección de la velocidad relativa" in page


@over(name=SEEDS, lang=LANGS)
def test_rolling_read_off_has_no_bare_length(name: str, lang: str) -> None:
    """ω = ±|v_O| / r: the divisor is a symbol, never a number with its unit."""
    assert not re.search(r"\| / [0-9][0-9.,]* ?m\b", rendered(name, lang)), (name, lang)


@pytest.mark.parametrize("lang", LANGS)
def test_inclined_wheels_roll_with_r(lang: str) -> None:
    """C5-1.2: each wheel (radius r = 1 m, in Data) rolls on its plane; since round 27b its ω is
    read off its vector equation about the contact, the arm K1O being the radius r:
    ω = −|v_OK1| / K1O = −|v_O| / r = −2.91 rad/s."""
    page = rendered("seed_c5_1_2_bar_on_inclined_wheels", lang)
    assert re.search(r"= −\|v_OK1\| / K1O = −2[.,]91 rad/s", page), lang
    assert re.search(r"= −\|v_QK2\| / K2Q = −2[.,]91 rad/s", page), lang
