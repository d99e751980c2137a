"""The page's exercise mode through the JSON API: `POST /api/exercise`.

    {"model": TEXT, "format": "yaml", "vary": ["s=300:500:10", ...], "seed": 7,
     "variant": 3, "lang": "eu", "answers": {"q1": "13.0", ...}, "reveal": false}

answers one variant of the model's exercise, as `kinematika exercise` draws it (the same
`vary` and `seed` give the same variants; without `vary`, the model's own data):

- without `answers`: the statement (HTML), the figure (a PNG data URL), the numbers asked
  (question id, words, unit) and the page's words — never the key's values;
- with `answers`: each typed number marked as `grade` marks it (right within the tolerance,
  else the usual mistake it shows, by the same diagnoses), with the feedback's words;
- with `"reveal": true` and answers (after a check): also the worked solution (`explain
  --format html` of the variant). No response carries a key value before a check.
"""
from __future__ import annotations

import base64
from typing import Any

from ..errors import KinematikaError

KEYS = ("vary", "seed", "variant", "answers", "reveal")
MAX_VARIANT = 1000


def exercise_options(body: dict) -> dict[str, Any]:
    """The exercise keys of a request, checked (a wrong one is a `usage` error naming it)."""
    vary = body.get("vary") or []
    if not (isinstance(vary, list) and all(isinstance(v, str) for v in vary)):
        raise KinematikaError("usage", "request-vary", "vary")
    out: dict[str, Any] = {"vary": vary,
                           "seed": _whole(body, "seed", 0, 0, 2 ** 63 - 1),
                           "variant": _whole(body, "variant", 1, 1, MAX_VARIANT)}
    answers = body.get("answers")
    if answers is not None and not (isinstance(answers, dict) and
                                    all(isinstance(k, str) and isinstance(v, (str, int, float))
                                        and not isinstance(v, bool) for k, v in answers.items())):
        raise KinematikaError("usage", "request-answers", "answers")
    out["answers"] = None if answers is None else {k: str(v) for k, v in answers.items()}
    reveal = body.get("reveal", False)
    if not isinstance(reveal, bool):
        raise KinematikaError("usage", "request-reveal", "reveal")
    if reveal and not out["answers"]:
        raise KinematikaError("usage", "reveal-after-check", "reveal")
    out["reveal"] = reveal
    return out


def _whole(body: dict, key: str, default: int, low: int, high: int) -> int:
    value = body.get(key, default)
    if not isinstance(value, int) or isinstance(value, bool) or not low <= value <= high:
        raise KinematikaError("usage", "request-whole-range", key, key=key, low=low, high=high)
    return value


def exercise_answer(req: Any) -> dict[str, Any]:
    """The answer to a checked `/api/exercise` request (see the module's docstring)."""
    from ..exercise.build import DEFAULT_SECTION, Exercise, make_exercise
    from ..exercise.catalogue import catalogue

    lang = req.get("lang", "en")
    model = req.how.model(req.model)
    vary, number = req.get("vary"), req.get("variant")
    if vary:
        ex = make_exercise(model, vary, number, req.get("seed"), lang)
    elif number != 1:
        raise KinematikaError("usage", "request-one-variant", "variant")
    else:
        ex = Exercise(model, model.exercise or DEFAULT_SECTION, [], req.get("seed"), lang)
        variant = ex.solve({})
        variant.number = 1
        ex.judged(variant)
        ex.variants.append(variant)
    variant = ex.variants[-1]
    variant.number = number
    out: dict[str, Any] = {"variant": number, "title": ex.title, "lang": lang}
    answers = req.get("answers")
    if answers is None:
        out.update(_statement(ex, variant, lang))
    else:
        out["marks"] = _marks(ex, variant, answers, lang)
        right = sum(1 for m in out["marks"] if m["correct"])
        out["score"] = {"right": right, "total": len(variant.rows),
                        "text": catalogue(lang).format("page-score", {"right": right, "total": len(variant.rows)})}
        if req.get("reveal"):
            from ..exercise.solutions import solution_html

            out["solution"] = solution_html(ex, variant, lang)
    return out


def _statement(ex: Any, variant: Any, lang: str) -> dict[str, Any]:
    from ..exercise.catalogue import catalogue
    from ..exercise.figure import statement_figure
    from ..exercise.statement import asked, statement_html, units_note

    stated = variant.all_stated(ex)
    png = statement_figure(ex, variant, lang)
    cat = catalogue(lang)
    words = {key: cat.format(key) for key in ("sheet-find", "page-check", "page-show", "page-your-answer",
                                               "page-link")}
    words["variant"] = cat.format("sheet-variant", {"n": variant.number})
    return {"statement": statement_html(ex, stated, lang),
            "figure": "data:image/png;base64," + base64.b64encode(png).decode(),
            "note": units_note(ex, lang), "words": words,
            "asks": [{"number": a.number, "words": a.words,
                      "parts": [{"question": row.question, "words": part,
                                 "unit": row.unit(ex.section.length.name)} for row, part in a.parts]}
                     for a in asked(ex, variant.rows, lang)]}


def _marks(ex: Any, variant: Any, answers: dict[str, str], lang: str) -> list[dict[str, Any]]:
    """Each typed number marked as `grade` marks it (its margin, the mistake it shows, an
    error carried forward from an earlier answer), with the feedback's words."""
    from ..exercise.catalogue import catalogue
    from ..exercise.grading import Marker, checked

    cat = catalogue(lang)
    marker = Marker(ex)
    marks = [m for question, text in answers.items()
             if (m := marker.mark("page", variant, question, text, f"answers.{question}")) is not None]
    out = []
    for mark in checked(marks, marker, variant):
        if mark.carried_from:
            feedback = cat.format("feedback-carried", {"question": mark.carried_from})
        elif mark.correct:
            feedback = cat.format("feedback-right")
        else:
            feedback = cat.format(f"mistake-{mark.diagnosis}") if mark.diagnosis else cat.format("feedback-wrong")
        out.append({"question": mark.question, "typed": mark.typed, "value": mark.value, "correct": mark.correct,
                    "diagnosis": mark.diagnosis, "feedback": feedback})
    return out
