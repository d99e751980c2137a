"""Issue 30, sixteenth round (a): what the English and Spanish readers still marked, each a
rule checked over the seeds and the languages where it applies:

1. the structure table has no "shapes" column (mostly empty on every seed): a round body's
   radius is folded into its cell ("*wheel*, circle of radius r"), and the Data section
   still states every radius;
2. the order of solution says what each step starts from — the bodies whose points its
   equation reads — and the decomposition sentence names no kind of input the mechanism may
   not have ("driven cranks and sliders" on a page with no slider).
"""
from __future__ import annotations

import re

import pytest

from .helpers import LANGS, SEEDS, rendered, over

SHAPES = {"en": "shapes", "es": "formas", "ca": "formes", "eu": "formak"}
RADIUS = {"en": "of radius", "es": "de radio", "ca": "de radi", "eu": "erradioko"}
STRUCTURE = {"en": "## Structure", "es": "## Estructura", "ca": "## Estructura", "eu": "## Egitura"}


def _structure_table(page: str) -> list[str]:
    start = page.index("\n| ", page.index("\n## ", page.index("\n## ") + 1))
    end = page.index("\n\n", start + 1)
    return page[start:end].strip().splitlines()


@over(name=SEEDS, lang=LANGS)
def test_the_structure_table_has_no_shapes_column(name, lang):
    """The header was `| no. | body | points | shapes |`, the last cell empty on most rows."""
    rows = _structure_table(rendered(name, lang, "md", drawings=False))
    header = [c.strip() for c in rows[0].strip("|").split("|")]
    assert SHAPES[lang] not in header, rows[0]
    assert all(len(r.strip("|").split("|")) == len(header) for r in rows), rows


# which bodies of a seed are round, and their radii, read off the statement (the yaml's
# circles), written as the page writes them
ROUND = {"seed_001_rolling_pair": {"roller R": "0.1 m"},
         "seed_c5_1_4_epicyclic": {"sun wheel": "r", "ring": "3·r", "planet 1": "r"},
         "seed_c5_1_7_semicylinder": {"semicylinder": "2·r", "wheel": "r"}}


@over(name=sorted(ROUND))
def test_a_round_body_cell_gives_its_radius(name):
    rows = _structure_table(rendered(name, "en", "md", drawings=False))
    for body, radius in ROUND[name].items():
        row = next(r for r in rows if f"*{body}*" in r)
        assert f"circle of radius {radius} " in row + " " or f"circle of radius {radius}|" in row.replace(" |", "|"), row


@pytest.mark.parametrize("lang", LANGS)
def test_the_data_section_still_states_every_radius(lang):
    page = rendered("seed_001_rolling_pair", lang, "md", drawings=False)
    data = page[:page.index(STRUCTURE[lang])]
    assert re.search(r"0[.,]1 m", data)


def _order(page: str) -> list[str]:
    return re.findall(r"^\d+\. .*$", page, flags=re.M)


def test_the_lever_is_found_from_the_slider_it_reads():
    """001 rolling: step 2 writes v_A = v_B + v_AB + v_{A∈R rel N}, v_A the slider's (given)
    and v_B the ground's: the order said "2. The *lever N*, from the *ground*"."""
    order = _order(rendered("seed_001_rolling_pair", "en", "md", drawings=False))
    assert "2. The *lever N*, from the *ground* and the *slider*." in order, order


def test_a_wheel_on_the_ground_keeps_the_ground_as_a_source():
    """C5-E.4: each lower wheel's equation starts at its contact with the ground (at rest)
    and its centre, pinned to the chassis: both are sources."""
    order = _order(rendered("seed_c5_e4_upper_wheel", "en", "md", drawings=False))
    for wheel in ("left", "right"):           # the left first, as asked (the sixteenth round (b))
        assert any(f"The *{wheel} wheel*, from the *ground* and the *chassis*." in item for item in order), order


def test_a_point_pinned_to_several_known_bodies_is_one_source():
    """C5-1.4: the sun wheel's step reads O at rest (pinned to the ground, the carrier and the
    ring) and planet 1's contact: "from planet 1 and the ground" (round 20f: in the order the
    step reads them, v_{J∈planet1} first), not four bodies."""
    order = _order(rendered("seed_c5_1_4_epicyclic", "en", "md", drawings=False))
    assert "4. The *sun wheel*, from *planet 1* and the *ground*." in order, order


NO_SLIDERS = {"en": "sliders", "es": "correderas", "ca": "corredores", "eu": "irristagailu"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_decomposition_names_no_input_kind_the_mechanism_lacks(lang):
    page = rendered("seed_001_r_pairs", lang, "md", drawings=False)
    assert NO_SLIDERS[lang] not in page.lower()
