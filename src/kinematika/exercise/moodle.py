"""The exercise as a Moodle XML quiz: one Cloze (embedded answers) question per variant.

Written as Moodle's importer reads it (`question/format/xml/format.php`, `readquestions`
and `import_multianswer`; the Cloze syntax of `question/type/multianswer/questiontype.php`):

- `<quiz>` holds a `category` question (the bank's category the variants go to, so that a
  quiz's "random question" draws one per student) and one `<question type="cloze">` per
  variant, each with `<name><text>`, `<questiontext format="html">` (its `<text>` in CDATA,
  the figure as a `<file name=… path="/" encoding="base64">` that the text shows as
  `@@PLUGINFILE@@/name`), `<generalfeedback format="html">` (the worked solution),
  `<penalty>`, `<hidden>` and `<idnumber>`.
- Each number asked is a subquestion `{1:NUMERICAL:=value:margin#feedback~…}`: the right
  value with its absolute margin (Moodle's numerical tolerance is absolute: the relative
  tolerance times the answer's size), then each usual mistake's value (`%0%`, no marks) with
  the feedback that names it, so that Moodle itself tells a student which mistake their
  number shows. Numbers are written as Moodle's `NUMBER_REGEX` reads them; a feedback's
  HTML has its `}`, `~`, `#`, `\\`, `&`, `<`, `>` and `"` written as numeric character
  references, which Moodle's parser does not take for delimiters and then decodes
  (`html_entity_decode`) back into that HTML.
"""
from __future__ import annotations

import base64
from html import escape
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


def figure_name(number: int) -> str:
    """The file name of variant `number`'s figure inside the Moodle quiz:
    ``kinematika-variant-007.png``."""
    return f"kinematika-variant-{number:03d}.png"


def quiz_xml(exercise: Any, figures: dict[int, bytes], solutions: Optional[dict[int, str]],
             mistakes: dict[int, list[Mistaken]]) -> str:
    """The quiz: a category, then one Cloze question per variant."""
    name = exercise.title
    category = f"$course$/top/kinematika/{name} (seed {exercise.seed})"
    parts = ['<?xml version="1.0" encoding="UTF-8"?>\n<quiz>\n',
             '  <question type="category">\n    <category>\n      <text>', _xml(category),
             '</text>\n    </category>\n  </question>\n']
    for v in exercise.variants:
        parts.append(_question(exercise, v, figures[v.number],
                               (solutions or {}).get(v.number, ""), mistakes.get(v.number, [])))
    parts.append("</quiz>\n")
    return "".join(parts)


def _question(exercise: Any, variant: Any, figure: bytes, solution: str, mistakes: list[Mistaken]) -> str:
    lang = exercise.lang
    cat = catalogue(lang)
    title = f"{exercise.title} — {cat.format('sheet-variant', {'n': variant.number})}"
    text = question_text(exercise, variant, lang, mistakes)
    file = figure_name(variant.number)
    return (f'  <question type="cloze">\n'
            f'    <name>\n      <text>{_xml(title)}</text>\n    </name>\n'
            f'    <questiontext format="html">\n      <text>{_cdata(text)}</text>\n'
            f'      <file name="{file}" path="/" encoding="base64">{base64.b64encode(figure).decode()}</file>\n'
            f'    </questiontext>\n'
            f'    <generalfeedback format="html">\n      <text>{_cdata(solution)}</text>\n'
            f'    </generalfeedback>\n'
            f'    <penalty>{PENALTY}</penalty>\n    <hidden>0</hidden>\n'
            f'    <idnumber>kinematika-{exercise.seed}-{variant.number:03d}</idnumber>\n'
            f'  </question>\n')


def question_text(exercise: Any, variant: Any, lang: str, mistakes: list[Mistaken]) -> str:
    """The question's HTML: the statement, the figure, the units, a Cloze field per number."""
    cat = catalogue(lang)
    items = []
    for a in asked(exercise, variant.rows, lang):
        fields = "; ".join(f"{escape(words) + ' = ' if words else ''}{cloze(row, exercise.tolerance, mistakes, lang)}"
                           f"&nbsp;{escape(row.unit(exercise.section.length.name))}" for row, words in a.parts)
        items.append(f"<li>{escape(a.words)}{': ' if a.parts[0][1] else ' = '}{fields}</li>")
    stated = variant.all_stated(exercise)
    return (statement_html(exercise, stated, lang)
            + f'<p><img src="@@PLUGINFILE@@/{figure_name(variant.number)}" alt="{escape(exercise.title)}"'
            f' style="max-width:100%;height:auto"></p>'
            + f"<p>{escape(units_note(exercise, lang))}</p>"
            + f"<p><b>{escape(cat.format('sheet-find'))}</b></p><ol>{''.join(items)}</ol>")


def cloze(row: Row, tolerance: float, mistakes: list[Mistaken], lang: str) -> str:
    """`{1:NUMERICAL:=v:m#right~%0%w:n#mistake~…}` for one number of the key."""
    cat = catalogue(lang)
    margin = row.margin(tolerance)
    alternatives = [f"={value_text(row.value)}:{value_text(margin)}#{cloze_text(cat.format('feedback-right'))}"]
    for kind, value, wrong_margin in distinct_mistakes(row, tolerance, mistakes):
        alternatives.append(f"%0%{value_text(value)}:{value_text(wrong_margin)}"
                            f"#{cloze_text(cat.format('mistake-' + kind))}")
    return "{1:NUMERICAL:" + "~".join(alternatives) + "}"


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
