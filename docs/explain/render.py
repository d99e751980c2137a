"""Render the six explanations of docs/explain.md in the four languages as HTML, then PNG
through headless Chromium.

    .venv/bin/python docs/explain/render.py [LANG ...]

Writes docs/explain/NAME.LANG.html and NAME.LANG.png (a full-page screenshot, trimmed).
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from PIL import Image, ImageChops

from kinematika.explain import explain

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parents[1] / "examples"
SIX = ["seed_c5_1_4_epicyclic", "quick_return", "seed_c5_2_1_tricycle", "tractor_trailer", "triad_six_bar",
       "spherical_four_bar"]
LANGS = ["en", "es", "ca", "eu"]
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars"]


def shoot(html: Path, png: Path, width: int = 1000, height: int = 30000) -> None:
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run(["chromium", *FLAGS, f"--user-data-dir={profile}", f"--screenshot={png}",
                        f"--window-size={width},{height}", html.as_uri()], check=True, capture_output=True)
    image = Image.open(png).convert("RGB")
    box = ImageChops.difference(image, Image.new("RGB", image.size, "white")).getbbox()
    page = image.crop((0, 0, width, min(height, box[3] + 40)))
    page.quantize(colors=64).save(png, optimize=True)


def main() -> None:
    for lang in sys.argv[1:] or LANGS:
        for name in SIX:
            html = HERE / f"{name}.{lang}.html"
            html.write_text(explain(EXAMPLES / f"{name}.yaml", lang=lang, fmt="html"), encoding="utf-8")
            shoot(html, HERE / f"{name}.{lang}.png")
            print(html.with_suffix(".png").name, flush=True)


if __name__ == "__main__":
    main()
