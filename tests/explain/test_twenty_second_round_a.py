"""Issue 30, twenty-second round (a): what a caption says of o′, where a centre read off two
velocities is placed, and one Basque form of the Coriolis term.

- C5-1.2, C5-2.2: "The image of the point O is o′, since o is the pole." read as if O were at
  the pole, where it is not: the image is lettered o′ only because the letter o names the
  pole ("The image of O is lettered o′, because the letter o names the pole."); where O's
  image IS at the pole the round-21 sentence "o′, the image of O, is at the pole o" stays.
- C5-1.4: I_planet1's paragraph closed the ring's step (Step 2) and "Instant centres" said
  "placed in Step 2, with the velocities of planet 1": the paragraph opens planet 1's step,
  just after the last velocity it reads, and the pointer names that step and the points.
- eu: "termino normal eta Coriolis termino guztiak" beside "Coriolisen terminoa" and
  "Coriolisenak": "Coriolisen termino(a/ak)" everywhere.
"""
from __future__ import annotations

import re

from .helpers import LANGS, NOTES_SEEDS, over, rendered

# what each language's caption says when o′ is lettered so because o is the pole, and the
# wording that read as if O were at the pole
LETTERED = {"en": "The image of O is lettered o′, because the letter o names the pole.",
            "es": "La imagen de O se designa o′, porque la letra o designa el polo.",
            "ca": "La imatge d’O es designa o′, perquè la lletra o designa el pol.",
            "eu": "O puntuaren irudia o′ izendatzen da, o letrak poloa izendatzen baitu."}
AT_POLE_READING = {"en": "since o is the pole", "es": "ya que o es el polo", "ca": "ja que o és el pol",
                   "eu": "o poloa baita"}
# the image of O said at the pole (round 21 (e)'s sentence)
AT_POLE = {"en": "o′, the image of O,", "es": "o′, la imagen de O,", "ca": "o′, la imatge d’O,",
           "eu": "o′, O-ren irudia,"}
# where another body's point at O has an image of its own, o′ is the fixed point O (round 25 (d))
AT_POLE_FIXED = {"en": "o′, the image of the fixed point O of", "es": "o′, la imagen del punto fijo O de",
                 "ca": "o′, la imatge del punt fix O de", "eu": "O puntu finkoaren irudia,"}


def _captions(page: str) -> list[str]:
    """The figures' captions of a Markdown page (italic paragraphs)."""
    return [m.group(1) for m in re.finditer(r"^\*(.+)\*$", page, re.M)]


@over(name=NOTES_SEEDS, lang=LANGS)
def test_o_prime_lettered_not_at_the_pole(name: str, lang: str) -> None:
    """A caption that letters O's image o′ says it is because the letter o names the pole,
    never "since o is the pole"; and it says so only where o′ is not said to be at the pole."""
    for caption in _captions(rendered(name, lang)):
        assert AT_POLE_READING[lang] not in caption, caption
        said = AT_POLE[lang] in caption or AT_POLE_FIXED[lang] in caption
        if "o′" in caption and not said:
            assert LETTERED[lang] in caption, caption
        if said:
            assert LETTERED[lang] not in caption, caption


def test_the_lettered_sentence_is_said_where_o_moves() -> None:
    """The check reads real captions: C5-1.2 and C5-2.2 (O not at the pole) say it."""
    for name in ("seed_c5_1_2_bar_on_inclined_wheels", "seed_c5_2_2_articulated"):
        assert any(LETTERED["en"] in c for c in _captions(rendered(name, "en"))), name


STEP = {"en": r"^### Step (\d+)", "es": r"^### Paso (\d+)", "ca": r"^### Pas (\d+)", "eu": r"^### (\d+)\. urratsa"}
POINTER = {"en": r"^(I_\S+): placed in Step (\d+), (?:from|with) the velocities of (.+)\.$",
           "es": r"^(I_\S+): hallado en el paso (\d+), (?:a partir de|con) las velocidades (.+)\.$",
           "ca": r"^(I_\S+): trobat al pas (\d+), (?:a partir de|amb) les velocitats (.+)\.$",
           "eu": r"^(I_\S+): (\d+)\. urratsean aurkitua, (.+) (?:puntuen abiaduretatik|\S*\s*abiadurekin)\.$"}


def _steps(page: str, lang: str) -> dict[int, str]:
    """Each velocity step's text by its number (the first level with steps: velocities)."""
    out: dict[int, str] = {}
    parts = re.split(STEP[lang], page, flags=re.M)
    for n, text in zip(parts[1::2], parts[2::2]):
        out.setdefault(int(n), text.split("\n## ")[0])
    return out


@over(name=NOTES_SEEDS, lang=LANGS)
def test_centre_placed_in_the_step_that_starts_from_it(name: str, lang: str) -> None:
    """A centre whose paragraph a velocity step holds (read off two velocities) is placed in
    the step of the body whose centre it is (the first step that writes v_I), and "Instant
    centres" names that step. (A centre placed from a rate, C5-1.5's, has no paragraph there.)"""
    page = rendered(name, lang, "md", drawings=False)
    steps = _steps(page, lang)
    for m in re.finditer(POINTER[lang], page, re.M):
        centre, n = m.group(1), int(m.group(2))
        held = [k for k, text in steps.items() if re.search(rf"^{re.escape(centre)}: ", text, re.M)]
        if not held:
            continue
        used = [k for k, text in steps.items() if f"v_{{{centre}}}" in text]
        assert held == [n], f"{centre}'s paragraph is in step(s) {held}, the pointer says {n}"
        assert not used or min(used) == n, f"{centre} is placed in step {n}, first used in step {min(used)}"


def test_the_pointer_is_checked_on_the_epicyclic() -> None:
    """The check reads a real pointer: C5-1.4's planet centre, Step 3, from A1 and Q."""
    page = rendered("seed_c5_1_4_epicyclic", "en", "md", drawings=False)
    assert "I_{planet1}: placed in Step 3, from the velocities of A1 and Q." in page


@over(name=NOTES_SEEDS)
def test_basque_coriolis_said_one_way(name: str) -> None:
    """The Basque page names the Coriolis term one way, "Coriolisen termino(a/ak)": never
    "Coriolis termino(ak)" nor "Coriolisenak" (001 p_pair, 001 rolling, C5-1.3)."""
    page = rendered(name, "eu", "md", drawings=False)
    bad = re.findall(r"\bCoriolis\s+termino\w*|\bCoriolisenak\b|\bCoriolis\b(?!en)", page)
    assert not bad, bad
