"""Issue 30, twenty-first round (e): one velocity one symbol, a translation said without the
direction's numbers, one sentence per image at the pole, the model's words marked as the body.

- 001 p_pair: the block N is pinned to the rocker at B; Step 2 wrote v_{B∈rocker} where the
  question, the caption and the answers wrote B∈N (and the answers' total v_B): a point of
  bodies pinned together has one label on the page (`Ctx.point_label`).
- C5-E.4: "its instant centre is at infinity, perpendicular to v_A1, in the direction (0, −1)":
  the velocity named, the direction's numbers add nothing.
- C5-E.1: "The image of the point O is o′, since o is the pole. o′ is at the pole o, since
  a_O = 0.": o′ said once, "o′, the image of O, is at the pole o, since a_O = 0."
- 001 rolling (en): AF "across the line" -> "perpendicular to the line", as es/ca/eu say.
- C5-1.8 (ca): the note's J^{geom} printed with its braces where the body writes a superscript;
  C5-E.6 (eu): "platerrari eta R *pinoiari*", one of two bodies marked in the Data.
"""
from __future__ import annotations

import re


from .helpers import EXAMPLES, LANGS, NOTES_SEEDS, over, plain_page, rendered, model_tree

def _model(name: str) -> dict:
    return model_tree(name)


def _labels(model: dict, body: str, lang: str) -> set:
    """How a page may write `body` in a subscript: its id, its notation index, its name in `lang`
    (the article off)."""
    named = ((model.get("names") or {}).get(lang) or {}).get("bodies") or {}
    out = {body, str((model.get("notation") or {}).get(f"index({body})", body))}
    if body in named:
        out.add(re.sub(r"^(el|la|els|les|los|las|l’)\s*", "", named[body]))
    return out


def pinned_points_named_twice(page: str, model: dict, lang: str) -> list:
    """The points where the model pins two bodies (a revolute joint's `at`) written P∈a and
    P∈b on one page: one material point, one velocity, under two names."""
    bad = []
    for j in model.get("joints", []):
        if j.get("type") != "revolute" or len(j.get("bodies", [])) != 2:
            continue
        point = j["at"]
        said = [{x for x in _labels(model, b, lang) if re.search(rf"{re.escape(point)}∈{re.escape(x)}(?![\w])", page)}
                for b in j["bodies"]]
        if all(said):
            bad.append(f"{point}∈{sorted(said[0])[0]} and {point}∈{sorted(said[1])[0]}")
    return bad


@over(name=NOTES_SEEDS, lang=LANGS)
def test_a_pinned_point_has_one_label(name: str, lang: str) -> None:
    """One material point of bodies pinned together, one symbol on the page."""
    bad = pinned_points_named_twice(plain_page(name, lang), _model(name), lang)
    assert not bad, "; ".join(bad)


def test_the_check_sees_two_labels_of_one_point() -> None:
    """The check itself: 001's old Step 2 (v_{B∈rocker}) beside its answers' B∈N."""
    model = _model("seed_001_p_pair_coriolis")
    old = "- v_{B∈rocker} = (2.822, 3.477) m/s\n| composition of the motion of B∈N, moving frame |"
    assert pinned_points_named_twice(old, model, "en") == ["B∈N and B∈rocker"]
    assert not pinned_points_named_twice(old.replace("B∈rocker", "B∈N"), model, "en")



@over(lang=LANGS)
def test_composition_answer_names_the_point_as_the_step(lang: str) -> None:
    """001 p_pair: v_B = v_E + v_BE of the rocker and v_B = v_drag + v_rel of the block are one
    v_B (the slides); the page writes it v_{B∈N} in Step 2, the composition and the answers."""
    page = plain_page("seed_001_p_pair_coriolis", lang)
    assert "B∈rocker" not in page and "B∈balan" not in page
    row = next(line for line in page.splitlines() if line.startswith("|") and "B∈N rel M} = (" in line)
    assert "v_{B∈N} = (" in row and "a_{B∈N} = (" in row, row
    assert not re.search(r"[va]_B = \(", row), row


TRANSLATION_DIRECTION = {"en": r"perpendicular to [va]_\S+, in the direction \(",
                         "es": r"perpendicular a [va]_\S+, \(", "ca": r"perpendicular a [va]_\S+, \(",
                         "eu": r"abiadurarekiko norabide perpendikularrean, \("}


@over(name=NOTES_SEEDS, lang=LANGS)
def test_translation_centre_without_direction_numbers(name: str, lang: str) -> None:
    """A centre at infinity said perpendicular to a named velocity adds no direction's numbers."""
    found = re.findall(TRANSLATION_DIRECTION[lang] + r"[^)]*\)", plain_page(name, lang))
    assert not found, found


@over(name=NOTES_SEEDS, lang=LANGS)
def test_image_at_the_pole_said_once(name: str, lang: str) -> None:
    """A caption says o′ in one sentence: where it is the image of O at the pole, the sentence
    that puts it at the pole says whose image it is."""
    for line in plain_page(name, lang).splitlines():
        if line.startswith("*") and "o′" in line:
            sentences = [s for s in re.split(r"(?<=\.) ", line) if "o′" in s]
            assert len(sentences) == 1, sentences


def test_geometric_point_radius_is_perpendicular_in_english() -> None:
    """001 rolling: AF is a radius perpendicular to the line of the lever (es/ca/eu say so)."""
    page = plain_page("seed_001_rolling_pair", "en")
    assert "is a radius, perpendicular to the line, and turns with it" in page
    assert "across the line" not in page


GEOM_NOTES = [s for s in NOTES_SEEDS if "^{geom}" in (EXAMPLES / f"{s}.yaml").read_text(encoding="utf-8")]


@over(name=GEOM_NOTES, lang=LANGS)
def test_model_words_write_the_geometric_mark_as_the_body(name: str, lang: str) -> None:
    """J^{geom} typed in a model's note is a superscript in HTML, as the body writes it."""
    page = rendered(name, lang, "html", drawings=False)
    assert "^{geom}" not in page
    assert "<sup>geom</sup>" in page


def test_geometric_mark_checked_somewhere() -> None:
    """The grid above is not empty: C5-1.8's notes type J^{geom}."""
    assert "seed_c5_1_8_contact_points" in GEOM_NOTES


def _first_words(name: str, lang: str) -> list:
    """The first word of each of the model's bodies' names of several words in `lang` (the
    chainring with pedals, plater pedalduna), the short form a model's words may use instead;
    only a word no other body's name begins with."""
    bodies = ((_model(name).get("names") or {}).get(lang) or {}).get("bodies") or {}
    firsts = [re.sub(r"^(el|la|els|les|los|las|l’)\s*", "", n).split() for n in bodies.values()]
    heads = [w[0] for w in firsts if w]
    # a first word several bodies share is the kind's noun ("the last strand, *strand 5*"), not one name
    return [w[0] for w in firsts if len(w) > 1 and len(w[0]) >= 4 and heads.count(w[0]) == 1]


@over(name=NOTES_SEEDS, lang=LANGS)
def test_data_words_mark_every_body_named(name: str, lang: str) -> None:
    """The model's Data words name each body by its name, marked as the page marks a body
    (italics): never one body italic and another, in the same words, upright under a short
    form (C5-E.6 eu: "platerrari eta R *pinoiari*", the chainring being the plater pedalduna;
    en "the chainring r and the *sprocket* R")."""
    data = ((_model(name).get("names") or {}).get(lang) or {}).get("data") or []
    page = plain_page(name, lang)
    for text in data:
        head = text[:12]
        line = next((ln for ln in page.splitlines() if ln.replace("*", "").startswith(head)), None)
        if line is None or "*" not in line:
            continue
        upright = re.findall(r"\w+", re.sub(r"\*[^*]+\*", " ", line))
        for first in _first_words(name, lang):
            # Basque declines the word (platerrari): its stem; elsewhere the word itself
            short = [w for w in upright if (w.startswith(first[:-1]) if lang == "eu" else w == first)]
            assert not short, (first, short, line)
