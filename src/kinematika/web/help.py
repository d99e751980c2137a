"""The format reference and the from-a-problem walk-through, served by the page's server
(`GET /help`, `GET /docs/NAME.md`) as HTML, one click from the editor.

The documents are the repository's own `docs/*.md` (one source: what the README links to
is what the page shows), rendered by markdown-it-py (CommonMark and tables; it comes with
rich, which the command line uses already). Only Markdown files and their PNG figures
inside `docs/` are served; a name that leaves the folder is refused.
"""
from __future__ import annotations

import html
import re
from functools import lru_cache
from pathlib import Path

from ..errors import KinematikaError

DOCS = Path(__file__).resolve().parents[3] / "docs"
TITLE = re.compile(r"^#\s+(.+)$", re.M)
STYLE = """body{font:15px/1.55 "DejaVu Sans",Arial,sans-serif;max-width:900px;margin:0 auto;
padding:14px 22px 60px;color:#212121}code,pre{font-family:"DejaVu Sans Mono",monospace;
font-size:13px}pre{background:#f4f6f8;padding:10px 12px;border-radius:6px;overflow:auto}
table{border-collapse:collapse;display:block;overflow:auto}td,th{border:1px solid #d9dee3;
padding:4px 8px;vertical-align:top}img{max-width:100%}nav{font-size:13px;margin-bottom:10px}
nav a{margin-right:14px}h1,h2,h3{color:#1f5fa8}"""
NAV = ('<nav><a href="/docs/model-format.md">model-format.md</a>'
       '<a href="/docs/from-a-problem.md">from-a-problem.md</a><a href="/">kinematika</a></nav>')


def page_html(name: str) -> str | bytes:
    """The HTML of `docs/NAME` (a Markdown file), or the bytes of a PNG figure beside it."""
    path = (DOCS / name).resolve()
    if not str(path).startswith(str(DOCS.resolve()) + "/") or path.suffix not in (".md", ".png") \
            or not path.is_file():
        raise KinematikaError("usage", "help-no-document", "name", name=name)
    if path.suffix == ".png":
        return path.read_bytes()
    return _rendered(str(path), path.stat().st_mtime)


@lru_cache(maxsize=16)
def _rendered(path: str, _mtime: float) -> str:
    from markdown_it import MarkdownIt

    text = Path(path).read_text(encoding="utf-8")
    found = TITLE.search(text)
    title = html.escape(found.group(1) if found else Path(path).name)
    here = Path(path).parent.relative_to(DOCS.resolve())
    body = MarkdownIt("commonmark", {"html": False}).enable("table").render(text)
    body = re.sub(r'(href|src)="(?![a-z]+:|/|#)([^"]+)"',
                  lambda m: f'{m.group(1)}="/docs/{(here / m.group(2)).as_posix()}"', body)
    return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><meta name="viewport" '
            f'content="width=device-width, initial-scale=1"><title>{title}</title><style>{STYLE}'
            f"</style></head><body>{NAV}{body}</body></html>")
