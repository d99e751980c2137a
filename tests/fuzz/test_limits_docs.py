"""The limits table of docs/model-format.md is `kinematika.limits`: the
same names, the same values, nothing missing or extra."""
from __future__ import annotations

import re

import pytest

from kinematika import limits

from .contract import ROOT

ROW = re.compile(r"^\| `([A-Z_]+)` \| ([^|]+) \|", re.MULTILINE)


def _table(text: str) -> dict[str, float]:
    return {name: float(value.replace(" ", "").replace(",", "")) for name, value in ROW.findall(text)}


@pytest.mark.parametrize("doc", ["docs/model-format.md"])
def test_the_documented_limits_are_the_modules(doc):
    table = _table((ROOT / doc).read_text(encoding="utf-8"))
    module = {name: float(value) for name, value in vars(limits).items()
              if name.isupper() and isinstance(value, (int, float))}
    assert table == module
