"""The printable pages of an exercise: one sheet per student (their name, the variant's
statement, its figure and a box for each number asked), and the answer key. HTML made to
print on A4 (`@page`), one sheet per page; `printing` turns them into PDF.

The key is made to be searched and kept small: a table of contents first (each student, their
variant and its data, linked to its pages, and a bookmark of the PDF for each), then
the parts of the worked solution that are the same in every variant (the structure of the
mechanism, the order of solution), printed once, then one section per variant: who was
given it, its data and figure, the numbers with their margins and the rest of the worked
solution. The figures of the solutions print as vector drawings without transparency
(`solutions.printable`), and every glyph of them is defined once in the whole key.
"""
from __future__ import annotations

import base64
import re
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
margin-bottom:3mm;gap:4mm}
header h1{font-size:14pt;margin:0}header .variant{font-size:11pt;color:#1f5fa8;font-weight:bold;white-space:nowrap}
p.student{display:flex;gap:4mm;margin:2mm 0 3mm;align-items:baseline}
p.student b{font-size:11.5pt}p.student span.line{flex:1;border-bottom:1px solid #555}
figure{margin:1mm 0;text-align:center}figure img{max-width:100%}
p.note{font-size:9pt;color:#444}
h2{font-size:11.5pt;margin:4mm 0 1mm;border-bottom:1px solid #ccc}
table.answers{border-collapse:collapse;width:100%}
table.answers td{padding:.9mm 1.5mm;vertical-align:bottom}
table.answers td.n{font-weight:bold;width:6mm}
table.answers td.box{border-bottom:1px solid #333;width:34mm}
table.answers td.unit{width:16mm}
table.key{border-collapse:collapse;margin:2mm 0}table.key td,table.key th{border:1px solid #ccc;
padding:.6mm 1.6mm;text-align:left;font-size:9pt}table.key th{background:#f1f4f9}table.key td.num{text-align:right;
font-variant-numeric:tabular-nums;white-space:nowrap}
code.id{font-family:"DejaVu Sans Mono",monospace;font-size:8pt;color:#555}
table.contents{border-collapse:collapse;width:100%;font-size:9.5pt}
table.contents td,table.contents th{border-bottom:1px solid #ddd;padding:.6mm 2mm;text-align:left}
table.contents th{background:#f1f4f9}table.contents a{color:#1f5fa8;text-decoration:none}
p.students{margin:1mm 0 2mm;font-size:10pt}
div.key-solution{column-count:2;column-gap:7mm;column-rule:1px solid #e3e3e3}
div.key-solution .kinematika-solution{font-size:8.6pt;line-height:1.3}
div.key-solution .kinematika-solution h1{font-size:11pt;column-span:all}
div.key-solution .kinematika-solution h2{font-size:10pt;margin:2mm 0 1mm}
div.key-solution .kinematika-solution h3{font-size:9.2pt;margin:1.5mm 0 .5mm}
div.key-solution .kinematika-solution p,div.key-solution .kinematika-solution ul{margin:.6mm 0}
div.key-solution .kinematika-solution figure{margin:1mm 0}
div.key-solution .kinematika-solution figure svg{width:100%!important;max-width:100%!important;height:auto}
div.key-solution .kinematika-solution figcaption{font-size:8pt}
div.key-solution .kinematika-solution table{font-size:8pt}
div.key-solution .kinematika-solution table.eq{font-size:7.4pt;max-width:100%}
p.common{font-size:9pt;color:#555;font-style:italic}
"""


def students_for(exercise: Any) -> list[Student]:
    """The sheets' students: the class with their variants, else one unnamed sheet per variant."""
    if exercise.students:
        return list(exercise.students)
    return [Student("", variant=v.number) for v in exercise.variants]


def figure_tag(data: bytes, alt: str) -> str:
    """A statement figure printed at its own size (its text at 9 pt), never wider than the page."""
    from .figure import printed_width

    return f'<figure><img src="{png_uri(data)}" alt="{escape(alt)}" style="width:{printed_width(data):.2f}in"></figure>'


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
    """One page per student: who (the name and id from the class list, else a line to write
    the name on), the statement, the figure, the boxes to fill in."""
    lang = exercise.lang
    cat = catalogue(lang)
    unit = exercise.section.length.name
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
                            f'<td class="unit">{escape(row.unit(unit))}</td></tr>')
        who = (f'<span>{escape(cat.format("sheet-student"))}:</span><b>{escape(s.label)}</b>' if s.id else
               f'<span>{escape(cat.format("sheet-name"))}:</span><span class="line"></span>')
        pages.append(
            f'<section class="sheet">{_header(exercise, v.number, lang)}<p class="student">{who}</p>'
            f"{statement_html(exercise, v.all_stated(exercise), lang)}"
            f"{figure_tag(figures[v.number], exercise.title)}"
            f'<p class="note">{escape(units_note(exercise, lang))}</p>'
            f"<h2>{escape(cat.format('sheet-find'))}</h2>"
            f'<table class="answers">{"".join(rows)}</table></section>\n')
    return _page(exercise.title, lang, "".join(pages))


def key_html(exercise: Any, figures: dict[int, bytes], solutions: dict[int, str]) -> str:
    """The answer key: contents, the solution's common part, then each variant (its students,
    data and figure, the numbers with their margins, the rest of its worked solution)."""
    from .solutions import printable, shared

    lang = exercise.lang
    cat = catalogue(lang)
    unit = exercise.section.length.name
    common, own = split_common({n: printable(s) for n, s in solutions.items() if s})
    given: dict[int, list[Student]] = {}
    for s in exercise.students:
        given.setdefault(s.variant, []).append(s)
    pages = [_contents(exercise, given, lang)]
    if common:
        pages.append(f'<section class="sheet" id="common"><header><h1>{escape(cat.format("key-common"))}</h1>'
                     f'</header><div class="key-solution">{common}</div></section>\n')
    for v in exercise.variants:
        rows = []
        for a in asked(exercise, v.rows, lang):
            for i, (row, words) in enumerate(a.parts):
                rows.append(f'<tr><td><code class="id">{escape(row.question)}</code></td>'
                            f"<td>{escape(a.words) if i == 0 else ''}</td>"
                            f"<td>{escape(words)}</td><td class=\"num\">{number_text(row.value, lang)}</td>"
                            f'<td class="num">{number_text(v.margin(row), lang, 2)}</td>'
                            f"<td>{escape(row.unit(unit))}</td></tr>")
        head = (f"<th></th><th colspan=\"2\">{escape(cat.format('key-question'))}</th>"
                f"<th>{escape(cat.format('key-value'))}</th><th>{escape(cat.format('key-margin'))}</th>")
        students = given.get(v.number, [])
        who = (f'<p class="students">{escape(cat.format("key-students"))}: '
               f'{escape(", ".join(s.label for s in students))}</p>') if students else ""
        solution = own.get(v.number, "")
        if solution and common:
            solution = f'<p class="common">{escape(cat.format("key-see-common"))}</p>{solution}'
        pages.append(
            f'<section class="sheet variant" id="variant-{v.number}">{_header(exercise, v.number, lang, "key-title")}{who}'
            f"{statement_html(exercise, v.all_stated(exercise), lang)}"
            f"{figure_tag(figures[v.number], exercise.title)}"
            f"<h2>{escape(cat.format('key-values'))}</h2>"
            f'<table class="key"><tr>{head}<th></th></tr>{"".join(rows)}</table>'
            + (f"<h2>{escape(cat.format('key-solution'))}</h2><div class=\"key-solution\">{solution}</div>"
               if solution else "") + "</section>\n")
    return shared(_page(f"{cat.format('key-title')}: {exercise.title}", lang, "".join(pages)))


def _contents(exercise: Any, given: dict[int, list[Student]], lang: str) -> str:
    """The key's first page: each student (or each variant), the variant and its data, linked;
    each link names the PDF's bookmark to the variant's pages (`data-bookmark`: the student
    and the variant, or the variant and its data), so a teacher finds a student's in the
    viewer's side panel."""
    cat = catalogue(lang)

    def variant(n: int) -> str:
        return cat.format("sheet-variant", {"n": n})
    from ..explain.render.names import unicode_name
    from .stated import stated_text

    names = [v.name for v in exercise.varies]
    written = {n: unicode_name(exercise.model.wording.symbol(n, lang) or n) for n in names}
    data = {v.number: ", ".join(f"{written[n]} = {stated_text(v.stated[n], exercise.unit_of(n), lang)}" for n in names)
            for v in exercise.variants}
    if given:
        head = (f"<tr><th>{escape(cat.format('sheet-student'))}</th><th>{escape(cat.format('key-variant'))}</th>"
                f"<th>{escape(cat.format('key-data'))}</th></tr>")
        rows = [f'<tr><td>{escape(s.label)}</td><td><a href="#variant-{s.variant}" '
                f'data-bookmark="{escape(s.label)} — {escape(variant(s.variant))}">{s.variant}</a></td>'
                f"<td>{escape(data[s.variant])}</td></tr>"
                for s in sorted((s for ss in given.values() for s in ss), key=lambda s: (s.name or s.id).lower())]
    else:
        head = (f"<tr><th>{escape(cat.format('key-variant'))}</th><th>{escape(cat.format('key-data'))}</th></tr>")
        rows = [f'<tr><td><a href="#variant-{n}" data-bookmark="{escape(variant(n))}: {escape(d)}">{n}</a></td>'
                f"<td>{escape(d)}</td></tr>" for n, d in data.items()]
    return (f'<section class="sheet" id="contents"><header><h1>{escape(cat.format("key-title"))}: '
            f"{escape(exercise.title)}</h1></header><h2>{escape(cat.format('key-contents'))}</h2>"
            f'<table class="contents">{head}{"".join(rows)}</table></section>\n')


_PART = re.compile(r"(?=<h2\b)|(?=<figure\b)|(?<=</figure>)")     # sections, and a figure apart
_OWN_IDS = re.compile(r"v\d{3}-")


def split_common(solutions: dict[int, str]) -> tuple[str, dict[int, str]]:
    """The parts (from one `<h2>` to the next, a figure a part of its own) that are the same in
    every variant's solution, once (with the solution's style), and each variant's solution
    without them (a section whose text is shared but whose figure is drawn at the variant's
    numbers keeps the figure in the variant's pages)."""
    if len(solutions) < 2:
        return "", solutions
    parts = {n: _parts(s) for n, s in solutions.items()}
    first = next(iter(parts.values()))
    same = [i for i in range(len(first[1])) if all(
        len(p[1]) == len(first[1]) and _OWN_IDS.sub("v-", p[1][i]) == _OWN_IDS.sub("v-", first[1][i])
        for p in parts.values())]
    if not same:
        return "", solutions
    style, chunks, close = first
    common = f'<div class="kinematika-solution">{style}{"".join(chunks[i] for i in same)}{close}'
    own = {n: f'<div class="kinematika-solution">{p[0]}{"".join(c for i, c in enumerate(p[1]) if i not in same)}{p[2]}'
           for n, p in parts.items()}
    return common, own


def _parts(solution: str) -> tuple[str, list[str], str]:
    """A solution fragment as (its style, its parts: the text before the first `<h2>`, then
    one per `<h2>` with each figure apart, and its closing tag)."""
    m = re.match(r'<div class="kinematika-solution">(<style>.*?</style>)(.*)(</div>)\s*$', solution, re.S)
    if m is None:
        return "", [solution], ""
    return m.group(1), _PART.split(m.group(2)), m.group(3)
