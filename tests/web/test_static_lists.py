"""Lists the page's static HTML repeats are the package's: the languages it offers are
`languages.LANGS` (a twin kept equal by this test; docs/architecture.md lists the others)."""
from __future__ import annotations

import re
from pathlib import Path

from kinematika.languages import LANGS

PAGE = (Path(__file__).parents[2] / "src" / "kinematika" / "web" / "static" / "index.html").read_text(encoding="utf-8")


def test_the_pages_languages_are_the_packages():
    for pick in ("language", "ui-language"):        # the explanation's and the page's (one choice)
        select = re.search(rf'<select id="{pick}".*?</select>', PAGE, re.DOTALL)
        assert select is not None, pick
        assert tuple(re.findall(r'<option value="([a-z]+)"', select.group(0))) == LANGS, pick
