"""docs/examples.md lists every planar example, links only files that exist, and every
example file opens with a comment saying what it shows."""
from __future__ import annotations

import re

from kinematika import load_model

from .helpers import EXAMPLES

DOC = (EXAMPLES.parent / "docs" / "examples.md").read_text(encoding="utf-8")


def test_every_planar_example_is_in_the_table_and_every_link_exists():
    named = set(re.findall(r"([a-z0-9_]+\.yaml)", DOC))
    planar = {f.name for f in EXAMPLES.glob("*.yaml") if load_model(f).dimension == 2}
    assert planar <= named, f"not in docs/examples.md: {sorted(planar - named)}"
    assert all((EXAMPLES / name).exists() for name in named), sorted(
        n for n in named if not (EXAMPLES / n).exists())


def test_every_documented_example_opens_with_a_comment():
    for name in re.findall(r"\]\(\.\./examples/([a-z0-9_]+\.yaml)\)", DOC):
        first = (EXAMPLES / name).read_text(encoding="utf-8").splitlines()[0]
        assert first.startswith("# "), name
