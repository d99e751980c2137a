"""The printable pages of an exercise: one sheet per student (the variant's statement, its
figure and a box for each number asked, named as `grade` reads it: q2.y), and the answer
key (each variant's data, the numbers with their margins, and the worked solution). HTML
made to print on A4 (`@page`), one sheet per page; `printing` turns them into PDF."""
from __future__ import annotations

import base64
from html import escape
from typing import Any

from .catalogue import catalogue
from .roster import Student
from .statement import asked, statement_html, units_note
from .stated import number_text

STYLE = """
@page{size:A4;margin:14mm 15mm}
body{font-family:"DejaVu Sans",Arial,sans-serif;color:#1b1b1b;font-size:10.5pt;line-height:1.4;margin:0}
section.sheet{break-after:page;padding:0 2mm}
section.sheet:last-child{break-after:auto}
header{display:flex;justify-content:space-between;align-items:baseline;border-bottom:2px solid #1f5fa8;
margin-bottom:3mm}
header h1{font-size:14pt;margin:0}header .variant{font-size:11pt;color:#1f5fa8;font-weight:bold}
p.student{display:flex;gap:8mm;margin:2mm 0 3mm}p.student span.line{flex:1;border-bottom:1px solid #555}
figure{margin:1mm 0;text-align:center}figure img{max-width:100%;max-height:100mm}
p.note{font-size:9pt;color:#444}
h2{font-size:11.5pt;margin:4mm 0 1mm;border-bottom:1px solid #ccc}
table.answers{border-collapse:collapse;width:100%}
table.answers td{padding:1mm 1.5mm;vertical-align:bottom}
table.answers td.n{font-weight:bold;width:6mm}
table.answers td.box{border-bottom:1px solid #333;width:32mm}
table.answers td.unit{width:16mm}table.answers td.id{font-family:"DejaVu Sans Mono",monospace;
font-size:8pt;color:#777;width:16mm}
table.key{border-collapse:collapse;margin:2mm 0}table.key td,table.key th{border:1px solid #ccc;
padding:.8mm 2mm;text-align:left}table.key th{background:#f1f4f9}table.key td.num{text-align:right;
font-variant-numeric:tabular-nums}
"""


def students_for(exercise: Any) -> list[Student]:
    """The sheets' students: the class with their variants, else one unnamed sheet per variant."""
    if exercise.students:
        return list(exercise.students)
    return [Student("", variant=v.number) for v in exercise.variants]


def png_uri(data: bytes) -> str:
    """PNG bytes as a data URI, so that a sheet's HTML holds its figure and prints on its own."""
    return "data:image/png;base64," + base64.b64encode(data).decode()


def _page(title: str, lang: str, body: str) -> str:
    return (f'<!DOCTYPE html>\n<html lang="{lang}">\n<head>\n<meta charset="utf-8">\n'
            f"<title>{escape(title)}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{body}</body>\n</html>\n")


def _header(exercise: Any, number: int, lang: str, title_key: str = "sheet-title") -> str:
    cat = catalogue(lang)
    return (f"<header><h1>{escape(cat.format(title_key))}: {escape(exercise.title)}</h1>"
            f'<span class="variant">{escape(cat.format("sheet-variant", {"n": number}))}</span></header>')


def sheets_html(exercise: Any, figures: dict[int, bytes], students: list[Student]) -> str:
    """One page per student: who, the statement, the figure, the boxes to fill in."""
    lang = exercise.lang
    cat = catalogue(lang)
    pages = []
    for s in students:
        v = exercise.variant(s.variant)
        rows = []
        for a in asked(exercise, v.rows, lang):
            for i, (row, words) in enumerate(a.parts):
                first = i == 0
                rows.append(f'<tr><td class="n">{f"{a.number}." if first else ""}</td>'
                            f"<td>{escape(a.words) if first else ''}</td><td>{escape(words)}</td>"
                            f'<td class="box" data-q="{escape(row.question)}"></td>'
                            f'<td class="unit">{escape(row.unit(exercise.section.length.name))}</td></tr>')
        pages.append(
            f'<section class="sheet">{_header(exercise, v.number, lang)}'
            f'<p class="student"><span>{escape(cat.format("sheet-student"))}: <b>{escape(s.label)}</b></span>'
            f'<span>{escape(cat.format("sheet-name"))}:</span><span class="line"></span></p>'
            f"{statement_html(exercise, v.all_stated(exercise), lang)}"
            f'<figure><img src="{png_uri(figures[v.number])}" alt="{escape(exercise.title)}"></figure>'
            f'<p class="note">{escape(units_note(exercise, lang))}</p>'
            f"<h2>{escape(cat.format('sheet-find'))}</h2>"
            f'<table class="answers">{"".join(rows)}</table></section>\n')
    return _page(exercise.title, lang, "".join(pages))


def key_html(exercise: Any, figures: dict[int, bytes], solutions: dict[int, str]) -> str:
    """The answer key: per variant, its data and figure, the numbers and the worked solution."""
    lang = exercise.lang
    cat = catalogue(lang)
    unit = exercise.section.length.name
    pages = []
    for v in exercise.variants:
        rows = []
        for a in asked(exercise, v.rows, lang):
            for row, words in a.parts:
                rows.append(f"<tr><td><code class=\"id\">{escape(row.question)}</code></td><td>{escape(a.words)}</td><td>{escape(words)}</td>"
                            f'<td class="num">{number_text(row.value, lang)}</td>'
                            f'<td class="num">{number_text(row.margin(exercise.tolerance), lang, 2)}</td>'
                            f"<td>{escape(row.unit(unit))}</td></tr>")
        head = (f"<th></th><th colspan=\"2\">{escape(cat.format('key-question'))}</th>"
                f"<th>{escape(cat.format('key-value'))}</th><th>{escape(cat.format('key-margin'))}</th>")
        pages.append(
            f'<section class="sheet">{_header(exercise, v.number, lang, "key-title")}'
            f"{statement_html(exercise, v.all_stated(exercise), lang)}"
            f'<figure><img src="{png_uri(figures[v.number])}" alt="{escape(exercise.title)}"></figure>'
            f"<h2>{escape(cat.format('key-values'))}</h2>"
            f'<table class="key"><tr>{head}<th></th></tr>{"".join(rows)}</table>'
            f"<h2>{escape(cat.format('key-solution'))}</h2>{solutions.get(v.number, '')}</section>\n")
    return _page(f"{cat.format('key-title')}: {exercise.title}", lang, "".join(pages))
