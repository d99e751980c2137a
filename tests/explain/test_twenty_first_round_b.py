"""Issue 30, twenty-first round (b): one word for the fixed body on a page. An absolute
centre or velocity is said relative to the ground (the notes' "respecte al terra") in every
sentence that says it, whatever the model calls its fixed body (C5-1.5's "relative to the
*ceiling*" beside "relative to the *ground*", C5-1.4's "respecto del *bastidor*"); the
structure table's fixed row keeps the model's name for it (C5-1.1 en: *ceiling*, as es
*techo*)."""
from __future__ import annotations

import re

import yaml

from .helpers import EXAMPLES, LANGS, SEEDS, over, plain_page

# the reference of a motion as each language writes it, the body's name captured
REFERENCE = {"en": r"relative to the \*([^*]+)\*", "es": r"respecto de(?:l| la) \*([^*]+)\*",
             "ca": r"respecte de(?:l| la|l’) ?\*([^*]+)\*", "eu": r"\*([^* ]+?)a?rekiko\*"}
WORD = {"en": "ground", "es": "suelo", "ca": "terra", "eu": "lurr"}


def _ground_name(name: str, lang: str) -> str:
    model = yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text())
    said = ((model.get("names") or {}).get(lang) or {}).get("bodies", {}).get("ground", "")
    return re.sub(r"^(el|la|l’) ", "", said)


@over(name=SEEDS, lang=LANGS)
def test_the_fixed_body_is_the_ground_where_it_is_a_reference(name: str, lang: str) -> None:
    own = _ground_name(name, lang)
    if not own or own.startswith(WORD[lang]):
        return
    stem = own[:-1] if lang == "eu" and own.endswith("a") else own
    refs = set(re.findall(REFERENCE[lang], plain_page(name, lang)))
    assert stem not in refs, (own, sorted(refs))


def test_pulley_on_cable_keeps_the_ceiling_in_its_table() -> None:
    """C5-1.1: the model names its fixed body the ceiling in every language."""
    page = plain_page("seed_c5_1_1_pulley_on_cable", "en")
    assert "| 1 | *ceiling* (fixed) |" in page
    assert "relative to the *ground*" in page
