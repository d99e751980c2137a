"""A variant's statement: the model's text with the variant's data, and what is asked, each
number a student gives with its unit, in the exercise's language.

The text is the model's `exercise.statement` in the language, its `{name}` placeholders
replaced by the parameters' values as stated (`400 mm`, `30°`); a model without one gets a
plain statement that lists its data. A question reads as the notes name it (the angular
velocity of the rocker, the velocity of point B of N relative to M) and each of its
numbers by its component or part (x, y; radius; the drag velocity's x).
"""
from __future__ import annotations

from dataclasses import dataclass
from html import escape
from typing import Any

from ..errors import KinematikaError
from ..model.exercise_section import PLACEHOLDER
from ..questions import QUESTIONS
from .catalogue import catalogue
from .key import Row
from .stated import stated_text

COMPONENTS = ("x", "y", "z")


def statement_html(exercise: Any, stated: dict, lang: str) -> str:
    """The statement's paragraphs (HTML), the data of the variant in place."""
    text = exercise.section.statement.get(lang)
    if text is None:
        if exercise.section.statement:
            raise KinematikaError("usage", "statement-missing", "--lang", lang=lang,
                                  langs=list(exercise.section.statement))
        return f"<p>{escape(default_statement(exercise, stated, lang))}</p>"

    def value(match: Any) -> str:
        name = match.group(1)
        return stated_text(stated[name], exercise.unit_of(name), lang)

    paragraphs = [p.strip() for p in text.split("\n\n") if p.strip()]
    return "".join(f"<p>{escape(PLACEHOLDER.sub(value, ' '.join(p.split())))}</p>" for p in paragraphs)


def default_statement(exercise: Any, stated: dict, lang: str) -> str:
    """The statement of a model without one: its data, listed."""
    from ..explain.render.names import unicode_name

    data = ", ".join(f"{unicode_name(name)} = {stated_text(value, exercise.unit_of(name), lang)}"
                     for name, value in stated.items())
    return catalogue(lang).format("statement-default", {"data": data})


@dataclass(frozen=True)
class Asked:
    """A graded question as the statement asks it: its words and its numbers (key rows),
    each with the words of its part."""

    number: int
    words: str
    parts: list[tuple[Row, str]]


def asked(exercise: Any, rows: list[Row], lang: str) -> list[Asked]:
    """The graded questions of a variant, in order, with their numbers."""
    model = exercise.model
    out: list[Asked] = []
    for k in exercise.asks:
        mine = [r for r in rows if r.ask == k]
        if not mine:
            continue
        q = model.questions[k - 1]
        out.append(Asked(k, question_words(model, q, lang), [(r, part_words(r, lang, model, q)) for r in mine]))
    return out


def question_words(model: Any, q: Any, lang: str) -> str:
    """A question in words, with the model's names in `lang` (`names:`): `the angular velocity
    of the rocker relative to the guide`; Catalan and Spanish contract a preposition with a
    name's article (`del portador`)."""
    from ..explain.catalogue import CONTRACTIONS

    cat = catalogue(lang)
    wording = model.wording
    frame = None if q.relative_to in (None, model.frame) else q.relative_to
    args: dict[str, Any] = {"frame": wording.body(frame or model.frame, lang)}
    target = q.target
    if hasattr(target, "point"):
        args.update(point=target.point, body=wording.body(target.body, lang))
    else:
        args.update(body=wording.body(str(target), lang), joint=wording.joint(str(target), lang))
    if q.moving is not None:
        args["frame"] = wording.body(q.moving, lang)
    key = f"ask-{q.kind}" + ("-rel" if frame and cat.has(f"ask-{q.kind}-rel") else "")
    written = q.echo.get(QUESTIONS[q.kind].name, "@")      # the target as the file writes it
    if hasattr(target, "point") and "@" not in str(written) and cat.has(key + "-point"):
        key += "-point"          # `{velocity: C}`: every body carrying C moves it alike
    if not cat.has(key):
        return cat.format("ask-other", {"n": q.index + 1})
    text = cat.format(key, args)
    for pattern, short in CONTRACTIONS.get(lang, ()):
        text = pattern.sub(short, text)
    return text


def part_words(row: Row, lang: str, model: Any = None, q: Any = None) -> str:
    """The words of one number of a question: `x`, `radius`, `drag velocity, x`; a contact's
    point of one body named by that body (`body_a` of the joint's first body)."""
    cat = catalogue(lang)
    parts = row.question.split(".")[1:]
    words = []
    for p in parts:
        if p in COMPONENTS:
            words.append(p)
        elif p in ("body_a", "body_b") and model is not None and q is not None:
            joint = next((j for j in model.joints if j.id == str(q.target)), None)
            body = (joint.a if p == "body_a" else joint.b) if joint is not None else p
            words.append(cat.format("part-of-body", {"body": model.wording.body(body, lang)}))
        else:
            key = f"part-{p}"
            words.append(cat.format(key) if cat.has(key) else p)
    return ", ".join(words)


def units_note(exercise: Any, lang: str) -> str:
    """How answers are given: units and signs (planar ω, α counter-clockwise positive)."""
    key = "units-note-planar" if exercise.model.dimension == 2 else "units-note-spatial"
    return catalogue(lang).format(key, {"unit": exercise.section.length.name})
