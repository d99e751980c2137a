"""Render the explanations of docs/explain.md as HTML, then PNG through headless Chromium:
the six of the table in the four languages, and every worked example of the notes
(examples/seed_*.yaml) in Basque and Catalan, the languages the notes are taught in.

    .venv/bin/python docs/explain/render.py [NAME ...] [--lang LANG ...]

Writes docs/explain/NAME.LANG.html and NAME.LANG.png (a full-page screenshot, trimmed).
Playwright drives Debian's /usr/bin/chromium (never `playwright install`).
"""
from __future__ import annotations

import argparse
import io
from pathlib import Path

from PIL import Image, ImageChops

import functools

import kinematika
from kinematika.explain import build, render

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parents[1] / "examples"
SIX = ["seed_c5_1_4_epicyclic", "quick_return", "seed_c5_2_1_tricycle", "tractor_trailer", "triad_six_bar",
       "spherical_four_bar"]
SEEDS = sorted(p.stem for p in EXAMPLES.glob("seed_*.yaml"))
LANGS = ["en", "es", "ca", "eu"]
NOTES_LANGS = ["eu", "ca"]
WIDTH = 1000


def jobs(names: list[str], langs: list[str]) -> list[tuple[str, str]]:
    """(example, language) pairs: the six in every language, the notes' examples in eu and ca."""
    out = [(n, lang) for n in SIX for lang in LANGS] + [(n, lang) for n in SEEDS for lang in NOTES_LANGS]
    out = list(dict.fromkeys(out))
    return [(n, lang) for n, lang in out if (not names or n in names) and (not langs or lang in langs)]


def shoot(page, html: Path, png: Path) -> None:
    """A full-page screenshot of `html`, trimmed of the white below, in 64 colours."""
    page.goto(html.as_uri())
    image = Image.open(io.BytesIO(page.screenshot(full_page=True))).convert("RGB")
    box = ImageChops.difference(image, Image.new("RGB", image.size, "white")).getbbox()
    image.crop((0, 0, WIDTH, min(image.size[1], box[3] + 40))).quantize(colors=64).save(png, optimize=True)


@functools.lru_cache(maxsize=None)
def document(name: str):
    """The explanation of an example, built once for all its languages (what `kinematika
    explain` builds before rendering it in one)."""
    return build(kinematika.solve(EXAMPLES / f"{name}.yaml"))


def main() -> None:
    from playwright.sync_api import sync_playwright

    parser = argparse.ArgumentParser()
    parser.add_argument("names", nargs="*")
    parser.add_argument("--lang", action="append", default=[])
    args = parser.parse_args()
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": WIDTH, "height": 1200})
        for name, lang in jobs(args.names, args.lang):
            html = HERE / f"{name}.{lang}.html"
            html.write_text(render(document(name), lang, "html"), encoding="utf-8")
            shoot(page, html, HERE / f"{name}.{lang}.png")
            print(html.with_suffix(".png").name, flush=True)
        browser.close()


if __name__ == "__main__":
    main()
