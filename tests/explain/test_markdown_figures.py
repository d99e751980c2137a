"""A Markdown page reads as plain text: its figures are images by reference (`![…][fig-1]`),
their SVG data after everything else (standard output: one self-contained page), or SVG
files beside the page (`-o page.md`: page.fig-1.svg …), linked by a relative name."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

from .helpers import EXAMPLES, SEEDS, body_of, rendered

LONGEST = 700                   # characters: a long table row, caption or reasoning paragraph (C5-1.4's Basque planet centre with its no-slip reason, 628), never a figure's data
IMAGE = re.compile(r"!\[[^\n]*?\]\[(fig-\d+)\]")
DEFINITION = re.compile(r"^\[(fig-\d+)\]: (\S+)$", re.M)


@pytest.mark.parametrize("name", SEEDS)
def test_the_text_has_no_long_line_and_each_figure_is_defined_at_the_end(name):
    """eu (every language is written by the same renderer): no line of the body longer
    than LONGEST; each image's reference has a definition, all after the last line of text,
    and each definition's data is an SVG that parses."""
    import base64

    page = rendered(name, "eu")
    body = body_of(page).rstrip()
    assert max(len(line) for line in body.splitlines()) <= LONGEST, name
    used, defined = IMAGE.findall(page), DEFINITION.findall(page)
    assert used and used == [label for label, _ in defined], name
    first = page.index(f"[{defined[0][0]}]: ")
    assert page[first:].strip().count("\n") == len(defined) - 1, "text after the definitions"
    for label, target in defined:
        assert target.startswith("data:image/svg+xml;base64,"), (name, label)
        svg = ET.fromstring(base64.b64decode(target.split(",", 1)[1]))
        assert svg.tag.endswith("svg"), (name, label)


def test_written_to_a_file_the_figures_are_svg_files_beside_it(tmp_path):
    """`-o` a Markdown page: its figures as files named after the page, each a valid SVG,
    each link a relative name that resolves beside the page; no data URI left in it."""
    from typer.testing import CliRunner

    from kinematika.cli import app

    out = tmp_path / "epicicloidal.md"
    run = CliRunner().invoke(app, ["explain", str(EXAMPLES / "seed_c5_1_4_epicyclic.yaml"), "--lang", "ca",
                                   "-o", str(out)])
    assert run.exit_code == 0 and run.exception is None, run.output
    page = out.read_text(encoding="utf-8")
    assert "data:image" not in page and max(len(line) for line in page.splitlines()) <= LONGEST
    defined = dict(DEFINITION.findall(page))
    assert set(IMAGE.findall(page)) == set(defined) and len(defined) >= 3
    for label, target in defined.items():
        assert target == f"epicicloidal.{label}.svg"
        assert ET.parse(tmp_path / target).getroot().tag.endswith("svg")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["epicicloidal.md", *defined.values()])


def test_a_markdown_reader_shows_the_images():
    """Python-Markdown (when installed) reads each reference as an <img> with its source."""
    markdown = pytest.importorskip("markdown")
    page = rendered("seed_c5_1_4_epicyclic", "ca")
    shown = markdown.markdown(page, extensions=["tables"])
    sources = re.findall(r'<img alt="[^"]*" src="(data:image/svg\+xml;base64,[A-Za-z0-9+/=]+)"', shown)
    assert sources == [target for _, target in DEFINITION.findall(page)] and len(sources) >= 3
    assert "[fig-" not in shown
