"""Issue 30, twenty-fourth round (c): the composition section and its symbols (docs/explain.md,
"Twenty-fourth round (c)").

- each half of a composition says which it opens: "Velocities. Drag:" … "Accelerations.
  Drag:" (001 p_pair, 001 rolling, C5-1.3 wrote "Drag:" twice, nothing between);
- the intro's Coriolis term in the page's own symbols, 2 ω_M × v_{B∈N rel M} (never the
  generic "2 ω × v_REL" of a vector the page does not write); one word joins two names in
  a subscript, rel, on every page and in every language (Catalan wrote "rel." on C5 pages
  and "rel" on 001's);
- a drag velocity with two names (v_ar,B, v_B∈M) is equated once, before either is used
  beside the other; a relative rotation term is v_{AF rel N}, not v_{AF,R rel N};
- a term's magnitude and direction are written with the term's own segment, above it and in
  the line below (v_AO1: ω·AO1; a_JC^n: ω²·JC, ∥ JC).
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, body_of, over, rendered

SECTION = {"en": "## Composition of motions", "es": "## Composición de movimientos",
           "ca": "## Composició de moviments", "eu": "## Mugimenduen konposizioa"}
DRAG = {"en": "Drag:", "es": "Arrastre:", "ca": "Arrossegament:", "eu": "Arrastrea:"}
HALVES = {"en": ("Velocities", "Accelerations"), "es": ("Velocidades", "Aceleraciones"),
          "ca": ("Velocitats", "Acceleracions"), "eu": ("Abiadurak", "Azelerazioak")}
POINT = {"en": "Point ", "es": "Punto ", "ca": "Punt ", "eu": " puntua"}
RELATIVE = {"en": "Relative: ", "es": "Relativo: ", "ca": "Relatiu: ", "eu": "Erlatiboa: "}


def _composition(md: str, lang: str) -> str:
    """The composition section of a Markdown page ('' when it has none)."""
    if SECTION[lang] not in md:
        return ""
    return md.split(SECTION[lang], 1)[1].split("\n## ", 1)[0]


@over(name=SEEDS, lang=LANGS)
def test_each_half_of_a_composition_says_which(name: str, lang: str) -> None:
    """Every drag heading names its half, velocities then accelerations, once a composed
    point: never "Drag:" alone, twice with nothing to tell the halves apart."""
    sec = _composition(rendered(name, lang, "md", drawings=False), lang)
    heads = [line.strip() for line in sec.splitlines() if line.strip().endswith(DRAG[lang])]
    points = [line for line in sec.splitlines() if line.endswith(":") and POINT[lang] in line
              and not line.strip().endswith(DRAG[lang])]
    vel, acc = HALVES[lang]
    assert heads == [f"{vel}. {DRAG[lang]}", f"{acc}. {DRAG[lang]}"] * len(points), heads


def test_the_three_compositions_are_halved() -> None:
    """The three pages a reader read (001 p_pair, 001 rolling, C5-1.3) in four languages have a
    composition, so the rule above is not met by having none."""
    for name in ("seed_001_p_pair_coriolis", "seed_001_rolling_pair", "seed_c5_1_3_bar_in_sleeve"):
        for lang in LANGS:
            sec = _composition(rendered(name, lang, "md", drawings=False), lang)
            assert f"{HALVES[lang][1]}. {DRAG[lang]}" in sec, (name, lang)


@over(name=SEEDS, lang=LANGS)
def test_the_coriolis_term_in_the_pages_symbols(name: str, lang: str) -> None:
    """The intro's Coriolis term is 2 ω_M × v_{…} with the relative velocity the section
    writes ("Relative: v_{B∈N rel M}, …") and the moving frame's ω, never a bare v_rel/v_REL."""
    sec = _composition(rendered(name, lang, "md", drawings=False), lang)
    if not sec:
        return
    intro = sec.strip().splitlines()[0]
    terms = re.findall(r"2 (ω_\S+) × (v_\{[^}]*\}|v_\S+?)[.,]", intro)
    assert terms, intro
    rel = [m.group(1) for m in re.finditer(re.escape(RELATIVE[lang]) + r"(v_\{[^}]*\}|v_\S+?),", sec)]
    assert {v for _, v in terms} == set(rel), (terms, rel)
    assert not re.search(r"\bv_(?:rel|REL)\b", intro), intro
    for w, v in terms:            # ω of the frame the relative velocity is seen from
        frame = re.search(r" rel (.+)\}$", v)
        assert frame and w in (f"ω_{frame.group(1)}", f"ω_{{{frame.group(1)}}}"), (w, v)


@over(name=SEEDS, lang=LANGS)
def test_one_word_joins_two_names(name: str, lang: str) -> None:
    """A subscript joins a body to the one it is seen from with rel, the same on every page
    and in every language (Catalan wrote v_{Q∈barra rel. suport} on C5-1.3 and v_{B∈N rel M}
    on 001)."""
    text = body_of(rendered(name, lang, "md", drawings=False))
    joined = set(re.findall(r"_\{[^}\n]* (rel\.?|REL|resp\.) [^}\n]*\}", text))
    assert joined <= {"rel"}, joined


@over(name=SEEDS, lang=LANGS)
def test_a_relative_term_names_no_body(name: str, lang: str) -> None:
    """A relative rotation term names its segment and the frame, v_{AF rel N}: its equation's
    target names the body (001 rolling's "v_{AF,R rel N}", a subscript of six parts)."""
    text = rendered(name, lang, "md", drawings=False)
    assert not re.search(r"[va]_\{[A-Z][A-Za-z0-9]*,[^}∈]+ rel [^}]+\}", text), name


@over(name=SEEDS, lang=LANGS)
def test_a_drag_with_two_names_is_equated_once(name: str, lang: str) -> None:
    """Where the drag velocity is a velocity the steps name (001's v_B∈M), the page writes
    v_ar,B = v_B∈M once, before its first v_ar,B (the figure's caption uses it), and never
    again."""
    text = body_of(rendered(name, lang, "md"))
    for drag, other in set(re.findall(r"([va]_\{\w+,\w+\}) = ([va]_\{\w+∈[^}]+\})", text)):
        equality = f"{drag} = {other}"
        assert text.count(equality) == 1, (equality, text.count(equality))
        assert text.index(equality) <= text.index(drag), (drag, text[text.index(drag) - 80:text.index(drag) + 40])


def test_the_guides_drag_is_equated_in_the_notation() -> None:
    """001 p_pair (ca): the notation line says v_ar,B = v_B∈M; the composition writes v_ar,B."""
    md = rendered("seed_001_p_pair_coriolis", "ca", "md", drawings=False)
    note = next(line for line in md.splitlines() if line.startswith("Notació:"))
    assert "v_{ar,B} = v_{B∈M} és la velocitat d’arrossegament de B" in note
    assert "a_{ar,B} = a_{B∈M} és l’acceleració d’arrossegament de B" in note
    assert "v_{ar,B} = (−0,8; 1,386) m/s" in md


CODE = re.compile(r"```\n(.*?)```", re.S)
TAIL = re.compile(r"·([A-Z][A-Za-z0-9′]*)$")


def _own(sub: str) -> str:
    """The segment a term's subscript names, its points in its order: a_{J^{geom}O}^n → JO,
    v_{AF rel N} → AF, v_{C1-J1} → C1J1."""
    sub = re.sub(r"\^\{?[ntNT]\}?$", "", sub)          # Basque a^N, a^T (twenty-seventh round (g))
    sub = re.sub(r"\^\{geom\}", "", sub).strip("{}")
    return sub.split(" rel ")[0].replace("-", "")


@over(name=SEEDS, lang=LANGS)
def test_a_terms_segment_is_its_own(name: str, lang: str) -> None:
    """Above a term (ω·XY, ω²·XY, α·XY), under it (⊥ XY, ∥ XY) and in its magnitude line
    (|a_XY^n| = ω² · XY), the segment is the term's own, its subscript's order (001 r_pairs
    wrote "ω_O1A² · AO1" under "ω_O1A²·O1A"; C5-1.8 "ω_roda²·CJ" over "a_JC^n ∥ JC")."""
    text = rendered(name, lang, "md", drawings=False)
    for block in CODE.findall(text):
        rows = block.rstrip("\n").split("\n")
        if len(rows) != 3:
            continue
        top, mid, bottom = rows
        terms = re.split(r"\s{2,}[=+]\s{2,}", mid.strip())
        above, below = re.split(r"\s{2,}", top.strip()), re.split(r"\s{2,}", bottom.strip())
        if not (len(terms) == len(above) == len(below)):
            continue
        for term, mag, way in zip(terms, above, below):
            sub = term.split("_", 1)[1] if "_" in term else ""
            m = TAIL.search(mag)
            if m and re.match(r"[va]_", term):
                assert _same(m.group(1), _own(sub)), (term, mag)
                seg = re.match(r"[⊥∥] (\S+)$", way)
                assert seg is None or _same(seg.group(1), _own(sub)), (term, way)
    for m in re.finditer(r"\|([va])_(\S+?)\| = \S+ · (\S+?), ", text):
        assert _same(m.group(3), _own(m.group(2))), m.group(0)


def _same(segment: str, own: str) -> bool:
    """Whether a written segment is the term's own: the same letters in order, or, for a term
    named by one point (a_S, the point S about the contact J), a segment from that point."""
    if re.fullmatch(r"[A-Z][a-z0-9′]*", own):
        return segment.startswith(own) and segment != own
    return segment == own
