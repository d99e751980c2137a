"""A variant's worked solution: `kinematika explain --format html` of that variant, taken as
it is (the notes' method, its figures inline as SVG), made a fragment that another page
holds (the key, a quiz question's general feedback): its body, and its style scoped to a
`div.kinematika-solution` so that it styles nothing else of the page that holds it."""
from __future__ import annotations

import re
from typing import Any

SCOPE = "kinematika-solution"
_STYLE = re.compile(r"<style>(.*?)</style>", re.S)
_BODY = re.compile(r"<body[^>]*>(.*)</body>", re.S)
_RULE = re.compile(r"([^{}]+)\{([^{}]*)\}")


def solution_html(exercise: Any, variant: Any, lang: str) -> str:
    """The worked solution of `variant` as an HTML fragment (`div.kinematika-solution`)."""
    import dataclasses

    from ..commands import How, explain_text

    titled = dataclasses.replace(exercise.model, name=exercise.title)     # the exercise's title
    page = explain_text(titled, lang, "html", how=How(set=variant.sets), length_unit=exercise.section.length.name)
    return fragment(page)


def fragment(page: str) -> str:
    """A whole HTML page as a scoped fragment: its body in a div, its style scoped to it."""
    style = _STYLE.search(page)
    body = _BODY.search(page)
    inner = body.group(1) if body else page
    css = scoped(style.group(1)) if style else ""
    return f'<div class="{SCOPE}"><style>{css}</style>{inner}</div>'


def scoped(css: str) -> str:
    """Each rule's selectors prefixed by `.kinematika-solution` (`body` becomes the div
    itself, without its page margins)."""
    out = []
    for selectors, body in _RULE.findall(css):
        names = []
        for sel in selectors.split(","):
            sel = " ".join(sel.split())
            names.append(f".{SCOPE}" if sel == "body" else f".{SCOPE} {sel}")
        if selectors.strip() == "body":
            body = re.sub(r"(max-width|margin|padding):[^;]*;?", "", body)
        out.append(f"{','.join(names)}{{{body}}}")
    return "".join(out)
