"""Issue 30, twenty-second round (b): a Basque reader's items on main's pages.

- the fixed body's row ties the model's name to the ground's word the text uses for every
  absolute centre's reference (C5-1.1, C5-1.5: "*sabaia* (finkoa)" beside "*lurrarekiko*");
- the Basque M/D legend says what the clashing letter marks, in one clause per letter;
- the Basque centre-on-a-line sentence has its verb ("perpendikularrak dira");
- the Basque model texts of C5-1.1, C5-1.3 and C5-E.6 (their own words).
"""

from __future__ import annotations

import re


from .helpers import LANGS, SEEDS, over, rendered, model_tree

# the ground's word as the page writes it, italic (the catalogues' ground-word, without article)
GROUND = {"en": "*ground*", "es": "*suelo*", "ca": "*terra*", "eu": "*lurra*"}
# the frame's row when the model names a shapeless frame otherwise: the reader's own words
# (twenty-seventh round (e): no longer tied to the ground's word, which the text no longer says)
TIED = {"en": "| 1 | *ceiling* (fixed) |", "es": "| 1 | *techo* (fijo) |",
        "ca": "| 1 | *sostre* (fix) |", "eu": "| 1 | *sabaia* (finkoa) |"}
# what each of the notes' letters marks, in Basque (001: M modulua, D norabidea)
MARKED = {"M": "modulu", "D": "norabide"}


def _frame_row(md: str) -> str:
    row = re.search(r"^\| 1 \| .*$", md, flags=re.M)
    assert row, "no structure table"
    return row.group(0)


@over(name=SEEDS, lang=LANGS)
def test_the_frame_row_names_the_ground_the_text_refers_to(name: str, lang: str) -> None:
    """Wherever the text says "relative to the *ground*" and the model names its fixed body
    otherwise (a ceiling, a fixed pulley, a track), that body's row says it is the ground:
    one rule for C5-1.1/1.5's ceiling and C5-1.6's "*polea finkoa* (*lurra*)", decided per
    language (Spanish 001 and C5-1.4 call the frame *bastidor*: "(fijo: el *suelo*)"). A name
    that says the ground's word as one of its words needs no tie (twenty-fourth round a:
    C5-1.8's Catalan "*terra cilíndric*")."""
    md = rendered(name, lang)
    row = _frame_row(md)
    if row.startswith(f"| 1 | {GROUND[lang]}") or GROUND[lang] not in md.replace(row, ""):
        return      # the model calls it the ground in this language, or the text never says the ground
    name_words = re.match(r"\| 1 \| \*([^*]+)\*", row).group(1).split()
    assert GROUND[lang] in row or GROUND[lang].strip("*") in name_words, row


@over(name=("seed_c5_1_1_pulley_on_cable", "seed_c5_1_5_pulley_block"), lang=LANGS)
def test_a_ceiling_is_fixed_and_tied_to_the_ground(name: str, lang: str) -> None:
    """A shapeless frame named otherwise: marked fixed, in the reader's words (and, since the
    twenty-seventh round (e), named so wherever it is a reference: no tie to the ground)."""
    md = rendered(name, lang)
    # its row names the parts welded to it (C5-1.5's strand 1, twenty-ninth round (b))
    assert _frame_row(md).startswith(TIED[lang].rstrip(" |")), _frame_row(md)


@over(name=SEEDS)
def test_the_basque_legend_says_what_a_clashing_letter_marks(name: str) -> None:
    """The old clause ("termino baten azpian letra hauek beti marka hauek dira, ez inoiz D
    puntua") is gone; a letter that is also a point of the model is said as a mark with what it
    marks, in a sentence of its own (twenty-fourth round (e)): "Hemen D letrak norabide
    ezaguna adierazten du; ez da D puntua"."""
    md = rendered(name, "eu")
    assert "ez inoiz" not in md and "termino baten azpian" not in md
    model = model_tree(name)
    clash = [m for m in ("M", "D") if m in (model.get("points") or {})]
    for letter in ("M", "D"):
        said = re.search(rf"{letter} letrak {MARKED[letter]} ezaguna adierazten du; ez da {letter} puntua", md)
        assert bool(said) == (letter in clash), (letter, clash)


def test_the_basque_centre_line_sentence_has_its_verb() -> None:
    """C5-1.5's I_polea3: "biak … zuzenarekiko perpendikularrak dira. Zuzen horretan …"."""
    md = rendered("seed_c5_1_5_pulley_block", "eu")
    assert "zuzenarekiko perpendikularrak dira. Zuzen horretan" in md
    for name in SEEDS:
        assert "zuzenarekiko perpendikularrak. " not in rendered(name, "eu"), name


def test_the_basque_model_texts_read_as_basque() -> None:
    """The models' own Basque words: C5-1.1's V of cable; C5-1.3's S, the support's centre
    (en: the sleeve, at the support's centre); C5-E.6's P, the crank's end (en: pedal axle,
    apart from C, the crank axle), and one name for the chainring in its radius."""
    assert "V formako kable simetriko batetik" in rendered("seed_c5_1_1_pulley_on_cable", "eu")
    assert "kable-V" not in rendered("seed_c5_1_1_pulley_on_cable", "eu")
    assert "| S | *euskarriaren* zentroa (gida bertatik doa) |" in rendered("seed_c5_1_3_bar_in_sleeve", "eu")
    bike = rendered("seed_c5_e6_bicycle", "eu")
    assert "| P | pedalaren muturra, C-tik L beherago |" in bike   # one word for the crank of length L (round 28 e; where, 29 b)
    assert "| C | pedalen ardatza |" in bike
    assert "| *R* | *plater pedaldunaren* erradioa |" in bike and "platerraren" not in bike
    assert ("hemen jarraitzen dugun haren ebazpenean, *plater pedaldunaren* erradioa R da eta "
            "*pinoiarena* r") in bike
