"""Issue 30, thirteenth round (a): what the readers of stop 41 quoted and graded B for —
contact points drawn without their letters, a segment written with a space beside a centre's
symbol ("I_S2 P"), M/D/? marks on a trivial equality (v_T2 = v_T1), and "welded" for a part
fixed to the frame. Each test is a rule checked over the 19 seeds in the languages where it
applies, and fails on the pages those readers read (main at dd647e2)."""
from __future__ import annotations

import base64
import re


from kinematika.draw.names import contact_names

from .helpers import LANGS, SEEDS, SVG, body_of, explained, rendered, over

CODE = re.compile(r"```.*?```", re.S)


def _text(page: str) -> str:
    """The Markdown page's prose and lists, without its code blocks (whose M marks are no
    point's name) and without its figures."""
    text = CODE.sub("", SVG.sub("", body_of(page)))
    # the marks' legend ("M magnitude known, D direction known, ? unknown; ⊥ and ∥ …") names no point
    return "\n".join(line for line in text.split("\n") if not ("?" in line and "⊥" in line and "∥" in line))


def _figure_labels(page: str) -> set[str]:
    """Every label the page's `draw` figures set (matplotlib's comment for each text)."""
    out: set[str] = set()
    for b64 in SVG.findall(page):
        out |= {c.strip() for c in re.findall(r"<!--(.*?)-->", base64.b64decode(b64).decode("utf-8"), re.S)}
    return out


def _named(text: str, name: str) -> bool:
    return re.search(rf"(?<![\w′']){re.escape(name)}(?![\w′'])", text) is not None


@over(name=SEEDS, lang=LANGS)
def test_contact_points_labelled_as_the_text_names_them(name, lang):
    """Every contact point the text names (J, K, T2 … that is no model point: those are
    labelled already) is labelled in the figures with the text's letter; a contact the text
    never names has no letter there. C5-1.1's J and K were two dots without letters."""
    sol, _ = explained(name)
    page = rendered(name, lang)
    text, labels = _text(page), _figure_labels(page)
    if not SVG.findall(page):
        return
    for jid, contact in contact_names(sol.model, sol).items():
        if contact in sol.model.points:
            continue
        if _named(text, contact):
            assert contact in labels, (name, lang, jid, contact)
        else:
            assert contact not in labels, (name, lang, jid, contact)


def test_pulley_on_cable_figure_has_j_and_k():
    """C5-1.1 by hand: the pulley touches the left strand at J and the right one at K, and
    the page says so; the mechanism's figure and the centres' figure both show J and K."""
    page = rendered("seed_c5_1_1_pulley_on_cable", "ca")
    for b64 in SVG.findall(page)[:2]:
        comments = {c.strip() for c in re.findall(r"<!--(.*?)-->", base64.b64decode(b64).decode(), re.S)}
        assert {"J", "K"} <= comments


# a segment whose one end is a centre's symbol, written with a space: "I_S2 P", "D I_roda1",
# "v_{O I_OJ}" (Markdown) and its HTML form (the symbol, a space, a point's span)
SPACED_MD = re.compile(r"I_(?:\{[^}]*\}|[^\s{}|,;:)]+) [A-Z][0-9]?(?![\w(])|(?<![\w])[A-Z][0-9]? I_")
SPACED_HTML = re.compile(r"<i>I</i><sub>[^<]*</sub> <span class=\"pt\">|</span> <i>I</i><sub>")


@over(name=SEEDS, lang=LANGS)
def test_segment_to_a_centre_runs_together(name, lang):
    """A segment from a centre's symbol to a point is written as every segment of the page,
    its two ends side by side: I_{S2}P, DI_{roda1}, v_{OI_{OJ}} (Markdown, the subscript
    closed), I<sub>S2</sub>P (HTML) — never "I_S2 P" or "D I_roda1"."""
    md = _text(rendered(name, lang)) + "\n".join(CODE.findall(body_of(rendered(name, lang))))
    bad = [m.group(0) for m in SPACED_MD.finditer(md)]
    assert not bad, (name, lang, bad[:5])
    html = SVG.sub("", rendered(name, lang, "html"))
    assert not SPACED_HTML.search(html), (name, lang)


def test_articulated_arm_is_written_as_the_notes_set_it():
    """C5-2.2 by hand: P turns about S2's centre I_S2, so v_P = ω_S2 × I_S2P and
    the segment I_{S2}P in Markdown and I<sub>S2</sub>P in HTML (ω_S2 is read off the term's x
    component since the twenty-fifth round (d), not off |v_P| / I_S2P)."""
    md = rendered("seed_c5_2_2_articulated", "en")
    assert "ω_S2 × I_{S2}P" in md
    html = rendered("seed_c5_2_2_articulated", "en", "html")
    assert re.search(r'<i>I</i><sub>S2</sub>(<span class="pt">)?P', html)


def _equalities(name: str) -> list:
    """The seed's equations of one point's motion set equal to another's (v_T2 = v_T1)."""
    _, doc = explained(name)
    return [e for e in doc.equations() if len(e.sides) == 1 and len(e.sides[0]) == 1
            and e.sides[0][0].kind == "point" and e.target.kind == "point"]


@over(name=SEEDS, lang=LANGS)
def test_trivial_equality_has_no_marks(name, lang):
    """v_T2 = v_T1 (two points of one contact, a point shared by two bodies, the points of a
    strand that translates) is one line, "v_T2 = v_T1 = (0; −2·v)", with no M/D/? rows: a
    vector equation of one term is not a polygon. Equations of two or more terms keep them."""
    blocks = "\n".join(CODE.findall(body_of(rendered(name, lang))))
    for e in _equalities(name):
        a, b = (re.escape(s.split("∈")[0]) for s in (e.target.sym.sub, e.sides[0][0].sym.sub))
        row = rf"(?m)^\s*[va]_\{{?{a}\b[^=\n]*=\s+[va]_\{{?{b}\b[^+=\n]*$"
        assert not re.search(row, blocks), (name, lang, a, b)
        assert e.equality


def test_pulley_block_strand_velocity_is_a_plain_equality():
    """C5-1.5 by hand: strand 2 translates, so its points T2 and T1 have one velocity, which
    T1's strand gives, v_T1 = (0, −2v) (the block rises at v, the free strand at 2v): the page
    writes "v_T2 = v_{T1∈pulley1} = (0, −2·v)" after its reason (T1 written once, as the
    pulley's material point: the sixteenth round (b))."""
    md = rendered("seed_c5_1_5_pulley_block", "en")
    assert "All the points of *strand 2* have one velocity:\n\nv_T2 = v_{T1∈pulley1} = (0, −2·v)\n" in md
    assert len(_equalities("seed_c5_1_5_pulley_block")) == 4


WELD = re.compile(r"weld|soldat|soldad|unid[oa]s? rígidamente|units? rígidament|unió rígida|unión rígida", re.I)


@over(name=SEEDS, lang=LANGS)
def test_no_weld_words(name, lang):
    """The notes say a part is fixed to the ground ("fixa a terra") and two bodies solidaris
    ("el pinyó és solidari a la roda posterior"), one rigid body: no "welded", "soldat",
    "unit rígidament" in any language (Basque keeps the notes' "lotuta")."""
    page = body_of(rendered(name, lang))
    bad = WELD.findall(SVG.sub("", page))
    assert not bad, (name, lang, bad[:3])


def test_the_planes_are_fixed_to_the_ground():
    """C5-1.2: the two planes are part of the ground, said as the notes say it."""
    # the frame's row names them (twenty-ninth round (b): no rows of their own)
    assert "| 1 | *ground* (fixed), with the *left plane* and the *right plane* |" in rendered("seed_c5_1_2_bar_on_inclined_wheels", "en")
    assert "| 1 | *terra* (fix), amb el *pla esquerre* i el *pla dret* |" in rendered("seed_c5_1_2_bar_on_inclined_wheels", "ca")
    assert "solidaris: un sol sòlid rígid" in rendered("seed_c5_e6_bicycle", "ca")
