"""A question of quiz.xml shown roughly as Moodle shows it (to look at, not a copy of Moodle's
renderer): the question text with each Cloze subquestion as a text box, filled with given
answers and marked (green right, red wrong, with the subquestion's feedback as Moodle shows
it on the box), then the general feedback; files at @@PLUGINFILE@@ shown from the XML."""
from __future__ import annotations

import html
import xml.etree.ElementTree as ET

from .moodle_rules import extract

STYLE = """
body{font-family:"DejaVu Sans",Arial,sans-serif;background:#f5f5f5;margin:0;padding:16px;font-size:14px}
.que{background:#fff;border:1px solid #dee2e6;border-radius:4px;display:flex;max-width:980px}
.info{background:#f8f9fa;border-right:1px solid #dee2e6;padding:10px;width:110px;font-size:12px;color:#444}
.info .no{font-size:16px;font-weight:bold;color:#0f6cbf}
.content{padding:12px 16px;flex:1}.formulation{background:#e7f3f5;border-radius:4px;padding:10px 14px}
input.cloze{font:inherit;padding:1px 4px;border:1px solid #8f959e;border-radius:3px}
input.right{border-color:#357a32;background:#eaf5e9}input.wrong{border-color:#ca3120;background:#fbeaea}
span.mark{font-weight:bold;margin:0 3px}span.mark.right{color:#357a32}span.mark.wrong{color:#ca3120}
span.fb{display:inline-block;background:#fcefdc;border:1px solid #f0c36d;border-radius:3px;font-size:12px;
padding:0 4px;margin-left:2px}
.outcome{background:#fcefdc;border-radius:4px;padding:10px 14px;margin-top:10px}
.outcome h4{margin:0 0 6px}
"""


def question_page(quiz_xml: str, number: int, answers: dict[int, str], feedback_limit: int = 4000) -> str:
    """Question `number` (1-based among the Cloze ones) with the subquestions' `answers`
    (position -> typed text), as a page."""
    root = ET.fromstring(quiz_xml.encode())
    q = root.findall("question[@type='cloze']")[number - 1]
    files = {f.get("name"): f.text for f in q.findall("questiontext/file")}
    text, subs = extract(q.findtext("questiontext/text"))
    for name, data in files.items():
        text = text.replace(f"@@PLUGINFILE@@/{name}", f"data:image/png;base64,{data}")
    for position, sub in enumerate(subs, start=1):
        typed = answers.get(position, "")
        box = _box(sub, typed)
        text = text.replace("{#%d}" % position, box, 1)
    general = q.findtext("generalfeedback/text") or ""
    if len(general) > feedback_limit:
        general = general[:general.rfind("<h2", 0, feedback_limit)] + "<p>…</p></div>"
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><style>{STYLE}</style></head><body>"
            f"<div class='que'><div class='info'>Question <span class='no'>{number}</span><br>Complete<br>"
            f"{len(answers)} of {len(subs)} answered</div><div class='content'>"
            f"<div class='formulation'>{text}</div><div class='outcome'><h4>General feedback</h4>{general}</div>"
            f"</div></div></body></html>")


def _box(sub, typed: str) -> str:
    size = max(len(a.answer) for a in sub.alternatives) + 1
    if not typed:
        return f"<input class='cloze' size='{size}'>"
    value = float(typed)
    chosen = next((a for a in sub.alternatives if abs(value - float(a.answer)) <= float(a.tolerance)), None)
    right = chosen is not None and chosen.fraction == 1
    mark = "✔" if right else "✘"
    kind = "right" if right else "wrong"
    feedback = f"<span class='fb'>{chosen.feedback}</span>" if chosen is not None and chosen.feedback else ""
    return (f"<input class='cloze {kind}' size='{size}' value='{html.escape(typed)}'>"
            f"<span class='mark {kind}'>{mark}</span>{feedback}")
