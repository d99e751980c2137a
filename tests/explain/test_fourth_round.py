"""The fourth teacher audit of issue 30 (Basque 4 A / 15 B): the recurring defects, each a
rule of the builder, checked on every seed in every language."""
from __future__ import annotations

import re

import pytest

from kinematika.explain.catalogue import LANGS

from .helpers import SEEDS, explained, rendered

# a velocity or acceleration of one point about another, or a segment after ⊥ ∥ × ·, written
# apart (v_{A-O1}, ⊥ O1-A) or run together from two one-letter labels (v_BA, ⊥ AB)
APART = re.compile(r"(?:\b[va]_\{|[⊥∥×·] )[A-Z][A-Z0-9]*-[A-Z][A-Z0-9]*\b")
TOGETHER = re.compile(r"(?:\b[va]_|[⊥∥×·] )([A-Z][A-Z])(?![\w{-]| [^\W\d_])")


def _text(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_one_notation_for_pairs_of_points_per_page(name, lang):
    """A page writes every pair of points one way: all apart (v_{B-A}, ⊥ A-B) once one label
    needs a separator (O1, J3, the reserved AB), else all run together (v_BA, ⊥ AB) — never
    v_{A-O1} beside v_BA on one sheet."""
    text = _text(name, lang)
    apart = sorted(set(APART.findall(text)))
    sol, _ = explained(name)
    together = sorted(set(TOGETHER.findall(text)) - set(sol.inst.points))   # v_RL: a point
    assert not (apart and together), (apart[:4], together[:4])
