"""The exercise as a Moodle XML quiz: one Cloze (embedded answers) question per variant.

Written as Moodle's importer reads it (`question/format/xml/format.php`, `readquestions`
and `import_multianswer`; the Cloze syntax of `question/type/multianswer/questiontype.php`):

- `<quiz>` holds a `category` question (the bank's category the variants go to, named after
  the problem in the class's language, so that a quiz's "random question" draws one per
  student) and one `<question type="cloze">` per variant, each with `<name><text>`, `<questiontext format="html">` (its `<text>` in CDATA,
  the figure as a `<file name=… path="/" encoding="base64">` that the text shows as
  `@@PLUGINFILE@@/name`), `<generalfeedback format="html">` (the worked solution),
  `<penalty>`, `<hidden>` and `<idnumber>`.
- Each number asked is a subquestion `{W:NUMERICAL:=value:margin#feedback~…}`: its grade W
  (a whole number, `ANSWER_REGEX_NORM`: the weights that make every question weigh the
  same, `weights`), the right value with its absolute margin (Moodle's numerical tolerance is absolute: the relative
  tolerance times the answer's size), then each usual mistake's value (`%0%`, no marks) with
  the feedback that names it, so that Moodle itself tells a student which mistake their
  number shows. Numbers are written as Moodle's `NUMBER_REGEX` reads them; a feedback's
  HTML has its `}`, `~`, `#`, `\\`, `&`, `<`, `>` and `"` written as numeric character
  references, which Moodle's parser does not take for delimiters and then decodes
  (`html_entity_decode`) back into that HTML.
- Units: a Cloze subquestion has none (`qtype_multianswer_extract_question` gives it
  `units = []`; `qtype_numerical_answer_processor::apply_units` then reads the number and
  leaves the unit unknown, so a typed unit is neither converted nor penalised), and the
  importer of a numerical question drops `<unitgradingtype>`
  (`qtype_numerical::save_unit_options` sets 0 unless the edit form's `unitrole` is there),
  so a penalty for a wrong unit cannot be imported as Moodle's own. It is written with the
  Cloze grammar instead: with `unit_penalty`, the right number written in each other unit
  of its kind (`915` for 0.915 m/s: mm/s) is an alternative worth `%(1 − penalty)%`, whose
  feedback says which unit the box asks for.
- With `split`, each graded question of each variant is a Cloze question of its own (the
  statement, the figure and that question's boxes) in a category per question
  (`TITLE/1. galdera`): a quiz draws a random variant of each part, and Moodle's grades and
  statistics are per part.
"""
from __future__ import annotations

import base64
from html import escape
from dataclasses import dataclass
from typing import Any, Optional

from .catalogue import catalogue
from .key import Row, value_text
from .mistakes import Mistaken
from .statement import asked, statement_html, units_note

PENALTY = "0.3333333"
CLOZE_SPECIAL = set('}~#&<>"')
# a backslash reaches the page as the reference &#92;: Moodle drops a backslash before } or #
# once the references are decoded, so it is decoded to that reference, which a browser shows
BACKSLASH = "&#38;#92;"
ROOT = "$course$/top/kinematika"


@dataclass(frozen=True)
class QuizOptions:
    """Moodle's own options of the quiz: a question per graded part (`split`), and the share
    of a box's grade a right number in another unit of its kind loses (`unit_penalty`, None:
    such a number is wrong)."""

    split: bool = False
    unit_penalty: Optional[float] = None


def figure_name(number: int) -> str:
    """The file name of variant `number`'s figure inside the Moodle quiz:
    ``kinematika-variant-007.png``."""
    return f"kinematika-variant-{number:03d}.png"


def quiz_xml(exercise: Any, figures: dict[int, bytes], solutions: Optional[dict[int, str]],
             mistakes: Optional[dict[int, list[Mistaken]]] = None, options: QuizOptions = QuizOptions()) -> str:
    """The quiz: a category named after the problem, then one Cloze question per variant; with
    `options.split`, a category per graded question, holding that part of every variant."""
    cat = catalogue(exercise.lang)
    parts = ['<?xml version="1.0" encoding="UTF-8"?>\n<quiz>\n']
    groups: list[tuple[str, Optional[int]]] = [(f"{ROOT}/{_category(exercise.title)}", None)]
    if options.split:
        groups = [(f"{ROOT}/{_category(exercise.title)}/{_category(cat.format('ask-other', {'n': k}))}", k)
                  for k in exercise.asks]
    for category, part in groups:
        parts += ['  <question type="category">\n    <category>\n      <text>', _xml(category),
                  '</text>\n    </category>\n  </question>\n']
        for v in exercise.variants:
            parts.append(_question(exercise, v, figures[v.number], (solutions or {}).get(v.number, ""),
                                   v.mistaken if mistakes is None else mistakes.get(v.number, []), options, part))
    parts.append("</quiz>\n")
    return "".join(parts)


def _category(name: str) -> str:
    """A category's name: Moodle's path separator `/` inside a name is written `//`."""
    return name.replace("/", "//")


def _question(exercise: Any, variant: Any, figure: bytes, solution: str, mistakes: list[Mistaken],
              options: QuizOptions, part: Optional[int]) -> str:
    lang = exercise.lang
    cat = catalogue(lang)
    title = f"{exercise.title} — {cat.format('sheet-variant', {'n': variant.number})}"
    ident = f"kinematika-{exercise.seed}-{variant.number:03d}"
    if part is not None:
        title += f" — {cat.format('ask-other', {'n': part})}"
        ident += f"-q{part}"
    text = question_text(exercise, variant, lang, mistakes, options, part)
    file = figure_name(variant.number)
    return (f'  <question type="cloze">\n'
            f'    <name>\n      <text>{_xml(title)}</text>\n    </name>\n'
            f'    <questiontext format="html">\n      <text>{_cdata(text)}</text>\n'
            f'      <file name="{file}" path="/" encoding="base64">{base64.b64encode(figure).decode()}</file>\n'
            f'    </questiontext>\n'
            f'    <generalfeedback format="html">\n      <text>{_cdata(solution)}</text>\n'
            f'    </generalfeedback>\n'
            f'    <penalty>{PENALTY}</penalty>\n    <hidden>0</hidden>\n'
            f'    <idnumber>{ident}</idnumber>\n'
            f'  </question>\n')


def question_text(exercise: Any, variant: Any, lang: str, mistakes: list[Mistaken],
                  options: QuizOptions = QuizOptions(), part: Optional[int] = None) -> str:
    """The question's HTML: the statement, the figure, the units, a Cloze field per number
    (of every graded question, or of question `part`), each weighted so that every question
    weighs the same (`weights`)."""
    from .weights import row_weights, whole

    cat = catalogue(lang)
    chosen = [a for a in asked(exercise, variant.rows, lang) if part is None or a.number == part]
    rows = [row for a in chosen for row, _ in a.parts]
    weights = whole(row_weights(rows, exercise.section.weights))
    length = exercise.section.length.name
    items = []
    for a in chosen:
        fields = "; ".join(f"{escape(words) + ' = ' if words else ''}"
                           f"{cloze(row, variant.tolerance_of(row), mistakes, lang, weights[row.question], options, exercise.section)}"
                           f"&nbsp;{escape(row.unit(length))}" for row, words in a.parts)
        items.append(f'<li value="{a.number}">{escape(a.words)}{": " if a.parts[0][1] else " = "}{fields}</li>')
    stated = variant.all_stated(exercise)
    return (statement_html(exercise, stated, lang)
            + f'<p><img src="@@PLUGINFILE@@/{figure_name(variant.number)}" alt="{escape(exercise.title)}"'
            f' style="max-width:100%;height:auto"></p>'
            + f"<p>{escape(units_note(exercise, lang))}</p>"
            + f"<p><b>{escape(cat.format('sheet-find'))}</b></p><ol>{''.join(items)}</ol>")


def cloze(row: Row, tolerance: float, mistakes: list[Mistaken], lang: str, weight: int = 1,
          options: QuizOptions = QuizOptions(), section: Any = None) -> str:
    """`{W:NUMERICAL:=v:m#right~%0%w:n#mistake~%P%u:k#unit~…}` for one number of the key: its
    weight, the right value with its absolute margin, each usual mistake's value (no marks)
    and, with a unit penalty, the right value in each other unit of its kind (the penalty off)."""
    cat = catalogue(lang)
    margin = row.margin(tolerance)
    alternatives = [f"={value_text(row.value)}:{value_text(margin)}#{cloze_text(cat.format('feedback-right'))}"]
    taken = [(row.value, margin)]
    if options.unit_penalty is not None and section is not None:
        # first, so that the right number in mm/s is credited, not taken for the data's mm as m
        credit = _percent(1 - options.unit_penalty)
        for unit, value, factor in other_units(row, section):
            m = margin * factor
            if all(abs(value - v) > m + w for v, w in taken):
                alternatives.append(f"%{credit}%{value_text(value)}:{value_text(m)}#" + cloze_text(cat.format(
                    "feedback-unit", {"unit": unit, "asked": row.unit(section.length.name)})))
                taken.append((value, m))
    for kind, value, wrong_margin in distinct_mistakes(row, tolerance, mistakes):
        if all(abs(value - v) > wrong_margin + w for v, w in taken):
            alternatives.append(f"%0%{value_text(value)}:{value_text(wrong_margin)}"
                                f"#{cloze_text(cat.format('mistake-' + kind))}")
            taken.append((value, wrong_margin))
    return "{" + str(weight) + ":NUMERICAL:" + "~".join(alternatives) + "}"


def _percent(share: float) -> str:
    """A fraction as Moodle's `%n%`: a plain decimal percentage, 0 to 100."""
    return f"{100 * min(max(share, 0.0), 1.0):.10g}"


def other_units(row: Row, section: Any) -> list[tuple[str, float, float]]:
    """The right value of `row` written in each other unit of its kind (mm/s and cm/s for a
    speed in m/s; rpm and °/s for a rate in rad/s): (the unit as printed, the value, the
    factor from the asked unit)."""
    from ..model.exercise_section import NAMES, UNITS
    from .typed import ROW_UNITS

    kind = ROW_UNITS.get(row.kind)
    if kind is None:
        return []
    base = section.length.size if kind in ("length", "speed", "accel") else 1.0
    asked_unit = row.unit(section.length.name)
    out = []
    for name in NAMES:
        unit = UNITS[name]
        if unit.kind != kind or unit.shown.replace("^2", "²") == asked_unit or name == "km/h":
            continue
        if abs(unit.size - base) <= 1e-12 * base:
            continue
        out.append((unit.shown.replace("^2", "²"), row.value * base / unit.size, base / unit.size))
    return out


def distinct_mistakes(row: Row, tolerance: float, mistakes: list[Mistaken]) -> list[tuple[str, float, float]]:
    """The mistakes of one number whose values neither match the right one nor an earlier
    mistake's (their margins do not overlap): (kind, value, margin), in `KINDS` order."""
    kept: list[tuple[str, float, float]] = [("", row.value, row.margin(tolerance))]
    for m in mistakes:
        wrong = m.rows.get(row.question)
        if wrong is None:
            continue
        margin = wrong.margin(tolerance)
        if all(abs(wrong.value - v) > margin + w for _, v, w in kept):
            kept.append((m.kind, wrong.value, margin))
    return kept[1:]


def cloze_text(text: str) -> str:
    """A plain feedback text inside a Cloze subquestion: as HTML (`escape`), then with the
    characters the Cloze parser reads as delimiters (`}`, `~`, `#`) and the HTML's own (`&`,
    `<`, `>`, `"`) as numeric character references, which the parser passes over and
    `html_entity_decode` turns back into that HTML; a backslash (which Moodle removes before
    `}` and `#` after decoding) as a reference that decodes to the reference `&#92;`."""
    return "".join(BACKSLASH if c == "\\" else f"&#{ord(c)};" if c in CLOZE_SPECIAL else c
                   for c in escape(text, quote=False))


def _cdata(text: str) -> str:
    """Text in CDATA, as Moodle's exporter writes it (`]]>` split between two sections)."""
    return "<![CDATA[" + text.replace("]]>", "]]]]><![CDATA[>") + "]]>"


def _xml(text: str) -> str:
    return escape(text, quote=True)
