"""The fourth teacher audit of issue 30 (Basque 4 A / 15 B): the recurring defects, each a
rule of the builder, checked on every seed in every language."""
from __future__ import annotations

import re
from pathlib import Path


import kinematika.explain

from kinematika.explain.catalogue import LANGS

from .helpers import SEEDS, explained, rendered, over

def _text(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


def _equation_lines(text: str) -> list[tuple[str, list[list[str]]]]:
    """(left side, right sides as lists of terms) of every equation of the page's code blocks."""
    out, inside = [], False
    for line in text.splitlines():
        if line.startswith("```"):
            inside = not inside
            continue
        if inside and " = " in line and not line.startswith(" "):
            parts = [p.strip() for p in re.split(r"\s+=\s+", " ".join(line.split()))]
            out.append((parts[0], [p.split(" + ") for p in parts[1:]]))
    return out


def _point(symbol: str) -> str:
    """The point a v_{F∈N} is the motion of (F), else the symbol."""
    m = re.match(r"[va]_\{([A-Z][A-Z0-9]*)∈", symbol)
    return m.group(1) if m else symbol


@over(name=SEEDS, lang=LANGS)
def test_a_drag_the_steps_wrote_is_referred_to_not_written_again(name, lang):
    """No equation repeats a sum of two or more terms an earlier equation of the page already
    wrote for another symbol (001's v_arr,B = v_A + v_BA after v_B∈M = v_A + v_BA): the
    composition of motions refers to the step's equation instead."""
    seen: list[tuple[str, list[str]]] = []
    for left, sides in _equation_lines(_text(name, lang)):
        for side in sides:
            if len(side) > 1:
                again = [l for l, s in seen if s[:len(side)] == side and l != left
                         and _point(l) != _point(left)]    # a contact's two material points: F∈N, F∈R
                assert not again, (left, side, again)
        seen += [(left, s) for s in sides]


LOCALES = Path(kinematika.explain.__file__).parent / "locales"


def _opening(key: str, lang: str) -> str:
    """The words a catalogue message opens with, before its first placeable."""
    line = next(x for x in (LOCALES / f"{lang}.ftl").read_text(encoding="utf-8").splitlines()
                if x.startswith(f"{key} = "))
    return line.split(" = ", 1)[1].split("{", 1)[0].strip()


@over(name=SEEDS, lang=LANGS)
def test_a_centre_is_placed_once(name, lang):
    """No centre is placed again, as a check, from the velocities once the page has placed it
    (C5-2.2's "check with the velocities found: … the same point: I_S2"): each instant
    centre of a page is derived once."""
    opening = _opening("centre-check", lang)
    assert len(opening) > 10
    assert opening not in _text(name, lang)


LEGEND = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}   # twelfth round
OMEGA = re.compile(r"ω_(\{[^}]*\}|(?:[^\s{}()|·,;:²/−+=×]|·(?=[a-zà-ÿ]{2}))+)")


@over(name=SEEDS, lang=LANGS)
def test_a_shortened_subscript_is_defined_on_the_page(name, lang):
    """Every ω_X the page writes is a body's whole name as written (ω_besoa, ω_{roda sup} is
    a name the model gives), a number (the structure's table), or defined once on the page
    ("Notation: ω_wheel is the angular velocity of the *fixed central wheel*", C5-E.2): never a symbol
    shortened away from a body's name that the student must guess."""
    from kinematika.model.subscripts import CODE, _words, read_off

    sol, _ = explained(name)
    spelt = sol.model.wording.bodies.get(lang, {})
    whole = {" ".join(_words(n)) for n in spelt.values()}
    whole |= {b for b in sol.model.bodies if b not in spelt}     # unnamed: the model's own word
    whole |= {w for n in spelt.values() for w in _words(n) if CODE.match(w)}   # ω_N of N blokea
    from kinematika.model.wording import PART_SUBSCRIPTS

    joining = {f" {words[lang]} " for words in PART_SUBSCRIPTS.values()}    # ω_{a rel b}: two names
    joining.add(f" {sol.model.wording.relative_word(lang)} ")             # the model's own (001: rel)
    points = set(sol.model.points)
    text = _text(name, lang)
    for sub in {m.group(1).strip("{}") for m in OMEGA.finditer(text)}:
        if sub.isdigit() or sub in whole or any(w in sub for w in joining):
            continue
        if any(read_off(sub, n, lang) for n in spelt.values()):
            continue                        # the name run together (ω_politja1): fifteenth round (b)
        if any(sub in (a + b, f"{a}-{b}") for a in points for b in points if a != b):
            continue                        # a bar's rate by its two points: C5-1.8's ω_OC (the notes' Ω_OC)
        legend = next((line for line in text.splitlines() if line.startswith(LEGEND[lang])), "")
        assert re.search(rf"ω_(?:{re.escape(sub)}|\{{{re.escape(sub)}\}}) \S", legend), sub   # "Notation: ω_X is …"


@over(name=SEEDS, lang=LANGS)
def test_the_mechanism_caption_says_which_velocities_it_draws(name, lang):
    """The mechanism's caption names the points whose velocities the figure draws (one arrow:
    "the arrow is the velocity of B"; C5-E.4's P at rest: "P is at rest"), never "the arrows
    are the velocities of its points" over a figure of one arrow or none."""
    from kinematika.draw.build import build_scene
    from kinematika.draw.options import DrawOptions
    from kinematika.explain.document import Drawing

    sol, doc = explained(name)
    fig = next(b for b in doc.blocks() if isinstance(b, Drawing) and b.caption.key == "fig.mechanism")
    scene = build_scene(sol.inst, sol, DrawOptions(**fig.options))
    drawn = {v.ref.split("@", 1)[0] for v in scene.vectors if v.kind == "velocity"}
    opening = _opening("fig-mechanism_named", lang).split(",")[0]
    caption = next(line for line in rendered(name, lang, "md").splitlines() if line.startswith("*" + opening))
    assert drawn, "the figure draws no velocity"
    for p in drawn:
        assert re.search(rf"(?<![\w-]){re.escape(p)}(?![\w-])", caption), (p, caption[:160])
