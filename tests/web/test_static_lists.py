"""Lists the page's static HTML repeats are the package's: the languages it offers are
`languages.LANGS` (a twin kept equal by this test; docs/architecture.md lists the others)."""
from __future__ import annotations

import re
from pathlib import Path

from kinematika.languages import LANGS

PAGE = (Path(__file__).parents[2] / "src" / "kinematika" / "web" / "static" / "index.html").read_text(encoding="utf-8")


def test_the_pages_languages_are_the_packages():
    select = re.search(r'<select id="language".*?</select>', PAGE, re.DOTALL)
    assert select is not None
    assert tuple(re.findall(r'<option value="([a-z]+)"', select.group(0))) == LANGS
