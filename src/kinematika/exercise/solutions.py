"""A variant's worked solution: `kinematika explain --format html` of that variant, taken as
it is (the notes' method, its figures inline as SVG), made a fragment that another page
holds (the key, a quiz question's general feedback): its body, and its style scoped to a
`div.kinematika-solution` so that it styles nothing else of the page that holds it.

Made to sit many to a page and to print small:

- every id of its figures carries the variant (`v007-d1-p3`), so that the figures of several
  variants on one page (the key, a Moodle review page) never borrow each other's clip paths;
- its figures are written compactly: no metadata, coordinates to a tenth of a point (a
  figure is at most 460 pt wide), no blank space between tags;
- a glyph (matplotlib writes text as glyph paths, defined once per figure) is defined once
  per page: a later figure's copy is dropped and its uses point at the first (`shared`);
- for printing (`printable`), translucent strokes and fills are given the colour they show
  on white paper, and a hatched ground a flat grey: Chromium prints an SVG's transparency and
  patterns as small images, 60 of them a variant, which made the key of 60 variants 64 MB.
"""
from __future__ import annotations

import re
from typing import Any

SCOPE = "kinematika-solution"
_STYLE = re.compile(r"<style>(.*?)</style>", re.S)
_BODY = re.compile(r"<body[^>]*>(.*)</body>", re.S)
_RULE = re.compile(r"([^{}]+)\{([^{}]*)\}")
_ID = re.compile(r'\bid="([^"]+)"')
_DECIMAL = re.compile(r"-?\d+\.\d{2,}")
# the attributes that hold coordinates in points (never a transform's scale)
_COORDINATES = re.compile(r'(\b(?:d|x|y|x1|y1|x2|y2|cx|cy|r|rx|ry|width|height|points)=")([^"]*)"')
_GLYPH = re.compile(r'<path id="([^"]+)"((?: [a-z-]+="[^"]*")*)\s*/>')      # a defined path: its id, the rest
HATCH_GREY = "#d5d5d5"


def solution_html(exercise: Any, variant: Any, lang: str) -> str:
    """The worked solution of `variant` as an HTML fragment (`div.kinematika-solution`)."""
    import dataclasses

    from ..commands import How, explain_text

    titled = dataclasses.replace(exercise.model, name=exercise.title)     # the exercise's title
    page = explain_text(titled, lang, "html", how=How(set=variant.sets), length_unit=exercise.section.length.name)
    return compact(prefixed(fragment(page), f"v{variant.number:03d}-"))


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
        out.append(f"{','.join(names)}{{{' '.join(body.split())}}}")
    return "".join(out)


def prefixed(html: str, prefix: str) -> str:
    """Every id of the fragment, and every reference to one, with `prefix` in front."""
    html = _ID.sub(lambda m: f'id="{prefix}{m.group(1)}"', html)
    html = re.sub(r"url\(#([^)]+)\)", lambda m: f"url(#{prefix}{m.group(1)})", html)
    return re.sub(r'href="#([^"]+)"', lambda m: f'href="#{prefix}{m.group(1)}"', html)


def compact(html: str) -> str:
    """The fragment's figures written compactly (no metadata, tenths of a point, no blank
    space between tags); its glyphs defined once (`shared`)."""
    def figure(m: re.Match) -> str:
        svg = re.sub(r"<metadata>.*?</metadata>", "", m.group(0), flags=re.S)
        svg = _COORDINATES.sub(lambda n: n.group(1) + _DECIMAL.sub(lambda d: _tenth(d.group(0)), n.group(2)) + '"', svg)
        svg = re.sub(r"\s*\n\s*", " ", svg)
        return re.sub(r">\s+<", "><", svg)
    return shared(re.sub(r"<svg\b.*?</svg>", figure, html, flags=re.S))


def _tenth(text: str) -> str:
    value = round(float(text), 1)
    return f"{value:.1f}".rstrip("0").rstrip(".") if value != int(value) else str(int(value))


def shared(html: str) -> str:
    """Each path a figure defines (`<defs>`: glyphs, markers) defined once in the page: a later
    definition of the same path (shape and style) is dropped and its uses point at the first."""
    first: dict[str, str] = {}
    renamed: dict[str, str] = {}

    def keep(m: re.Match) -> str:
        ident, shape = m.group(1), m.group(2)
        if shape in first:
            renamed[ident] = first[shape]
            return ""
        first[shape] = ident
        return m.group(0)
    html = re.sub(r"<defs>.*?</defs>", lambda d: _GLYPH.sub(keep, d.group(0)), html, flags=re.S)
    if not renamed:
        return html
    return re.sub(r'href="#([^"]+)"', lambda m: f'href="#{renamed.get(m.group(1), m.group(1))}"', html)


def printable(html: str) -> str:
    """The fragment as it prints small and searchable: translucent colours made opaque as
    they look on white, hatched patches a flat grey, the patterns dropped."""
    html = re.sub(r'style="([^"]*)"', lambda m: f'style="{_opaque(m.group(1))}"', html)
    html = re.sub(r"<[a-z]+\b[^>]*\bopacity=\"[^>]*>", _opaque_tag, html)
    html = re.sub(r"fill:\s*url\(#[^)]*\)", f"fill: {HATCH_GREY}", html)
    return re.sub(r"<pattern\b.*?</pattern>", "", html, flags=re.S)


def _opaque(style: str) -> str:
    """A style's `opacity`, `fill-opacity` and `stroke-opacity` folded into its colours."""
    decl = [d.split(":", 1) for d in style.split(";") if ":" in d]
    props = {k.strip(): v.strip() for k, v in decl}
    whole = float(props.pop("opacity", 1) or 1)
    for paint in ("fill", "stroke"):
        alpha = whole * float(props.pop(f"{paint}-opacity", 1) or 1)
        colour = props.get(paint, "")
        if alpha < 1 and re.fullmatch(r"#[0-9a-fA-F]{6}", colour):
            props[paint] = _on_white(colour, alpha)
    return "; ".join(f"{k}: {v}" for k, v in props.items())


def _opaque_tag(m: re.Match) -> str:
    """A tag's `opacity` attributes folded into its `stroke` and `fill` colours."""
    tag = m.group(0)
    attrs = dict(re.findall(r'\b([a-z-]+)="([^"]*)"', tag))
    whole = float(attrs.get("opacity", 1) or 1)
    for paint in ("fill", "stroke"):
        alpha = whole * float(attrs.get(f"{paint}-opacity", 1) or 1)
        colour = attrs.get(paint, "")
        if alpha < 1 and re.fullmatch(r"#[0-9a-fA-F]{6}", colour):
            tag = tag.replace(f'{paint}="{colour}"', f'{paint}="{_on_white(colour, alpha)}"')
    return re.sub(r'\s(?:opacity|fill-opacity|stroke-opacity)="[^"]*"', "", tag)


def _on_white(colour: str, alpha: float) -> str:
    channels = [int(colour[i:i + 2], 16) for i in (1, 3, 5)]
    return "#" + "".join(f"{round(255 - alpha * (255 - c)):02x}" for c in channels)
