"""Moodle's reading of a Cloze question, ported from the public moodle repository
(question/type/multianswer/questiontype.php: ANSWER_REGEX and its parts,
qtype_multianswer_extract_question, qtype_multianswer_validate_question; and
question/format/xml/format.php: readquestions, import_multianswer, import_text_with_files),
to test quiz.xml as Moodle's importer reads it.

PHP's PCRE lookbehind `(?<!\\\\|&|&amp;)` has alternatives of different widths, which
Python's `re` refuses: it is written as three lookbehinds, which mean the same.
"""
from __future__ import annotations

import html
import re
from dataclasses import dataclass

FRACTION = r"=|%(-?[0-9]+(?:[.,][0-9]*)?)%"
ANSWER = r".+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$)"
FEEDBACK = r".*?(?<!\\)(?=[~}]|$)"
ALTERNATIVE = f"({FRACTION})?({ANSWER})(#({FEEDBACK}))?"
TYPES = ("(NUMERICAL|NM)|(MULTICHOICE|MC)|(MULTICHOICE_V|MCV)|(MULTICHOICE_H|MCH)|"
         "(SHORTANSWER|SA|MW)|(SHORTANSWER_C|SAC|MWC)|"
         "(MULTICHOICE_S|MCS)|(MULTICHOICE_VS|MCVS)|(MULTICHOICE_HS|MCHS)|"
         "(MULTIRESPONSE|MR)|(MULTIRESPONSE_H|MRH)|(MULTIRESPONSE_S|MRS)|(MULTIRESPONSE_HS|MRHS)")
START = r"\{([0-9]*):(" + TYPES + "):"
ANSWER_REGEX = re.compile(START + "(" + ALTERNATIVE + "(~" + ALTERNATIVE + ")*)\\}", re.S)
ALTERNATIVE_REGEX = re.compile("~?" + ALTERNATIVE, re.S)
NUMBER = r"-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)"
NUMERICAL_ALTERNATIVE = re.compile("^(" + NUMBER + ")(:" + NUMBER + ")?$", re.S)
NORM, TYPE_NUMERICAL, ALTERNATIVES = 1, 3, 16
ALT_FRACTION, ALT_PERCENT, ALT_ANSWER, ALT_FEEDBACK = 1, 2, 3, 5
NUMERICAL_CORRECT, NUMERICAL_MARGIN = 1, 6


@dataclass
class Alternative:
    fraction: float
    answer: str
    tolerance: str
    feedback: str


@dataclass
class Subquestion:
    qtype: str
    mark: str
    alternatives: list[Alternative]


def extract(text: str) -> tuple[str, list[Subquestion]]:
    """qtype_multianswer_extract_question: the subquestions, and the text with {#n} left."""
    subs = []
    position = 1
    while True:
        found = ANSWER_REGEX.search(text)
        if not found:
            break
        numerical = bool(found.group(TYPE_NUMERICAL))
        mark = found.group(NORM) if found.group(NORM) != "" else "1"
        remaining = found.group(ALTERNATIVES)
        alts = []
        while True:
            alt = ALTERNATIVE_REGEX.search(remaining)
            if not alt:
                break
            if alt.group(ALT_FRACTION) == "=":
                fraction = 1.0
            elif alt.group(ALT_PERCENT):
                fraction = 0.01 * float(alt.group(ALT_PERCENT).replace(",", "."))
            else:
                fraction = 0.0
            feedback = alt.group(ALT_FEEDBACK)
            if feedback is not None:
                feedback = html.unescape(feedback).replace("\\}", "}").replace("\\#", "#")
            answer, tolerance = alt.group(ALT_ANSWER), ""
            number = NUMERICAL_ALTERNATIVE.search(answer) if numerical else None
            if number:
                answer = number.group(NUMERICAL_CORRECT)
                tolerance = number.group(NUMERICAL_MARGIN) or "0"
            alts.append(Alternative(fraction, answer, tolerance, feedback or ""))
            remaining = remaining.split(alt.group(0), 1)[1]
        subs.append(Subquestion("numerical" if numerical else "other", mark, alts))
        text = text.replace(found.group(0), "{#%d}" % position, 1)
        position += 1
    return text, subs


def valid_number(text: str) -> bool:
    """qtype_numerical::is_valid_number, for the plain numbers written here."""
    return re.fullmatch(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?", text.strip()) is not None


def validate(subs: list[Subquestion]) -> list[str]:
    """qtype_multianswer_validate_question's errors (empty: valid)."""
    errors = []
    if not subs:
        errors.append("questionsmissing")
    for i, sub in enumerate(subs, start=1):
        answers = [a for a in sub.alternatives if a.answer.strip() != ""]
        if not answers:
            errors.append(f"sub {i}: notenoughanswers")
        for a in answers:
            if sub.qtype == "numerical" and not (valid_number(a.answer) or a.answer.strip() == "*"):
                errors.append(f"sub {i}: answermustbenumberorstar {a.answer!r}")
        if not any(a.fraction == 1 for a in answers):
            errors.append(f"sub {i}: fractionsnomax")
    return errors
